# SPDX-License-Identifier: MIT
"""Replay: a recording (World.start_recording) run again, every step's hash checked."""

import ctypes as C
from typing import Any, Optional

from ._native import apply_settings, check, check_last, lib
from .world import _RUNTIME_SETTINGS, Bytes, World, _as_bytes


class Replay:
    """A recording replayed in a world of its own, made from the snapshot it starts with.

    step(n) runs up to n more recorded steps, each with the calls recorded before it, and
    stops after the first whose state hash differs from the recorded one; divergent_step
    names it (None while every hash matched). seek(k) goes to step k, backwards too.
    runtime is the host's wiring (worker_count, simd_path, enable_profile). A recording
    the library refuses raises InvalidSnapshot with its message. Use it as a context
    manager, or call close(); it also closes when collected."""

    def __init__(self, recording: Bytes, **runtime: Any) -> None:
        self._id = 0
        unknown = sorted(set(runtime) - set(_RUNTIME_SETTINGS))
        if unknown:
            raise TypeError("Replay takes the host's wiring only (%s), not %s"
                            % (", ".join(_RUNTIME_SETTINGS), ", ".join(unknown)))
        data = _as_bytes(recording, "Replay", "start_recording")
        world_def = lib.i2d_default_world_def()
        apply_settings(world_def, runtime, "world")
        replay_id = lib.i2d_replay_open(data, len(data), C.byref(world_def))
        if not replay_id:
            check_last()
        self._id = replay_id
        self._world = World._borrow(lib.i2d_replay_get_world(replay_id))

    def __enter__(self) -> "Replay":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __del__(self) -> None:
        if getattr(self, "_id", 0) and lib is not None:
            lib.i2d_replay_close(self._id)
            self._id = 0

    def close(self) -> None:
        """Closes the replay; its world goes with it. Closing twice is harmless."""
        if self._id:
            replay_id, self._id = self._id, 0
            self._world._forget()
            check(lib.i2d_replay_close(replay_id))

    @property
    def world(self) -> World:
        """The replay's world, to read as the replay goes (the replay owns it)."""
        return self._world

    def step(self, count: int = 1) -> int:
        """Replays up to count more steps; returns how many ran (fewer at the end of the
        recording or after a step whose hash differed)."""
        ran = lib.i2d_replay_step(self._id, count)
        check_last()
        return ran

    @property
    def current_step(self) -> int:
        """Steps replayed so far."""
        value = lib.i2d_replay_get_step(self._id)
        check_last()
        return value

    @property
    def step_count(self) -> int:
        """Steps in the recording."""
        value = lib.i2d_replay_get_step_count(self._id)
        check_last()
        return value

    @property
    def divergent_step(self) -> Optional[int]:
        """The first step whose hash differed from the recording's (1 for the first step),
        or None."""
        value = lib.i2d_replay_get_divergent_step(self._id)
        check_last()
        return None if value < 0 else value

    def seek(self, step: int) -> None:
        """Goes to step (0 to step_count): the world as it was after that many recorded
        steps, before the calls recorded after it."""
        check(lib.i2d_replay_seek(self._id, step))
