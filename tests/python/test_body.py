# SPDX-License-Identifier: MIT
"""Body: every property and action through the package."""

import math

import pytest

import impulse2d
from conftest import close, make_ground


def test_pose_velocity_and_mass(world):
    body = world.create_body(position=(1.0, 2.0), angle=0.5, linear_velocity=(3.0, 4.0), angular_velocity=0.25)
    body.create_box(0.5, 1.0, density=2.0)
    assert body.type == impulse2d.DYNAMIC
    assert close(body.position, (1.0, 2.0))
    assert math.isclose(body.angle, 0.5, abs_tol=1e-6)
    assert close(body.rotation, (math.cos(0.5), math.sin(0.5)))
    assert close(body.linear_velocity, (3.0, 4.0))
    assert body.angular_velocity == 0.25
    assert math.isclose(body.mass, 2.0 * 1.0 * 2.0, rel_tol=1e-6)
    assert math.isclose(body.rotational_inertia, 4.0 * (1.0 + 4.0) / 12.0, rel_tol=1e-5)
    assert close(body.world_center_of_mass, (1.0, 2.0))

    body.position = (5.0, 6.0)
    body.angle = -1.0
    assert close(body.position, (5.0, 6.0)) and math.isclose(body.angle, -1.0, abs_tol=1e-6)
    body.set_transform((0.0, 0.0), 0.0)
    assert body.position == (0.0, 0.0) and body.rotation == (1.0, 0.0)
    body.linear_velocity = (-1.0, 0.0)
    body.angular_velocity = 2.0
    assert body.linear_velocity == (-1.0, 0.0) and body.angular_velocity == 2.0


def test_static_and_kinematic_bodies(world):
    ground = make_ground(world)
    assert ground.type == impulse2d.STATIC and ground.mass == 0.0 and not ground.awake
    ground.linear_velocity = (1.0, 0.0)  # ignored by static bodies, as in C
    assert ground.linear_velocity == (0.0, 0.0)
    mover = world.create_body(impulse2d.KINEMATIC, linear_velocity=(1.0, 0.0))
    world.step(0.5, 4)
    assert close(mover.position, (0.5, 0.0))


def test_forces_and_impulses(world):
    world.gravity = (0.0, 0.0)
    body = world.create_body()
    body.create_circle(0.5, density=1.0 / (math.pi * 0.25))  # 1 kg
    body.apply_linear_impulse((2.0, 0.0))
    assert close(body.linear_velocity, (2.0, 0.0))
    body.apply_angular_impulse(body.rotational_inertia * 3.0)
    assert math.isclose(body.angular_velocity, 3.0, rel_tol=1e-5)
    body.linear_velocity = (0.0, 0.0)
    body.angular_velocity = 0.0
    body.apply_force((0.0, 60.0))  # 60 N for 1/60 s: 1 m/s
    body.apply_torque(0.0)
    world.step(1.0 / 60.0, 1)
    assert close(body.linear_velocity, (0.0, 1.0))
    body.apply_force((1.0, 0.0), point=(0.0, 1.0))  # off centre: torque
    world.step(1.0 / 60.0, 1)
    assert body.angular_velocity < 0.0


def test_sleep_user_data_shapes_and_destroy(world):
    body = world.create_body()
    circle = body.create_circle(0.5)
    box = body.create_box(0.2, 0.2, center=(1.0, 0.0), angle=0.3)
    assert set(body.shapes) == {circle, box}
    assert body.awake
    body.awake = False
    assert not body.awake
    body.awake = True
    assert body.awake
    body.user_data = {"name": "crate"}
    assert body.user_data == {"name": "crate"}
    body.destroy()
    assert not body.is_valid and not circle.is_valid
    with pytest.raises(impulse2d.InvalidHandle):
        body.user_data
    with pytest.raises(impulse2d.InvalidHandle):
        body.destroy()
