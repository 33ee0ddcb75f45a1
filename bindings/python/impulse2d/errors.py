# SPDX-License-Identifier: MIT
"""Exceptions raised for the library's status codes, and for loading problems."""

from typing import Dict, Type


class Impulse2DError(Exception):
    """Base of every error the library reports. ``status`` is the C status code and
    ``str(error)`` the library's message, e.g. ``i2d_body_set_linear_velocity:
    velocity.x is NaN``."""

    status: int = -1

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class InvalidArgument(Impulse2DError, ValueError):
    """I2D_ERR_INVALID_ARGUMENT: NaN or infinite values, bad sizes, out-of-range settings."""

    status = 1


class InvalidHandle(Impulse2DError):
    """I2D_ERR_INVALID_HANDLE: the world, body or shape was destroyed (or never existed)."""

    status = 2


class WorldLocked(Impulse2DError):
    """I2D_ERR_WORLD_LOCKED: the world was changed from inside a query callback, or called
    at all from inside a contact hook."""

    status = 3


class CapacityError(Impulse2DError):
    """I2D_ERR_CAPACITY: a documented limit (e.g. 4096 worlds alive at once) was reached."""

    status = 4


class OutOfMemory(Impulse2DError, MemoryError):
    """I2D_ERR_OUT_OF_MEMORY: the library could not allocate."""

    status = 5


class InvalidSnapshot(Impulse2DError, ValueError):
    """I2D_ERR_INVALID_SNAPSHOT: bytes that are not a snapshot or rollback state this world
    can take (truncated, corrupted, of a newer format, another world's state, or a state
    saved before the world's bodies, shapes or joints changed). The world is unchanged."""

    status = 7


class LibraryError(ImportError):
    """The native library could not be found or loaded, or it does not describe its
    structs, or it does not match this package (LayoutMismatch)."""


class LayoutMismatch(LibraryError):
    """The loaded library's public structs do not fit this package: a field the package
    reads or writes is missing or of another kind, or ctypes cannot lay a struct out as
    the library describes it. Calling it would misread or corrupt memory, so it is
    refused."""


STATUS_ERRORS: Dict[int, Type[Impulse2DError]] = {
    cls.status: cls
    for cls in (InvalidArgument, InvalidHandle, WorldLocked, CapacityError, OutOfMemory, InvalidSnapshot)
}


def error_for(status: int, message: str) -> Impulse2DError:
    """The exception for a non-zero status code, carrying the library's message."""
    cls = STATUS_ERRORS.get(status, Impulse2DError)
    error = cls(message or "status %d" % status)
    if cls is Impulse2DError:
        error.status = status
    return error
