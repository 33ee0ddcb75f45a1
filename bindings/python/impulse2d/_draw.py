# SPDX-License-Identifier: MIT
"""Debug drawing (i2d_world_draw, include/impulse2d/toolkit.h) through a Python drawer: a C
callback for each of the drawer's draw_* methods, turning the library's values into tuples;
the named colours.

The library calls the callbacks on the calling thread, before i2d_world_draw returns, so
they live as long as one World.draw call. An exception must not unwind through the
library: the first one a method raises is kept, the rest of the pass no longer calls the
drawer, and World.draw raises it once the library is done."""

import ctypes as C
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Optional, Sequence

from ._native import check, lib, vec2
from ._structs import AABB, DRAW_CALLBACKS, DRAW_FLAGS, Transform as _Transform, Vec2
from .types import Transform, Vec

if TYPE_CHECKING:  # pragma: no cover
    from .world import World

# The colours i2d_world_draw gives, 0xRRGGBB. The header defines them as macros, which the
# library cannot describe at run time as it does its structs, so they are repeated here;
# tests/python/test_debug_draw.py compares them with include/impulse2d/toolkit.h.
# A shape's colour says its body's state; the first that holds wins, in this order.
COLOR_QUARANTINED = 0xFF3333  #: a body the step quarantined (non-finite state)
COLOR_DISABLED = 0x666666  #: a disabled body
COLOR_SENSOR = 0x33CCFF  #: a sensor shape on an enabled body
COLOR_STATIC = 0x80E680
COLOR_KINEMATIC = 0x8080E6
COLOR_BULLET = 0xE6E64D  #: a bullet, awake
COLOR_AWAKE = 0xE6B380  #: a dynamic body awake
COLOR_ASLEEP = 0x999999  #: a dynamic body asleep
# Joints (the last three with joint_extras).
COLOR_JOINT = 0x7FB89A
COLOR_JOINT_ANCHOR = 0x2E8B57
COLOR_JOINT_LIMIT = 0xE05050
COLOR_JOINT_MOTOR = 0xB050E0
COLOR_JOINT_SPRING = 0x50A0E0
# Boxes, bodies and contacts.
COLOR_BOUNDS = 0xFFD700
COLOR_ISLAND = 0xFF4500
COLOR_MASS = 0xF5F5F5
COLOR_CONTACT = 0x3366FF  #: a contact point within the contact slop
COLOR_SPECULATIVE = 0xC8C8C8  #: a contact point farther apart than the slop
COLOR_CONTACT_NORMAL = 0x696969
COLOR_CONTACT_IMPULSE = 0xFF00FF
COLOR_FRICTION_IMPULSE = 0xFFFF00
#: graph_colors: a contact of constraint colour k is drawn GRAPH_COLORS[k % 12].
GRAPH_COLORS = (
    0xFF0000, 0xFF8000, 0xFFFF00, 0x80FF00, 0x00FF00, 0x00FF80, 0x00FFFF, 0x0080FF, 0x0000FF, 0x8000FF, 0xFF00FF,
    0xFF0080,
)
COLOR_GRAPH_OVERFLOW = 0xFFFFFF  #: graph_colors: a contact solved after the coloured ones

COLORS = {name: value for name, value in globals().items() if name.startswith("COLOR_")}

# The callbacks' C types; vertex arrays and text arrive as addresses, converted below.
_COLOR, _CONTEXT = C.c_uint32, C.c_void_p
_FUNCTION_TYPES = {
    "draw_polygon": C.CFUNCTYPE(None, C.c_void_p, C.c_int32, _COLOR, _CONTEXT),
    "draw_solid_polygon": C.CFUNCTYPE(None, _Transform, C.c_void_p, C.c_int32, C.c_float, _COLOR, _CONTEXT),
    "draw_circle": C.CFUNCTYPE(None, Vec2, C.c_float, _COLOR, _CONTEXT),
    "draw_solid_circle": C.CFUNCTYPE(None, _Transform, C.c_float, _COLOR, _CONTEXT),
    "draw_solid_capsule": C.CFUNCTYPE(None, Vec2, Vec2, C.c_float, _COLOR, _CONTEXT),
    "draw_segment": C.CFUNCTYPE(None, Vec2, Vec2, _COLOR, _CONTEXT),
    "draw_transform": C.CFUNCTYPE(None, _Transform, _CONTEXT),
    "draw_point": C.CFUNCTYPE(None, Vec2, C.c_float, _COLOR, _CONTEXT),
    "draw_string": C.CFUNCTYPE(None, Vec2, C.c_char_p, _COLOR, _CONTEXT),
}
assert tuple(_FUNCTION_TYPES) == DRAW_CALLBACKS


