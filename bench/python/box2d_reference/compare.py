#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""impulse2d.gym's LunarLander against the same episodes on Box2D 2.4 (lander.cpp): for
seeds 0..N-1, with the PD pilot and with no engine, the return and the ending of each,
and how far the observations drift apart over the first 40 frames.

Usage: g++ -O2 -std=c++17 lander.cpp -lbox2d -o lander     (apt-get install libbox2d-dev)
       python3 compare.py [seeds] [path/to/lander]        (default 20 seeds, ./lander)
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "bindings", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tests", "python"))

import numpy as np  # noqa: E402

from impulse2d.gym import LunarLander  # noqa: E402
from impulse2d.gym.terrain import random_terrain  # noqa: E402
from test_gym_lunar_lander import pilot  # noqa: E402  (the same pilot lander.cpp flies)

FRAMES = 1000


def box2d_episode(program, seed, mode):
    """Rows [frame, 8 observations, reward, terminated] from lander.cpp, given the
    seed's draws in impulse2d.gym's order: terrain, push, then two per frame."""
    rng = np.random.default_rng(seed)
    terrain = random_terrain(rng)
    push = (rng.uniform(-1000.0, 1000.0), rng.uniform(-1000.0, 1000.0))
    dispersion = rng.uniform(-1.0, 1.0, size=2 * (FRAMES + 1))
    numbers = list(terrain.ys) + [terrain.pad_height, *push] + list(dispersion)
    text = " ".join([mode] + ["%.17g" % v for v in numbers])
    out = subprocess.run([program], input=text, capture_output=True, text=True, check=True).stdout
    return np.array([[float(v) for v in line.split()] for line in out.splitlines() if line.strip()])


def impulse2d_episode(seed, mode):
    env = LunarLander()
    obs, _ = env.reset(seed=seed)
    rows = [np.r_[0, obs, 0, 0]]
    for frame in range(1, FRAMES + 1):
        obs, reward, terminated, _, _ = env.step(pilot(obs) if mode == "pilot" else 0)
        rows.append(np.r_[frame, obs, reward, terminated])
        if terminated:
            break
    env.close()
    return np.array(rows)


def main():
    seeds = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    program = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "lander")
    np.set_printoptions(precision=3, suppress=True)
    for mode in ("pilot", "idle"):
        print("== %s" % mode)
        print("seed   Box2D frames return end | impulse2d frames return end | max |diff| frames 0-40 (x y vx vy angle spin)")
        returns, same_end = [], 0
        for seed in range(seeds):
            ref, ours = box2d_episode(program, seed, mode), impulse2d_episode(seed, mode)
            n = min(len(ref), len(ours), 41)
            drift = np.abs(ref[:n, 1:7] - ours[:n, 1:7]).max(axis=0)
            ref_return, our_return = ref[1:, 9].sum(), ours[1:, 9].sum()
            returns.append((ref_return, our_return))
            same_end += ref[-1, 9] == ours[-1, 9]
            print("%4d %12d %6.0f %+4.0f | %16d %6.0f %+4.0f | %s" % (
                seed, len(ref) - 1, ref_return, ref[-1, 9], len(ours) - 1, our_return, ours[-1, 9], drift))
        returns = np.array(returns)
        print("mean return Box2D %.1f, impulse2d %.1f; median |difference| %.1f; same ending %d of %d" % (
            returns[:, 0].mean(), returns[:, 1].mean(), np.median(np.abs(returns[:, 0] - returns[:, 1])),
            same_end, seeds))


if __name__ == "__main__":
    main()
