# SPDX-License-Identifier: MIT
"""Box2D: the pybox2d (Box2D 2.3) Python API that Gymnasium's Box2D environments use,
implemented on the impulse2d physics engine (the impulse2d package), not on Box2D.

    import Box2D
    world = Box2D.b2World()                       # gravity (0, -10), sleeping on
    ground = world.CreateStaticBody(shapes=Box2D.b2EdgeShape(vertices=[(-20, 0), (20, 0)]))
    box = world.CreateDynamicBody(position=(0, 4))
    box.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    world.Step(1 / 60, 6, 2)

Box2D.b2 holds the same names without their prefix (b2.world, b2.vec2, b2.pi, ...).
Where impulse2d and Box2D differ (substeps for iterations, callbacks after the step,
sleep thresholds, sharp polygons) see README.md next to this package and
docs/box2d_compat.md."""

import math as _math

from ._vec import b2Rot, b2Transform, b2Vec2
from ._shapes import b2CircleShape, b2EdgeShape, b2Filter, b2FixtureDef, b2PolygonShape, b2Shape
from ._fixture import b2Fixture
from ._body import b2Body, b2BodyDef, b2_dynamicBody, b2_kinematicBody, b2_staticBody
from ._joints import (b2DistanceJoint, b2DistanceJointDef, b2Joint, b2JointDef, b2JointEdge, b2PrismaticJoint,
                      b2PrismaticJointDef, b2RevoluteJoint, b2RevoluteJointDef, b2WeldJoint, b2WeldJointDef,
                      b2WheelJoint, b2WheelJointDef)
from ._joints import (e_distanceJoint, e_gearJoint, e_mouseJoint, e_prismaticJoint, e_pulleyJoint,
                      e_revoluteJoint, e_unknownJoint, e_weldJoint, e_wheelJoint)
from ._callbacks import (b2Contact, b2ContactEdge, b2ContactFilter, b2ContactListener, b2DestructionListener,
                         b2QueryCallback, b2RayCastCallback)
from ._world import b2AABB, b2MassData, b2World, DEFAULT_SUBSTEPS, _DEF_OF_JOINT
from impulse2d.errors import Impulse2DError, InvalidArgument, InvalidHandle, WorldLocked

__version__ = "2.3.10"  # the pybox2d API level it stands in for
__version_info__ = (2, 3, 10)

_DEF_OF_JOINT.update({b2RevoluteJoint: b2RevoluteJointDef, b2PrismaticJoint: b2PrismaticJointDef,
                      b2DistanceJoint: b2DistanceJointDef, b2WeldJoint: b2WeldJointDef,
                      b2WheelJoint: b2WheelJointDef})

b2_pi = _math.pi
b2_maxPolygonVertices = 8
b2_linearSlop = 0.005
b2_angularSlop = 2.0 / 180.0 * b2_pi
b2_polygonRadius = 0.0  # impulse2d polygons carry no skin (Box2D's: 2 * linearSlop)
b2_maxFloat = 3.402823466e38
b2_epsilon = 1.192092896e-07
b2_timeToSleep = 0.5
b2_linearSleepTolerance = 0.01
b2_angularSleepTolerance = 2.0 / 180.0 * b2_pi
b2_version = (2, 3, 1)

b2LoopShape = None  # chains are not provided (see README)
del b2LoopShape


def b2Dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def b2Cross(a, b):
    if isinstance(a, (int, float)):
        return b2Vec2(-a * b[1], a * b[0])
    if isinstance(b, (int, float)):
        return b2Vec2(b * a[1], -b * a[0])
    return a[0] * b[1] - a[1] * b[0]


def b2Distance(a, b):
    return _math.hypot(a[0] - b[0], a[1] - b[1])


def b2Mul(transform, v):
    return transform * v


def b2MulT(transform, v):
    return transform.apply_inverse(v)


def _fill_b2(namespace, target):
    """Box2D.b2's names from this module's: b2_foo -> foo, b2AABB -> AABB (capital
    after the prefix kept), b2World -> world."""
    for name, value in list(namespace.items()):
        if name == "b2" or not name.startswith("b2") or len(name) < 3:
            continue
        if name[2] == "_":
            short = name[3].lower() + name[4:]
        elif len(name) > 3 and name[3].isupper():
            short = name[2:]
        else:
            short = name[2].lower() + name[3:]
        setattr(target, short, value)


from . import b2  # noqa: E402  (filled from the names above)

_fill_b2(globals(), b2)
