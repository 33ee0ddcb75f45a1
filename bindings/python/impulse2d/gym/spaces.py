# SPDX-License-Identifier: MIT
"""Observation and action spaces: Gymnasium's own when it is installed, otherwise
small stand-ins with the same attributes (shape, dtype, low/high or n) and sample(),
contains() and seed(), so that code written against the spaces runs either way."""

from typing import Optional

import numpy as np

from . import constants as K

try:
    from gymnasium import spaces as _gymnasium_spaces
except ImportError:
    _gymnasium_spaces = None


class _Box:
    def __init__(self, low, high, shape=None, dtype=np.float32, seed: Optional[int] = None) -> None:
        self.dtype = np.dtype(dtype)
        self.shape = tuple(shape) if shape is not None else np.shape(low)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self._rng = np.random.default_rng(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._rng = np.random.default_rng(seed)

    def sample(self) -> np.ndarray:
        return self._rng.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x) -> bool:
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all((x >= self.low) & (x <= self.high)))

    def __repr__(self) -> str:
        return "Box(%s, %s)" % (self.shape, self.dtype)


class _Discrete:
    def __init__(self, n: int, seed: Optional[int] = None) -> None:
        self.n, self.shape, self.dtype = int(n), (), np.dtype(np.int64)
        self._rng = np.random.default_rng(seed)

    def seed(self, seed: Optional[int] = None) -> None:
        self._rng = np.random.default_rng(seed)

    def sample(self) -> np.int64:
        return np.int64(self._rng.integers(self.n))

    def contains(self, x) -> bool:
        return np.ndim(x) == 0 and float(x) == int(x) and 0 <= int(x) < self.n

    def __repr__(self) -> str:
        return "Discrete(%d)" % self.n


class _MultiDiscrete:
    def __init__(self, nvec) -> None:
        self.nvec = np.asarray(nvec, dtype=np.int64)
        self.shape, self.dtype = self.nvec.shape, np.dtype(np.int64)
        self._rng = np.random.default_rng()

    def seed(self, seed: Optional[int] = None) -> None:
        self._rng = np.random.default_rng(seed)

    def sample(self) -> np.ndarray:
        return self._rng.integers(self.nvec)

    def contains(self, x) -> bool:
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all((x >= 0) & (x < self.nvec)))

    def __repr__(self) -> str:
        return "MultiDiscrete(%s)" % (self.nvec,)


def box(low, high, shape=None):
    if _gymnasium_spaces is not None:
        return _gymnasium_spaces.Box(low, high, shape=shape, dtype=np.float32)
    return _Box(low, high, shape)


def observation_space(count: Optional[int] = None):
    """One lander's (8,) observation space, or a batch's (count, 8)."""
    low, high = np.array(K.OBSERVATION_LOW, np.float32), np.array(K.OBSERVATION_HIGH, np.float32)
    if count is not None:
        low, high = np.tile(low, (count, 1)), np.tile(high, (count, 1))
    return box(low, high)


def action_space(continuous: bool, count: Optional[int] = None):
    """Discrete(4) or Box(-1, 1, (2,)) for one lander; MultiDiscrete or an (count, 2) box
    for a batch, as Gymnasium batches them."""
    if continuous:
        return box(-1.0, 1.0, (2,) if count is None else (count, 2))
    if count is None:
        return _gymnasium_spaces.Discrete(4) if _gymnasium_spaces is not None else _Discrete(4)
    nvec = np.full(count, 4, dtype=np.int64)
    return _gymnasium_spaces.MultiDiscrete(nvec) if _gymnasium_spaces is not None else _MultiDiscrete(nvec)
