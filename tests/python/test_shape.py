# SPDX-License-Identifier: MIT
"""Shape: every kind, its geometry and material."""

import math

import pytest

import impulse2d
from conftest import close, make_ground


def test_every_kind_and_its_geometry(world):
    body = world.create_body(impulse2d.STATIC, position=(1.0, 0.0))
    circle = body.create_circle(0.5, center=(0.25, 0.0))
    box = body.create_box(1.0, 0.5)
    polygon = body.create_polygon([(0, 0), (1, 0), (0, 1)])
    capsule = body.create_capsule((0, 0), (1, 0), 0.25)
    segment = body.create_segment((-1, 0), (1, 0))
    assert [s.type for s in (circle, box, polygon, capsule, segment)] == [
        impulse2d.ShapeType.CIRCLE,
        impulse2d.ShapeType.POLYGON,
        impulse2d.ShapeType.POLYGON,
        impulse2d.ShapeType.CAPSULE,
        impulse2d.ShapeType.SEGMENT,
    ]
    assert circle.geometry() == ((0.25, 0.0), 0.5)
    assert sorted(box.geometry()) == sorted([(-1.0, -0.5), (1.0, -0.5), (1.0, 0.5), (-1.0, 0.5)])
    assert len(polygon.geometry()) == 3
    assert capsule.geometry() == ((0.0, 0.0), (1.0, 0.0), 0.25)
    assert segment.geometry() == ((-1.0, 0.0), (1.0, 0.0))
    lower, upper = circle.aabb
    assert close(lower, (0.75, -0.5)) and close(upper, (1.75, 0.5))
    assert circle.body == body and circle.world is world


def test_material_filter_and_sensor(world):
    body = world.create_body()
    shape = body.create_circle(0.5, density=3.0, friction=0.2, restitution=0.4, filter=(2, 5, -1))
    assert shape.density == 3.0
    assert abs(shape.friction - 0.2) < 1e-7 and abs(shape.restitution - 0.4) < 1e-7
    assert shape.filter == (2, 5, -1)
    shape.friction = 0.9
    shape.restitution = 0.0
    shape.filter = (1, 0xFFFF)
    assert abs(shape.friction - 0.9) < 1e-7 and shape.restitution == 0.0 and shape.filter == (1, 0xFFFF, 0)
    sensor = body.create_box(1.0, 1.0, is_sensor=True)
    assert sensor.is_sensor and not shape.is_sensor
    with pytest.raises(impulse2d.InvalidArgument, match="friction"):
        shape.friction = -1.0
    with pytest.raises(TypeError, match="unknown shape setting"):
        body.create_circle(0.5, bounciness=1.0)


def test_destroy(world):
    body = world.create_body()
    shape = body.create_circle(0.5)
    shape.destroy()
    assert not shape.is_valid and body.shapes == []
    with pytest.raises(impulse2d.InvalidHandle, match="stale"):
        shape.friction


# ---- Runtime changes and contact data (issue 40) ------------------------------------------


def test_a_grown_circle_rises(world):
    make_ground(world)
    ball = world.create_body(position=(0.0, 0.5))
    shape = ball.create_circle(0.5, density=1.0)
    for _ in range(60):
        world.step()
    assert abs(ball.position[1] - 0.5) < 0.02
    shape.set_circle(1.0)
    assert shape.geometry() == ((0.0, 0.0), 1.0)
    assert math.isclose(ball.mass, math.pi, rel_tol=1e-5)
    for _ in range(120):
        world.step()
    assert abs(ball.position[1] - 1.0) < 0.02
    with pytest.raises(impulse2d.InvalidArgument):
        shape.set_circle(-1.0)


def test_new_geometry_of_every_kind(world):
    body = world.create_body(impulse2d.STATIC)
    shape = body.create_circle(0.5)
    shape.set_capsule((0, 0), (1, 0), 0.25)
    assert shape.type == impulse2d.ShapeType.CAPSULE and shape.geometry() == ((0.0, 0.0), (1.0, 0.0), 0.25)
    shape.set_segment((-1, 0), (1, 0))
    assert shape.type == impulse2d.ShapeType.SEGMENT and shape.geometry() == ((-1.0, 0.0), (1.0, 0.0))
    shape.set_polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    assert shape.type == impulse2d.ShapeType.POLYGON and sorted(shape.geometry()) == [(0, 0), (0, 1), (1, 0), (1, 1)]
    with pytest.raises(impulse2d.InvalidArgument):
        shape.set_polygon([(0, 0), (1, 0)])
    with pytest.raises(impulse2d.InvalidArgument):
        shape.set_segment((0, 0), (float("nan"), 0))
    assert shape.type == impulse2d.ShapeType.POLYGON  # refused: untouched


