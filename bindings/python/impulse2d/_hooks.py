# SPDX-License-Identifier: MIT
"""A world's contact hooks (include/impulse2d/toolkit.h) on the Python side: the C
callbacks that hand the user's functions the package's objects, and what those functions
raised, kept for World.step.

The library calls the hooks inside i2d_world_step, on whichever of its threads finds the
pair. ctypes releases the GIL for the step and takes it again for each call, so the hooks
run one at a time whatever the worker count. An exception must not unwind through the
library (ctypes would print it and answer false, turning the pair off): it is kept, the
pair gets the hook's neutral answer, true, and World.step raises it after the step."""

import weakref
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Optional

from ._library import _CUSTOM_FILTER_FN, _PRE_SOLVE_FN
from ._native import check, lib
from ._structs import Manifold as _Manifold
from .shape import Shape, manifold_of

if TYPE_CHECKING:  # pragma: no cover
    from .world import World


class Hooks:
    """The hooks of one World. It holds the C callbacks for as long as the library may call
    them (ctypes frees a callback object's code with the object)."""

    def __init__(self, world: "World") -> None:
        # A weak reference: the callbacks then keep no cycle through the World, which a
        # program that drops it destroys at once, as it does a World without hooks.
        self._world = weakref.ref(world)
        self._callbacks: Dict[str, Any] = {}
        self._raised: List[BaseException] = []

    def set_custom_filter(self, fn: Optional[Callable[[Shape, Shape], Any]]) -> None:
        def custom_filter(shape_a: int, shape_b: int, _context: Any) -> bool:
            world = self._world()
            return self._answer(fn, Shape(world, shape_a), Shape(world, shape_b))

        self._set("custom_filter", fn, _CUSTOM_FILTER_FN, custom_filter, lib.i2d_world_set_custom_filter_callback)

    def set_pre_solve(self, fn: Optional[Callable[..., Any]]) -> None:
        def pre_solve(shape_a: int, shape_b: int, manifold: int, _context: Any) -> bool:
            world = self._world()
            shown = manifold_of(_Manifold.from_address(manifold))
            return self._answer(fn, Shape(world, shape_a), Shape(world, shape_b), shown)

        self._set("pre_solve", fn, _PRE_SOLVE_FN, pre_solve, lib.i2d_world_set_pre_solve_callback)

    def take_raised(self) -> Optional[BaseException]:
        """The first exception a hook raised since the last call, if any; forgets the rest."""
        raised, self._raised = self._raised, []
        return raised[0] if raised else None

    def _set(self, kind: str, fn: Any, fn_type: Any, trampoline: Callable[..., bool], setter: Any) -> None:
        if fn is not None and not callable(fn):
            raise TypeError("World.set_%s takes a callable or None, not %s" % (kind, type(fn).__name__))
        callback = fn_type() if fn is None else fn_type(trampoline)  # fn_type(): NULL, which clears
        check(setter(self._world().id, callback, None))
        # Replaced only once the library took the new one: a refused call (WorldLocked, a
        # destroyed world) leaves the old callback set, so it must stay alive.
        self._callbacks[kind] = callback

    def _answer(self, fn: Callable[..., Any], *args: Any) -> bool:
        try:
            return bool(fn(*args))
        except BaseException as error:  # never let Python unwind through C: World.step raises it
            self._raised.append(error)
            return True
