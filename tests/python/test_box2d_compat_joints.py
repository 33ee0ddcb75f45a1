# SPDX-License-Identifier: MIT
"""Box2D joint defs and joints: revolute (reference angle, motor, limits, speed),
prismatic, distance and weld, joint lists and destruction."""

import math

import pytest

import impulse2d
from box2d_compat_fixture import Box2D, b2, step


def _pair(world, angle_b=0.0):
    base = world.CreateStaticBody(position=(0, 5), angle=0.1)
    arm = world.CreateDynamicBody(position=(1, 5), angle=angle_b)
    arm.CreatePolygonFixture(box=(1, 0.1), density=1)
    return base, arm


def test_revolute_def_takes_the_reference_angle_from_its_bodies():
    world = Box2D.b2World()
    base, arm = _pair(world, angle_b=0.5)
    rjd = b2.revoluteJointDef(bodyA=base, bodyB=arm, localAnchorA=(0, 0), localAnchorB=(-1, 0))
    assert rjd.referenceAngle == pytest.approx(0.4)  # bodyB.angle - bodyA.angle
    assert b2.revoluteJointDef(bodyA=base, bodyB=arm, referenceAngle=0.0).referenceAngle == 0.0
    assert b2.revoluteJointDef().referenceAngle == 0.0
    init = b2.revoluteJointDef()
    init.Initialize(base, arm, (0, 5))
    assert init.referenceAngle == pytest.approx(0.4)
    assert init.localAnchorA == pytest.approx((0, 0))
    assert init.localAnchorB == pytest.approx((-math.cos(0.5), math.sin(0.5)))  # (0, 5) in the arm's frame
    joint = world.CreateJoint(rjd)
    assert joint.angle == pytest.approx(0.0, abs=1e-6) and joint.referenceAngle == pytest.approx(0.4)
    assert joint.bodyA is base and joint.bodyB is arm and joint.type == Box2D.e_revoluteJoint


def test_revolute_motor_drives_at_its_speed_and_limits_hold():
    world = Box2D.b2World(gravity=(0, 0))
    base, arm = _pair(world)
    joint = world.CreateJoint(b2.revoluteJointDef(bodyA=base, bodyB=arm, localAnchorA=(0, 0), localAnchorB=(-1, 0),
                                                  enableMotor=True, maxMotorTorque=1000, motorSpeed=1.0,
                                                  referenceAngle=0.0))
    step(world, 0.5)
    assert joint.speed == pytest.approx(1.0, rel=1e-3) and joint.motorSpeed == 1.0
    assert joint.angle == pytest.approx(0.5 - 0.1, abs=0.03)  # B's angle minus A's
    joint.motorSpeed = -2.0
    joint.maxMotorTorque = 500.0
    assert joint.maxMotorTorque == 500.0
    step(world, 0.25)
    assert joint.speed == pytest.approx(-2.0, rel=1e-3)
    joint.limits = (-0.3, 0.3)
    joint.limitEnabled = True
    joint.maxMotorTorque = 5.0  # the limit is soft: a gentle motor leans on it
    step(world, 1.0)
    assert joint.angle == pytest.approx(-0.3, abs=0.02) and joint.lowerLimit == pytest.approx(-0.3)
    assert abs(joint.GetMotorTorque(60.0)) == pytest.approx(5.0, rel=1e-3)  # stalled at its max


def test_joint_lists_and_destruction():
    world = Box2D.b2World()
    base, arm = _pair(world)
    joint = world.CreateRevoluteJoint(bodyA=base, bodyB=arm, anchor=(0, 5))
    assert [e.joint for e in base.joints] == [joint] and base.joints[0].other is arm
    assert arm.joints[0].other is base and world.joints == [joint]
    world.DestroyJoint(joint)
    assert base.joints == [] and arm.joints == [] and world.jointCount == 0
    with pytest.raises(impulse2d.InvalidHandle):
        world.DestroyJoint(joint)
    again = world.CreateJoint(type=b2.revoluteJoint, bodyA=base, bodyB=arm, localAnchorB=(-1, 0))
    world.DestroyBody(arm)  # takes its joints along
    assert base.joints == [] and world.joints == [] and not again.active
    with pytest.raises(ValueError):
        world.CreateJoint(b2.revoluteJointDef(bodyA=base))


