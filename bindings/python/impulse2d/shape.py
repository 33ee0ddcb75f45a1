# SPDX-License-Identifier: MIT
"""Shape: a value handle for a shape attached to a body."""

import ctypes as C
from typing import TYPE_CHECKING, Any, Callable, List, Sequence, Tuple, Union

from ._native import check, check_last, lib, make_filter, pair, rot, vec2
from ._structs import Capsule, Circle, ContactData as _ContactData, Filter, Polygon, Segment
from ._structs import SurfaceMaterial as _SurfaceMaterial, Transform, Vec2
from .types import ContactData, DistanceResult, Manifold, ManifoldPoint, ShapeType, SurfaceMaterial, Vec

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

    def set_density(self, density: float, update_body_mass: bool = True) -> None:
        """kg/m^2 in [0, 1e10]. update_body_mass False leaves the body's mass as it is
        until the next shape change or Body.apply_mass_from_shapes."""
        check(lib.i2d_shape_set_density(self._id, density, update_body_mass))

    @property
    def material(self) -> SurfaceMaterial:
        """Friction, restitution, rolling resistance and tangent speed as one
        SurfaceMaterial; set it with one or any 4-tuple in that order (ranges as in the
        shape def). Touching contacts take the new values at the next step."""
        m = lib.i2d_shape_get_material(self._id)
        check_last()
        return SurfaceMaterial(m.friction, m.restitution, m.rolling_resistance, m.tangent_speed)

    @material.setter
    def material(self, value: Sequence[float]) -> None:
        friction, restitution, rolling_resistance, tangent_speed = value
        m = _SurfaceMaterial(
            friction=friction, restitution=restitution, rolling_resistance=rolling_resistance, tangent_speed=tangent_speed
        )
        check(lib.i2d_shape_set_material(self._id, m))

    @property
    def is_sensor(self) -> bool:
        value = lib.i2d_shape_is_sensor(self._id)
        check_last()
        return bool(value)

    # ---- Event flags (as the shape def's fields of the same names) ----------------------

    @property
    def sensor_events_enabled(self) -> bool:
        """Whether sensors see this shape (shape def enable_sensor_events); a change
        applies to visits that begin after it."""
        value = lib.i2d_shape_are_sensor_events_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    @sensor_events_enabled.setter
    def sensor_events_enabled(self, value: bool) -> None:
        check(lib.i2d_shape_enable_sensor_events(self._id, value))

    @property
    def contact_events_enabled(self) -> bool:
        """Whether the shape's contacts give begin and end events (enable_contact_events)."""
        value = lib.i2d_shape_are_contact_events_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    @contact_events_enabled.setter
    def contact_events_enabled(self, value: bool) -> None:
        check(lib.i2d_shape_enable_contact_events(self._id, value))

    @property
    def hit_events_enabled(self) -> bool:
        """Whether the shape's contacts give hit events (enable_hit_events)."""
        value = lib.i2d_shape_are_hit_events_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    @hit_events_enabled.setter
    def hit_events_enabled(self, value: bool) -> None:
        check(lib.i2d_shape_enable_hit_events(self._id, value))

    @property
    def pre_solve_events_enabled(self) -> bool:
        """Whether the shape's touching contacts reach World.set_pre_solve's hook
        (enable_pre_solve_events); a change applies from the next step."""
        value = lib.i2d_shape_are_pre_solve_events_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    @pre_solve_events_enabled.setter
    def pre_solve_events_enabled(self, value: bool) -> None:
        check(lib.i2d_shape_enable_pre_solve_events(self._id, value))

    # ---- New geometry --------------------------------------------------------------------
    # Checked as at creation; the kind may change (a chain's segments are refused). The
    # body's mass is made again from its shapes (unless Body.mass_data overrode it), its
    # contacts are made afresh at the next step, and it wakes.

    def set_circle(self, radius: float, center: Sequence[float] = (0.0, 0.0)) -> None:
        """Makes the shape a circle centred at center (body frame)."""
        check(lib.i2d_shape_set_circle(self._id, C.byref(Circle(center=vec2(center), radius=radius))))

    def set_capsule(self, center1: Sequence[float], center2: Sequence[float], radius: float) -> None:
        """Makes the shape a capsule: every point within radius of center1-center2."""
        capsule = Capsule(center1=vec2(center1), center2=vec2(center2), radius=radius)
        check(lib.i2d_shape_set_capsule(self._id, C.byref(capsule)))

    def set_segment(self, point1: Sequence[float], point2: Sequence[float]) -> None:
        """Makes the shape a two-sided segment."""
        check(lib.i2d_shape_set_segment(self._id, C.byref(Segment(point1=vec2(point1), point2=vec2(point2)))))

    def set_polygon(self, points: Sequence[Sequence[float]], radius: float = 0.0) -> None:
        """Makes the shape the convex hull of 3 to 8 points (body frame), rounded by
        radius (i2d_make_polygon, then i2d_shape_set_polygon)."""
        polygon = Polygon()
        check(lib.i2d_make_polygon(_points(points), len(points), radius, C.byref(polygon)))
        check(lib.i2d_shape_set_polygon(self._id, C.byref(polygon)))

    # ---- What touches it now ----------------------------------------------------------------

    def contact_data(self) -> List[ContactData]:
        """The body's touching contacts that involve this shape, as the last step left
        them (Body.contact_data for the whole body). Works inside query callbacks."""
        return _contacts(self._world, lib.i2d_shape_get_contact_data, self._id)

    def sensor_overlaps(self) -> List["Shape"]:
        """The shapes visiting this sensor as of the last step: those whose sensor begin
        event came and whose end event has not. InvalidArgument if it is not a sensor."""
        count = lib.i2d_shape_get_sensor_overlaps(self._id, None, 0)
        while True:
            if not count:
                check_last()
                return []
            ids = (C.c_uint64 * count)()
            total = lib.i2d_shape_get_sensor_overlaps(self._id, C.addressof(ids), count)
            if total <= count:
                return [Shape(self._world, ids[i]) for i in range(total)]
            count = total

    def closest_point(self, target: Sequence[float]) -> Vec:
        """The point of the shape (its outline grown by its radius, inside included)
        closest to target, in world coordinates: target itself when the shape holds it."""
        v = lib.i2d_shape_get_closest_point(self._id, vec2(target))
        if v.x == 0.0 and v.y == 0.0:
            check_last()
        return (v.x, v.y)


