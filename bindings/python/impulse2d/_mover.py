# SPDX-License-Identifier: MIT
"""The character mover (include/impulse2d/toolkit.h) on the Python side: capsules, planes
and filters turned into the C structs and back. World.move_character, cast_mover and
collide_mover call the functions here; solve_planes and clip_vector are the package's.

Capsules are (center1, center2, radius) triples, as Shape.geometry() gives a capsule's, so
a character's capsule can come from a shape. Planes are CollisionPlanes (or tuples that
make one); a rigid plane's push_limit is math.inf here and FLT_MAX in C, because the C
API refuses infinities and Python programs write inf for "no limit"."""

import ctypes as C
import math
from typing import TYPE_CHECKING, Any, Dict, Iterable, List, Optional, Sequence, Tuple

from ._native import check, check_last, lib, pair, vec2
from ._structs import Capsule, CharacterResult as _CharacterResult, CollisionPlane as _CollisionPlane
from ._structs import QueryFilter
from .shape import Shape
from .types import CharacterResult, CollisionPlane, PlaneResult, Vec

if TYPE_CHECKING:  # pragma: no cover
    from .world import World

# The largest float32: the C API's push_limit of a rigid plane (FLT_MAX).
_FLT_MAX = 3.4028234663852886e38
# collide_mover's first guess at how many planes touch a character: a floor, a wall, a
# ceiling and a step, with room to spare; a crowd costs a second call.
_PLANE_GUESS = 8
# The def's settings World.move_character takes by keyword (its filter apart).
CHARACTER_SETTINGS = ("max_slope_angle", "step_height", "snap_distance", "skin", "max_iterations", "push_mass")

CapsuleLike = Tuple[Sequence[float], Sequence[float], float]


def capsule_struct(capsule: CapsuleLike) -> Capsule:
    center1, center2, radius = capsule
    return Capsule(center1=vec2(center1), center2=vec2(center2), radius=radius)


def query_filter(value: Any) -> QueryFilter:
    """A QueryFilter from None (every shape), (category_bits, mask_bits) or a QueryFilter."""
    if value is None:
        return lib.i2d_default_query_filter()
    if isinstance(value, QueryFilter):
        return value
    category_bits, mask_bits = value
    return QueryFilter(category_bits=category_bits, mask_bits=mask_bits)


def _plane_struct(plane: Any) -> Any:
    p = plane if isinstance(plane, CollisionPlane) else CollisionPlane(*plane)
    c = _CollisionPlane(push=p.push, clip_velocity=p.clip_velocity)
    c.plane.normal = vec2(p.normal)
    c.plane.offset = p.offset
    c.push_limit = _FLT_MAX if p.push_limit == math.inf else p.push_limit
    return c


def _plane_array(planes: Iterable[Any]) -> Any:
    structs = [_plane_struct(p) for p in planes]
    return (_CollisionPlane * len(structs))(*structs)


def _plane_of(c: Any) -> CollisionPlane:
    limit = math.inf if c.push_limit >= _FLT_MAX else c.push_limit
    return CollisionPlane(pair(c.plane.normal), c.plane.offset, limit, c.push, bool(c.clip_velocity))


def solve_planes(target_delta: Sequence[float], planes: Iterable[Any]) -> PlaneResult:
    """The move nearest target_delta with offset + dot(normal, move) >= 0 for every rigid
    plane, soft planes pushing at most their push_limit (i2d_solve_planes: each plane
    pushes along its normal, never pulls, sweeping until the pushes settle). planes are
    CollisionPlanes or (normal, offset[, push_limit[, push[, clip_velocity]]]) tuples.
    InvalidArgument, with the library's message, for NaN or infinite values, a normal not
    of unit length (within 1e-3), a negative push_limit, an offset or delta beyond 1e9."""
    array = _plane_array(planes)
    result = lib.i2d_solve_planes(vec2(target_delta), C.addressof(array), len(array))
    check_last()
    return PlaneResult(pair(result.translation), result.iteration_count, tuple(p.push for p in array))


def clip_vector(vector: Sequence[float], planes: Iterable[Any]) -> Vec:
    """vector less its part that runs into the planes with clip_velocity set: the nearest
    vector that runs into none of them (in a corner of two, possibly zero), so that a
    velocity does not build up against a wall (i2d_clip_vector). Planes and refusals as
    for solve_planes."""
    array = _plane_array(planes)
    clipped = lib.i2d_clip_vector(vec2(vector), C.addressof(array), len(array))
    check_last()
    return pair(clipped)


def cast_mover(world: "World", capsule: CapsuleLike, translation: Sequence[float], filter: Any) -> float:
    fraction = lib.i2d_world_cast_mover(world.id, C.byref(capsule_struct(capsule)), vec2(translation),
                                        query_filter(filter))
    check_last()
    return fraction


def collide_mover(world: "World", capsule: CapsuleLike, filter: Any) -> List[CollisionPlane]:
    mover, qf = capsule_struct(capsule), query_filter(filter)
    capacity = _PLANE_GUESS
    while True:
        out = (_CollisionPlane * capacity)()
        total = lib.i2d_world_collide_mover(world.id, C.byref(mover), qf, C.addressof(out), capacity)
        check_last()
        if total <= capacity:
            return [_plane_of(out[i]) for i in range(total)]
        capacity = total  # the library counted them all: one more call gets them


def character_def(settings: Dict[str, Optional[float]], filter: Any) -> Any:
    """The library's default character def with the settings given (None: the default)."""
    d = lib.i2d_default_character_def()
    for name in CHARACTER_SETTINGS:
        value = settings[name]
        if value is not None:
            setattr(d, name, value)
    if filter is not None:
        d.filter = query_filter(filter)
    return d


def move_character(
    world: "World", d: Any, capsule: CapsuleLike, position: Sequence[float], velocity: Sequence[float],
    time_step: float,
) -> CharacterResult:
    out = _CharacterResult()
    check(lib.i2d_world_move_character(world.id, C.byref(d), C.byref(capsule_struct(capsule)), vec2(position),
                                       vec2(velocity), time_step, C.byref(out)))
    ground = Shape(world, out.ground_shape) if out.ground_shape else None
    return CharacterResult(pair(out.position), pair(out.velocity), bool(out.on_ground), pair(out.ground_normal),
                           ground, pair(out.ground_velocity), out.hit_count)
