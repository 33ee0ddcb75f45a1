# SPDX-License-Identifier: MIT
"""The loaded library, its struct classes, and the helpers every wrapper uses to turn
statuses into errors."""

import ctypes as C
from typing import Any, Dict, Sequence, Tuple

from . import _library
from .errors import error_for

lib = _library.load()
#: The struct classes built from the loaded library's description (see _structs.py).
structs = lib._impulse2d_structs
Filter, Rot, Vec2 = structs.Filter, structs.Rot, structs.Vec2


def last_error() -> Exception:
    """The exception for the thread's last status (which must not be I2D_OK)."""
    return error_for(lib.i2d_last_status(), (lib.i2d_last_error_message() or b"").decode())


def check(status: int) -> None:
    """Raises the exception mapped from a returned status, with the library's message."""
    if status:
        raise error_for(status, (lib.i2d_last_error_message() or b"").decode())


def check_last() -> None:
    """Raises if the last call failed: for getters, whose failure value is a zero."""
    status = lib.i2d_last_status()
    if status:
        raise error_for(status, (lib.i2d_last_error_message() or b"").decode())


def vec2(value: Sequence[float]) -> Vec2:
    x, y = value
    return Vec2(x, y)


def rot(angle: float) -> Rot:
    return lib.i2d_make_rot(angle)


def make_filter(value: Any) -> Filter:
    """A Filter from (category_bits, mask_bits[, group_index]) or a Filter."""
    if isinstance(value, Filter):
        return value
    parts = tuple(value)
    return Filter(category_bits=parts[0], mask_bits=parts[1], group_index=parts[2] if len(parts) > 2 else 0)


# A job system of C callbacks is for C and C++ callers; from Python, worker_count alone
# starts the library's own threads.
_HIDDEN_FIELDS = ("internal_cookie", "user_data", "enqueue_task", "finish_task", "user_task_context")
# Per def struct class, the fields settings may name, with their types: built once per
# class (a world's reset builds dozens of shapes, each through apply_settings).
_SETTABLE_FIELDS: Dict[type, Dict[str, Any]] = {}


def _settable_fields(struct_class: type) -> Dict[str, Any]:
    fields = _SETTABLE_FIELDS.get(struct_class)
    if fields is None:
        fields = {name: ctype for name, ctype in struct_class._fields_ if name not in _HIDDEN_FIELDS}
        _SETTABLE_FIELDS[struct_class] = fields
    return fields


def apply_settings(def_struct: C.Structure, settings: Dict[str, Any], kind: str) -> None:
    """Copies keyword settings into a def's fields of the same name, converting pairs
    to vectors; unknown names are a TypeError that lists the known ones."""
    fields = _settable_fields(type(def_struct))
    for name, value in settings.items():
        if name not in fields:
            raise TypeError(
                "unknown %s setting %r; known settings: %s" % (kind, name, ", ".join(sorted(fields)))
            )
        ctype = fields[name]
        if ctype is Vec2:
            value = vec2(value)
        elif ctype is Rot:
            value = value if isinstance(value, Rot) else rot(value)
        elif ctype is Filter:
            value = make_filter(value)
        setattr(def_struct, name, value)


def pair(v: Vec2) -> Tuple[float, float]:
    return (v.x, v.y)
