# SPDX-License-Identifier: MIT
"""LunarLander: one LunarLander-v3 episode at a time with gymnasium.Env's API (a
gymnasium.Env when Gymnasium is installed). It runs the same simulation as
VectorLunarLander (a fleet of one), so a seed gives the same episode in both."""

from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import constants as K
from . import spaces
from .engines import continuous_throttles, discrete_throttles
from .fleet import DEFAULT_SUBSTEPS, LanderFleet
from .render import render_rgb

try:
    from gymnasium import Env as _Base
except ImportError:
    _Base = object


class LunarLander(_Base):
    metadata = {"render_modes": ["rgb_array"], "render_fps": K.FRAMES_PER_SECOND}

    def __init__(self, render_mode: Optional[str] = None, continuous: bool = False,
                 gravity: float = K.DEFAULT_GRAVITY, enable_wind: bool = False,
                 wind_power: float = K.DEFAULT_WIND_POWER, turbulence_power: float = K.DEFAULT_TURBULENCE_POWER,
                 max_episode_steps: Optional[int] = K.DEFAULT_MAX_EPISODE_STEPS,
                 substeps: int = DEFAULT_SUBSTEPS) -> None:
        if render_mode not in (None, "rgb_array"):
            raise ValueError("LunarLander renders rgb_array pictures only; got render_mode %r" % (render_mode,))
        self.render_mode = render_mode
        self.continuous = bool(continuous)
        self.max_episode_steps = max_episode_steps
        self.fleet = LanderFleet(1, gravity, enable_wind, wind_power, turbulence_power, substeps, workers=1)
        self.observation_space = spaces.observation_space()
        self.action_space = spaces.action_space(self.continuous)
        self._elapsed = 0
        self._started = False

    def reset(self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
              ) -> Tuple[np.ndarray, Dict]:
        """A new episode (seeded if seed is given); returns the (8,) float32 observation
        after its first frame, which fires no engine, and {}."""
        if _Base is not object:
            super().reset(seed=seed)
        if seed is not None or not self._started:
            self.fleet.seed(0, seed)
        self._started = True
        self.fleet.rebuild(0)
        noop = np.zeros((1, 2)) if self.continuous else np.zeros(1, dtype=np.int64)
        self._elapsed = 0
        return self._frame(noop).observations[0], {}

    def step(self, action) -> Tuple[np.ndarray, float, bool, bool, Dict]:
        if not self._started:
            raise RuntimeError("call reset() before step()")
        if self.continuous:
            batch = np.asarray(action, dtype=np.float64).reshape(1, 2)
        else:
            if not self.action_space.contains(action):
                raise ValueError("%r is not a LunarLander action (0, 1, 2 or 3)" % (action,))
            batch = np.array([int(action)], dtype=np.int64)
        result = self._frame(batch)
        self._elapsed += 1
        truncated = self.max_episode_steps is not None and self._elapsed >= self.max_episode_steps
        return (result.observations[0], float(result.rewards[0]), bool(result.terminated[0]), bool(truncated), {})

    def render(self) -> Optional[np.ndarray]:
        """With render_mode "rgb_array", a (400, 600, 3) uint8 picture; otherwise None."""
        if self.render_mode != "rgb_array" or not self._started:
            return None
        return render_rgb(self.fleet.worlds[0], self.fleet.terrains[0])

    def close(self) -> None:
        self.fleet.close()

    def _frame(self, actions: np.ndarray):
        throttles = continuous_throttles(actions) if self.continuous else discrete_throttles(actions)
        return self.fleet.frame(throttles)
