# SPDX-License-Identifier: MIT
"""b2Body and b2BodyDef over impulse2d body ids.

Each body id has exactly one b2Body (the world keeps them in a dict), so the bodies a
contact or a joint hands back are the very objects created: they compare and hash
equal, and carry the attributes a program set on them (environments hang their own
fields, such as ground_contact, on bodies)."""

import math
import weakref

import impulse2d

from ._fixture import b2Fixture, fixture_def_from
from ._native import check, check_last, lib, structs
from ._shapes import b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape
from ._vec import b2Transform, b2Vec2, as_pair

Vec2, Rot = structs.Vec2, structs.Rot

b2_staticBody, b2_kinematicBody, b2_dynamicBody = 0, 1, 2


class b2BodyDef(object):
    """What CreateBody takes: Box2D 2.3's fields and defaults."""

    def __init__(self, **kwargs):
        self.type = b2_staticBody
        self.position = (0.0, 0.0)
        self.angle = 0.0
        self.linearVelocity = (0.0, 0.0)
        self.angularVelocity = 0.0
        self.linearDamping = 0.0
        self.angularDamping = 0.0
        self.allowSleep = True
        self.awake = True
        self.fixedRotation = False
        self.bullet = False
        self.active = True
        self.gravityScale = 1.0
        self.userData = None
        self.fixtures = None
        self.shapes = None
        self.shapeFixture = None
        for key, value in kwargs.items():
            if key not in self.__dict__:
                raise AttributeError('Invalid keyword argument "%s" for b2BodyDef' % key)
            setattr(self, key, value)


def _body_type(value):
    # The C library numbers body types static 0, kinematic 1, dynamic 2, as Box2D does.
    return int(value)


