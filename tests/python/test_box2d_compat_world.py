# SPDX-License-Identifier: MIT
"""Box2D.b2World and b2Body: defaults, motion against closed forms, sleep, creation
styles, destruction and bad input."""

import gc
import math

import pytest

import impulse2d
from impulse2d._native import lib
from box2d_compat_fixture import Box2D, Recorder, b2, ground, step


def test_default_gravity_and_free_fall():
    world = Box2D.b2World()
    assert world.gravity == (0, -10) and world.allowSleeping
    ball = world.CreateDynamicBody(position=(0, 100))
    ball.CreateCircleFixture(radius=0.5, density=1)
    step(world, 1.0)
    assert ball.linearVelocity.y == pytest.approx(-10.0, rel=1e-4)  # v = -g t
    # y = y0 - g t^2 / 2 within the discretisation of 60 steps (semi-implicit Euler)
    assert ball.position.y == pytest.approx(100 - 5.0, abs=0.1)
    world2 = Box2D.b2World((0, 0), contactListener=None, doSleep=False)
    assert world2.gravity == (0, 0) and not world2.allowSleeping


def test_speed_is_capped_as_box2d_caps_travel_per_step():
    # Box2D 2.3: at most 2 m per step, 100 m/s at 50 Hz (the compat world's cap).
    world = Box2D.b2World(gravity=(0, 0))
    spark = world.CreateDynamicBody()
    spark.CreateCircleFixture(radius=2 / 30.0, density=3.5)
    spark.ApplyLinearImpulse((13.0, 0), spark.worldCenter, True)  # 13 N s on 49 g: 265 m/s uncapped
    world.Step(1 / 50.0, 6, 2)
    assert spark.linearVelocity.length == pytest.approx(100.0, rel=1e-4)
    assert spark.position.x == pytest.approx(2.0, rel=1e-3)


def test_body_at_rest_falls_asleep_after_half_a_second():
    world = Box2D.b2World()
    ground(world)
    box = world.CreateDynamicBody(position=(0, 0.5))
    box.CreatePolygonFixture(box=(0.5, 0.5), density=1, friction=0.3)
    slept_at = None
    for i in range(180):
        world.Step(1 / 60.0, 8, 3)
        if not box.awake:
            slept_at = (i + 1) / 60.0
            break
    assert slept_at is not None and 0.45 <= slept_at <= 0.8
    box.ApplyForceToCenter((10, 0), True)
    assert box.awake
    no_sleep = Box2D.b2World(doSleep=False)
    ground(no_sleep)
    other = no_sleep.CreateDynamicBody(position=(0, 0.5))
    other.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    step(no_sleep, 2.0)
    assert other.awake


def test_body_state_mass_and_frames():
    world = Box2D.b2World(gravity=(0, 0))
    body = world.CreateDynamicBody(position=(2, 3), angle=0.5, userData={"name": "b"})
    body.CreatePolygonFixture(box=(1, 0.5, (1, 0), 0), density=2)
    assert body.mass == pytest.approx(4.0)  # 2 x 1 m^2 x 2 kg/m^2
    assert body.localCenter.x == pytest.approx(1.0)
    # about the origin: I_c + m d^2 = m (w^2 + h^2) / 12 + m * 1
    assert body.inertia == pytest.approx(4 * (4 + 1) / 12 + 4, rel=1e-5)
    assert body.worldCenter.x == pytest.approx(2 + math.cos(0.5)) and body.angle == pytest.approx(0.5)
    p = body.GetWorldPoint((1, 0))
    assert p == pytest.approx(body.worldCenter) and body.GetLocalPoint(p) == pytest.approx((1, 0))
    assert body.GetWorldVector((1, 0)) == pytest.approx((math.cos(0.5), math.sin(0.5)))
    assert body.GetLocalVector(body.GetWorldVector((0, 1))) == pytest.approx((0, 1))
    assert body.transform * (0, 0) == pytest.approx((2, 3))
    assert body.userData == {"name": "b"}
    marker = object()
    body.userData = marker
    assert body.userData is marker
    body.linearVelocity = (1, 0)
    body.angularVelocity = 2.0
    assert body.linearVelocity == (1, 0) and body.angularVelocity == 2.0
    body.position = (5, 5)
    body.angle = 1.0
    assert body.position == pytest.approx((5, 5)) and body.angle == pytest.approx(1.0)


def test_forces_impulses_and_torques():
    world = Box2D.b2World(gravity=(0, 0))
    body = world.CreateDynamicBody(position=(0, 0))
    body.CreateCircleFixture(radius=1, density=1 / math.pi)  # mass 1, I = 1/2
    body.ApplyLinearImpulse((2, 0), body.worldCenter, True)
    assert body.linearVelocity.x == pytest.approx(2.0)
    body.ApplyAngularImpulse(1.0, True)
    assert body.angularVelocity == pytest.approx(2.0)  # dw = J / I
    body.linearVelocity, body.angularVelocity = (0, 0), 0
    body.ApplyForceToCenter((6, 0), True)
    body.ApplyTorque(0.5, True)
    world.Step(0.5, 6, 2)
    assert body.linearVelocity.x == pytest.approx(3.0, rel=1e-4)  # F t / m
    assert body.angularVelocity == pytest.approx(0.5, rel=1e-4)  # T t / I
    world.Step(0.5, 6, 2)  # forces last one step, as Box2D's with autoClearForces
    assert body.linearVelocity.x == pytest.approx(3.0, rel=1e-4)
    body.linearVelocity, body.angularVelocity = (0, 0), 0
    body.ApplyForce((0, 1), body.worldCenter + (1, 0), True)  # 1 m off-centre: torque 1 N m too
    world.Step(0.5, 6, 2)
    assert body.angularVelocity == pytest.approx(1.0, rel=1e-4)


