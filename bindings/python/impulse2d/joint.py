# SPDX-License-Identifier: MIT
"""Joint: a value handle for a joint between two bodies (include/impulse2d/joint.h)."""

import ctypes as C
from typing import TYPE_CHECKING, Any, Dict, Sequence, Tuple

from ._native import apply_settings, check, check_last, lib, vec2
from ._structs import JOINT_DEFS, JointEvents, Vec2
from .body import Body
from .types import Vec

if TYPE_CHECKING:  # pragma: no cover
    from .world import World

_ID = C.c_uint64
_STATUS = C.c_int32

# Kinds in i2d_joint_type order: the C enum's value is the index.
KINDS: Tuple[str, ...] = tuple(JOINT_DEFS)

# The base fields every kind shares, as create_joint takes them.
_BASE_SETTINGS = ("local_anchor_a", "local_anchor_b", "collide_connected", "force_threshold", "torque_threshold")


def _declare() -> Dict[str, Dict[str, Any]]:
    """Declares every joint function the package calls and returns, per kind, the
    settings it reads and writes after creation and their ctypes type (from the def
    struct, which the library describes: its getter and setter per def field,
    i2d_<kind>_joint_get_<field>)."""
    common = {
        "i2d_joint_destroy": (_STATUS, [_ID]),
        "i2d_joint_is_valid": (C.c_bool, [_ID]),
        "i2d_joint_get_type": (C.c_int32, [_ID]),
        "i2d_joint_get_body_a": (_ID, [_ID]),
        "i2d_joint_get_body_b": (_ID, [_ID]),
        "i2d_joint_get_reaction_force": (Vec2, [_ID]),
        "i2d_joint_get_reaction_torque": (C.c_float, [_ID]),
        "i2d_joint_wake_bodies": (_STATUS, [_ID]),
        "i2d_world_get_joint_events": (JointEvents, [_ID]),
        "i2d_world_get_joint_count": (C.c_int32, [_ID]),
        "i2d_joint_in_world": (_ID, [_ID, _ID]),
    }
    for field in _BASE_SETTINGS:
        ctype = Vec2 if field.startswith("local_anchor") else C.c_bool if field == "collide_connected" else C.c_float
        common["i2d_joint_get_" + field] = (ctype, [_ID])
        common["i2d_joint_set_" + field] = (_STATUS, [_ID, ctype])
    settings: Dict[str, Dict[str, Any]] = {}
    for kind, def_struct in JOINT_DEFS.items():
        common["i2d_default_%s_joint_def" % kind] = (def_struct, [])
        common["i2d_joint_create_" + kind] = (_ID, [_ID, C.POINTER(def_struct)])
        fields = {name: ctype for name, ctype in def_struct._fields_ if name not in ("base", "internal_cookie")}
        settings[kind] = {}
        for name, ctype in fields.items():
            getter, setter = "i2d_%s_joint_get_%s" % (kind, name), "i2d_%s_joint_set_%s" % (kind, name)
            # A def field without its getter and setter (a library newer than its
            # accessors) is still set at creation, by name like every setting.
            if hasattr(lib, getter) and hasattr(lib, setter):
                common[getter] = (ctype, [_ID])
                common[setter] = (_STATUS, [_ID, ctype])
                settings[kind][name] = ctype
    for name, (restype, argtypes) in common.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = restype, argtypes
    return settings


_SETTINGS = _declare()


def create(world: "World", kind: str, body_a: Body, body_b: Body, settings: Dict[str, Any]) -> "Joint":
    """World.create_joint's work: a def of the kind with the settings, then create."""
    if kind not in JOINT_DEFS:
        raise ValueError("unknown joint kind %r; known kinds: %s" % (kind, ", ".join(KINDS)))
    joint_def = getattr(lib, "i2d_default_%s_joint_def" % kind)()
    base = {name: settings.pop(name) for name in _BASE_SETTINGS if name in settings}
    apply_settings(joint_def.base, base, "joint")
    apply_settings(joint_def, settings, kind + " joint")
    joint_def.base.body_a, joint_def.base.body_b = body_a.id, body_b.id
    joint_id = getattr(lib, "i2d_joint_create_" + kind)(world.id, C.byref(joint_def))
    if not joint_id:
        check_last()
    return Joint(world, joint_id)


