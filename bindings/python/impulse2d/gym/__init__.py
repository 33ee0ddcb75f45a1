# SPDX-License-Identifier: MIT
"""impulse2d.gym: Gymnasium's LunarLander-v3 on impulse2d, with a native vectorised
version for reinforcement learning (many landers, one library call per step).

    from impulse2d.gym import VectorLunarLander

    envs = VectorLunarLander(num_envs=256)
    observations, infos = envs.reset(seed=0)
    observations, rewards, terminations, truncations, infos = envs.step(actions)

Gymnasium is optional. When it is installed, importing this package registers
impulse2d/LunarLander-v3 and impulse2d/LunarLanderContinuous-v3 (see registration.py).
See docs/gym.md."""

from .constants import DEFAULT_MAX_EPISODE_STEPS, FRAMES_PER_SECOND
from .registration import ENVIRONMENT_IDS, register
from .single_env import LunarLander
from .vector_env import VectorLunarLander

register()

__all__ = ["LunarLander", "VectorLunarLander", "register", "ENVIRONMENT_IDS",
           "DEFAULT_MAX_EPISODE_STEPS", "FRAMES_PER_SECOND"]