def _points(address: int, count: int) -> List[Vec]:
    """count i2d_vec2 at address as (x, y) tuples: one read of the floats, then pairs."""
    floats = (C.c_float * (2 * count)).from_address(address)[:]
    return list(zip(floats[0::2], floats[1::2]))


def _transform(xf: Any) -> Transform:
    return Transform((xf.p.x, xf.p.y), (xf.q.c, xf.q.s))


def _pair(v: Any) -> Vec:
    return (v.x, v.y)


class _Pass:
    """One World.draw: keeps the C callbacks alive for the call and the first exception a
    drawer method raised."""

    def __init__(self) -> None:
        self.callbacks: List[Any] = []
        self.raised: Optional[BaseException] = None

    def call(self, method: Callable[..., Any], *args: Any) -> None:
        if self.raised is not None:
            return  # the pass goes on in C; the drawer has had its say
        try:
            method(*args)
        except BaseException as error:  # never let Python unwind through C: World.draw raises it
            self.raised = error


# For each callback, the C function over the drawer's method: the library's values as the
# package's (tuples, Transform, str).
def _polygon(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda vertices, count, color, _c: run.call(method, _points(vertices, count), color)


def _solid_polygon(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda xf, vertices, count, radius, color, _c: run.call(
        method, _transform(xf), _points(vertices, count), radius, color)


def _circle(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda center, radius, color, _c: run.call(method, _pair(center), radius, color)


def _solid_circle(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda xf, radius, color, _c: run.call(method, _transform(xf), radius, color)


def _solid_capsule(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda p1, p2, radius, color, _c: run.call(method, _pair(p1), _pair(p2), radius, color)


def _segment(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda p1, p2, color, _c: run.call(method, _pair(p1), _pair(p2), color)


def _transform_frame(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda xf, _c: run.call(method, _transform(xf))


def _point(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda p, size, color, _c: run.call(method, _pair(p), size, color)


def _string(run: _Pass, method: Callable[..., Any]) -> Callable[..., None]:
    return lambda p, text, color, _c: run.call(method, _pair(p), text.decode("utf-8", "replace"), color)


_TRAMPOLINES = {
    "draw_polygon": _polygon,
    "draw_solid_polygon": _solid_polygon,
    "draw_circle": _circle,
    "draw_solid_circle": _solid_circle,
    "draw_solid_capsule": _solid_capsule,
    "draw_segment": _segment,
    "draw_transform": _transform_frame,
    "draw_point": _point,
    "draw_string": _string,
}


def _method(drawer: Any, name: str) -> Optional[Callable[..., Any]]:
    """The drawer's method for a callback; None (not drawn) when it has none."""
    method = getattr(drawer, name, None)
    if method is not None and not callable(method):
        raise TypeError("the drawer's %s is a %s, not a method" % (name, type(method).__name__))
    return method


def _code_address(callback: Any) -> int:
    """The C function pointer a ctypes callback holds. Read from its storage rather than
    through ctypes.cast, which records the callback in its own keep-alive dictionary (a
    cycle that only the garbage collector would free, with the drawer it refers to)."""
    return C.c_void_p.from_address(C.addressof(callback)).value


def _connect(d: Any, drawer: Any, run: _Pass) -> None:
    for name in DRAW_CALLBACKS:
        method = _method(drawer, name)
        if method is not None:
            callback = _FUNCTION_TYPES[name](_TRAMPOLINES[name](run, method))
            run.callbacks.append(callback)
            setattr(d, name, _code_address(callback))


def draw(world: "World", drawer: Any, flags: Dict[str, bool], bounds_box: Optional[Sequence[Sequence[float]]]) -> None:
    """World.draw: flags holds every i2d_debug_draw draw_* flag by name."""
    d = lib.i2d_default_debug_draw()
    run = _Pass()
    _connect(d, drawer, run)
    # By the names USES checked at load: a misspelt flag is a KeyError here rather than a
    # new attribute on the ctypes struct that the library never sees.
    for name in DRAW_FLAGS:
        setattr(d, name, bool(flags[name]))
    if bounds_box is not None:
        lower, upper = bounds_box
        d.drawing_bounds = AABB(min=vec2(lower), max=vec2(upper))
        d.use_drawing_bounds = True
    try:
        check(lib.i2d_world_draw(world.id, C.byref(d)))
    finally:
        # The callbacks' closures refer to the pass that holds them; dropping them (and the
        # exception, whose traceback holds the pass too) leaves no cycle, so the drawer is
        # freed as soon as the caller lets go of it rather than at the next collection.
        run.callbacks.clear()
    raised, run.raised = run.raised, None
    if raised is not None:
        try:
            raise raised
        finally:
            del raised  # its traceback holds this frame: a local naming it would be a cycle