def test_creation_styles_and_types():
    world = Box2D.b2World()
    fd = b2.fixtureDef(shape=b2.polygonShape(box=(1, 1)), density=1)
    a = world.CreateBody(b2.bodyDef(type=b2.dynamicBody, position=(0, 5), fixtures=fd))
    b = world.CreateDynamicBody(position=(3, 5), fixtures=[fd, b2.fixtureDef(shape=b2.circleShape(radius=0.5))])
    c = world.CreateStaticBody(shapes=[b2.edgeShape(vertices=[(0, 0), (1, 0)]), b2.polygonShape(box=(1, 1))])
    k = world.CreateKinematicBody(position=(0, 10), linearVelocity=(1, 0))
    assert (a.type, b.type, c.type, k.type) == (2, 2, 0, 1)
    assert len(a.fixtures) == 1 and len(b.fixtures) == 2 and len(c.fixtures) == 2
    assert a.mass == pytest.approx(4.0) and b.mass == pytest.approx(4.0)  # the circle's density is 0
    world.Step(1.0, 6, 2)
    assert k.position.x == pytest.approx(1.0) and k.position.y == pytest.approx(10.0)
    assert set(world.bodies) == {a, b, c, k} and world.bodyCount == 4


def test_destroy_body_and_stale_use():
    world = Box2D.b2World()
    body = world.CreateDynamicBody(position=(0, 1))
    body.CreatePolygonFixture(box=(1, 1), density=1)
    world.DestroyBody(body)
    assert world.bodyCount == 0
    with pytest.raises(impulse2d.InvalidHandle) as error:
        body.position
    assert "i2d_body_get_position" in str(error.value)
    with pytest.raises(impulse2d.InvalidHandle) as error:
        world.DestroyBody(body)
    assert "i2d_body_destroy" in str(error.value)


def test_bad_input_raises_with_the_library_message():
    world = Box2D.b2World()
    with pytest.raises(impulse2d.InvalidArgument) as error:
        world.CreateDynamicBody(position=(float("nan"), 0))
    assert "i2d_body_create" in str(error.value) and "NaN" in str(error.value)
    body = world.CreateDynamicBody()
    with pytest.raises(impulse2d.InvalidArgument) as error:
        body.linearVelocity = (float("inf"), 0)
    assert "i2d_body_set_linear_velocity" in str(error.value)
    with pytest.raises(impulse2d.InvalidArgument):
        world.Step(-1.0, 6, 2)
    with pytest.raises(AttributeError):
        world.CreateDynamicBody(positon=(0, 0))


def test_awake_can_be_set_and_forces_may_leave_a_sleeper_asleep():
    world = Box2D.b2World()
    body = world.CreateDynamicBody(position=(0, 10), awake=False,
                                   fixtures=b2.fixtureDef(shape=b2.circleShape(radius=0.5), density=1))
    assert not body.awake
    body.ApplyForceToCenter((0, 100), False)  # wake=False: a sleeping body ignores it
    step(world, 0.5)
    assert not body.awake and body.position.y == pytest.approx(10.0)
    body.awake = True
    step(world, 0.5)
    assert body.awake and body.position.y < 10.0
    body.awake = False
    assert not body.awake


def test_world_and_body_contact_lists():
    world = Box2D.b2World()
    floor = ground(world)
    box = world.CreateDynamicBody(position=(0, 0.5))
    box.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    step(world, 0.2)
    assert world.contactCount == 1 and len(world.contacts) == 1
    edge = box.contacts[0]
    assert edge.other is floor and edge.contact.touching
    assert floor.contacts[0].other is box


def test_body_settings_pass_through():
    world = Box2D.b2World()
    body = world.CreateDynamicBody(position=(0, 10), linearDamping=0.5, angularDamping=0.25, gravityScale=0.0,
                                   fixedRotation=True, bullet=True, allowSleep=False)
    body.CreateCircleFixture(radius=0.5, density=1)
    assert (body.linearDamping, body.angularDamping, body.gravityScale) == (0.5, 0.25, 0.0)
    assert body.fixedRotation and body.bullet and not body.sleepingAllowed
    step(world, 1.0)
    assert body.position.y == pytest.approx(10.0)  # gravity scale 0
    body.gravityScale = 1.0
    body.type = Box2D.b2_staticBody
    assert body.type == b2.staticBody and body.mass == 0.0
    step(world, 0.5)
    assert body.position.y == pytest.approx(10.0)
    body.type = b2.dynamicBody
    body.active = False  # out of the world: no motion, no contacts
    assert not body.active
    step(world, 0.5)
    assert body.position.y == pytest.approx(10.0)
    body.active = True
    step(world, 0.5)
    assert body.position.y < 10.0


def test_a_dropped_world_is_freed_at_once():
    # No reference cycle through the world: its C world goes when the last reference
    # does, without waiting for the cyclic collector (LunarLander makes a world per reset).
    gc.disable()
    try:
        world = Box2D.b2World()
        world.contactListener = Recorder()
        floor = ground(world)
        box = world.CreateDynamicBody(position=(0, 0.5))
        box.CreatePolygonFixture(box=(0.5, 0.5), density=1)
        world.CreateJoint(b2.revoluteJointDef(bodyA=floor, bodyB=box))
        step(world, 0.2)
        world_id = world.impulse2d_world.id
        assert lib.i2d_world_is_valid(world_id)
        del world
        assert not lib.i2d_world_is_valid(world_id)
        with pytest.raises(impulse2d.InvalidHandle):
            box.position
        with pytest.raises(impulse2d.InvalidHandle):
            box.world
    finally:
        gc.enable()