class b2Body(object):
    """A rigid body. Getters read the library each time (one call each, two for a
    transform); a body or world destroyed raises impulse2d.InvalidHandle."""

    def __init__(self, world, body_id, body_type, user_data):
        self._world_ref = weakref.ref(world)
        self._id = body_id
        self._type = body_type
        self._fixtures = []
        self._joint_edges = []
        self.userData = user_data

    def __repr__(self):
        return "b2Body(0x%016x)" % self._id

    @property
    def _world(self):
        # Bodies refer to their world weakly: no cycle keeps a dropped world (LunarLander
        # makes a new one every reset) and its C world alive until the cyclic collector
        # runs; impulse2d allows 4096 live worlds. As in pybox2d, a body does not keep its
        # world: once the world is gone, using the body raises.
        world = self._world_ref()
        if world is None:
            raise impulse2d.InvalidHandle("b2Body 0x%016x: its b2World no longer exists" % self._id)
        return world

    # ---- pose and velocity ------------------------------------------------------------
    @property
    def position(self):
        v = lib.i2d_body_get_position(self._id)
        if v.x == 0.0 and v.y == 0.0:
            check_last()
        return b2Vec2(v.x, v.y)

    @position.setter
    def position(self, value):
        check(lib.i2d_body_set_transform(self._id, Vec2(*as_pair(value)), lib.i2d_body_get_rotation(self._id)))

    @property
    def angle(self):
        q = lib.i2d_body_get_rotation(self._id)
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        return math.atan2(q.s, q.c)

    @angle.setter
    def angle(self, value):
        check(lib.i2d_body_set_transform(self._id, lib.i2d_body_get_position(self._id), lib.i2d_make_rot(value)))

    @property
    def transform(self):
        t = lib.i2d_body_get_transform(self._id)
        q = t.q
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        return b2Transform._raw(t.p.x, t.p.y, q.c, q.s)

    @transform.setter
    def transform(self, value):
        position, angle = value
        check(lib.i2d_body_set_transform(self._id, Vec2(*as_pair(position)), lib.i2d_make_rot(angle)))

    def SetTransform(self, position, angle):
        self.transform = (position, angle)

    @property
    def linearVelocity(self):
        v = lib.i2d_body_get_linear_velocity(self._id)
        if v.x == 0.0 and v.y == 0.0:
            check_last()
        return b2Vec2(v.x, v.y)

    @linearVelocity.setter
    def linearVelocity(self, value):
        check(lib.i2d_body_set_linear_velocity(self._id, Vec2(*as_pair(value))))

    @property
    def angularVelocity(self):
        w = lib.i2d_body_get_angular_velocity(self._id)
        if w == 0.0:
            check_last()
        return w

    @angularVelocity.setter
    def angularVelocity(self, value):
        check(lib.i2d_body_set_angular_velocity(self._id, value))

    @property
    def worldCenter(self):
        v = lib.i2d_body_get_world_center_of_mass(self._id)
        check_last()
        return b2Vec2(v.x, v.y)

    @property
    def localCenter(self):
        v = lib.i2d_body_get_local_center_of_mass(self._id)
        check_last()
        return b2Vec2(v.x, v.y)

    # ---- mass -------------------------------------------------------------------------
    @property
    def mass(self):
        m = lib.i2d_body_get_mass(self._id)
        if m == 0.0:
            check_last()
        return m

    @property
    def inertia(self):
        """About the body origin, as Box2D's GetInertia (impulse2d's is about the centre
        of mass)."""
        m = lib.i2d_body_get_mass_data(self._id)
        if m.mass == 0.0:
            check_last()
        c = m.center
        return m.rotational_inertia + m.mass * (c.x * c.x + c.y * c.y)

    @property
    def massData(self):
        m = lib.i2d_body_get_mass_data(self._id)
        check_last()
        from ._world import b2MassData

        c = m.center
        return b2MassData(mass=m.mass, center=(c.x, c.y), I=m.rotational_inertia + m.mass * (c.x * c.x + c.y * c.y))

    @massData.setter
    def massData(self, value):
        cx, cy = as_pair(value.center)
        inertia = value.I - value.mass * (cx * cx + cy * cy)
        impulse2d.Body(self._world._w, self._id).mass_data = (value.mass, (cx, cy), inertia)

    def ResetMassData(self):
        check(lib.i2d_body_apply_mass_from_shapes(self._id))

    # ---- state ------------------------------------------------------------------------
    @property
    def type(self):
        return self._type

    @type.setter
    def type(self, value):
        check(lib.i2d_body_set_type(self._id, _body_type(value)))
        self._type = _body_type(value)

    @property
    def awake(self):
        value = lib.i2d_body_is_awake(self._id)
        if not value:
            check_last()
        return bool(value)

    @awake.setter
    def awake(self, value):
        check(lib.i2d_body_set_awake(self._id, bool(value)))

    @property
    def sleepingAllowed(self):
        return impulse2d.Body(self._world._w, self._id).sleep_enabled

    @sleepingAllowed.setter
    def sleepingAllowed(self, value):
        check(lib.i2d_body_enable_sleep(self._id, bool(value)))

    @property
    def active(self):
        return impulse2d.Body(self._world._w, self._id).enabled

    @active.setter
    def active(self, value):
        body = impulse2d.Body(self._world._w, self._id)
        body.enable() if value else body.disable()

    def _setting(name):
        return property(lambda self: getattr(impulse2d.Body(self._world._w, self._id), name),
                        lambda self, v: setattr(impulse2d.Body(self._world._w, self._id), name, v))

    fixedRotation = _setting("fixed_rotation")
    bullet = _setting("bullet")
    gravityScale = _setting("gravity_scale")
    linearDamping = _setting("linear_damping")
    angularDamping = _setting("angular_damping")
    del _setting

    @property
    def world(self):
        return self._world

    @property
    def fixtures(self):
        return list(self._fixtures)

    @property
    def joints(self):
        """b2JointEdges (joint, other), as pybox2d lists them."""
        return list(self._joint_edges)

    @property
    def contacts(self):
        """b2ContactEdges of the pairs touching this body (as the listener saw them)."""
        from ._callbacks import b2ContactEdge

        edges = []
        for contact in self._world._touching.values():
            if contact.fixtureA._body is self:
                edges.append(b2ContactEdge(contact, contact.fixtureB._body))
            elif contact.fixtureB._body is self:
                edges.append(b2ContactEdge(contact, contact.fixtureA._body))
        return edges

    # ---- forces -----------------------------------------------------------------------
    def ApplyForce(self, force, point, wake=True):
        check(lib.i2d_body_apply_force(self._id, Vec2(*force), Vec2(*point), wake))

    def ApplyForceToCenter(self, force, wake=True):
        check(lib.i2d_body_apply_force_to_center(self._id, Vec2(*force), wake))

    def ApplyTorque(self, torque, wake=True):
        check(lib.i2d_body_apply_torque(self._id, torque, wake))

    def ApplyLinearImpulse(self, impulse, point, wake=True):
        check(lib.i2d_body_apply_linear_impulse(self._id, Vec2(*impulse), Vec2(*point), wake))

    def ApplyAngularImpulse(self, impulse, wake=True):
        check(lib.i2d_body_apply_angular_impulse(self._id, impulse, wake))

    # ---- frames (from one transform read) ----------------------------------------------
    def GetWorldPoint(self, localPoint):
        return self.transform * localPoint

    def GetWorldVector(self, localVector):
        q = lib.i2d_body_get_rotation(self._id)
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        x, y = localVector
        return b2Vec2(q.c * x - q.s * y, q.s * x + q.c * y)

    def GetLocalPoint(self, worldPoint):
        return self.transform.apply_inverse(worldPoint)

    def GetLocalVector(self, worldVector):
        q = lib.i2d_body_get_rotation(self._id)
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        x, y = worldVector
        return b2Vec2(q.c * x + q.s * y, -q.s * x + q.c * y)

    def GetLinearVelocityFromWorldPoint(self, worldPoint):
        v = lib.i2d_body_get_world_point_velocity(self._id, Vec2(*worldPoint))
        check_last()
        return b2Vec2(v.x, v.y)

    def GetLinearVelocityFromLocalPoint(self, localPoint):
        return self.GetLinearVelocityFromWorldPoint(self.GetWorldPoint(localPoint))

    # ---- fixtures ---------------------------------------------------------------------
    def CreateFixture(self, defn=None, **kwargs):
        """CreateFixture(fixtureDef) or CreateFixture(shape=..., density=..., ...)."""
        if defn is None:
            defn = fixture_def_from(kwargs)
        elif not isinstance(defn, b2FixtureDef):  # a bare shape, as b2Body::CreateFixture(shape, density)
            defn = b2FixtureDef(shape=defn, density=kwargs.pop("density", 0.0))
        fixture = b2Fixture(self, defn)
        self._fixtures.insert(0, fixture)  # Box2D lists the newest fixture first
        return fixture

    def CreatePolygonFixture(self, **kwargs):
        return self.CreateFixture(fixture_def_from(kwargs, b2PolygonShape))

    def CreateCircleFixture(self, **kwargs):
        return self.CreateFixture(fixture_def_from(kwargs, b2CircleShape))

    def CreateEdgeFixture(self, **kwargs):
        return self.CreateFixture(fixture_def_from(kwargs, b2EdgeShape))

    def DestroyFixture(self, fixture):
        if fixture not in self._fixtures:
            raise impulse2d.InvalidArgument("the fixture does not belong to this body")
        self._world._fixture_ending(fixture)
        check(lib.i2d_shape_destroy(fixture._id))
        self._fixtures.remove(fixture)
        fixture._forget()
