# SPDX-License-Identifier: MIT
"""b2World over an impulse2d.World: bodies, joints, stepping, the contact listener and
the queries."""

import importlib.util
import os
import struct

import impulse2d

from ._body import b2Body, b2BodyDef, b2_dynamicBody, b2_kinematicBody, b2_staticBody
from ._callbacks import b2Contact
from ._joints import (JOINT_CLASSES, b2DistanceJointDef, b2JointEdge, b2PrismaticJointDef,
                      b2RevoluteJointDef, b2WeldJointDef, b2WheelJointDef)
from ._native import C, check, check_last, lib, structs
from ._settle import RevoluteSpec, settle
from ._shapes import b2EdgeShape, b2FixtureDef, b2PolygonShape
from ._vec import b2Vec2, as_pair

Vec2 = structs.Vec2

#: impulse2d substeps per Step. Box2D's velocity and position iteration counts have no
#: counterpart (impulse2d's soft step solves once per substep). Joint limits are soft
#: rows as stiff as the substep allows, and the environments drive light limbs with
#: strong motors against their limits: under random commands a BipedalWalker-like knee
#: overshoots its limit by about 0.34 rad at 4 substeps, 0.12 at 8, 0.04 at 16. 8 costs a
#: walker's step about 10 us. A world's substeps attribute (or b2World(substeps=...))
#: overrides it.
DEFAULT_SUBSTEPS = 8

#: Box2D 2.3 caps a body's travel at 2 m per step (b2_maxTranslation), scaling its
#: velocity down: 100 m/s at Gymnasium's 50 Hz. impulse2d caps the speed itself, once for
#: the world; LunarLander's engine particles leave at over 200 m/s without it.
MAXIMUM_LINEAR_SPEED = 100.0

#: Joints as stiff as the substep allows (the library caps joint_hertz at a quarter of the
#: substep rate), nearest to Box2D's rigid joints and limits.
JOINT_HERTZ = 1e5

#: Box2D 2.3 lets a body sleep after 0.5 s below 0.01 m/s and 2 deg/s. impulse2d has one
#: threshold on a body's speed and on its spin times its largest extent. Box2D's 0.01 m/s
#: would keep a lander resting on motor-loaded legs awake for ever (its soft limits let
#: it creep at about 0.02 m/s), and LunarLander pays for a lander at rest: 0.05 m/s, the
#: library's own default.
SLEEP_SPEED_THRESHOLD = 0.05
TIME_TO_SLEEP = 0.5


def _ray_result_struct():
    """A struct.Struct reading (shape, point x, y, normal x, y, fraction) from one
    i2d_ray_result, at the offsets the library described (see impulse2d/_layout.py)."""
    R, V = structs.RayResult, structs.Vec2
    parts = [(R.shape.offset, "Q"), (R.point.offset + V.x.offset, "f"), (R.point.offset + V.y.offset, "f"),
             (R.normal.offset + V.x.offset, "f"), (R.normal.offset + V.y.offset, "f"), (R.fraction.offset, "f")]
    if parts != sorted(parts):  # unpack gives fields in memory order
        raise ImportError("Box2D compat: i2d_ray_result's fields are not in the order this module reads")
    fmt, at = "=", 0
    for offset, code in parts:
        fmt += "x" * (offset - at) + code
        at = offset + struct.calcsize("=" + code)
    return struct.Struct(fmt), C.sizeof(R)


_RAY_RESULT, _RAY_RESULT_SIZE = _ray_result_struct()
_cast_ray_all = lib.i2d_world_cast_ray_all


