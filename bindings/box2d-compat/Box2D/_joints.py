# SPDX-License-Identifier: MIT
"""Joint definitions and joints: revolute, prismatic, distance and weld, over
impulse2d's joints of the same kinds."""

import impulse2d

from ._native import check, check_last, lib
from ._vec import b2Vec2, as_pair

e_unknownJoint, e_revoluteJoint, e_prismaticJoint, e_distanceJoint = 0, 1, 2, 3
e_pulleyJoint, e_mouseJoint, e_gearJoint, e_wheelJoint, e_weldJoint = 4, 5, 6, 7, 8


class b2JointDef(object):
    """Fields shared by every def. As pybox2d, bodyA and bodyB are set before the other
    keywords, and the revolute, prismatic and weld defs take referenceAngle =
    bodyB.angle - bodyA.angle at construction when both bodies are given and
    referenceAngle is not."""

    _fields = {}
    _reference = False

    def __init__(self, **kwargs):
        self.bodyA = self.bodyB = None
        self.localAnchorA = (0.0, 0.0)
        self.localAnchorB = (0.0, 0.0)
        self.collideConnected = False
        self.userData = None
        for key, value in self._fields.items():
            setattr(self, key, value)
        if "bodyA" in kwargs:
            self.bodyA = kwargs.pop("bodyA")
        if "bodyB" in kwargs:
            self.bodyB = kwargs.pop("bodyB")
        for key, value in kwargs.items():
            if key not in self.__dict__ and not isinstance(getattr(type(self), key, None), property):
                raise AttributeError('Invalid keyword argument "%s" for %s' % (key, type(self).__name__))
            setattr(self, key, value)
        if self._reference and self.bodyA is not None and self.bodyB is not None and "referenceAngle" not in kwargs:
            self.referenceAngle = self.bodyB.angle - self.bodyA.angle

    @property
    def anchor(self):
        if self.bodyA is not None:
            return self.bodyA.GetWorldPoint(self.localAnchorA)
        return self.bodyB.GetWorldPoint(self.localAnchorB)

    @anchor.setter
    def anchor(self, value):
        self.localAnchorA = self.bodyA.GetLocalPoint(value)
        self.localAnchorB = self.bodyB.GetLocalPoint(value)

    def Initialize(self, bodyA, bodyB, anchor, *rest):
        """As Box2D's: the bodies, the local anchors of a world anchor, and for kinds with
        one the reference angle."""
        self.bodyA, self.bodyB = bodyA, bodyB
        self.anchor = anchor
        if self._reference:
            self.referenceAngle = bodyB.angle - bodyA.angle
        if rest and hasattr(self, "localAxisA"):
            self.localAxisA = bodyA.GetLocalVector(rest[0])

    def _settings(self):
        return {"local_anchor_a": as_pair(self.localAnchorA), "local_anchor_b": as_pair(self.localAnchorB),
                "collide_connected": bool(self.collideConnected)}


class b2RevoluteJointDef(b2JointDef):
    _kind = "revolute"
    _reference = True
    _fields = dict(referenceAngle=0.0, enableLimit=False, lowerAngle=0.0, upperAngle=0.0,
                   enableMotor=False, motorSpeed=0.0, maxMotorTorque=0.0)

    def _settings(self):
        s = b2JointDef._settings(self)
        s.update(reference_angle=self.referenceAngle, enable_limit=bool(self.enableLimit),
                 lower_angle=self.lowerAngle, upper_angle=self.upperAngle, enable_motor=bool(self.enableMotor),
                 motor_speed=self.motorSpeed, max_motor_torque=self.maxMotorTorque)
        return s


# A def's axis in world coordinates: localAxisA turned by bodyA, as Box2D 2.3's
# prismatic and wheel defs take it.
_world_axis = property(lambda s: s.bodyA.GetWorldVector(s.localAxisA),
                       lambda s, v: setattr(s, "localAxisA", s.bodyA.GetLocalVector(v)))


