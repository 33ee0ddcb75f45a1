# SPDX-License-Identifier: MIT
"""The 8 numbers a policy sees, scaled as Gymnasium's LunarLander-v3 scales them:
position relative to the pad in half-screens, velocity in half-screens per frame,
the hull's angle (radians, not wrapped), its spin in units of 2.5 rad/s, and whether
each leg touches the ground."""

import math

import numpy as np

from . import constants as K

HALF_WIDTH = K.SCREEN_WIDTH / 2
HALF_HEIGHT = K.SCREEN_HEIGHT / 2
# The hull's origin sits this far above the pad when the lander stands on it.
STANDING_HEIGHT = K.LEG_DROP_PIXELS / K.PIXELS_PER_METRE


def unwrap_angle(previous: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    """Box2D 2.3 reports a body's angle as it accumulated (two turns are 4 pi), and so
    does the observation: the new angle is the old plus the wound difference."""
    turned = np.arctan2(sin.astype(np.float64), cos.astype(np.float64)) - previous
    return previous + (turned + math.pi) % (2 * math.pi) - math.pi


def state_of(position: np.ndarray, velocity: np.ndarray, angle: np.ndarray, spin: np.ndarray,
             legs_down: np.ndarray, pad_height: np.ndarray) -> np.ndarray:
    """The observations as float64 rows (the reward is computed from these; the
    policy gets them as float32). position and velocity (n, 2), legs_down (n, 2) bool."""
    state = np.empty((len(angle), 8), dtype=np.float64)
    state[:, 0] = (position[:, 0] - HALF_WIDTH) / HALF_WIDTH
    state[:, 1] = (position[:, 1] - (pad_height + STANDING_HEIGHT)) / HALF_HEIGHT
    state[:, 2] = velocity[:, 0] * HALF_WIDTH / K.FRAMES_PER_SECOND
    state[:, 3] = velocity[:, 1] * HALF_HEIGHT / K.FRAMES_PER_SECOND
    state[:, 4] = angle
    state[:, 5] = 20.0 * spin / K.FRAMES_PER_SECOND
    state[:, 6:8] = legs_down
    return state