def _compiled_ray_cast():
    """Box2D._raycast (RayCast's loop in C, built by pip where a compiler and Python's
    headers are) bound to the library ctypes loaded; None without it, or with
    IMPULSE2D_COMPAT_PURE set, and RayCast runs its Python loop. IMPULSE2D_COMPAT_RAYCAST
    names a module built elsewhere (a source tree's CMake build)."""
    if os.environ.get("IMPULSE2D_COMPAT_PURE"):
        return None
    path = os.environ.get("IMPULSE2D_COMPAT_RAYCAST")
    try:
        if path:
            spec = importlib.util.spec_from_file_location(__package__ + "._raycast", path)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
        else:
            from . import _raycast as module
    except ImportError:
        if path:
            raise
        return None
    module.bind(C.cast(_cast_ray_all, C.c_void_p).value)
    return module.ray_cast


_ray_cast = _compiled_ray_cast()

_step = lib.i2d_world_step
_contact_events = lib.i2d_world_get_contact_events
_sensor_events = lib.i2d_world_get_sensor_events

_BODY_DEF = lib.i2d_default_body_def()
_BodyDef = type(_BODY_DEF)

_MIX_MAXIMUM = 2  # i2d_mixing_rule: Box2D mixes restitution as the larger of the two
_ALL = 0xFFFFFFFFFFFFFFFF


class b2AABB(object):
    __slots__ = ("lowerBound", "upperBound")

    def __init__(self, lowerBound=(0.0, 0.0), upperBound=(0.0, 0.0)):
        self.lowerBound, self.upperBound = b2Vec2(*lowerBound), b2Vec2(*upperBound)

    @property
    def center(self):
        return (self.lowerBound + self.upperBound) * 0.5

    @property
    def extents(self):
        return (self.upperBound - self.lowerBound) * 0.5

    def __contains__(self, point):
        x, y = point
        return self.lowerBound.x <= x <= self.upperBound.x and self.lowerBound.y <= y <= self.upperBound.y

    def __repr__(self):
        return "b2AABB(lowerBound=%r, upperBound=%r)" % (self.lowerBound, self.upperBound)


class b2MassData(object):
    """mass, center (body frame) and I (about the body origin, as Box2D)."""

    def __init__(self, mass=0.0, center=(0.0, 0.0), I=0.0):
        self.mass, self.center, self.I = mass, b2Vec2(*center), I


def _pair_key(a, b):
    return (a, b) if a < b else (b, a)


