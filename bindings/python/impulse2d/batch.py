# SPDX-License-Identifier: MIT
"""Many worlds stepped in one call (i2d_worlds_step), as reinforcement learning steps its
environments: the whole batch runs with the GIL released, on the calling thread and a
pool of worker threads the library keeps between calls, and each world ends with the
same bits as if stepped alone by World.step."""

import ctypes as C
from typing import List, Optional, Sequence

from ._native import check, lib
from .world import World


class WorldBatch:
    """A fixed list of worlds to step together again and again: the id array and the
    batch def are built once, so a step costs one call into the library.

    A world destroyed after the batch was made makes its steps refused (its id is then
    stale), with no world stepped; make a new batch without it."""

    def __init__(self, worlds: Sequence[World], workers: int = 1) -> None:
        self._worlds: List[World] = list(worlds)  # held, so none is collected while batched
        for index, world in enumerate(self._worlds):
            if not isinstance(world, World):
                raise TypeError("worlds[%d] is %s, not an impulse2d.World" % (index, type(world).__name__))
        self._ids = (C.c_uint64 * len(self._worlds))(*(world.id for world in self._worlds))
        self._def = lib.i2d_default_batch_def()
        self._def.worker_count = workers

    def __len__(self) -> int:
        return len(self._worlds)

    @property
    def worlds(self) -> List[World]:
        return list(self._worlds)

    @property
    def workers(self) -> int:
        """Threads that step worlds, the calling thread among them."""
        return int(self._def.worker_count)

    def step(self, time_step: float = 1.0 / 60.0, substeps: int = 4) -> None:
        """Steps every world by time_step in substeps. Bad input (a destroyed world, a
        world listed twice, a bad time step or worker count) raises with the library's
        message and steps no world. Raises, once all are stepped, the first exception a
        contact hook raised in any of them."""
        status = lib.i2d_worlds_step(C.addressof(self._ids), len(self._worlds), time_step, substeps, C.byref(self._def))
        raised: Optional[BaseException] = None
        if World._hooks_ever_set:
            for world in self._worlds:
                exception = world._take_hook_exception()
                raised = raised or exception
        check(status)
        if raised is not None:
            raise raised


def step_worlds(worlds: Sequence[World], time_step: float = 1.0 / 60.0, substeps: int = 4, workers: int = 1) -> None:
    """Steps the worlds in one call, as WorldBatch(worlds, workers).step(time_step,
    substeps); a loop that steps the same worlds every time keeps a WorldBatch instead."""
    WorldBatch(worlds, workers).step(time_step, substeps)
