#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""impulse2d.gym's VectorLunarLander flown by a PD pilot: 16 landers side by side,
one vector step per frame, finished landers restarted by the next step (NEXT_STEP
autoreset). Prints each finished episode's return and the landing rate; with a file
name, also saves the first lander's picture (rgb_array rendering) as a PNG.

Usage: python3 lunar_lander.py [episodes] [picture.png]     (default 32 episodes)
"""

import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

import numpy as np  # noqa: E402

from impulse2d.gym import VectorLunarLander  # noqa: E402

LANDERS = 16


def pilot(observations):
    """Discrete actions for a batch of observations: lean toward the pad, hold a
    height that falls as the lander nears it, and once a leg is down only cushion."""
    x, y, vx, vy, angle, spin, left_down, right_down = observations.T
    lean = np.clip(0.5 * x + 1.0 * vx, -0.4, 0.4)
    turn = 0.5 * (lean - angle) - 1.0 * spin
    lift = 0.5 * (0.5 * np.abs(x) - y) - 0.5 * vy
    down = (left_down > 0) | (right_down > 0)
    turn = np.where(down, 0.0, turn)
    lift = np.where(down, -0.5 * vy, lift)
    return np.select([(lift > np.abs(turn)) & (lift > 0.05), turn < -0.05, turn > 0.05], [2, 3, 1], 0)


def save_png(path, image):
    height, width, _ = image.shape
    rows = b"".join(b"\x00" + image[r].tobytes() for r in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def main():
    episodes = int(sys.argv[1]) if len(sys.argv) > 1 else 32
    picture = sys.argv[2] if len(sys.argv) > 2 else None
    envs = VectorLunarLander(LANDERS, render_mode="rgb_array" if picture else None)
    observations, _ = envs.reset(seed=0)
    returns = np.zeros(LANDERS)
    finished, landed, frames = [], 0, 0
    while len(finished) < episodes:
        observations, rewards, terminations, truncations, _ = envs.step(pilot(observations))
        frames += 1
        if picture and frames == 120:
            save_png(picture, envs.render()[0])
        returns += rewards
        for index in np.flatnonzero(terminations | truncations):
            finished.append(returns[index])
            landed += bool(terminations[index] and rewards[index] == 100.0)
            returns[index] = 0.0  # the next step restarts this lander with reward 0
    envs.close()
    finished = np.array(finished[:episodes])
    print("returns:", " ".join("%.0f" % r for r in finished))
    print("%d episodes, mean return %.1f, %d landed at rest, %d above 200" % (
        len(finished), finished.mean(), landed, int((finished > 200).sum())))


if __name__ == "__main__":
    main()