class b2World(object):
    """A world. Callbacks run after each Step, from impulse2d's contact and sensor
    events: the step's end events, then its begin events."""

    def __init__(self, gravity=(0.0, -10.0), doSleep=True, **kwargs):
        self._w = impulse2d.World(
            gravity=as_pair(gravity), enable_sleep=bool(doSleep), sleep_speed_threshold=SLEEP_SPEED_THRESHOLD,
            time_to_sleep=TIME_TO_SLEEP, restitution_mixing=_MIX_MAXIMUM, joint_hertz=JOINT_HERTZ,
            maximum_linear_speed=MAXIMUM_LINEAR_SPEED)
        self._wid = self._w.id
        self._bodies = {}
        self._fixtures = {}
        self._joints = {}
        self._settle_pending = False  # a revolute joint made since the last step
        self._touching = {}
        self._sensor_count = 0  # sensor fixtures: without any, a step reads no sensor events
        self._ray_capacity = 16
        self._ray_buffer = (structs.RayResult * self._ray_capacity)()
        self._ray_address = C.addressof(self._ray_buffer)
        self._id_capacity = 64
        self._id_buffer = (C.c_uint64 * self._id_capacity)()
        self._query_filter = structs.QueryFilter(category_bits=_ALL, mask_bits=_ALL)
        self._ray_origin, self._ray_translation = Vec2(0.0, 0.0), Vec2(0.0, 0.0)
        self.substeps = DEFAULT_SUBSTEPS
        self.contactListener = None
        self.destructionListener = None
        self.contactFilter = None
        for key, value in kwargs.items():
            if key not in self.__dict__ and not hasattr(type(self), key):
                raise AttributeError('Invalid keyword argument "%s" for b2World' % key)
            setattr(self, key, value)

    @property
    def impulse2d_world(self):
        """The impulse2d.World underneath, for what the Box2D API lacks."""
        return self._w

    # ---- settings ---------------------------------------------------------------------
    @property
    def gravity(self):
        return b2Vec2(*self._w.gravity)

    @gravity.setter
    def gravity(self, value):
        self._w.gravity = as_pair(value)

    @property
    def allowSleeping(self):
        return self._w.settings["enable_sleep"]

    @allowSleeping.setter
    def allowSleeping(self, value):
        self._w.enable_sleeping(bool(value))

    doSleep = allowSleeping

    @property
    def continuousPhysics(self):
        return self._w.settings["enable_continuous"]

    @continuousPhysics.setter
    def continuousPhysics(self, value):
        self._w.enable_continuous(bool(value))

    # Box2D switches with no impulse2d counterpart: kept so programs that set them run.
    autoClearForces = True
    warmStarting = True
    subStepping = False

    def ClearForces(self):
        """impulse2d clears applied forces after every step already."""

    # ---- contents ---------------------------------------------------------------------
    @property
    def bodies(self):
        return list(self._bodies.values())

    @property
    def joints(self):
        return list(self._joints.values())

    @property
    def contacts(self):
        return list(self._touching.values())

    bodyCount = property(lambda self: len(self._bodies))
    jointCount = property(lambda self: len(self._joints))
    contactCount = property(lambda self: len(self._touching))

    # ---- bodies -----------------------------------------------------------------------
    def CreateBody(self, defn=None, **kwargs):
        """CreateBody(b2BodyDef) or CreateBody(position=..., fixtures=..., ...)."""
        if defn is None:
            defn = b2BodyDef(**kwargs)
        elif kwargs:
            raise TypeError("CreateBody takes a b2BodyDef or keywords, not both")
        # The library's default def is Box2D's (static, at rest, gravity scale 1, may
        # sleep): only what differs is written (a NaN differs from 0 and is written, to
        # be refused by the library).
        d = _BodyDef.from_buffer_copy(_BODY_DEF)
        body_type = d.type = int(defn.type)
        x, y = defn.position
        if x or y:
            d.position = Vec2(x, y)
        if defn.angle:
            d.rotation = lib.i2d_make_rot(defn.angle)
        x, y = defn.linearVelocity
        if x or y:
            d.linear_velocity = Vec2(x, y)
        if defn.angularVelocity:
            d.angular_velocity = defn.angularVelocity
        if defn.linearDamping:
            d.linear_damping = defn.linearDamping
        if defn.angularDamping:
            d.angular_damping = defn.angularDamping
        if defn.gravityScale != 1.0:
            d.gravity_scale = defn.gravityScale
        if defn.fixedRotation:
            d.fixed_rotation = True
        if not defn.allowSleep:
            d.enable_sleep = False
        if defn.bullet:
            d.is_bullet = True
        body_id = lib.i2d_body_create(self._wid, C.byref(d))
        if not body_id:
            check_last()
        body = b2Body(self, body_id, body_type, defn.userData)
        self._bodies[body_id] = body
        try:
            for fd in _listed(defn.fixtures):
                body.CreateFixture(fd)
            if defn.shapes is not None:
                template = defn.shapeFixture or b2FixtureDef()
                for shape in _listed(defn.shapes):
                    body.CreateFixture(_with_shape(template, shape))
            if not defn.awake:
                body.awake = False
            if not defn.active:
                body.active = False
        except BaseException:
            self.DestroyBody(body)
            raise
        return body

    def CreateStaticBody(self, defn=None, **kwargs):
        return self._create_typed(b2_staticBody, defn, kwargs)

    def CreateDynamicBody(self, defn=None, **kwargs):
        return self._create_typed(b2_dynamicBody, defn, kwargs)

    def CreateKinematicBody(self, defn=None, **kwargs):
        return self._create_typed(b2_kinematicBody, defn, kwargs)

    def _create_typed(self, body_type, defn, kwargs):
        if defn is None:
            defn = b2BodyDef(**kwargs)
        defn.type = body_type
        return self.CreateBody(defn)

    def DestroyBody(self, body):
        """Ends the body's contacts (EndContact for every pair the listener saw begin),
        destroys its joints, then the body."""
        if body._world is not self:
            raise impulse2d.InvalidArgument("DestroyBody: the body belongs to another world")
        if self._bodies.get(body._id) is not body:  # destroyed already: the world keeps its live ones
            check(lib.i2d_body_destroy(body._id))  # raises the library's InvalidHandle
        for fixture in body._fixtures:
            self._fixture_ending(fixture)
        for edge in list(body._joint_edges):
            self._forget_joint(edge.joint)
        check(lib.i2d_body_destroy(body._id))
        for fixture in body._fixtures:
            fixture._forget()
        self._bodies.pop(body._id, None)

    def _fixture_ending(self, fixture):
        """EndContact for each pair with the fixture that had a BeginContact (called
        before its shape goes, as Box2D does from DestroyBody and DestroyFixture)."""
        shape_id = fixture._id
        ended = [key for key in self._touching if shape_id in key]
        listener = self.contactListener
        for key in ended:
            contact = self._touching.pop(key)
            contact.touching = False
            if listener is not None:
                listener.EndContact(contact)

    # ---- joints -----------------------------------------------------------------------
    def CreateJoint(self, defn=None, **kwargs):
        """CreateJoint(jointDef) or CreateJoint(type=revoluteJointDef, bodyA=..., ...)."""
        if defn is None:
            def_class = kwargs.pop("type", None)
            if def_class is None:
                raise TypeError("CreateJoint needs a joint def or type=<a joint def class>")
            def_class = _DEF_OF_JOINT.get(def_class, def_class)
            defn = def_class(**kwargs)
        kind = getattr(defn, "_kind", None)
        if kind is None:
            raise TypeError("CreateJoint: unsupported joint def %r" % (defn,))
        body_a, body_b = defn.bodyA, defn.bodyB
        if body_a is None or body_b is None:
            raise ValueError("CreateJoint: bodyA and bodyB must both be set")
        w = self._w
        handle = w.create_joint(kind, impulse2d.Body(w, body_a._id), impulse2d.Body(w, body_b._id), **defn._settings())
        joint = JOINT_CLASSES[kind](self, handle.id, body_a, body_b, defn.userData)
        if kind == "revolute":
            # Closed, if apart, by Box2D's position iterations before the next step.
            joint._settle_spec = RevoluteSpec(defn)
            self._settle_pending = True
        self._joints[handle.id] = joint
        body_a._joint_edges.append(b2JointEdge(joint, body_b))
        body_b._joint_edges.append(b2JointEdge(joint, body_a))
        return joint

    def CreateRevoluteJoint(self, **kwargs):
        return self.CreateJoint(b2RevoluteJointDef(**kwargs))

    def CreatePrismaticJoint(self, **kwargs):
        return self.CreateJoint(b2PrismaticJointDef(**kwargs))

    def CreateDistanceJoint(self, **kwargs):
        return self.CreateJoint(b2DistanceJointDef(**kwargs))

    def CreateWeldJoint(self, **kwargs):
        return self.CreateJoint(b2WeldJointDef(**kwargs))

    def CreateWheelJoint(self, **kwargs):
        return self.CreateJoint(b2WheelJointDef(**kwargs))

    def DestroyJoint(self, joint):
        check(lib.i2d_joint_destroy(joint._id))
        self._forget_joint(joint)

    def _forget_joint(self, joint):
        self._joints.pop(joint._id, None)
        for body in (joint._bodyA, joint._bodyB):
            body._joint_edges = [e for e in body._joint_edges if e.joint is not joint]

    # ---- stepping ---------------------------------------------------------------------
    def Step(self, timeStep, velocityIterations=8, positionIterations=3):
        """Advances by timeStep in self.substeps impulse2d substeps (the iteration counts
        are accepted and unused), then reports the step's contacts to the listener. After
        a revolute joint's creation, positionIterations of Box2D's position correction
        first close its gap (_settle.py)."""
        if self._settle_pending:
            self._settle_pending = False
            specs = [j._settle_spec for j in self._joints.values() if getattr(j, "_settle_spec", None)]
            settle(specs, positionIterations, _is_dynamic, self._polygons_touching_ground, self._static_edges_near)
        status = _step(self._wid, timeStep, self.substeps)
        if status:
            check(status)
        events = _contact_events(self._wid)
        if events.begin_count or events.end_count or self._sensor_count:
            self._report(events)

    def _static_edges_near(self, low_x, low_y, high_x, high_y):
        """The end points (world frame) of the static edge fixtures whose shapes overlap
        the box, for the settle's contacts: the world's tree finds them, so a course of
        hundreds of edges costs what the few under the walker cost."""
        edges = []
        for shape_id in self._shape_ids_in(structs.AABB(min=Vec2(low_x, low_y), max=Vec2(high_x, high_y))):
            fixture = self._fixtures.get(shape_id)
            if fixture is None or fixture._sensor or not isinstance(fixture._shape, b2EdgeShape):
                continue
            body = fixture._body
            if body._type == b2_staticBody:
                edges.append((tuple(body.GetWorldPoint(fixture._shape._v1)),
                              tuple(body.GetWorldPoint(fixture._shape._v2))))
        return edges

    @staticmethod
    def _polygons_touching_ground(body):
        """The body's solid polygons (body frame points) that collide with static shapes
        of category 1, the default ground; others (a lander's particles) keep out of it."""
        return [fixture._shape._vertices for fixture in body._fixtures
                if isinstance(fixture._shape, b2PolygonShape) and not fixture._sensor and fixture._filter[1] & 1]

    def _report(self, events):
        fixtures, touching, listener = self._fixtures, self._touching, self.contactListener
        sensors = _sensor_events(self._wid)
        # Ends before begins: a pair changes state at most once per step, and a body
        # moving from one shape to its neighbour (a leg across two terrain edges) then
        # ends on "touching the new one", whatever flags the listener keeps per body.
        for i in range(events.end_count):
            e = events.end_events[i]
            self._end(e.shape_a, e.shape_b, touching, listener)
        for i in range(sensors.end_count):
            e = sensors.end_events[i]
            self._end(e.sensor_shape, e.visitor_shape, touching, listener)
        for i in range(events.begin_count):
            e = events.begin_events[i]
            self._begin(e.shape_a, e.shape_b, fixtures, touching, listener)
        for i in range(sensors.begin_count):
            e = sensors.begin_events[i]
            self._begin(e.sensor_shape, e.visitor_shape, fixtures, touching, listener, True)

    @staticmethod
    def _begin(a, b, fixtures, touching, listener, sensor=False):
        key = _pair_key(a, b)
        if key in touching:
            return
        fa, fb = fixtures.get(a), fixtures.get(b)
        if fa is None or fb is None:
            return
        if sensor and not _box2d_pairs(fa, fb):
            return
        contact = touching[key] = b2Contact(fa, fb)
        if listener is not None:
            listener.BeginContact(contact)

    @staticmethod
    def _end(a, b, touching, listener):
        contact = touching.pop(_pair_key(a, b), None)
        if contact is None:
            return
        contact.touching = False
        if listener is not None:
            listener.EndContact(contact)

    # ---- queries ----------------------------------------------------------------------
    def RayCast(self, callback, point1, point2):
        """Reports the fixtures the segment point1-point2 crosses to
        callback.ReportFixture, nearest first (Box2D's order is unspecified), honouring
        -1 (ignore), 0 (stop), a fraction (clip) and 1 (go on)."""
        x1, y1 = point1
        x2, y2 = point2
        if _ray_cast is not None:
            if _ray_cast(self._wid, x1, y1, x2, y2, _ALL, _ALL, self._fixtures, callback.ReportFixture, b2Vec2) < 0:
                check_last()
            return
        # Kept structs, refilled: making two ctypes structs a call costs more than the cast.
        origin, translation = self._ray_origin, self._ray_translation
        origin.x, origin.y = x1, y1
        translation.x, translation.y = x2 - x1, y2 - y1
        total = _cast_ray_all(self._wid, origin, translation, self._query_filter, self._ray_address,
                              self._ray_capacity)
        if total <= 0:
            if total < 0:
                check_last()
            return
        if total > self._ray_capacity:
            self._ray_capacity = total
            self._ray_buffer = (structs.RayResult * total)()
            self._ray_address = C.addressof(self._ray_buffer)
            total = _cast_ray_all(self._wid, origin, translation, self._query_filter, self._ray_address, total)
        # All read before any callback, which may cast again into the same buffer; one
        # struct.unpack per hit reads them faster than ctypes field access.
        buffer, unpack, size = self._ray_buffer, _RAY_RESULT.unpack_from, _RAY_RESULT_SIZE
        hits = [unpack(buffer, i * size) for i in range(total)]
        fixtures, report, limit, vec = self._fixtures, callback.ReportFixture, 1.0, b2Vec2._raw
        for shape_id, px, py, nx, ny, fraction in hits:
            if fraction > limit:
                break
            fixture = fixtures.get(shape_id)
            if fixture is None:
                continue
            answer = report(fixture, vec(px, py), vec(nx, ny), fraction)
            if answer == 0:
                break
            if 0 < answer < limit:
                limit = answer

    def _shape_ids_in(self, box):
        """The ids of the shapes whose boxes overlap box (a C AABB), from the world's tree."""
        while True:
            total = lib.i2d_world_overlap_aabb_ids(self._wid, box, self._query_filter,
                                                   C.addressof(self._id_buffer), self._id_capacity)
            if total < 0:
                check_last()
            if total <= self._id_capacity:
                break
            self._id_capacity = total
            self._id_buffer = (C.c_uint64 * total)()
        return self._id_buffer[:total]

    def QueryAABB(self, callback, aabb):
        """Reports each fixture whose shape overlaps the box to callback.ReportFixture
        until it returns False."""
        lo, hi = aabb.lowerBound, aabb.upperBound
        for shape_id in self._shape_ids_in(structs.AABB(min=Vec2(lo[0], lo[1]), max=Vec2(hi[0], hi[1]))):
            fixture = self._fixtures.get(shape_id)
            if fixture is not None and not callback.ReportFixture(fixture):
                break

    def __repr__(self):
        return "b2World(bodies=%d, joints=%d)" % (len(self._bodies), len(self._joints))


def _is_dynamic(body):
    return body._type == b2_dynamicBody


def _listed(value):
    if value is None:
        return ()
    if isinstance(value, (list, tuple)):
        return value
    return (value,)


def _with_shape(template, shape):
    fd = b2FixtureDef(density=template.density, friction=template.friction, restitution=template.restitution,
                      isSensor=template.isSensor, userData=template.userData)
    fd.filter = template.filter
    fd.shape = shape
    return fd


def _box2d_pairs(fa, fb):
    """Box2D's rule for a pair to make a contact: different bodies, one dynamic, and the
    filters agreeing. impulse2d's sensors see static shapes too; Box2D's do not."""
    ba, bb = fa._body, fb._body
    if ba is bb or (ba._type != b2_dynamicBody and bb._type != b2_dynamicBody):
        return False
    (category_a, mask_a, group_a), (category_b, mask_b, group_b) = fa._filter, fb._filter
    if group_a == group_b and group_a != 0:
        return group_a > 0
    return bool(mask_a & category_b) and bool(category_a & mask_b)


_DEF_OF_JOINT = {}  # filled by the package: joint classes to their defs, for CreateJoint(type=...)
