# SPDX-License-Identifier: MIT
"""Shape: a value handle for a shape attached to a body."""

from typing import TYPE_CHECKING, Any, List, Tuple, Union

from ._native import check, check_last, lib, make_filter, pair
from ._structs import Filter
from .types import ShapeType, Vec

if TYPE_CHECKING:  # pragma: no cover
    from .body import Body
    from .world import World

ShapeGeometry = Union[Tuple[Vec, float], List[Vec], Tuple[Vec, Vec, float], Tuple[Vec, Vec]]


class Shape:
    """A shape of a body. Compares and hashes by its id; stays a valid Python object
    after the shape is destroyed, but every call then raises InvalidHandle."""

    __slots__ = ("_id", "_world")

    def __init__(self, world: "World", shape_id: int) -> None:
        self._world = world
        self._id = shape_id

    @property
    def id(self) -> int:
        """The shape's 64-bit id (i2d_shape_id.bits)."""
        return self._id

    @property
    def world(self) -> "World":
        return self._world

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Shape) and other._id == self._id

    def __hash__(self) -> int:
        return hash(self._id)

    def __repr__(self) -> str:
        return "Shape(0x%016x)" % self._id

    def __copy__(self) -> "Shape":
        return self

    def __reduce__(self) -> Tuple[Any, ...]:
        # As Body's: the shape of the same index and generation in the copied world.
        return (_shape_in, (self._world, self._id))

    @property
    def is_valid(self) -> bool:
        """False once the shape, its body or its world was destroyed."""
        return bool(lib.i2d_shape_is_valid(self._id))

    def destroy(self) -> None:
        """Removes the shape; its body's mass is updated."""
        check(lib.i2d_shape_destroy(self._id))

    @property
    def body(self) -> "Body":
        from .body import Body

        body_id = lib.i2d_shape_get_body(self._id)
        if not body_id:
            check_last()
        return Body(self._world, body_id)

    @property
    def type(self) -> ShapeType:
        value = lib.i2d_shape_get_type(self._id)
        check_last()
        return ShapeType(value)

    def geometry(self) -> ShapeGeometry:
        """The geometry in the body frame: ((x, y), radius) for a circle, a list of
        vertices for a polygon, ((x1, y1), (x2, y2), radius) for a capsule and
        ((x1, y1), (x2, y2)) for a segment."""
        kind = self.type
        if kind == ShapeType.CIRCLE:
            c = lib.i2d_shape_get_circle(self._id)
            return (pair(c.center), c.radius)
        if kind == ShapeType.CAPSULE:
            c = lib.i2d_shape_get_capsule(self._id)
            return (pair(c.center1), pair(c.center2), c.radius)
        if kind == ShapeType.SEGMENT:
            s = lib.i2d_shape_get_segment(self._id)
            return (pair(s.point1), pair(s.point2))
        p = lib.i2d_shape_get_polygon(self._id)
        return [pair(p.vertices[i]) for i in range(p.count)]

    @property
    def aabb(self) -> Tuple[Vec, Vec]:
        """Tight world bounds as ((min_x, min_y), (max_x, max_y))."""
        box = lib.i2d_shape_get_aabb(self._id)
        check_last()
        return (pair(box.min), pair(box.max))

    @property
    def density(self) -> float:
        """kg/m^2."""
        value = lib.i2d_shape_get_density(self._id)
        check_last()
        return value

    @property
    def friction(self) -> float:
        value = lib.i2d_shape_get_friction(self._id)
        check_last()
        return value

    @friction.setter
    def friction(self, value: float) -> None:
        check(lib.i2d_shape_set_friction(self._id, value))

    @property
    def restitution(self) -> float:
        value = lib.i2d_shape_get_restitution(self._id)
        check_last()
        return value

    @restitution.setter
    def restitution(self, value: float) -> None:
        check(lib.i2d_shape_set_restitution(self._id, value))

    @property
    def filter(self) -> Tuple[int, int, int]:
        """(category_bits, mask_bits, group_index)."""
        f = lib.i2d_shape_get_filter(self._id)
        check_last()
        return (f.category_bits, f.mask_bits, f.group_index)

    @filter.setter
    def filter(self, value: Union[Tuple[int, int], Tuple[int, int, int], Filter]) -> None:
        check(lib.i2d_shape_set_filter(self._id, make_filter(value)))

    @property
    def is_sensor(self) -> bool:
        value = lib.i2d_shape_is_sensor(self._id)
        check_last()
        return bool(value)


def _shape_in(world: "World", shape_id: int) -> Shape:
    """Shape.__reduce__'s way back, as body._body_in."""
    return Shape(world, lib.i2d_shape_in_world(shape_id, world.id))
