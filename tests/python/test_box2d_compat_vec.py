# SPDX-License-Identifier: MIT
"""Box2D.b2Vec2, b2Transform and b2Rot: values, arithmetic and tuple interchange."""

import math

import pytest

from box2d_compat_fixture import Box2D, b2


def test_vec2_is_a_sequence_of_two_floats():
    v = Box2D.b2Vec2(3, 4)
    assert len(v) == 2 and v[0] == 3.0 and v[1] == 4.0 and v[-1] == 4.0
    assert list(v) == [3.0, 4.0] and tuple(v) == (3.0, 4.0) and v.tuple == (3.0, 4.0)
    x, y = v
    assert (x, y) == (3.0, 4.0)
    with pytest.raises(IndexError):
        v[2]
    assert Box2D.b2Vec2((1, 2)) == (1, 2) and Box2D.b2Vec2() == (0, 0)
    assert b2.vec2 is Box2D.b2Vec2


def test_vec2_arithmetic_and_length():
    a, b = Box2D.b2Vec2(1, 2), Box2D.b2Vec2(3, -1)
    assert a + b == (4, 1) and a - b == (-2, 3) and (1, 1) + a == (2, 3) and (5, 5) - a == (4, 3)
    assert a * 2 == (2, 4) and 2 * a == (2, 4) and a / 2 == (0.5, 1) and -a == (-1, -2)
    assert isinstance(a * 2.0, Box2D.b2Vec2) and isinstance((1, 1) + a, Box2D.b2Vec2)
    assert Box2D.b2Vec2(3, 4).length == 5.0 and Box2D.b2Vec2(3, 4).lengthSquared == 25.0
    assert a.dot(b) == 1.0 and a.cross(b) == -7.0
    c = Box2D.b2Vec2(0, 10)
    assert c.Normalize() == 10.0 and c == (0, 1)
    c += (1, 1)
    assert c == (1, 2)
    c *= 3
    assert c == (3, 6)
    c[0] = 7
    assert c.x == 7.0
    assert Box2D.b2Vec2(1, 2) != Box2D.b2Vec2(1, 3)


def test_transform_maps_points_and_round_trips():
    t = Box2D.b2Transform((1, 2), math.pi / 2)
    p = t * (1, 0)
    assert isinstance(p, Box2D.b2Vec2)
    assert p.x == pytest.approx(1.0) and p.y == pytest.approx(3.0)
    back = t.apply_inverse(p)
    assert back.x == pytest.approx(1.0) and back.y == pytest.approx(0.0, abs=1e-12)
    assert t.position == (1, 2) and t.angle == pytest.approx(math.pi / 2)
    # transform * vec * float, as the environments' renderers write it
    q = t * Box2D.b2Vec2(0, 1) * 30
    assert q.x == pytest.approx(0.0, abs=1e-9) and q.y == pytest.approx(60.0)
    r = Box2D.b2Rot(math.pi)
    assert (r * (1, 0)).x == pytest.approx(-1.0)


def test_prefixed_and_short_names():
    assert b2.pi == Box2D.b2_pi == math.pi
    assert b2.world is Box2D.b2World and b2.AABB is Box2D.b2AABB
    assert b2.polygonShape is Box2D.b2PolygonShape and b2.circleShape is Box2D.b2CircleShape
    assert b2.edgeShape is Box2D.b2EdgeShape and b2.fixtureDef is Box2D.b2FixtureDef
    assert b2.contactListener is Box2D.b2ContactListener and b2.rayCastCallback is Box2D.b2RayCastCallback
    assert b2.queryCallback is Box2D.b2QueryCallback and b2.revoluteJointDef is Box2D.b2RevoluteJointDef
    assert b2.staticBody == Box2D.b2_staticBody == 0 and b2.dynamicBody == 2 and b2.kinematicBody == 1
    assert b2.distanceJointDef and b2.weldJointDef and b2.prismaticJointDef and b2.bodyDef
