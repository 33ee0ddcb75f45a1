# SPDX-License-Identifier: MIT
"""World: lifetime, stepping, settings, counters."""

import gc
import math
import pickle

import pytest

import impulse2d
from conftest import close, make_ground, make_pile


def test_context_manager_destroys_the_world():
    with impulse2d.World() as world:
        body = world.create_body()
        assert world.is_valid and body.is_valid
    assert not world.is_valid and world.id == 0
    assert not body.is_valid
    with pytest.raises(impulse2d.InvalidHandle, match="destroyed"):
        body.position
    world.destroy()  # twice is harmless


def test_step_moves_a_falling_body_by_gravity():
    with impulse2d.World(gravity=(0.0, -10.0)) as world:
        ball = world.create_body(position=(0.0, 100.0))
        ball.create_circle(0.5)
        for _ in range(60):
            world.step(1.0 / 60.0, 4)
        x, y = ball.position
        # a second of free fall under semi-implicit Euler: about 5 m
        assert x == 0.0 and 94.8 < y < 95.1
        vx, vy = ball.linear_velocity
        assert abs(vy + 10.0) < 1e-3


def test_settings_reach_the_world_def():
    with impulse2d.World(gravity=(1.0, 2.0), enable_sleep=False, contact_hertz=30.0) as world:
        assert world.gravity == (1.0, 2.0)
        world.gravity = (0.0, -3.0)
        assert world.gravity == (0.0, -3.0)
    with pytest.raises(TypeError, match="unknown world setting 'gravityy'"):
        impulse2d.World(gravityy=(0, 0))
    with pytest.raises(impulse2d.InvalidArgument, match="contact_hertz"):
        impulse2d.World(contact_hertz=-1.0)


def test_worker_threads_give_the_same_state():
    hashes = []
    for workers in (1, 2):
        with impulse2d.World(worker_count=workers) as world:
            make_pile(world, count=300)
            for _ in range(30):
                world.step()
            hashes.append(world.state_hash)
    assert hashes[0] == hashes[1]
    with pytest.raises(impulse2d.InvalidArgument, match="worker_count"):
        impulse2d.World(worker_count=0)
    with pytest.raises(TypeError, match="unknown world setting 'enqueue_task'"):
        impulse2d.World(enqueue_task=None)


def test_counters_and_state_hash_follow_the_scene(world):
    make_pile(world, count=10)
    c = world.counters
    assert c.body_count == 11 and c.shape_count == 11
    before = world.state_hash
    world.step()
    assert world.state_hash != before
    assert world.counters.contact_count > 0


def test_garbage_collected_worlds_are_destroyed():
    # 4096 worlds may live at once: dropping 5000 unreferenced ones must free their slots.
    for _ in range(5000):
        world = impulse2d.World()
        make_ground(world)
        del world
    gc.collect()
    with impulse2d.World() as world:
        assert world.is_valid


def test_repr_and_identity(world):
    a = world.create_body()
    same = impulse2d.Body(world, a.id)
    assert a == same and hash(a) == hash(same) and a != world.create_body()
    assert "Body(0x" in repr(a) and "World(0x" in repr(world)


# ---- Settings after creation, origin shift, length units (issue 40) ----------------------


def test_settings_after_creation_read_back(world):
    settings = world.settings
    assert settings["gravity"] == (0.0, -10.0) and settings["length_units_per_meter"] == 1.0
    assert "internal_cookie" not in settings and "enqueue_task" not in settings
    world.enable_sleeping(False)
    world.enable_continuous(False)
    assert world.settings["enable_impact_chains"]
    world.enable_impact_chains(False)
    world.set_contact_tuning(30.0, 5.0, 2.0)
    world.set_joint_tuning(20.0, 1.5)
    world.set_restitution_threshold(2.5)
    world.set_hit_event_threshold(3.5)
    s = world.settings
    assert not s["enable_sleep"] and not s["enable_continuous"] and not s["enable_impact_chains"]
    assert (s["contact_hertz"], s["contact_damping_ratio"], s["contact_push_max_speed"]) == (30.0, 5.0, 2.0)
    assert (s["joint_hertz"], s["joint_damping_ratio"]) == (20.0, 1.5)
    assert (s["restitution_threshold"], s["hit_event_threshold"]) == (2.5, 3.5)
    with impulse2d.World(**s) as twin:
        assert twin.settings == s
    for call, args in ((world.set_contact_tuning, (-1.0, 5.0, 2.0)), (world.set_joint_tuning, (20.0, float("nan"))),
                       (world.set_restitution_threshold, (-1.0,)), (world.set_hit_event_threshold, (float("inf"),))):
        with pytest.raises(impulse2d.InvalidArgument):
            call(*args)
    assert world.settings == s  # refused: untouched


def test_sleeping_off_wakes_every_body(world):
    make_ground(world)
    box = world.create_body(position=(0.0, 0.5))
    box.create_box(0.5, 0.5)
    for _ in range(120):
        world.step()
    assert not box.awake
    world.enable_sleeping(False)
    assert box.awake


def test_shift_origin_moves_positions_by_minus_origin(world):
    bodies = make_pile(world, count=10)
    for _ in range(10):
        world.step()
    before = [b.position for b in bodies]
    origin = (100.0, -50.0)
    world.shift_origin(origin)
    for (x, y), body in zip(before, bodies):
        assert close(body.position, (x - origin[0], y - origin[1]), tol=1e-4)
    world.step()
    with pytest.raises(impulse2d.InvalidArgument):
        world.shift_origin((float("nan"), 0.0))
    with pytest.raises(impulse2d.InvalidArgument):
        world.shift_origin((2e9, 0.0))


def test_a_world_in_50_units_per_metre():
    positions = []
    for units in (1.0, 50.0):
        with impulse2d.World(length_units_per_meter=units) as world:
            assert world.gravity == (0.0, -10.0 * units) and world.settings["length_units_per_meter"] == units
            ground = world.create_body(impulse2d.STATIC, position=(0.0, -units))
            ground.create_box(50.0 * units, units)
            box = world.create_body(position=(0.0, 3.0 * units))
            box.create_box(0.5 * units, 0.5 * units, density=1.0 / units ** 2)
            for _ in range(90):
                world.step()
            assert math.isclose(box.mass, 1.0, rel_tol=1e-5)
            positions.append(box.position)
    assert math.isclose(positions[1][1] / 50.0, positions[0][1], rel_tol=1e-3)
    with impulse2d.World(length_units_per_meter=50.0, gravity=(0.0, -10.0)) as world:
        assert world.gravity == (0.0, -10.0)  # given settings are taken as given
    with pytest.raises(impulse2d.InvalidArgument, match="length_units_per_meter"):
        impulse2d.World(length_units_per_meter=1e5)


def test_world_user_data_is_a_python_reference(world):
    assert world.user_data is None
    marker = {"level": 3}
    world.user_data = marker
    assert world.user_data is marker
    copy = pickle.loads(pickle.dumps(world))
    try:
        assert copy.user_data == marker
    finally:
        copy.destroy()
