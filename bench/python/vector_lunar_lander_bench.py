#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Steps per second of impulse2d.gym.VectorLunarLander with random actions, at
N = 1, 16, 64, 256 and 1024 sub-envs (autoresets included, as in training).

One "step" is one sub-env advancing one frame: a vector step of N sub-envs counts N.
Each measurement runs about --frames sub-env steps after a warm-up, and the median of
--repeat repeats is printed, with the worker count that stepped the worlds.

Usage: python3 bench/python/vector_lunar_lander_bench.py [--repeat 5] [--frames 20000]
           [--workers 1] [--continuous] [--sizes 1,16,64,256,1024]
"""

import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

import numpy as np  # noqa: E402

from impulse2d.gym import VectorLunarLander  # noqa: E402


def random_actions(env, rng, count):
    if env.continuous:
        return rng.uniform(-1.0, 1.0, size=(count, env.num_envs, 2)).astype(np.float32)
    return rng.integers(0, 4, size=(count, env.num_envs))


def steps_per_second(num_envs, frames, repeat, workers, continuous):
    env = VectorLunarLander(num_envs, continuous=continuous, workers=workers)
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    vector_steps = max(10, frames // num_envs)
    for action in random_actions(env, rng, min(vector_steps, 50)):  # warm-up
        env.step(action)
    rates = []
    for _ in range(repeat):
        actions = random_actions(env, rng, vector_steps)
        start = time.perf_counter()
        for action in actions:
            env.step(action)
        rates.append(vector_steps * num_envs / (time.perf_counter() - start))
    env.close()
    return statistics.median(rates)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--frames", type=int, default=20000, help="sub-env steps per repeat")
    parser.add_argument("--workers", type=int, default=1, help="threads stepping the worlds")
    parser.add_argument("--continuous", action="store_true")
    parser.add_argument("--sizes", default="1,16,64,256,1024")
    args = parser.parse_args()
    kind = "continuous" if args.continuous else "discrete"
    print("VectorLunarLander, %s actions, random policy, %d worker(s), median of %d" % (
        kind, args.workers, args.repeat))
    print("%6s %14s" % ("N", "steps/s"))
    for size in (int(s) for s in args.sizes.split(",")):
        rate = steps_per_second(size, args.frames, args.repeat, args.workers, args.continuous)
        print("%6d %14.0f" % (size, rate), flush=True)


if __name__ == "__main__":
    main()
