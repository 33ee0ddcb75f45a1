# SPDX-License-Identifier: MIT
"""impulse2d.step_worlds and WorldBatch: many worlds in one call, each ending with the
bits World.step gives it alone; bad input raises with the library's message and steps
no world; the GIL is released for the whole batch; a hook's exception is re-raised."""

import bisect
import sys
import threading
import time

import pytest

import impulse2d
from conftest import make_ground, make_pile


def piles(count, bodies=20):
    worlds = []
    for k in range(count):
        world = impulse2d.World()
        make_pile(world, count=bodies, seed=3 + k)
        worlds.append(world)
    return worlds


def hashes(worlds):
    return [world.state_hash for world in worlds]


@pytest.mark.parametrize("workers", [1, 2, 4])
def test_step_worlds_gives_each_world_its_bits_alone(workers):
    batched, alone = piles(6), piles(6)
    for _ in range(40):
        impulse2d.step_worlds(batched, 1.0 / 60.0, 4, workers=workers)
        for world in alone:
            world.step(1.0 / 60.0, 4)
    assert hashes(batched) == hashes(alone)
    assert len(set(hashes(batched))) == 6  # the worlds differ, so the check sees each


def test_world_batch_steps_the_same_worlds_again_and_again():
    worlds = piles(64, bodies=4)
    batch = impulse2d.WorldBatch(worlds, workers=2)
    assert len(batch) == 64 and batch.workers == 2 and batch.worlds == worlds
    before = hashes(worlds)
    for _ in range(10):
        batch.step()
    assert all(a != b for a, b in zip(before, hashes(worlds)))


def test_a_destroyed_world_refuses_the_batch_and_steps_none():
    worlds = piles(3)
    batch = impulse2d.WorldBatch(worlds)
    before = hashes(worlds)
    gone = worlds[1]
    gone.destroy()
    with pytest.raises(impulse2d.InvalidHandle, match=r"worlds\[1\]: world id is stale"):
        batch.step()
    with pytest.raises(impulse2d.InvalidHandle, match=r"worlds\[1\]: world id is null"):
        impulse2d.step_worlds(worlds)
    assert [worlds[0].state_hash, worlds[2].state_hash] == [before[0], before[2]]


def test_bad_batches_raise_with_the_library_message_and_step_none():
    worlds = piles(2)
    before = hashes(worlds)
    with pytest.raises(impulse2d.InvalidArgument, match=r"worlds\[2\]: the world is listed twice"):
        impulse2d.step_worlds([worlds[0], worlds[1], worlds[0]])
    with pytest.raises(impulse2d.InvalidArgument, match="worker_count is 0"):
        impulse2d.step_worlds(worlds, workers=0)
    with pytest.raises(impulse2d.InvalidArgument, match="time_step is NaN"):
        impulse2d.step_worlds(worlds, float("nan"))
    with pytest.raises(impulse2d.InvalidArgument, match="substep_count is 0"):
        impulse2d.step_worlds(worlds, 1.0 / 60.0, 0)
    with pytest.raises(TypeError, match=r"worlds\[1\] is int"):
        impulse2d.step_worlds([worlds[0], worlds[1].id])
    assert hashes(worlds) == before
    impulse2d.step_worlds([])  # an empty batch is fine


def crowd(side=40):
    """side x side touching balls on a ground: contacts in every step."""
    world = impulse2d.World()
    make_ground(world)
    for i in range(side):
        for j in range(side):
            world.create_body(position=(0.95 * i - side / 2, 0.5 + 0.95 * j)).create_circle(0.5)
    return world


def test_the_gil_is_released_while_the_batch_steps():
    batch = impulse2d.WorldBatch([crowd() for _ in range(16)])
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())

    counter = threading.Thread(target=count)
    counter.start()
    calls = []
    try:
        for _ in range(6):
            start = time.perf_counter()
            batch.step(1.0 / 60.0, 16)
            calls.append((start, time.perf_counter()))
    finally:
        done.set()
        counter.join()
    # A thread holding the GIL lets another run Python only when it drops it between
    # bytecodes, at most one switch interval after being asked: in the middle of a call
    # longer than two intervals, Python on the other thread means the GIL was released.
    switch = sys.getswitchinterval()
    shortest = min(end - start for start, end in calls)
    assert shortest > 3 * switch, "calls of %.1f ms are too short to tell" % (1e3 * shortest)
    inside = 0
    for start, end in calls:
        inside += bisect.bisect_left(ticks, end - 1.5 * switch) - bisect.bisect_right(ticks, start + 1.5 * switch)
    assert inside > 0, "no Python ran during %d batch calls" % len(calls)


def test_a_hook_exception_is_raised_after_the_batch():
    worlds = [impulse2d.World() for _ in range(3)]
    for world in worlds[:2]:
        for body in make_pile(world, count=6):
            body.shapes[0].pre_solve_events_enabled = True
    make_ground(worlds[2])

    def fails(a, b, manifold):
        raise RuntimeError("hook refused to answer")

    worlds[1].set_pre_solve(fails)
    with pytest.raises(RuntimeError, match="hook refused to answer"):
        for _ in range(60):
            impulse2d.step_worlds(worlds)
    # Forgotten once raised: the next batch without the hook is clean.
    worlds[1].set_pre_solve(None)
    impulse2d.step_worlds(worlds)