def test_density_and_body_mass(world):
    body = world.create_body()
    shape = body.create_box(0.5, 0.5, density=1.0)
    assert math.isclose(body.mass, 1.0, rel_tol=1e-6)
    shape.set_density(3.0, update_body_mass=False)
    assert shape.density == 3.0 and math.isclose(body.mass, 1.0, rel_tol=1e-6)
    body.apply_mass_from_shapes()
    assert math.isclose(body.mass, 3.0, rel_tol=1e-6)
    shape.set_density(2.0)
    assert math.isclose(body.mass, 2.0, rel_tol=1e-6)
    with pytest.raises(impulse2d.InvalidArgument):
        shape.set_density(-1.0)


def test_material_and_event_flags(world):
    shape = world.create_body().create_circle(0.5, friction=0.25, restitution=0.5)
    assert shape.material == impulse2d.SurfaceMaterial(0.25, 0.5, 0.0, 0.0)
    shape.material = impulse2d.SurfaceMaterial(0.75, 0.125, 0.5, 2.0)
    assert shape.material == (0.75, 0.125, 0.5, 2.0) and shape.friction == 0.75
    with pytest.raises(impulse2d.InvalidArgument):
        shape.material = (-1.0, 0.0, 0.0, 0.0)
    assert shape.material == (0.75, 0.125, 0.5, 2.0)
    for name in ("sensor_events_enabled", "contact_events_enabled", "hit_events_enabled"):
        for value in (True, False):
            setattr(shape, name, value)
            assert getattr(shape, name) is value
    shape.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        shape.material
    with pytest.raises(impulse2d.InvalidHandle):
        shape.hit_events_enabled


def test_a_sensor_lists_its_visitor(world):
    world.gravity = (0.0, 0.0)
    gate = world.create_body(impulse2d.STATIC)
    sensor = gate.create_box(1.0, 1.0, is_sensor=True)
    solid = gate.create_box(0.1, 0.1, center=(5.0, 0.0))
    visitor = world.create_body(position=(0.25, 0.0)).create_circle(0.25, enable_sensor_events=True)
    world.create_body(position=(10.0, 0.0)).create_circle(0.25, enable_sensor_events=True)  # outside
    assert sensor.sensor_overlaps() == []
    world.step()
    assert sensor.sensor_overlaps() == [visitor]
    visitor.body.position = (20.0, 0.0)
    world.step()
    assert sensor.sensor_overlaps() == []
    with pytest.raises(impulse2d.InvalidArgument):
        solid.sensor_overlaps()


def test_closest_point(world):
    shape = world.create_body(impulse2d.STATIC, position=(2.0, 0.0)).create_circle(1.0)
    assert close(shape.closest_point((5.0, 0.0)), (3.0, 0.0))
    assert shape.closest_point((2.5, 0.25)) == (2.5, 0.25)  # inside: the target itself
    with pytest.raises(impulse2d.InvalidArgument):
        shape.closest_point((float("nan"), 0.0))


def test_contact_data_of_one_shape(world):
    make_ground(world)
    body = world.create_body(position=(0.0, 0.5))
    low = body.create_box(0.5, 0.5)
    high = body.create_circle(0.25, center=(0.0, 2.0))
    for _ in range(60):
        world.step()
    [contact] = low.contact_data()
    assert low in (contact.shape_a, contact.shape_b) and len(contact.points) == 2
    assert high.contact_data() == [] and body.contact_data() == [contact]


def test_distance_between_two_circles():
    r = impulse2d.shape_distance([(0.0, 0.0)], [(3.0, 0.0)], radius_a=0.5, radius_b=1.0)
    assert r == impulse2d.DistanceResult((0.5, 0.0), (2.0, 0.0), (1.0, 0.0), 1.5)
    # the same circles placed by their transforms
    moved = impulse2d.shape_distance([(0.0, 0.0)], [(0.0, 0.0)], 0.5, 1.0, position_a=(1.0, 1.0), position_b=(1.0, 4.0))
    assert close(moved.point_a, (1.0, 1.5)) and close(moved.normal, (0.0, 1.0)) and math.isclose(moved.distance, 1.5)
    # a unit square turned 45 degrees reaches sqrt(2)/2 towards a point 2 away
    square = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    turned = impulse2d.shape_distance(square, [(2.0, 0.0)], angle_a=math.pi / 4)
    assert math.isclose(turned.distance, 2.0 - math.sqrt(0.5), rel_tol=1e-5)
    overlap = impulse2d.shape_distance([(0.0, 0.0)], [(0.5, 0.0)], 0.5, 0.5)
    assert overlap.distance == 0.0 and overlap.normal == (0.0, 0.0)
    with pytest.raises(impulse2d.InvalidArgument):
        impulse2d.shape_distance([(i, 0.0) for i in range(9)], [(0.0, 0.0)])
    with pytest.raises(impulse2d.InvalidArgument):
        impulse2d.shape_distance([], [(0.0, 0.0)])
    with pytest.raises(impulse2d.InvalidArgument):
        impulse2d.shape_distance([(0.0, 0.0)], [(1.0, 0.0)], radius_a=-1.0)
