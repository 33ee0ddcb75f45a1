# SPDX-License-Identifier: MIT
"""impulse2d.gym imports without Gymnasium, registers nothing then, and registers its
ids and entry points with Gymnasium when a gymnasium module is importable."""

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
