# SPDX-License-Identifier: MIT
"""Box2D shapes, fixtureDef and fixtures: geometry kept in the body frame, defs reused
and edited, fixture properties, sensors set later, and bad shapes refused."""

import math

import pytest

import impulse2d
from box2d_compat_fixture import Box2D, b2, step


def test_polygon_box_circle_and_edge_descriptions():
    square = b2.polygonShape(box=(1, 2))
    assert square.vertices == [(-1, -2), (1, -2), (1, 2), (-1, 2)] and square.vertexCount == 4
    turned = b2.polygonShape()
    turned.SetAsBox(1, 0.5, (2, 0), math.pi / 2)
    xs = sorted(round(v[0], 6) for v in turned.vertices)
    assert xs == [1.5, 1.5, 2.5, 2.5] and turned.centroid == pytest.approx((2, 0))
    # a hull, counter-clockwise, from points given in any order (and one inside)
    hull = b2.polygonShape(vertices=[(0, 0), (1, 1), (1, 0), (0, 1), (0.5, 0.5)])
    assert len(hull.vertices) == 4 and set(hull.vertices) == {(0, 0), (1, 0), (1, 1), (0, 1)}
    area2 = sum(x1 * y2 - x2 * y1 for (x1, y1), (x2, y2) in zip(hull.vertices, hull.vertices[1:] + hull.vertices[:1]))
    assert area2 == pytest.approx(2.0)  # positive: counter-clockwise
    disc = b2.circleShape(radius=0.25, pos=(1, 2))
    assert disc.radius == 0.25 and disc.pos == (1, 2) and disc.type == Box2D.b2Shape.e_circle
    edge = b2.edgeShape(vertices=[(0, 0), (3, 0)])
    assert edge.vertices == [(0, 0), (3, 0)] and edge.vertex2 == (3, 0)


def test_fixture_def_fields_reach_the_fixture():
    world = Box2D.b2World()
    fd = b2.fixtureDef(shape=b2.polygonShape(box=(0.5, 0.5)), density=3, friction=0.4, restitution=0.25,
                       categoryBits=0x0020, maskBits=0x0001, groupIndex=-2, userData="leg")
    assert (fd.categoryBits, fd.maskBits, fd.groupIndex) == (0x20, 0x1, -2)
    body = world.CreateDynamicBody(fixtures=fd)
    f = body.fixtures[0]
    assert f.body is body and f.userData == "leg" and not f.sensor and f.type == Box2D.b2Shape.e_polygon
    assert f.density == 3 and f.friction == pytest.approx(0.4) and f.restitution == pytest.approx(0.25)
    assert (f.filterData.categoryBits, f.filterData.maskBits, f.filterData.groupIndex) == (0x20, 0x1, -2)
    assert body.mass == pytest.approx(3.0)
    f.density = 1
    assert body.mass == pytest.approx(1.0)
    f.friction = 0.9
    assert f.friction == pytest.approx(0.9)
    view = f.filterData
    view.maskBits = 0x3  # refilters at once (pybox2d's copy would not)
    assert impulse2d.Shape(world.impulse2d_world, f._id).filter == (0x20, 0x3, -2)
    copy = b2.filter(categoryBits=0x40, maskBits=0x1, groupIndex=0)
    f.filterData = copy
    assert (view.categoryBits, view.maskBits, view.groupIndex) == (0x40, 0x1, 0)
    assert f.TestPoint(body.position) and not f.TestPoint((5, 5))
    lo, hi = f.aabb.lowerBound, f.aabb.upperBound
    assert lo == pytest.approx((-0.5, -0.5)) and hi == pytest.approx((0.5, 0.5))


def test_defs_and_shapes_are_reused_and_edited_between_bodies():
    world = Box2D.b2World()
    fd = b2.fixtureDef(shape=b2.polygonShape(vertices=[(0, 0), (1, 0), (1, 1)]), density=1)
    first = world.CreateStaticBody(fixtures=fd)
    fd.shape.vertices = [(0, 0), (2, 0), (2, 2), (0, 2)]  # BipedalWalker edits the def's shape
    second = world.CreateStaticBody(fixtures=fd)
    assert len(first.fixtures[0].shape.vertices) == 3  # the fixture kept its own copy
    assert second.fixtures[0].shape.vertices == [(0, 0), (2, 0), (2, 2), (0, 2)]
    assert type(second.fixtures[0].shape) is b2.polygonShape


def test_create_fixture_styles():
    world = Box2D.b2World()
    body = world.CreateDynamicBody()
    a = body.CreatePolygonFixture(box=(1, 1), density=1)
    b = body.CreateCircleFixture(radius=1, pos=(3, 0), density=2)
    c = body.CreateFixture(shape=b2.edgeShape(vertices=[(0, 0), (1, 0)]))
    d = body.CreateFixture(b2.fixtureDef(shape=b2.circleShape(radius=0.5)))
    e = body.CreateFixture(b2.circleShape(radius=0.5), density=0)
    assert type(b.shape) is b2.circleShape and b.shape.pos == (3, 0) and b.shape.radius == 1
    assert set(body.fixtures) == {a, b, c, d, e}
    assert body.mass == pytest.approx(4 + 2 * math.pi, rel=1e-5)
    body.DestroyFixture(b)
    assert b not in body.fixtures and body.mass == pytest.approx(4.0, rel=1e-5)


def test_sensor_toggles_keep_the_same_fixture():
    world = Box2D.b2World()
    body = world.CreateStaticBody(fixtures=b2.fixtureDef(shape=b2.polygonShape(box=(1, 1)), userData="tile"))
    fixture = body.fixtures[0]
    fixture.sensor = True
    assert body.fixtures[0] is fixture and fixture.sensor and fixture.userData == "tile"
    assert impulse2d.Shape(world.impulse2d_world, fixture._id).is_sensor
    ball = world.CreateDynamicBody(position=(0, 3))
    ball.CreateCircleFixture(radius=0.5, density=1)
    step(world, 1.5)
    assert ball.position.y < -1  # fell through the sensor
    fixture.sensor = False
    assert not impulse2d.Shape(world.impulse2d_world, fixture._id).is_sensor


def test_bad_shapes_raise_with_the_library_message():
    with pytest.raises(impulse2d.InvalidArgument) as error:
        b2.polygonShape(vertices=[(0, 0)])
    assert "i2d_make_polygon" in str(error.value)
    with pytest.raises(impulse2d.InvalidArgument):
        b2.polygonShape(vertices=[(0, 0), (1, 0), (2, 0)])  # collinear: no area
    with pytest.raises(impulse2d.InvalidArgument):
        b2.edgeShape(vertices=[(0, 0)])
    world = Box2D.b2World()
    body = world.CreateDynamicBody()
    with pytest.raises(impulse2d.InvalidArgument) as error:
        body.CreateCircleFixture(radius=-1, density=1)
    assert "i2d_shape_create_circle" in str(error.value)
    with pytest.raises(impulse2d.InvalidArgument) as error:
        body.CreatePolygonFixture(box=(1, 1), density=-1)
    assert "density" in str(error.value)
    with pytest.raises(impulse2d.InvalidArgument):
        body.CreateFixture(b2.fixtureDef(shape=b2.polygonShape()))  # no vertices yet
    assert body.fixtures == []
