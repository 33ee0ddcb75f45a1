#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Python binding costs: per-call overhead of single-body calls, and ns per body of the
bulk NumPy calls on 10,000 bodies (target: at most 20 ns per body).

The plain transform write puts every body back where it is. Three more lines show what
other writes cost: new poses that stay within the shapes' fat boxes, teleports that
re-insert every shape in the broadphase tree, and the plain write in a world that sleeps
(there each write restarts the rest timers of what the bodies touch).

Usage: python3 bench/python_overhead.py [--repeat N]
Prints the median of N timed repeats (default 15) of each measurement.
"""

import argparse
import itertools
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bindings", "python"))

import numpy as np  # noqa: E402

import impulse2d  # noqa: E402
from impulse2d._native import lib  # noqa: E402

BODY_COUNT = 10_000
NUDGE = 0.01  # m: well within the fat boxes' 0.1 m margin, so no shape is re-inserted
TELEPORT = 0.5  # m: beyond the margin, so every shape is re-inserted


def median_seconds(fn, repeat, inner):
    """Median over repeat runs of the time of one of inner calls to fn."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(inner):
            fn()
        times.append((time.perf_counter() - start) / inner)
    return statistics.median(times)


def build_scene(world):
    """A ground and BODY_COUNT boxes in rows, stepped once; returns the boxes."""
    ground = world.create_body(impulse2d.STATIC, position=(0.0, -1.0))
    ground.create_box(600.0, 1.0)
    bodies = []
    for i in range(BODY_COUNT):
        body = world.create_body(position=((i % 500) * 1.2 - 300.0, 0.5 + 1.2 * (i // 500)))
        body.create_box(0.5, 0.5)
        bodies.append(body)
    world.step()
    return bodies


def print_per_body(name, fn, repeat):
    print("  %-45s %8.2f ns" % (name, 1e9 * median_seconds(fn, repeat, 50) / BODY_COUNT))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args()
    print("impulse2d %s, %s, Python %s, NumPy %s" % (
        impulse2d.library_version, impulse2d.library_path, sys.version.split()[0], np.__version__))
    with impulse2d.World(enable_sleep=False) as world:
        bodies = build_scene(world)
        body = bodies[0]
        body_id = body.id

        print("\nper call (median of %d repeats of 20,000 calls)" % args.repeat)
        calls = [
            ("lib.i2d_body_get_position(id)  raw ctypes", lambda: lib.i2d_body_get_position(body_id)),
            ("body.position                   package", lambda: body.position),
            ("body.angular_velocity = 0.5     package", lambda: setattr(body, "angular_velocity", 0.5)),
            ("body.linear_velocity = (1, 0)   package", lambda: setattr(body, "linear_velocity", (1.0, 0.0))),
        ]
        for name, fn in calls:
            print("  %-45s %8.0f ns" % (name, 1e9 * median_seconds(fn, args.repeat, 20_000)))

        ids = world.body_ids(bodies)
        xf = np.empty((BODY_COUNT, 4), np.float32)
        linear = np.empty((BODY_COUNT, 2), np.float32)
        angular = np.empty(BODY_COUNT, np.float32)
        world.transforms(ids, out=xf)
        new_linear = np.full((BODY_COUNT, 2), 0.25, np.float32)
        new_angular = np.full(BODY_COUNT, 0.5, np.float32)
        print("\nbulk, %d bodies (median of %d repeats of 50 calls), ns per body" % (BODY_COUNT, args.repeat))
        bulk = [
            ("world.transforms(ids, out=xf)", lambda: world.transforms(ids, out=xf)),
            ("world.transforms(ids)  (allocates)", lambda: world.transforms(ids)),
            ("world.velocities(ids, out arrays)", lambda: world.velocities(ids, linear, angular)),
            ("world.set_velocities(ids, linear, angular)", lambda: world.set_velocities(ids, new_linear, new_angular)),
            ("world.set_transforms(ids, xf)", lambda: world.set_transforms(ids, xf)),
            ("world.transforms(bodies)  (list of Body)", lambda: world.transforms(bodies)),
        ]
        for name, fn in bulk:
            print_per_body(name, fn, args.repeat)
        per_body_loop = median_seconds(lambda: [b.position for b in bodies], max(3, args.repeat // 3), 1)
        print("  %-45s %8.2f ns" % ("[b.position for b in bodies]  (for scale)", 1e9 * per_body_loop / BODY_COUNT))

        # Each call alternates between the poses and the moved ones, so that every call
        # moves every body (an even count of calls per repeat ends where it started).
        nudged, moved = xf.copy(), xf.copy()
        nudged[:, 0] += NUDGE
        moved[:, 0] += TELEPORT
        nudges = itertools.cycle([nudged, xf])
        teleports = itertools.cycle([moved, xf])
        print_per_body("set_transforms, moved %g m (no re-insert)" % NUDGE,
                       lambda: world.set_transforms(ids, next(nudges)), args.repeat)
        print_per_body("set_transforms, moved %g m (all re-inserted)" % TELEPORT,
                       lambda: world.set_transforms(ids, next(teleports)), args.repeat)
    with impulse2d.World() as sleeping_world:
        ids = sleeping_world.body_ids(build_scene(sleeping_world))
        xf = sleeping_world.transforms(ids)
        print_per_body("set_transforms(ids, xf), world that sleeps",
                       lambda: sleeping_world.set_transforms(ids, xf), args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