def test_bad_joint_values_raise_with_the_library_message():
    world = Box2D.b2World()
    base, arm = _pair(world)
    with pytest.raises(impulse2d.InvalidArgument) as error:
        world.CreateJoint(b2.revoluteJointDef(bodyA=base, bodyB=arm, enableLimit=True, lowerAngle=1, upperAngle=-1))
    assert "i2d_joint_create_revolute" in str(error.value)
    joint = world.CreateJoint(b2.revoluteJointDef(bodyA=base, bodyB=arm))
    with pytest.raises(impulse2d.InvalidArgument):
        joint.maxMotorTorque = -1.0


def test_prismatic_distance_and_weld():
    world = Box2D.b2World(gravity=(0, 0))
    base = world.CreateStaticBody(position=(0, 0))
    slider = world.CreateDynamicBody(position=(0, 0))
    slider.CreateCircleFixture(radius=0.2, density=1)
    prism = world.CreateJoint(b2.prismaticJointDef(bodyA=base, bodyB=slider, localAxisA=(1, 0), enableMotor=True,
                                                   maxMotorForce=1000, motorSpeed=2.0))
    step(world, 0.5)
    assert prism.speed == pytest.approx(2.0, rel=1e-3) and prism.translation == pytest.approx(1.0, abs=0.05)
    assert slider.position.y == pytest.approx(0.0, abs=1e-3)

    gravity_world = Box2D.b2World()
    anchor = gravity_world.CreateStaticBody(position=(0, 10))
    bob = gravity_world.CreateDynamicBody(position=(3, 10))
    bob.CreateCircleFixture(radius=0.1, density=1)
    rod = gravity_world.CreateJoint(b2.distanceJointDef(bodyA=anchor, bodyB=bob, localAnchorA=(0, 0),
                                                        localAnchorB=(0, 0)))
    assert rod.length == pytest.approx(3.0)  # from the anchors, as pybox2d's def does
    step(gravity_world, 2.0)
    assert (bob.position - anchor.position).length == pytest.approx(3.0, abs=0.02)

    glued = gravity_world.CreateDynamicBody(position=(0, 8), angle=0.3)
    glued.CreatePolygonFixture(box=(0.2, 0.2), density=1)
    weld = gravity_world.CreateJoint(b2.weldJointDef(bodyA=anchor, bodyB=glued, localAnchorA=(0, -2)))
    step(gravity_world, 1.0)
    assert glued.position == pytest.approx((0, 8), abs=0.02) and glued.angle == pytest.approx(0.3, abs=0.01)
    assert weld.type == Box2D.e_weldJoint


def test_more_substeps_stiffen_a_limit_against_a_strong_motor():
    # A light limb driven into its limit by a strong motor (a walker's knee): impulse2d's
    # limit is a soft row as stiff as the substep allows, Box2D's is rigid. Here 4 substeps
    # let about 0.11 rad through, the default 8 about 0.03, 16 under 0.01.
    overshoot = {}
    for substeps in (4, 8, 16):
        world = Box2D.b2World(gravity=(0, 0), substeps=substeps)
        assert world.substeps == substeps
        hull = world.CreateStaticBody(position=(0, 0))
        shin = world.CreateDynamicBody(position=(0, -0.4))
        shin.CreatePolygonFixture(box=(0.08, 0.4), density=1)
        joint = world.CreateJoint(b2.revoluteJointDef(bodyA=hull, bodyB=shin, localAnchorA=(0, 0),
                                                      localAnchorB=(0, 0.4), enableMotor=True, maxMotorTorque=80,
                                                      motorSpeed=-6, enableLimit=True, lowerAngle=-0.5,
                                                      upperAngle=0.5))
        step(world, 1.0, 50)
        overshoot[substeps] = joint.lowerLimit - joint.angle
    assert Box2D.b2World().substeps == Box2D.DEFAULT_SUBSTEPS == 8
    assert overshoot[4] > overshoot[8] > overshoot[16] > 0
    assert overshoot[8] < 0.05 and overshoot[16] < 0.015


def test_wheel_joint_spring_and_motor():
    world = Box2D.b2World()
    ground = world.CreateStaticBody(shapes=b2.edgeShape(vertices=[(-50, 0), (50, 0)]))
    chassis = world.CreateDynamicBody(position=(0, 1.0))
    chassis.CreatePolygonFixture(box=(1, 0.2), density=1)
    wheel = world.CreateDynamicBody(position=(0, 0.5))
    wheel.CreateCircleFixture(radius=0.5, density=1, friction=0.9)
    joint = world.CreateJoint(b2.wheelJointDef(bodyA=chassis, bodyB=wheel, localAnchorA=(0, -0.5),
                                               localAxisA=(0, 1), enableMotor=True, maxMotorTorque=50,
                                               motorSpeed=-2.0, frequencyHz=4.0, dampingRatio=0.7))
    assert joint.type == Box2D.e_wheelJoint and joint.springFrequencyHz == 4.0 and ground
    step(world, 2.0)
    assert joint.speed == pytest.approx(-2.0, rel=0.02)  # the motor turns the wheel clockwise...
    assert wheel.linearVelocity.x == pytest.approx(1.0, rel=0.05)  # ...and it rolls right at w r
    assert 0 < joint.translation < 0.1  # the chassis sags onto the wheel: B's anchor rises along the axis


