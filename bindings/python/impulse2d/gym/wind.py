# SPDX-License-Identifier: MIT
"""Wind and turbulence: a smooth pseudo-random force and torque on the hull while
neither leg touches the ground, each from a counter started at a random integer."""

import math

import numpy as np

from . import constants as K


def random_start(rng: np.random.Generator) -> int:
    """A counter's start; the wind's then the turbulence's are drawn, in that order,
    right after the initial push, as Gymnasium does."""
    return int(rng.integers(-K.WIND_START_RANGE, K.WIND_START_RANGE))


def gust(counter: int) -> float:
    """The wind's shape in [-1, 1]: two incommensurate sines through a tanh."""
    k = K.WIND_FREQUENCY
    return math.tanh(math.sin(2 * k * counter) + math.sin(math.pi * k * counter))
