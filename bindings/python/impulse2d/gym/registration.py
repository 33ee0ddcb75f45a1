# SPDX-License-Identifier: MIT
"""Registers the environments with Gymnasium, when it is installed:

    impulse2d/LunarLander-v3            discrete actions
    impulse2d/LunarLanderContinuous-v3  continuous actions

each with max_episode_steps 1000 and reward_threshold 200 as Gymnasium's own, an
entry point to LunarLander (gymnasium.make) and a vector entry point to
VectorLunarLander (gymnasium.make_vec(..., vectorization_mode="vector_entry_point"))."""

from . import constants as K

ENVIRONMENT_IDS = ("impulse2d/LunarLander-v3", "impulse2d/LunarLanderContinuous-v3")


def register() -> bool:
    """Registers the ids with Gymnasium; returns False, having done nothing, without
    Gymnasium, and True otherwise (also when they were registered already)."""
    try:
        import gymnasium
    except ImportError:
        return False
    for env_id, continuous in zip(ENVIRONMENT_IDS, (False, True)):
        if env_id in gymnasium.registry:
            continue
        gymnasium.register(
            id=env_id,
            entry_point="impulse2d.gym.single_env:LunarLander",
            vector_entry_point="impulse2d.gym.vector_env:VectorLunarLander",
            kwargs={"continuous": continuous},
            max_episode_steps=K.DEFAULT_MAX_EPISODE_STEPS,
            reward_threshold=200,
        )
    return True



