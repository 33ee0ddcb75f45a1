# SPDX-License-Identifier: MIT
"""Shape: every kind, its geometry and material."""

import pytest

import impulse2d
from conftest import close


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