class b2PrismaticJointDef(b2JointDef):
    _kind = "prismatic"
    _reference = True
    _fields = dict(localAxisA=(1.0, 0.0), referenceAngle=0.0, enableLimit=False, lowerTranslation=0.0,
                   upperTranslation=0.0, enableMotor=False, maxMotorForce=0.0, motorSpeed=0.0)

    axis = _world_axis

    def _settings(self):
        s = b2JointDef._settings(self)
        s.update(local_axis_a=as_pair(self.localAxisA), reference_angle=self.referenceAngle,
                 enable_limit=bool(self.enableLimit), lower_translation=self.lowerTranslation,
                 upper_translation=self.upperTranslation, enable_motor=bool(self.enableMotor),
                 max_motor_force=self.maxMotorForce, motor_speed=self.motorSpeed)
        return s


class b2DistanceJointDef(b2JointDef):
    """frequencyHz 0 is a rigid rod, as in Box2D 2.3; above 0 a spring."""

    _kind = "distance"
    _fields = dict(length=1.0, frequencyHz=0.0, dampingRatio=0.0)

    def __init__(self, **kwargs):
        b2JointDef.__init__(self, **kwargs)
        if "localAnchorA" in kwargs and "localAnchorB" in kwargs and "length" not in kwargs:
            self.length = (self.anchorB - self.anchorA).length

    anchorA = property(lambda s: s.bodyA.GetWorldPoint(s.localAnchorA),
                       lambda s, v: setattr(s, "localAnchorA", s.bodyA.GetLocalPoint(v)))
    anchorB = property(lambda s: s.bodyB.GetWorldPoint(s.localAnchorB),
                       lambda s, v: setattr(s, "localAnchorB", s.bodyB.GetLocalPoint(v)))

    def Initialize(self, bodyA, bodyB, anchorA, anchorB):
        self.bodyA, self.bodyB = bodyA, bodyB
        self.anchorA, self.anchorB = anchorA, anchorB
        self.length = (b2Vec2(*anchorB) - anchorA).length

    def _settings(self):
        s = b2JointDef._settings(self)
        s.update(length=self.length, enable_spring=self.frequencyHz > 0, hertz=self.frequencyHz,
                 damping_ratio=self.dampingRatio)
        return s


class b2WeldJointDef(b2JointDef):
    """frequencyHz and dampingRatio soften the angular part, as in Box2D 2.3."""

    _kind = "weld"
    _reference = True
    _fields = dict(referenceAngle=0.0, frequencyHz=0.0, dampingRatio=0.0)

    def _settings(self):
        s = b2JointDef._settings(self)
        s.update(reference_angle=self.referenceAngle, angular_hertz=self.frequencyHz,
                 angular_damping_ratio=self.dampingRatio)
        return s


class b2WheelJointDef(b2JointDef):
    """Box2D 2.3's wheel: a suspension spring (frequencyHz, dampingRatio; default 2 Hz
    and 0.7) along localAxisA and a motor on the turning."""

    _kind = "wheel"
    _fields = dict(localAxisA=(1.0, 0.0), enableMotor=False, maxMotorTorque=0.0, motorSpeed=0.0,
                   frequencyHz=2.0, dampingRatio=0.7)

    axis = _world_axis

    def _settings(self):
        s = b2JointDef._settings(self)
        s.update(local_axis_a=as_pair(self.localAxisA), enable_spring=self.frequencyHz > 0, hertz=self.frequencyHz,
                 damping_ratio=self.dampingRatio, enable_motor=bool(self.enableMotor),
                 max_motor_torque=self.maxMotorTorque, motor_speed=self.motorSpeed)
        return s


class b2JointEdge(object):
    __slots__ = ("joint", "other")

    def __init__(self, joint, other):
        self.joint, self.other = joint, other

    def __repr__(self):
        return "b2JointEdge(joint=%r, other=%r)" % (self.joint, self.other)


class b2Joint(object):
    """A joint; bodyA and bodyB are the world's b2Body objects."""

    type = e_unknownJoint

    def __init__(self, world, joint_id, bodyA, bodyB, user_data):
        self._id = joint_id
        self._bodyA, self._bodyB = bodyA, bodyB
        self.userData = user_data

    bodyA = property(lambda self: self._bodyA)
    bodyB = property(lambda self: self._bodyB)

    def _handle(self):
        return impulse2d.Joint(self._bodyA._world._w, self._id)

    @property
    def anchorA(self):
        return self._bodyA.GetWorldPoint(self._handle().get("local_anchor_a"))

    @property
    def anchorB(self):
        return self._bodyB.GetWorldPoint(self._handle().get("local_anchor_b"))

    @property
    def active(self):
        return bool(lib.i2d_joint_is_valid(self._id))

    def GetReactionForce(self, inv_dt):
        """N; impulse2d's reaction is already a force over the last step."""
        return b2Vec2(*self._handle().reaction_force)

    def GetReactionTorque(self, inv_dt):
        return self._handle().reaction_torque

    def __repr__(self):
        return "%s(0x%016x)" % (type(self).__name__, self._id)


