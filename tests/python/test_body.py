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


# ---- Runtime settings (issue 40) --------------------------------------------------------


def test_mass_data_override_gives_f_equals_m_a(world):
    world.gravity = (0.0, 0.0)
    body = world.create_body()
    body.create_circle(0.5, density=1.0)
    from_shapes = body.mass_data
    assert math.isclose(from_shapes.mass, math.pi * 0.25, rel_tol=1e-6) and from_shapes.center == (0.0, 0.0)
    body.mass_data = impulse2d.MassData(2.0, (0.25, 0.0), 0.5)
    assert body.mass_data == (2.0, (0.25, 0.0), 0.5) and body.mass == 2.0
    for _ in range(60):  # 4 N on 2 kg for a second: 2 m/s
        body.apply_force((4.0, 0.0))
        world.step(1.0 / 60.0, 4)
    assert math.isclose(body.linear_velocity[0], 2.0, rel_tol=1e-3)
    body.apply_mass_from_shapes()
    assert math.isclose(body.mass, from_shapes.mass, rel_tol=1e-6)
    with pytest.raises(impulse2d.InvalidArgument):
        body.mass_data = (-1.0, (0.0, 0.0), 0.5)
    with pytest.raises(impulse2d.InvalidArgument):
        body.mass_data = (1.0, (float("nan"), 0.0), 0.5)
    with pytest.raises(impulse2d.InvalidArgument):  # static bodies have no mass
        make_ground(world).mass_data = (1.0, (0.0, 0.0), 1.0)


def test_disabling_a_body_makes_what_rests_on_it_fall(world):
    shelf = world.create_body(impulse2d.STATIC)
    shelf.create_box(2.0, 0.5)  # top at y = 0.5
    crate = world.create_body(position=(0.0, 1.0))
    crate.create_box(0.5, 0.5)
    for _ in range(120):
        world.step()
    assert math.isclose(crate.position[1], 1.0, abs_tol=0.02)
    shelf.disable()
    assert not shelf.enabled and not shelf.awake
    shelf.disable()  # a no-op
    for _ in range(30):  # half a second of free fall: about 1.25 m
        world.step()
    assert crate.position[1] < 1.0 - 1.0 and crate.contact_data() == []
    shelf.enable()
    assert shelf.enabled
    shelf.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        shelf.enabled
    with pytest.raises(impulse2d.InvalidHandle):
        shelf.enable()


def test_target_transform_moves_a_kinematic_body_there(world):
    platform = world.create_body(impulse2d.KINEMATIC)
    platform.create_box(1.0, 0.1)
    platform.set_target_transform((1.0, 2.0), 1.0 / 60.0, angle=0.05)
    world.step(1.0 / 60.0, 4)
    assert close(platform.position, (1.0, 2.0), tol=1e-5)
    assert math.isclose(platform.angle, 0.05, abs_tol=1e-5)
    platform.set_target_transform((1.0, 2.0), 1.0 / 60.0, rotation=(1.0, 0.0))
    world.step(1.0 / 60.0, 4)
    assert math.isclose(platform.angle, 0.0, abs_tol=1e-5)
    with pytest.raises(impulse2d.InvalidArgument):
        platform.set_target_transform((0.0, 0.0), 0.0)
    with pytest.raises(impulse2d.InvalidArgument):  # dynamic bodies are refused
        world.create_body().set_target_transform((0.0, 0.0), 1.0 / 60.0)


def test_motion_and_sleep_settings(world):
    body = world.create_body(position=(0.0, 100.0))
    body.create_circle(0.5)
    assert not body.bullet and body.sleep_enabled and not body.fixed_rotation
    assert body.gravity_scale == 1.0 and body.linear_damping == 0.0 and body.angular_damping == 0.0
    assert math.isclose(body.sleep_threshold, 0.05, rel_tol=1e-6)
    body.bullet = True
    body.sleep_enabled = False
    body.sleep_threshold = 0.2
    body.linear_damping = 0.5
    body.angular_damping = 0.25
    assert body.bullet and not body.sleep_enabled and math.isclose(body.sleep_threshold, 0.2, rel_tol=1e-6)
    assert body.linear_damping == 0.5 and body.angular_damping == 0.25
    body.linear_damping = 0.0
    body.gravity_scale = 0.5
    assert body.gravity_scale == 0.5
    for _ in range(60):  # a second at half gravity: 5 m/s
        world.step(1.0 / 60.0, 4)
    assert math.isclose(body.linear_velocity[1], -5.0, rel_tol=1e-4)
    body.angular_velocity = 3.0
    body.fixed_rotation = True
    assert body.fixed_rotation and body.angular_velocity == 0.0
    for name, bad in (("gravity_scale", float("inf")), ("linear_damping", -1.0), ("angular_damping", float("nan")),
                      ("sleep_threshold", -1.0)):
        with pytest.raises(impulse2d.InvalidArgument):
            setattr(body, name, bad)
    body.destroy()
    for name in ("bullet", "sleep_enabled", "sleep_threshold", "gravity_scale", "linear_damping", "fixed_rotation",
                 "mass_data"):
        with pytest.raises(impulse2d.InvalidHandle):
            getattr(body, name)


def test_sleep_disabled_keeps_a_resting_body_awake(world):
    make_ground(world)
    body = world.create_body(position=(0.0, 0.5))
    body.create_box(0.5, 0.5)
    body.sleep_enabled = False
    for _ in range(120):
        world.step()
    assert body.awake
    body.sleep_enabled = True
    for _ in range(120):
        world.step()
    assert not body.awake


def test_contact_data_of_a_resting_box(world):
    ground = make_ground(world)
    box = world.create_body(position=(0.0, 0.5))
    box.create_box(0.5, 0.5, density=1.0)  # 1 kg
    for _ in range(60):
        world.step(1.0 / 60.0, 4)
    [contact] = box.contact_data()
    assert contact == ground.contact_data()[0]
    assert {contact.shape_a.body, contact.shape_b.body} == {ground, box}
    expected = (0.0, 1.0) if contact.shape_a.body == ground else (0.0, -1.0)
    assert close(contact.normal, expected)
    assert len(contact.points) == 2 and len(contact.normal_impulses) == 2
    assert sorted(round(p.point[0], 4) for p in contact.points) == [-0.5, 0.5]
    # at rest: m g time_step / substeps in all
    assert math.isclose(sum(contact.normal_impulses), 10.0 / 60.0 / 4.0, rel_tol=1e-3)
    box.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        box.contact_data()
