# SPDX-License-Identifier: MIT
"""Each lander's random stream (NumPy's default generator, PCG64, as Gymnasium's
np_random), with the two dispersion draws every frame takes served from blocks drawn
ahead: a frame then costs one gather for all the landers, not a generator call each.

Drawing ahead must not change what a stream gives. Gymnasium draws an episode's terrain
and push from the same stream right after the last frame's dispersion, so a reset first
puts the stream back where the frames' draws left it: the state saved before the block,
advanced by the draws taken (each uniform double is one 64-bit output of PCG64)."""

from typing import List, Optional

import numpy as np

# Frames of dispersion drawn ahead per lander. An episode of LunarLander lasts 60 to
# 1,000 frames; refills then cost a generator call per lander every 64 frames.
BLOCK_FRAMES = 64
DRAWS_PER_FRAME = 2


class LanderStreams:
    def __init__(self, count: int) -> None:
        self._generators: List[np.random.Generator] = [np.random.default_rng() for _ in range(count)]
        self._block = np.zeros((count, BLOCK_FRAMES, DRAWS_PER_FRAME))
        self._taken = np.full(count, BLOCK_FRAMES, dtype=np.int64)  # frames of the block used
        self._state_before_block: List[Optional[dict]] = [None] * count
        self._rows = np.arange(count)

    def seed(self, index: int, seed: Optional[int]) -> None:
        """A new stream for lander index (None draws fresh entropy)."""
        self._generators[index] = np.random.default_rng(seed)
        self._drop_block(index)

    def for_episode(self, index: int) -> np.random.Generator:
        """Lander index's stream where its frames' draws left it, for a reset's draws."""
        generator = self._generators[index]
        state = self._state_before_block[index]
        if state is not None:
            generator.bit_generator.state = state
            generator.bit_generator.advance(DRAWS_PER_FRAME * int(self._taken[index]))
        self._drop_block(index)
        return generator

    def dispersion(self) -> np.ndarray:
        """This frame's draws of every lander, uniform in [-1, 1): (count, 2)."""
        for index in np.flatnonzero(self._taken == BLOCK_FRAMES).tolist():
            generator = self._generators[index]
            self._state_before_block[index] = generator.bit_generator.state
            self._block[index] = generator.uniform(-1.0, 1.0, size=(BLOCK_FRAMES, DRAWS_PER_FRAME))
            self._taken[index] = 0
        draws = self._block[self._rows, self._taken]
        self._taken += 1
        return draws

    def _drop_block(self, index: int) -> None:
        self._state_before_block[index] = None
        self._taken[index] = BLOCK_FRAMES
