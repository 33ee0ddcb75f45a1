# SPDX-License-Identifier: MIT
"""VectorLunarLander: num_envs LunarLander-v3 episodes side by side, in one object,
with Gymnasium 1.x's vector API and its default autoreset mode, NEXT_STEP:

* step() returns a finished sub-env's last observation with terminated or truncated
  set; the NEXT step() resets that sub-env instead of applying its action, and
  returns its first observation with reward 0 and terminated = truncated = False.
* reset(seed=s) seeds sub-env i with s + i (as Gymnasium's SyncVectorEnv does); later
  autoresets continue each sub-env's own random stream.
* A sub-env is truncated once it has taken max_episode_steps steps (1000 by default,
  like the registered LunarLander-v3); truncated and terminated may both be True."""

from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import constants as K
from . import spaces
from .engines import NOOP_DISCRETE, continuous_throttles, discrete_throttles
from .fleet import DEFAULT_SUBSTEPS, LanderFleet
from .render import render_rgb

try:
    from gymnasium.vector import VectorEnv as _Base
    from gymnasium.vector import AutoresetMode as _AutoresetMode

    _NEXT_STEP: Any = _AutoresetMode.NEXT_STEP
except ImportError:
    _Base, _NEXT_STEP = object, "NextStep"

Seeds = Union[None, int, Sequence[Optional[int]]]


class VectorLunarLander(_Base):
    metadata = {"render_modes": ["rgb_array"], "render_fps": K.FRAMES_PER_SECOND, "autoreset_mode": _NEXT_STEP}

    def __init__(self, num_envs: int = 1, continuous: bool = False, gravity: float = K.DEFAULT_GRAVITY,
                 enable_wind: bool = False, wind_power: float = K.DEFAULT_WIND_POWER,
                 turbulence_power: float = K.DEFAULT_TURBULENCE_POWER,
                 max_episode_steps: Optional[int] = K.DEFAULT_MAX_EPISODE_STEPS, render_mode: Optional[str] = None,
                 substeps: int = DEFAULT_SUBSTEPS, workers: int = 1) -> None:
        if render_mode not in (None, "rgb_array"):
            raise ValueError("VectorLunarLander renders rgb_array pictures only; got render_mode %r" % (render_mode,))
        self.num_envs = int(num_envs)
        self.continuous = bool(continuous)
        self.max_episode_steps = max_episode_steps
        self.render_mode = render_mode
        self.fleet = LanderFleet(self.num_envs, gravity, enable_wind, wind_power, turbulence_power, substeps, workers)
        self.single_observation_space = spaces.observation_space()
        self.single_action_space = spaces.action_space(self.continuous)
        self.observation_space = spaces.observation_space(self.num_envs)
        self.action_space = spaces.action_space(self.continuous, self.num_envs)
        self._elapsed = np.zeros(self.num_envs, dtype=np.int64)
        self._needs_reset = np.zeros(self.num_envs, dtype=bool)
        self._started = False

    # ---- Gymnasium's vector API ---------------------------------------------------------

    def reset(self, *, seed: Seeds = None, options: Optional[Dict[str, Any]] = None) -> Tuple[np.ndarray, Dict]:
        """Starts every sub-env's episode; returns observations (num_envs, 8) float32 and {}."""
        for index, sub_seed in enumerate(self._sub_seeds(seed)):
            if sub_seed is not None or not self._started:
                self.fleet.seed(index, sub_seed)
            self.fleet.rebuild(index)
        self._started = True
        result = self.fleet.frame(self._throttles(self._noop_actions()))
        self._elapsed[:] = 0
        self._needs_reset[:] = False
        return result.observations, {}

    def step(self, actions) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, Dict]:
        """One frame for every sub-env: (observations (n, 8) float32, rewards (n,) float64,
        terminations (n,) bool, truncations (n,) bool, {})."""
        if not self._started:
            raise RuntimeError("call reset() before step()")
        resetting = self._needs_reset.copy()
        actions = self._checked(actions)
        for index in np.flatnonzero(resetting):
            self.fleet.rebuild(int(index))
            actions[index] = self._noop_actions()[index]
        result = self.fleet.frame(self._throttles(actions))
        self._elapsed += 1
        self._elapsed[resetting] = 0
        terminated = result.terminated & ~resetting
        truncated = np.zeros(self.num_envs, dtype=bool)
        if self.max_episode_steps is not None:
            truncated = (self._elapsed >= self.max_episode_steps) & ~resetting
        rewards = np.where(resetting, 0.0, result.rewards)
        self._needs_reset = terminated | truncated
        return result.observations, rewards, terminated, truncated, {}

    def render(self) -> Optional[Tuple[np.ndarray, ...]]:
        """With render_mode "rgb_array", one (400, 600, 3) uint8 picture per sub-env (as
        Gymnasium's SyncVectorEnv.render gives); otherwise None."""
        if self.render_mode != "rgb_array" or not self._started:
            return None
        return tuple(render_rgb(world, terrain) for world, terrain in zip(self.fleet.worlds, self.fleet.terrains))

    def close(self, **kwargs: Any) -> None:
        self.fleet.close()

    def __del__(self) -> None:
        fleet = getattr(self, "fleet", None)
        if fleet is not None:
            fleet.close()

    # ---- Actions and seeds -------------------------------------------------------------

    def _sub_seeds(self, seed: Seeds):
        if seed is None or isinstance(seed, (int, np.integer)):
            return [None if seed is None else int(seed) + i for i in range(self.num_envs)]
        seeds = list(seed)
        if len(seeds) != self.num_envs:
            raise ValueError("got %d seeds for %d sub-envs" % (len(seeds), self.num_envs))
        return seeds

    def _noop_actions(self) -> np.ndarray:
        if self.continuous:
            return np.zeros((self.num_envs, 2), dtype=np.float64)
        return np.full(self.num_envs, NOOP_DISCRETE, dtype=np.int64)

    def _checked(self, actions) -> np.ndarray:
        expected = (self.num_envs, 2) if self.continuous else (self.num_envs,)
        actions = np.array(actions, dtype=np.float64 if self.continuous else None, copy=True)
        if actions.shape != expected:
            raise ValueError("actions have shape %s; expected %s" % (actions.shape, expected))
        return actions

    def _throttles(self, actions: np.ndarray):
        return continuous_throttles(actions) if self.continuous else discrete_throttles(actions)
