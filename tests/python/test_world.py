# SPDX-License-Identifier: MIT
"""World: lifetime, stepping, settings, counters."""

import gc

import pytest

import impulse2d
from conftest import make_ground, make_pile


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
    # 256 worlds may live at once: dropping 600 unreferenced ones must free their slots.
    for _ in range(600):
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
