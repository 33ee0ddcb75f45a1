# SPDX-License-Identifier: MIT
"""The reward: the change of a "shaping" potential (near the pad, slow, upright, legs
down is good) minus fuel, replaced by +-100 when the episode ends."""

import numpy as np

from . import constants as K


def shaping(state: np.ndarray) -> np.ndarray:
    """The potential of observation rows (float64): -100 per unit of distance to the pad
    and of speed (both in observation units), -100 per radian of tilt, +10 per leg down."""
    distance = np.sqrt(state[:, 0] ** 2 + state[:, 1] ** 2)
    speed = np.sqrt(state[:, 2] ** 2 + state[:, 3] ** 2)
    return -100.0 * distance - 100.0 * speed - 100.0 * np.abs(state[:, 4]) + 10.0 * state[:, 6] + 10.0 * state[:, 7]


def frame_reward(potential: np.ndarray, previous_potential: np.ndarray, fuel: np.ndarray) -> np.ndarray:
    """Potential gained since the last frame, minus fuel. previous_potential is NaN on
    an episode's first frame, whose gain counts as 0."""
    gained = np.where(np.isnan(previous_potential), 0.0, potential - np.nan_to_num(previous_potential))
    return gained - fuel


def episode_end(reward: np.ndarray, crashed: np.ndarray, off_screen: np.ndarray, at_rest: np.ndarray):
    """(reward, terminated): a crash (the hull touched the moon) or leaving the screen
    sideways scores -100; a lander that fell asleep scores +100, which wins if both
    happen in one frame (Gymnasium checks rest last)."""
    failed = crashed | off_screen
    reward = np.where(failed, K.CRASHED_REWARD, reward)
    reward = np.where(at_rest, K.LANDED_REWARD, reward)
    return reward, failed | at_rest