class Joint:
    """A joint of a World, created by World.create_joint. Compares and hashes by its
    id. Every kind's settings are read and written with get(name) and set(name, value),
    names as the kind's C def fields (e.g. "motor_speed" of a revolute joint)."""

    __slots__ = ("_id", "_world")

    def __init__(self, world: "World", joint_id: int) -> None:
        self._world = world
        self._id = joint_id

    @property
    def id(self) -> int:
        """The joint's 64-bit id (i2d_joint_id.bits)."""
        return self._id

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Joint) and other._id == self._id

    def __hash__(self) -> int:
        return hash(self._id)

    def __repr__(self) -> str:
        return "Joint(0x%016x)" % self._id

    def __copy__(self) -> "Joint":
        return self

    def __reduce__(self) -> Tuple[Any, ...]:
        # As Body's: the joint of the same index and generation in the copied world.
        return (_joint_in, (self._world, self._id))

    @property
    def is_valid(self) -> bool:
        """False once the joint, one of its bodies or its world was destroyed."""
        return bool(lib.i2d_joint_is_valid(self._id))

    def destroy(self) -> None:
        check(lib.i2d_joint_destroy(self._id))

    @property
    def kind(self) -> str:
        """"revolute", "distance", ... (the C i2d_joint_type)."""
        value = lib.i2d_joint_get_type(self._id)
        check_last()
        return KINDS[value]

    @property
    def body_a(self) -> Body:
        body_id = lib.i2d_joint_get_body_a(self._id)
        check_last()
        return Body(self._world, body_id)

    @property
    def body_b(self) -> Body:
        body_id = lib.i2d_joint_get_body_b(self._id)
        check_last()
        return Body(self._world, body_id)

    @property
    def reaction_force(self) -> Vec:
        """The force on body B over the last step, N."""
        v = lib.i2d_joint_get_reaction_force(self._id)
        check_last()
        return (v.x, v.y)

    @property
    def reaction_torque(self) -> float:
        value = lib.i2d_joint_get_reaction_torque(self._id)
        check_last()
        return value

    def wake_bodies(self) -> None:
        check(lib.i2d_joint_wake_bodies(self._id))

    def _function(self, verb: str, name: str) -> Tuple[Any, str]:
        if name in _BASE_SETTINGS:
            return getattr(lib, "i2d_joint_%s_%s" % (verb, name)), name
        kind = self.kind
        if name not in _SETTINGS[kind]:
            known = sorted(_SETTINGS[kind]) + list(_BASE_SETTINGS)
            raise AttributeError("a %s joint has no setting %r; known: %s" % (kind, name, ", ".join(known)))
        return getattr(lib, "i2d_%s_joint_%s_%s" % (kind, verb, name)), name

    def get(self, name: str) -> Any:
        """A setting: a float, a bool or an (x, y) pair."""
        fn, _ = self._function("get", name)
        value = fn(self._id)
        check_last()
        return (value.x, value.y) if isinstance(value, Vec2) else value

    def set(self, name: str, value: Any) -> None:
        """Changes a setting (checked as the def would be) and wakes the two bodies."""
        fn, _ = self._function("set", name)
        if fn.argtypes[1] is Vec2:
            value = vec2(value)
        check(fn(self._id, value))


def _joint_in(world: "World", joint_id: int) -> Joint:
    """Joint.__reduce__'s way back, as body._body_in."""
    return Joint(world, lib.i2d_joint_in_world(joint_id, world.id))


def joint_events(world: "World") -> Sequence[Joint]:
    """The joints whose reaction passed a threshold in the last step."""
    e = lib.i2d_world_get_joint_events(world.id)
    check_last()
    return [Joint(world, e.events[i].joint) for i in range(e.count)]


def joint_count(world: "World") -> int:
    count = lib.i2d_world_get_joint_count(world.id)
    check_last()
    return count
