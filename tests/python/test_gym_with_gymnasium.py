# SPDX-License-Identifier: MIT
"""impulse2d.gym through Gymnasium itself, where it is installed (skipped otherwise):
registration, gymnasium.make with its checkers, check_env, and the native vector env
against Gymnasium's own SyncVectorEnv of the single env, bit for bit through autoresets."""

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import impulse2d.gym  # noqa: E402,F401  (registers the ids)
from impulse2d.gym import LunarLander  # noqa: E402


def test_ids_are_registered_and_make_wraps_a_time_limit():
    for env_id in ("impulse2d/LunarLander-v3", "impulse2d/LunarLanderContinuous-v3"):
        assert env_id in gymnasium.registry
    env = gymnasium.make("impulse2d/LunarLander-v3")
    assert env.spec.max_episode_steps == 1000
    obs, _ = env.reset(seed=0)
    assert env.observation_space.contains(obs)


def test_check_env_passes():
    from gymnasium.utils.env_checker import check_env

    check_env(LunarLander())
    check_env(LunarLander(continuous=True, render_mode="rgb_array"))


def test_native_vector_env_equals_gymnasium_sync_vector_env():
    sync = gymnasium.make_vec("impulse2d/LunarLander-v3", num_envs=3, vectorization_mode="sync")
    native = gymnasium.make_vec("impulse2d/LunarLander-v3", num_envs=3, vectorization_mode="vector_entry_point")
    assert native.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP
    a, _ = sync.reset(seed=9)
    b, _ = native.reset(seed=9)
    assert a.tobytes() == b.tobytes()
    rng = np.random.default_rng(0)
    ends = 0
    for _ in range(600):
        actions = rng.integers(0, 4, 3)
        expected, got = sync.step(actions), native.step(actions)
        for x, y in zip(expected[:4], got[:4]):
            assert np.array_equal(x, y)
        ends += int(expected[2].sum() + expected[3].sum())
    assert ends >= 3
