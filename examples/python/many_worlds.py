#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Many small worlds, as reinforcement-learning environments use them: 256 worlds of
20 bodies each, every body's state read as arrays after every step; stepped in turn
with World.step, then all in one call with a WorldBatch on 2 threads (the GIL released
meanwhile). Prints steps per second of each (one step = one world advanced by 1/60 s).

Usage: python3 many_worlds.py [rounds]      (default 100 rounds: 25,600 steps)
"""

import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

import numpy as np  # noqa: E402

import impulse2d  # noqa: E402

WORLDS = 256
BODIES = 20


def make_world(seed):
    world = impulse2d.World()
    ground = world.create_body(impulse2d.STATIC, position=(0.0, -1.0))
    ground.create_box(20.0, 1.0)
    rng = np.random.default_rng(seed)
    bodies = []
    for i in range(BODIES):
        body = world.create_body(position=(rng.uniform(-5, 5), 0.5 + 1.1 * i), angle=rng.uniform(-1, 1))
        if i % 2:
            body.create_circle(0.4)
        else:
            body.create_box(0.4, 0.4)
        bodies.append(body)
    return world, world.body_ids(bodies)


def read_states(envs, xf, linear, angular):
    """Every body's transform and velocities, as an agent's observation would take them."""
    checksum = 0.0
    for world, ids in envs:
        world.transforms(ids, out=xf)
        world.velocities(ids, linear_out=linear, angular_out=angular)
        checksum += float(xf[0, 1])
    return checksum


def run(envs, rounds, step_all):
    # Preallocated outputs: a step reads 20 transforms and velocities without allocating.
    xf = np.empty((BODIES, 4), np.float32)
    linear = np.empty((BODIES, 2), np.float32)
    angular = np.empty(BODIES, np.float32)
    checksum = 0.0
    start = time.perf_counter()
    for _ in range(rounds):
        step_all()
        checksum += read_states(envs, xf, linear, angular)
    return time.perf_counter() - start, checksum


def report(how, rounds, elapsed, checksum):
    steps = rounds * WORLDS
    print("%s: %d worlds x %d bodies, %d rounds: %d steps in %.2f s" % (how, WORLDS, BODIES, rounds, steps, elapsed))
    print("  %.0f steps per second (%.1f us per step, state read included), checksum %.3f"
          % (steps / elapsed, 1e6 * elapsed / steps, checksum))


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    in_turn = [make_world(seed) for seed in range(WORLDS)]
    batched = [make_world(seed) for seed in range(WORLDS)]

    def step_in_turn():
        for world, _ids in in_turn:
            world.step(1.0 / 60.0, 4)

    batch = impulse2d.WorldBatch([world for world, _ids in batched], workers=2)
    report("in turn", rounds, *run(in_turn, rounds, step_in_turn))
    report("one batch, 2 threads", rounds, *run(batched, rounds, lambda: batch.step(1.0 / 60.0, 4)))
    same = all(a.state_hash == b.state_hash for (a, _), (b, _) in zip(in_turn, batched))
    print("same state in both: %s" % ("yes" if same else "NO"))
    for world, _ids in in_turn + batched:
        world.destroy()
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
