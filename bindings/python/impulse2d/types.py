# SPDX-License-Identifier: MIT
"""Enumerations and the named tuples that events and queries return."""

import enum
from typing import NamedTuple, Tuple, TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .body import Body
    from .shape import Shape

Vec = Tuple[float, float]


class BodyType(enum.IntEnum):
    """i2d_body_type."""

    STATIC = 0  #: never moves
    KINEMATIC = 1  #: moves by its velocity only, pushes dynamic bodies
    DYNAMIC = 2  #: moved by gravity, forces and contacts


class ShapeType(enum.IntEnum):
    """i2d_shape_type."""

    CIRCLE = 0
    CAPSULE = 1
    SEGMENT = 2
    POLYGON = 3
    CHAIN_SEGMENT = 4  #: one segment of a chain (one-sided, no mass)


class ContactBegin(NamedTuple):
    """Two shapes started touching during the last step."""

    shape_a: "Shape"
    shape_b: "Shape"


class ContactEnd(NamedTuple):
    """Two shapes stopped touching (or one was destroyed; its Shape may be stale)."""

    shape_a: "Shape"
    shape_b: "Shape"


class SensorBegin(NamedTuple):
    """A visitor shape started overlapping a sensor shape."""

    sensor: "Shape"
    visitor: "Shape"


class SensorEnd(NamedTuple):
    """A visitor shape stopped overlapping a sensor shape."""

    sensor: "Shape"
    visitor: "Shape"


class BodyMove(NamedTuple):
    """A body that moved during the last step."""

    body: "Body"
    position: Vec
    rotation: Vec  #: (cosine, sine)
    fell_asleep: bool


class BodyQuarantine(NamedTuple):
    """A body the last step froze because its state stopped being finite: it was made
    static at the pose it started the step from. Set its type again to bring it back."""

    body: "Body"
    position: Vec
    rotation: Vec  #: (cosine, sine)
    former_type: BodyType


class RayHit(NamedTuple):
    """The closest shape a ray hit."""

    shape: "Shape"
    point: Vec
    normal: Vec
    fraction: float


class Counters(NamedTuple):
    """Sizes of a world (i2d_world_counters)."""

    body_count: int
    shape_count: int
    contact_count: int
    pair_count: int
    static_tree_height: int
    kinematic_tree_height: int
    dynamic_tree_height: int
    awake_body_count: int
    sleeping_island_count: int
