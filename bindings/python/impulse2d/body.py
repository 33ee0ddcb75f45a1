# SPDX-License-Identifier: MIT
"""Body: a value handle for a rigid body."""

import ctypes as C
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Tuple

from ._native import apply_settings, check, check_last, lib, pair, rot, vec2
from ._structs import Circle, MassData as _MassData, Rot, Transform, Vec2
from .shape import Shape, _contacts
from .types import BodyType, ContactData, MassData, Vec

if TYPE_CHECKING:  # pragma: no cover
    from .world import World


class Body:
    """A rigid body of a World, created by World.create_body. Compares and hashes by
    its id. Getters and setters raise InvalidHandle once the body or its world was
    destroyed, InvalidArgument for NaN or infinite values, WorldLocked inside a query
    callback."""

    __slots__ = ("_id", "_world")

    def __init__(self, world: "World", body_id: int) -> None:
        self._world = world
        self._id = body_id

    @property
    def id(self) -> int:
        """The body's 64-bit id (i2d_body_id.bits), as the bulk calls take them."""
        return self._id

    @property
    def world(self) -> "World":
        return self._world

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Body) and other._id == self._id

    def __hash__(self) -> int:
        return hash(self._id)

    def __repr__(self) -> str:
        return "Body(0x%016x)" % self._id

    def __copy__(self) -> "Body":
        return self

    def __reduce__(self) -> Tuple[Any, ...]:
        # pickle and copy.deepcopy copy the world (once, however many of its bodies come
        # along) and give the body of the same index and generation in the copy.
        return (_body_in, (self._world, self._id))

    @property
    def is_valid(self) -> bool:
        """False once the body or its world was destroyed."""
        return bool(lib.i2d_body_is_valid(self._id))

    def destroy(self) -> None:
        """Destroys the body and its shapes."""
        check(lib.i2d_body_destroy(self._id))
        self._world._user_data.pop(self._id, None)

    @property
    def type(self) -> BodyType:
        value = lib.i2d_body_get_type(self._id)
        check_last()
        return BodyType(value)

    # ---- Pose and velocity -----------------------------------------------------------

    @property
    def position(self) -> Vec:
        """The body origin in world coordinates, m."""
        v = lib.i2d_body_get_position(self._id)
        if v.x == 0.0 and v.y == 0.0:  # a bad id answers zero: only then ask why
            check_last()
        return (v.x, v.y)

    @position.setter
    def position(self, value: Sequence[float]) -> None:
        check(lib.i2d_body_set_transform(self._id, vec2(value), lib.i2d_body_get_rotation(self._id)))

    @property
    def rotation(self) -> Vec:
        """(cosine, sine) of the body's angle."""
        q = lib.i2d_body_get_rotation(self._id)
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        return (q.c, q.s)

    @property
    def angle(self) -> float:
        """The body's angle in (-pi, pi], radians counter-clockwise."""
        q = lib.i2d_body_get_rotation(self._id)
        if q.c == 0.0 and q.s == 0.0:
            check_last()
        return lib.i2d_rot_get_angle(q)

    @angle.setter
    def angle(self, value: float) -> None:
        check(lib.i2d_body_set_transform(self._id, lib.i2d_body_get_position(self._id), rot(value)))

    def set_transform(
        self, position: Sequence[float], angle: float = 0.0, rotation: Optional[Sequence[float]] = None
    ) -> None:
        """Teleports the body: origin at position, turned by angle (radians), or by
        rotation = (cosine, sine) when given (normalised within 1e-3)."""
        q = Rot(*rotation) if rotation is not None else rot(angle)
        check(lib.i2d_body_set_transform(self._id, vec2(position), q))

    @property
    def linear_velocity(self) -> Vec:
        """Velocity of the centre of mass, m/s."""
        v = lib.i2d_body_get_linear_velocity(self._id)
        if v.x == 0.0 and v.y == 0.0:
            check_last()
        return (v.x, v.y)

    @linear_velocity.setter
    def linear_velocity(self, value: Sequence[float]) -> None:
        check(lib.i2d_body_set_linear_velocity(self._id, vec2(value)))

    @property
    def angular_velocity(self) -> float:
        """rad/s, counter-clockwise positive."""
        w = lib.i2d_body_get_angular_velocity(self._id)
        if w == 0.0:
            check_last()
        return w

    @angular_velocity.setter
    def angular_velocity(self, value: float) -> None:
        check(lib.i2d_body_set_angular_velocity(self._id, value))

    # ---- Mass ------------------------------------------------------------------------

    @property
    def mass(self) -> float:
        """kg; 0 for static and kinematic bodies."""
        m = lib.i2d_body_get_mass(self._id)
        if m == 0.0:
            check_last()
        return m

    @property
    def rotational_inertia(self) -> float:
        """kg m^2 about the centre of mass."""
        i = lib.i2d_body_get_rotational_inertia(self._id)
        if i == 0.0:
            check_last()
        return i

    @property
    def world_center_of_mass(self) -> Vec:
        v = lib.i2d_body_get_world_center_of_mass(self._id)
        check_last()
        return (v.x, v.y)

    @property
    def mass_data(self) -> MassData:
        """(mass kg, centre of mass in the body frame, rotational inertia kg m^2 about
        it). Setting it (a MassData or any such tuple) overrides what the shapes give a
        dynamic body: mass > 0, inertia >= 0 (0 stops rotation), centre within 1e5 of
        the origin; it holds through later shape changes until apply_mass_from_shapes.
        Static and kinematic bodies refuse it (InvalidArgument). Wakes the body."""
        m = lib.i2d_body_get_mass_data(self._id)
        if m.mass == 0.0:
            check_last()
        return MassData(m.mass, (m.center.x, m.center.y), m.rotational_inertia)

    @mass_data.setter
    def mass_data(self, value: Sequence[Any]) -> None:
        mass, center, inertia = value
        check(lib.i2d_body_set_mass_data(self._id, _MassData(mass=mass, center=vec2(center), rotational_inertia=inertia)))

    def apply_mass_from_shapes(self) -> None:
        """Drops a mass_data override: the mass comes from the shapes' densities again."""
        check(lib.i2d_body_apply_mass_from_shapes(self._id))

    # ---- Forces and impulses -----------------------------------------------------------

    def apply_force(self, force: Sequence[float], point: Sequence[float] = None, wake: bool = True) -> None:
        """Adds a force (N) for the next step, at a world point (default: the centre of
        mass, which adds no torque)."""
        if point is None:
            check(lib.i2d_body_apply_force_to_center(self._id, vec2(force), wake))
        else:
            check(lib.i2d_body_apply_force(self._id, vec2(force), vec2(point), wake))

    def apply_torque(self, torque: float, wake: bool = True) -> None:
        """Adds a torque (N m) for the next step."""
        check(lib.i2d_body_apply_torque(self._id, torque, wake))

    def apply_linear_impulse(self, impulse: Sequence[float], point: Sequence[float] = None, wake: bool = True) -> None:
        """Changes the velocity at once by impulse / mass (N s), at a world point
        (default: the centre of mass)."""
        at = vec2(point) if point is not None else lib.i2d_body_get_world_center_of_mass(self._id)
        check(lib.i2d_body_apply_linear_impulse(self._id, vec2(impulse), at, wake))

    def apply_angular_impulse(self, impulse: float, wake: bool = True) -> None:
        check(lib.i2d_body_apply_angular_impulse(self._id, impulse, wake))

    # ---- Sleep and user data ----------------------------------------------------------

    @property
    def awake(self) -> bool:
        """False for static and sleeping bodies. Setting False puts the body and what
        touches it to sleep; True wakes them."""
        value = lib.i2d_body_is_awake(self._id)
        if not value:
            check_last()
        return bool(value)

    @awake.setter
    def awake(self, value: bool) -> None:
        check(lib.i2d_body_set_awake(self._id, value))

    @property
    def quarantined(self) -> bool:
        """True after a step froze the body because its state went non-finite (it is
        static now); False again once its type is set."""
        value = lib.i2d_body_is_quarantined(self._id)
        if not value:
            check_last()
        return bool(value)

    @property
    def sleep_enabled(self) -> bool:
        """Default True (body def enable_sleep). False keeps the body, and whatever
        touches it, awake, and wakes it now."""
        value = lib.i2d_body_is_sleep_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    @sleep_enabled.setter
    def sleep_enabled(self, value: bool) -> None:
        check(lib.i2d_body_enable_sleep(self._id, value))

    @property
    def sleep_threshold(self) -> float:
        """The speed below which the body counts as resting, length units per second, in
        [0, 1e5]; it starts as the world's sleep_speed_threshold."""
        value = lib.i2d_body_get_sleep_threshold(self._id)
        if value == 0.0:
            check_last()
        return value

    @sleep_threshold.setter
    def sleep_threshold(self, value: float) -> None:
        check(lib.i2d_body_set_sleep_threshold(self._id, value))

    # ---- Enabling -------------------------------------------------------------------------

    def disable(self) -> None:
        """Takes the body out of the world: its shapes leave the broadphase (no contacts,
        queries or sensor visits; its contacts end with end events and what touched it
        wakes), its joints are not solved, it neither moves nor sleeps (awake is False).
        It keeps its shapes, joints, velocity, forces and user data, and every getter and
        setter still works on it. A no-op when already disabled."""
        check(lib.i2d_body_disable(self._id))

    def enable(self) -> None:
        """Brings a disabled body back where it stands, awake. A no-op when enabled."""
        check(lib.i2d_body_enable(self._id))

    @property
    def enabled(self) -> bool:
        """False after disable(), until enable()."""
        value = lib.i2d_body_is_enabled(self._id)
        if not value:
            check_last()
        return bool(value)

    # ---- Motion settings (as the body def's fields) ----------------------------------------

    def set_target_transform(
        self,
        position: Sequence[float],
        time_step: float,
        angle: float = 0.0,
        rotation: Optional[Sequence[float]] = None,
    ) -> None:
        """Sets a kinematic body's velocities so that it reaches position, turned by angle
        (or rotation = (cosine, sine), normalised within 1e-3), in time_step seconds (> 0):
        the way to move a scripted platform and have what rides it follow. Static and
        dynamic bodies refuse it (InvalidArgument). Wakes the body if it moves."""
        q = Rot(*rotation) if rotation is not None else rot(angle)
        check(lib.i2d_body_set_target_transform(self._id, Transform(p=vec2(position), q=q), time_step))

    @property
    def bullet(self) -> bool:
        """Continuous collision against dynamic bodies too (body def is_bullet)."""
        value = lib.i2d_body_is_bullet(self._id)
        if not value:
            check_last()
        return bool(value)

    @bullet.setter
    def bullet(self, value: bool) -> None:
        check(lib.i2d_body_set_bullet(self._id, value))

    @property
    def gravity_scale(self) -> float:
        """Multiplies the world's gravity for this body; finite, may be negative. Setting
        it wakes the body."""
        value = lib.i2d_body_get_gravity_scale(self._id)
        if value == 0.0:
            check_last()
        return value

    @gravity_scale.setter
    def gravity_scale(self, value: float) -> None:
        check(lib.i2d_body_set_gravity_scale(self._id, value))

    @property
    def linear_damping(self) -> float:
        """1/s, >= 0."""
        value = lib.i2d_body_get_linear_damping(self._id)
        if value == 0.0:
            check_last()
        return value

    @linear_damping.setter
    def linear_damping(self, value: float) -> None:
        check(lib.i2d_body_set_linear_damping(self._id, value))

    @property
    def angular_damping(self) -> float:
        """1/s, >= 0."""
        value = lib.i2d_body_get_angular_damping(self._id)
        if value == 0.0:
            check_last()
        return value

    @angular_damping.setter
    def angular_damping(self, value: float) -> None:
        check(lib.i2d_body_set_angular_damping(self._id, value))

    @property
    def fixed_rotation(self) -> bool:
        """A fixed-rotation body never turns; setting True stops its spin. Wakes the body."""
        value = lib.i2d_body_is_fixed_rotation(self._id)
        if not value:
            check_last()
        return bool(value)

    @fixed_rotation.setter
    def fixed_rotation(self, value: bool) -> None:
        check(lib.i2d_body_set_fixed_rotation(self._id, value))

    @property
    def user_data(self) -> Any:
        """Any Python object, kept by the World (not passed to C)."""
        if not self.is_valid:
            check_last()
        return self._world._user_data.get(self._id)

    @user_data.setter
    def user_data(self, value: Any) -> None:
        if not self.is_valid:
            check_last()
        self._world._user_data[self._id] = value

    # ---- Shapes ------------------------------------------------------------------------

    def _shape_def(self, settings: Dict[str, Any]) -> Any:
        shape_def = lib.i2d_default_shape_def()
        apply_settings(shape_def, settings, "shape")
        return shape_def

    def _created(self, shape_id: int) -> Shape:
        if not shape_id:
            check_last()
        return Shape(self._world, shape_id)

    def create_circle(self, radius: float, center: Sequence[float] = (0.0, 0.0), **settings: Any) -> Shape:
        """A circle centred at center (body frame). Settings are the shape def's fields:
        density, friction, restitution, rolling_resistance, tangent_speed, is_sensor,
        enable_contact_events, enable_sensor_events, filter, and the contact hooks'
        opt-ins enable_custom_filtering and enable_pre_solve_events (World.set_custom_filter,
        World.set_pre_solve)."""
        circle = Circle(center=vec2(center), radius=radius)
        return self._created(lib.i2d_shape_create_circle(self._id, C.byref(self._shape_def(settings)), C.byref(circle)))

    def create_box(
        self, half_width: float, half_height: float, center: Sequence[float] = None, angle: float = 0.0, **settings: Any
    ) -> Shape:
        """A box of the given half sizes, centred on the body origin or at center,
        turned by angle in the body frame."""
        shape_def = C.byref(self._shape_def(settings))
        if center is None and angle == 0.0:
            return self._created(lib.i2d_shape_create_box(self._id, shape_def, half_width, half_height))
        at = vec2(center if center is not None else (0.0, 0.0))
        return self._created(lib.i2d_shape_create_offset_box(self._id, shape_def, half_width, half_height, at, rot(angle)))

    def create_polygon(self, points: Sequence[Sequence[float]], **settings: Any) -> Shape:
        """The convex hull of 3 to 8 points (body frame)."""
        array = (Vec2 * max(len(points), 1))(*[vec2(p) for p in points])
        return self._created(
            lib.i2d_shape_create_polygon(self._id, C.byref(self._shape_def(settings)), array, len(points))
        )

    def create_capsule(
        self, center1: Sequence[float], center2: Sequence[float], radius: float, **settings: Any
    ) -> Shape:
        """Every point within radius of the segment center1-center2 (body frame)."""
        return self._created(
            lib.i2d_shape_create_capsule(
                self._id, C.byref(self._shape_def(settings)), vec2(center1), vec2(center2), radius
            )
        )

    def create_segment(self, point1: Sequence[float], point2: Sequence[float], **settings: Any) -> Shape:
        """A two-sided segment (body frame), for static geometry."""
        return self._created(
            lib.i2d_shape_create_segment(self._id, C.byref(self._shape_def(settings)), vec2(point1), vec2(point2))
        )

    @property
    def shapes(self) -> List[Shape]:
        count = lib.i2d_body_get_shape_count(self._id)
        check_last()
        ids = (C.c_uint64 * max(count, 1))()
        lib.i2d_body_get_shapes(self._id, C.addressof(ids), count)
        return [Shape(self._world, ids[i]) for i in range(count)]

    def contact_data(self) -> List[ContactData]:
        """The body's touching contacts as the last step left them (sensor visits
        excluded): shapes, normal, manifold points and the last substep's impulses, in
        no documented order but the same for the same world. Works inside query
        callbacks."""
        return _contacts(self._world, lib.i2d_body_get_contact_data, self._id)


def _body_in(world: "World", body_id: int) -> Body:
    """Body.__reduce__'s way back: the body in (a copy of) its world, or an invalid Body
    (id 0) when that world has none."""
    return Body(world, lib.i2d_body_in_world(body_id, world.id))