def _points(points: Sequence[Sequence[float]]) -> Any:
    """A Vec2 array of points (one element at least, so that ctypes has an address)."""
    return (Vec2 * max(len(points), 1))(*[vec2(p) for p in points])


def _contacts(world: "World", get: Callable[..., int], owner_id: int) -> List[ContactData]:
    """A body's or shape's contact data: sized by a call of capacity 0, then filled."""
    count = get(owner_id, None, 0)
    while True:
        if not count:
            check_last()
            return []
        array = (_ContactData * count)()
        total = get(owner_id, C.addressof(array), count)
        if total <= count:
            break
        count = total
    found = []
    for c in array[:total]:
        m = manifold_of(c.manifold)
        n = len(m.points)
        found.append(
            ContactData(
                Shape(world, c.shape_a), Shape(world, c.shape_b), m.normal, m.points,
                tuple(c.normal_impulses[:n]), tuple(c.tangent_impulses[:n]),
            )
        )
    return found


def manifold_of(m: Any) -> Manifold:
    """A C i2d_manifold as the package's Manifold: its normal and its point_count points."""
    points = tuple(ManifoldPoint(pair(p.point), p.penetration, p.id) for p in m.points[: m.point_count])
    return Manifold(pair(m.normal), points)


def shape_distance(
    points_a: Sequence[Sequence[float]],
    points_b: Sequence[Sequence[float]],
    radius_a: float = 0.0,
    radius_b: float = 0.0,
    position_a: Sequence[float] = (0.0, 0.0),
    angle_a: float = 0.0,
    position_b: Sequence[float] = (0.0, 0.0),
    angle_b: float = 0.0,
) -> DistanceResult:
    """The closest points of two convex shapes, each the convex hull of 1 to 8 points
    rounded by its radius (1 point: a circle; 2: a capsule) and placed at its position,
    turned by its angle (i2d_make_proxy, i2d_shape_distance). A pure function, no world:
    it works in metres (its tolerances are those of a world in metres). Overlapping
    shapes give distance 0 and a zero normal. InvalidArgument for a count outside 1..8,
    NaN, infinite or out-of-range values."""
    proxies = []
    for points, radius in ((points_a, radius_a), (points_b, radius_b)):
        proxy = lib.i2d_make_proxy(_points(points), len(points), radius)
        if not proxy.count:
            check_last()
        proxies.append(proxy)
    xa = Transform(p=vec2(position_a), q=rot(angle_a))
    xb = Transform(p=vec2(position_b), q=rot(angle_b))
    r = lib.i2d_shape_distance(C.byref(proxies[0]), xa, C.byref(proxies[1]), xb)
    check_last()
    return DistanceResult(pair(r.point_a), pair(r.point_b), pair(r.normal), r.distance)


def _shape_in(world: "World", shape_id: int) -> Shape:
    """Shape.__reduce__'s way back, as body._body_in."""
    return Shape(world, lib.i2d_shape_in_world(shape_id, world.id))
