# SPDX-License-Identifier: MIT
"""impulse2d.gym imports without Gymnasium, registers nothing then, and registers its
ids and entry points with Gymnasium when a gymnasium module is importable; where
Gymnasium is installed, gymnasium.make, check_env and make_vec work with them."""

import importlib
import sys
import types

import pytest

import impulse2d.gym
from impulse2d.gym import registration


def gymnasium_installed():
    try:
        importlib.import_module("gymnasium")
        return True
    except ImportError:
        return False


@pytest.mark.skipif(gymnasium_installed(), reason="Gymnasium is installed here")
def test_without_gymnasium_import_works_and_register_is_a_no_op():
    assert "gymnasium" not in sys.modules
    assert impulse2d.gym.register() is False
    assert "gymnasium" not in sys.modules
    env = impulse2d.gym.LunarLander()
    obs, _ = env.reset(seed=0)
    assert env.action_space.n == 4 and env.action_space.contains(3) and not env.action_space.contains(4)
    assert env.observation_space.contains(obs)


class FakeGymnasium(types.ModuleType):
    """Just what register() uses: a registry and register()."""

    def __init__(self):
        super().__init__("gymnasium")
        self.registry = {}
        self.calls = []

    def register(self, **spec):
        self.calls.append(spec)
        self.registry[spec["id"]] = spec


def test_register_with_gymnasium_registers_both_ids_once(monkeypatch):
    fake = FakeGymnasium()
    monkeypatch.setitem(sys.modules, "gymnasium", fake)
    assert registration.register() is True
    assert registration.register() is True  # a second call adds nothing
    ids = [call["id"] for call in fake.calls]
    assert ids == ["impulse2d/LunarLander-v3", "impulse2d/LunarLanderContinuous-v3"]
    for call, continuous in zip(fake.calls, (False, True)):
        assert call["kwargs"] == {"continuous": continuous}
        assert call["max_episode_steps"] == 1000 and call["reward_threshold"] == 200
        module, name = call["entry_point"].split(":")
        assert getattr(importlib.import_module(module), name) is impulse2d.gym.LunarLander
        module, name = call["vector_entry_point"].split(":")
        assert getattr(importlib.import_module(module), name) is impulse2d.gym.VectorLunarLander


# Through Gymnasium itself, where it is installed (kept in this file, which always has a
# test to run, so that CTest does not see a file of skips as "no tests").
needs_gymnasium = pytest.mark.skipif(not gymnasium_installed(), reason="Gymnasium is not installed")


@needs_gymnasium
def test_ids_are_registered_and_make_wraps_a_time_limit():
    import gymnasium

    for env_id in registration.ENVIRONMENT_IDS:
        assert env_id in gymnasium.registry
    env = gymnasium.make("impulse2d/LunarLander-v3")
    assert env.spec.max_episode_steps == 1000
    obs, _ = env.reset(seed=0)
    assert env.observation_space.contains(obs)


@needs_gymnasium
def test_check_env_passes():
    from gymnasium.utils.env_checker import check_env

    check_env(impulse2d.gym.LunarLander())
    check_env(impulse2d.gym.LunarLander(continuous=True, render_mode="rgb_array"))


@needs_gymnasium
def test_native_vector_env_equals_gymnasium_sync_vector_env():
    """Gymnasium's SyncVectorEnv over the single env and the native vector env give the
    same bits, through autoresets."""
    import gymnasium
    import numpy as np

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
