# SPDX-License-Identifier: MIT
"""Gymnasium's own Box2D environments, unmodified, on the compat module: skipped where
Gymnasium is not installed (it is not a dependency). Where it is, this is the end-to-end
check: LunarLander's heuristic pilot lands and comes to rest (the +100 for a lander that
is not awake), BipedalWalker's lidar sees the ground, CarRacing's wheels visit tiles."""

import math

import pytest

import box2d_compat_fixture  # noqa: F401  (puts the compat Box2D first on sys.path)

try:
    import gymnasium as gym
    import numpy as np
    import pygame  # noqa: F401  (the Box2D environments import it)
except ImportError:
    gym = None

# Skipped test by test, not the module: a file whose every test is skipped at import
# collects nothing, and pytest's exit status 5 would fail its CTest test.
needs_gymnasium = pytest.mark.skipif(gym is None, reason="Gymnasium, NumPy and pygame are not installed")


@needs_gymnasium
def test_lunar_lander_heuristic_lands_and_sleeps():
    from gymnasium.envs.box2d.lunar_lander import heuristic

    env = gym.make("LunarLander-v3").unwrapped
    assert type(env.world).__module__.startswith("Box2D._")
    landed = 0
    for seed in (1, 2, 3, 4):
        state, _ = env.reset(seed=seed)
        total = 0.0
        for _ in range(1000):
            state, reward, terminated, truncated, _ = env.step(heuristic(env, state))
            total += reward
            if terminated or truncated:
                break
        if terminated and reward == 100 and not env.lander.awake:
            landed += 1
            assert total > 200
    assert landed >= 3
    env.close()


@needs_gymnasium
def test_bipedal_walker_lidar_sees_flat_ground():
    env = gym.make("BipedalWalker-v3").unwrapped
    state, _ = env.reset(seed=0)
    for _ in range(10):
        state, *_ = env.step(np.zeros(4))
    y = env.hull.position.y
    terrain_y = env.terrain_y[0]  # the start of the course is flat
    # the straight-down ray: from the hull to the ground, over the lidar's range
    assert state[14] == pytest.approx((y - terrain_y) / (160 / 30.0), abs=0.02)
    assert all(0 < state[14 + i] <= 1 for i in range(10))
    env.close()


@needs_gymnasium
def test_car_racing_wheels_visit_tiles():
    env = gym.make("CarRacing-v3").unwrapped
    env.reset(seed=0)
    total = 0.0
    for i in range(60):
        _, reward, *_ = env.step(np.array([0.0, 0.3, 0.0]))
        total += reward
    assert env.tile_visited_count > 3
    assert total > 0  # 1000 / tiles per tile beats 0.1 per frame
    assert all(len(w.tiles) >= 1 for w in env.car.wheels)  # on the road
    assert math.isfinite(env.car.hull.linearVelocity.length)
    env.close()