def _reading(kind, field, doc=None):
    """A read-only property over i2d_<kind>_joint_get_<field> (a zero asks whether the
    call failed)."""
    get = getattr(lib, "i2d_%s_joint_get_%s" % (kind, field))

    def getter(self):
        value = get(self._id)
        if not value:
            check_last()
        return value

    return property(getter, doc=doc)


def _accessor(kind, field):
    put = getattr(lib, "i2d_%s_joint_set_%s" % (kind, field))

    def setter(self, value):
        check(put(self._id, value))

    return _reading(kind, field).setter(setter)


class b2RevoluteJoint(b2Joint):
    type = e_revoluteJoint

    angle = _reading("revolute", "angle", """B's angle relative to A minus the reference angle,
        wound into (-pi, pi] (Box2D 2.3 does not wind it).""")

    @property
    def speed(self):
        """rad/s: B's spin minus A's, as Box2D's GetJointSpeed."""
        return self._bodyB.angularVelocity - self._bodyA.angularVelocity

    motorSpeed = _accessor("revolute", "motor_speed")
    maxMotorTorque = _accessor("revolute", "max_motor_torque")
    motorEnabled = _accessor("revolute", "enable_motor")
    limitEnabled = _accessor("revolute", "enable_limit")
    lowerLimit = _accessor("revolute", "lower_angle")
    upperLimit = _accessor("revolute", "upper_angle")
    referenceAngle = _reading("revolute", "reference_angle")

    @property
    def limits(self):
        return (self.lowerLimit, self.upperLimit)

    @limits.setter
    def limits(self, value):
        lower, upper = value
        check(lib.i2d_revolute_joint_set_limits(self._id, lower, upper))

    def GetMotorTorque(self, inv_dt=None):
        return lib.i2d_revolute_joint_get_motor_torque(self._id)

    def EnableMotor(self, flag):
        self.motorEnabled = flag

    def EnableLimit(self, flag):
        self.limitEnabled = flag

    def SetLimits(self, lower, upper):
        self.limits = (lower, upper)

    def SetMotorSpeed(self, speed):
        self.motorSpeed = speed

    def SetMaxMotorTorque(self, torque):
        self.maxMotorTorque = torque


class b2PrismaticJoint(b2Joint):
    type = e_prismaticJoint

    translation = _reading("prismatic", "translation")

    speed = _reading("prismatic", "speed")

    motorSpeed = _accessor("prismatic", "motor_speed")
    maxMotorForce = _accessor("prismatic", "max_motor_force")
    motorEnabled = _accessor("prismatic", "enable_motor")
    limitEnabled = _accessor("prismatic", "enable_limit")
    lowerLimit = _accessor("prismatic", "lower_translation")
    upperLimit = _accessor("prismatic", "upper_translation")


class b2DistanceJoint(b2Joint):
    type = e_distanceJoint
    length = _accessor("distance", "length")
    frequency = _accessor("distance", "hertz")
    dampingRatio = _accessor("distance", "damping_ratio")


class b2WeldJoint(b2Joint):
    type = e_weldJoint


class b2WheelJoint(b2Joint):
    type = e_wheelJoint

    translation = _reading("wheel", "translation")

    @property
    def speed(self):
        """rad/s: B's spin minus A's, as Box2D's GetJointSpeed."""
        return self._bodyB.angularVelocity - self._bodyA.angularVelocity

    motorSpeed = _accessor("wheel", "motor_speed")
    maxMotorTorque = _accessor("wheel", "max_motor_torque")
    motorEnabled = _accessor("wheel", "enable_motor")
    springFrequencyHz = _accessor("wheel", "hertz")
    springDampingRatio = _accessor("wheel", "damping_ratio")


JOINT_CLASSES = {"revolute": b2RevoluteJoint, "prismatic": b2PrismaticJoint,
                 "distance": b2DistanceJoint, "weld": b2WeldJoint, "wheel": b2WheelJoint}
