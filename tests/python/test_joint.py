# SPDX-License-Identifier: MIT
"""Joint: creating every kind, its settings through get and set, refusals and ids."""

import math

import pytest

import impulse2d
from conftest import make_ground


def test_every_kind_is_created_with_its_settings(world):
    ground = make_ground(world)
    box = world.create_body(position=(0.0, 2.0))
    box.create_box(0.5, 0.5)
    kinds = ("distance", "filter", "motor", "mouse", "prismatic", "revolute", "weld", "wheel")
    joints = [world.create_joint(kind, ground, box) for kind in kinds]
    assert world.joint_count == len(kinds)
    assert [j.kind for j in joints] == list(kinds)
    assert joints[0].body_a == ground and joints[0].body_b == box
    assert joints[4].get("local_axis_a") == (1.0, 0.0)  # prismatic default
    assert joints[7].get("hertz") == 1.0  # wheel default


def test_settings_round_trip_and_refusals(world):
    ground = make_ground(world)
    box = world.create_body(position=(0.0, 2.0))
    box.create_box(0.5, 0.5)
    hinge = world.create_joint("revolute", ground, box, local_anchor_a=(0.0, 2.5), local_anchor_b=(0.0, 0.5),
                               enable_motor=True, motor_speed=2.0, max_motor_torque=10.0)
    assert hinge.get("motor_speed") == 2.0 and hinge.get("enable_motor") is True
    assert hinge.get("local_anchor_a") == (0.0, 2.5)
    hinge.set("upper_angle", 1.0)
    hinge.set("lower_angle", -1.0)
    assert hinge.get("lower_angle") == -1.0 and hinge.get("upper_angle") == 1.0
    with pytest.raises(impulse2d.InvalidArgument, match="lower_angle"):
        hinge.set("lower_angle", 1.5)
    assert hinge.get("lower_angle") == -1.0
    with pytest.raises(impulse2d.InvalidArgument, match="hertz"):
        hinge.set("hertz", -1.0)
    with pytest.raises(impulse2d.InvalidArgument, match="same body"):
        world.create_joint("weld", box, box)
    with pytest.raises(impulse2d.InvalidArgument, match="dynamic"):
        world.create_joint("weld", ground, make_ground(world))
    with pytest.raises(AttributeError):
        hinge.get("length")
    with pytest.raises(TypeError):
        world.create_joint("distance", ground, box, no_such_setting=1.0)
    assert world.joint_count == 1


def test_ids_go_stale_with_the_body(world):
    ground = make_ground(world)
    box = world.create_body(position=(0.0, 2.0))
    box.create_box(0.5, 0.5)
    rope = world.create_joint("distance", ground, box, length=2.0)
    assert rope.is_valid and math.isclose(rope.get("length"), 2.0)
    box.destroy()
    assert not rope.is_valid and world.joint_count == 0
    with pytest.raises(impulse2d.InvalidHandle):
        rope.get("length")


def test_world_def_joint_settings():
    with impulse2d.World(joint_hertz=30.0, joint_damping_ratio=1.0) as world:
        assert world.is_valid
    with pytest.raises(impulse2d.InvalidArgument, match="joint_hertz"):
        impulse2d.World(joint_hertz=-1.0)


def test_breakable_joint_is_listed(world):
    anchor = world.create_body(impulse2d.STATIC, position=(0.0, 10.0))
    box = world.create_body(position=(0.0, 8.0))
    box.create_box(0.5, 0.5)  # 1 kg: 10 N of weight
    hinge = world.create_joint("revolute", anchor, box, local_anchor_a=(0.0, -1.0), local_anchor_b=(0.0, 1.0),
                               force_threshold=1.0)
    for _ in range(10):
        world.step(1 / 60, 4)
    assert world.joint_events() == [hinge]
    assert math.isclose(hinge.reaction_force[1], 10.0, rel_tol=0.05)
    hinge.destroy()
    world.step(1 / 60, 4)
    assert world.joint_events() == [] and world.joint_count == 0