def test_a_joint_created_apart_is_closed_before_the_step_without_velocity():
    # Two free bodies in zero gravity, a hinge between anchors 0.5 m apart: Box2D's
    # position correction moves both by their inverse masses (the 3 kg body a third as
    # far as the 1 kg one), so their centre of mass stays where it was, and gives them
    # no velocity.
    world = Box2D.b2World(gravity=(0, 0))
    heavy = world.CreateDynamicBody(position=(0, 0))
    heavy.CreatePolygonFixture(box=(0.5, 0.5), density=3.0)
    light = world.CreateDynamicBody(position=(1.5, 0))
    light.CreatePolygonFixture(box=(0.5, 0.5), density=1.0)
    center_before = (heavy.mass * heavy.worldCenter + light.mass * light.worldCenter) / (heavy.mass + light.mass)
    joint = world.CreateJoint(b2.revoluteJointDef(bodyA=heavy, bodyB=light, localAnchorA=(0.5, 0),
                                                  localAnchorB=(-0.5, 0)))
    assert (joint.anchorA - joint.anchorB).length == pytest.approx(0.5)
    world.Step(1.0 / 60.0, 8, 3)
    assert (joint.anchorA - joint.anchorB).length < 1e-3
    center_after = (heavy.mass * heavy.worldCenter + light.mass * light.worldCenter) / (heavy.mass + light.mass)
    assert (center_after - center_before).length < 1e-4
    assert heavy.position.x == pytest.approx(0.125, abs=2e-3)  # a quarter of the gap
    assert light.position.x == pytest.approx(1.125, abs=2e-3)  # three quarters
    assert heavy.linearVelocity.length < 1e-3 and light.linearVelocity.length < 1e-3


def test_a_joint_created_outside_its_limits_is_turned_back_inside():
    world = Box2D.b2World(gravity=(0, 0))
    base = world.CreateStaticBody(position=(0, 0))
    arm = world.CreateDynamicBody(position=(1, 0))
    arm.CreatePolygonFixture(box=(1, 0.1), density=1.0)
    joint = world.CreateJoint(b2.revoluteJointDef(bodyA=base, bodyB=arm, localAnchorA=(0, 0), localAnchorB=(-1, 0),
                                                  enableLimit=True, lowerAngle=0.5, upperAngle=1.0))
    assert joint.angle == pytest.approx(0.0)
    world.Step(1.0 / 60.0, 8, 60)
    assert 0.5 - 1e-3 <= joint.angle <= 1.0
    assert abs(arm.angularVelocity) < 0.01  # a soft limit closing 0.5 rad itself leaves it spinning


def test_a_box_built_sunk_into_an_edge_is_pushed_out_before_the_step_without_velocity():
    # Box2D's position iterations push a hinged box built 0.1 m into the ground back out
    # (to within its slop) without giving it velocity; impulse2d alone pushes it out at
    # its contact push speed.
    world = Box2D.b2World(gravity=(0, 0))
    ground = world.CreateStaticBody(position=(0, 0))
    ground.CreateEdgeFixture(vertices=[(-5, 0), (5, 0)])
    box = world.CreateDynamicBody(position=(0, 0.4))  # half height 0.5: 0.1 m sunk
    box.CreatePolygonFixture(box=(0.5, 0.5), density=1.0)
    arm = world.CreateDynamicBody(position=(0, 1.4))  # hinged on the box's top, free
    arm.CreatePolygonFixture(box=(0.1, 0.5), density=1.0, maskBits=0)
    world.CreateJoint(b2.revoluteJointDef(bodyA=box, bodyB=arm, localAnchorA=(0, 0.5), localAnchorB=(0, -0.5)))
    world.Step(1.0 / 60.0, 8, 60)
    assert box.position.y - 0.5 > -0.02  # out, but for Box2D's slops
    assert box.linearVelocity.length < 0.1
