# SPDX-License-Identifier: MIT
"""World: owns everything in it; a context manager that destroys it on exit."""

import ctypes as C
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, Union

from ._native import apply_settings, check, check_last, lib, pair, rot, vec2
from ._structs import AABB, QueryFilter
from ._hooks import Hooks
from ._library import _OVERLAP_FN, _WRITE_FN
from . import _draw, _mover
from . import joint as _joint
from ._mover import CapsuleLike
from .body import Body
from .errors import InvalidArgument, InvalidHandle
from .joint import Joint
from .shape import Shape
from .types import (
    BodyMove,
    BodyQuarantine,
    BodyType,
    CharacterResult,
    CollisionPlane,
    ContactBegin,
    ContactEnd,
    Counters,
    Manifold,
    RayHit,
    SensorBegin,
    SensorEnd,
    Vec,
)

try:
    import numpy as np
except ImportError:  # pragma: no cover - exercised only without NumPy
    np = None

BodyList = Union[Sequence[Body], "np.ndarray"]


def _numpy() -> Any:
    if np is None:
        raise ImportError("the bulk state calls need NumPy (Debian: apt-get install python3-numpy)")
    return np


def _query_filter(category_bits: int, mask_bits: int) -> QueryFilter:
    return QueryFilter(category_bits=category_bits, mask_bits=mask_bits)


_ALL_BITS = 0xFFFFFFFFFFFFFFFF

# The world def's fields that wire a world to its host rather than describe what it
# simulates: a snapshot does not hold them, so a world made from one takes them anew.
_RUNTIME_SETTINGS = ("worker_count", "simd_path", "enable_profile")

Bytes = Union[bytes, bytearray, memoryview]


def _as_bytes(data: Bytes, function: str, saved_by: str) -> bytes:
    if isinstance(data, bytes):
        return data
    if isinstance(data, (bytearray, memoryview)):
        return bytes(data)
    raise TypeError("World.%s takes bytes (as World.%s returns), not %s" % (function, saved_by, type(data).__name__))


def _unpickle(snapshot: bytes, runtime: Dict[str, Any]) -> "World":
    """A World from World.__reduce__'s snapshot and host wiring. A SIMD path the saving
    machine asked for and this one lacks is left to the library's choice: every path
    computes the same bits."""
    runtime = dict(runtime)
    if "simd_path" in runtime and not lib.i2d_simd_path_supported(runtime["simd_path"]):
        del runtime["simd_path"]
    return World.from_snapshot(snapshot, **runtime)


class World:
    """A simulated world. Use it as a context manager, or call destroy(); a World that
    is garbage-collected while alive is destroyed then too.

    >>> with impulse2d.World(gravity=(0, -10)) as world:
    ...     ball = world.create_body(position=(0, 4))
    ...     ball.create_circle(0.5)
    ...     world.step(1 / 60, 4)

    Settings are the C world def's fields (include/impulse2d/types.h), e.g.
    contact_hertz, restitution_threshold, enable_sleep, time_to_sleep, and worker_count
    (threads that share each step; the results are the same bits for every count).
    gravity defaults to (0, -10) m/s^2.

    length_units_per_meter (default 1, range [1e-3, 1e4]) makes a world count lengths in
    other units, pixels say: World(length_units_per_meter=50) starts from
    i2d_default_world_def_in_units(50), whose length-bearing defaults (gravity (0, -500),
    slop, speeds, thresholds) are scaled, and every length, speed and acceleration given
    to or read from it is in those units (densities per square unit). Other settings
    given with it are taken as given, in those units. The pure function shape_distance
    stays in metres.

    A world saves itself as bytes and comes back from them, bit for bit: save_snapshot,
    from_snapshot and restore_snapshot (portable, between processes and machines), and
    save_state and restore_state (rollback within this world). pickle and copy.deepcopy
    go through a snapshot, so a world moves to another process with multiprocessing.
    """

    # Whether any world in this process was ever given a contact hook: until one is, a
    # batch step has no hook exception to look for in its worlds (a loop over 256 worlds
    # after each batch step cost 2 % of a vector environment's frame).
    _hooks_ever_set = False

    def __init__(
        self, gravity: Optional[Sequence[float]] = None, length_units_per_meter: float = 1.0, **settings: Any
    ) -> None:
        self._id = 0
        self._user_data: Dict[int, Any] = {}
        self._runtime = {name: settings[name] for name in _RUNTIME_SETTINGS if name in settings}
        if length_units_per_meter == 1.0:
            world_def = lib.i2d_default_world_def()
        else:
            world_def = lib.i2d_default_world_def_in_units(length_units_per_meter)
            check_last()
        if gravity is not None:
            settings["gravity"] = gravity
        apply_settings(world_def, settings, "world")
        world_id = lib.i2d_world_create(C.byref(world_def))
        if not world_id:
            check_last()
        self._id = world_id

    # ---- Lifetime ----------------------------------------------------------------------

    def __enter__(self) -> "World":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.destroy()

    def __del__(self) -> None:
        if getattr(self, "_id", 0) and not getattr(self, "_borrowed", False) and lib is not None:
            lib.i2d_world_destroy(self._id)
            self._id = 0

    def destroy(self) -> None:
        """Destroys the world and everything in it; their handles become invalid.
        Destroying twice is harmless. A world a Replay owns is the replay's to close."""
        if getattr(self, "_borrowed", False):
            raise InvalidArgument("World.destroy: this world belongs to a Replay; close the replay")
        if self._id:
            world_id, self._id = self._id, 0
            self._user_data.clear()
            check(lib.i2d_world_destroy(world_id))
            self._hooks = None  # the library no longer calls them

    @classmethod
    def _borrow(cls, world_id: int) -> "World":
        """A World for an id another object owns (a Replay's world): never destroyed here."""
        world = cls.__new__(cls)
        world._id = world_id
        world._user_data = {}
        world._runtime = {}
        world._borrowed = True
        return world

    def _forget(self) -> None:
        """Its owner destroyed it: the id is no longer this object's to use."""
        self._id = 0
        self._user_data.clear()
        self._hooks = None

    @property
    def id(self) -> int:
        """The world's 64-bit id (i2d_world_id.bits); 0 once destroyed."""
        return self._id

    @property
    def is_valid(self) -> bool:
        return bool(self._id) and bool(lib.i2d_world_is_valid(self._id))

    def __repr__(self) -> str:
        return "World(0x%016x)" % self._id if self._id else "World(destroyed)"

    # ---- Stepping and settings -----------------------------------------------------------

    def step(self, time_step: float = 1.0 / 60.0, substeps: int = 4) -> None:
        """Advances the world by time_step seconds in substeps equal substeps. Raises,
        once the step is done, the first exception a contact hook raised during it."""
        status = lib.i2d_world_step(self._id, time_step, substeps)
        raised = self._take_hook_exception()
        check(status)
        if raised is not None:
            raise raised

    def _take_hook_exception(self) -> Optional[BaseException]:
        """The first exception a contact hook raised in the last step, forgotten here."""
        hooks = getattr(self, "_hooks", None)
        return hooks.take_raised() if hooks is not None else None

    @property
    def gravity(self) -> Vec:
        g = lib.i2d_world_get_gravity(self._id)
        check_last()
        return (g.x, g.y)

    @gravity.setter
    def gravity(self, value: Sequence[float]) -> None:
        check(lib.i2d_world_set_gravity(self._id, vec2(value)))

    @property
    def counters(self) -> Counters:
        c = lib.i2d_world_get_counters(self._id)
        check_last()
        return Counters(*(getattr(c, name) for name in Counters._fields))

    @property
    def state_hash(self) -> int:
        """64-bit hash of every transform, velocity and contact impulse."""
        h = lib.i2d_world_get_state_hash(self._id)
        check_last()
        return h

    @property
    def settings(self) -> Dict[str, Any]:
        """The world's settings as World's keyword arguments (the world def's fields
        but the C-only wiring: gravity and vectors as tuples): the values the setters
        below last gave, the rest as created. World(**world.settings) makes a world like
        this one."""
        world_def = lib.i2d_world_get_settings(self._id)
        check_last()
        hidden = ("internal_cookie", "user_data", "enqueue_task", "finish_task", "user_task_context")
        values = {}
        for name, _ctype in world_def._fields_:
            if name not in hidden:
                value = getattr(world_def, name)
                values[name] = pair(value) if hasattr(value, "x") else value
        return values

    # Settings after creation: each is checked as in the world def (InvalidArgument, the
    # world untouched), takes effect at the next step and wakes what it must. settings
    # reads them back.

    def enable_sleeping(self, flag: bool) -> None:
        """Turns sleep on or off for the whole world (enable_sleep); off wakes every body."""
        check(lib.i2d_world_enable_sleeping(self._id, flag))

    def enable_continuous(self, flag: bool) -> None:
        """Turns continuous collision on or off (enable_continuous)."""
        check(lib.i2d_world_enable_continuous(self._id, flag))

    def enable_impact_chains(self, flag: bool) -> None:
        """Turns impacts passed from body to body within a step, taken one at a time, on or
        off (enable_impact_chains)."""
        check(lib.i2d_world_enable_impact_chains(self._id, flag))

    def set_contact_tuning(self, hertz: float, damping_ratio: float, push_max_speed: float) -> None:
        """Contact stiffness (contact_hertz), damping (contact_damping_ratio) and the
        speed at which overlap is pushed out (contact_push_max_speed)."""
        check(lib.i2d_world_set_contact_tuning(self._id, hertz, damping_ratio, push_max_speed))

    def set_joint_tuning(self, hertz: float, damping_ratio: float) -> None:
        """Joint stiffness (joint_hertz) and damping (joint_damping_ratio)."""
        check(lib.i2d_world_set_joint_tuning(self._id, hertz, damping_ratio))

    def set_restitution_threshold(self, speed: float) -> None:
        """The approach speed below which contacts do not bounce (restitution_threshold)."""
        check(lib.i2d_world_set_restitution_threshold(self._id, speed))

    def set_hit_event_threshold(self, speed: float) -> None:
        """The approach speed from which contacts give hit events (hit_event_threshold)."""
        check(lib.i2d_world_set_hit_event_threshold(self._id, speed))

    def shift_origin(self, new_origin: Sequence[float]) -> None:
        """Moves the world's origin to new_origin (a point in the present coordinates):
        every position the world keeps or reports becomes its old value less new_origin,
        nothing wakes and no contact is lost, so a world kilometres across keeps its
        precision near the player. A rollback state saved before is refused after it.
        InvalidArgument for a new origin that is not finite or lies beyond 1e9, or one
        that would put a body beyond 1e9; WorldLocked inside a query callback."""
        check(lib.i2d_world_shift_origin(self._id, vec2(new_origin)))

    @property
    def user_data(self) -> Any:
        """Any Python object, kept by this World object (the C world's user data pointer
        is not used from Python); pickle and deepcopy carry it along."""
        return getattr(self, "_world_user_data", None)

    @user_data.setter
    def user_data(self, value: Any) -> None:
        self._world_user_data = value

    # ---- Snapshots and rollback states (include/impulse2d/snapshot.h) ---------------------

    def _save(self, size_of: Any, save: Any) -> bytes:
        size = size_of(self._id)
        if not size:
            check_last()
        buffer = C.create_string_buffer(size)
        written = C.c_size_t(0)
        check(save(self._id, buffer, size, C.byref(written)))
        return buffer.raw[: written.value]

    def save_snapshot(self) -> bytes:
        """The whole world as portable bytes: every body, shape, joint, contact and
        setting, but not the host's wiring (worker_count, simd_path, enable_profile) nor
        Python-side user data. A world restored from them steps on to the same bits as
        this one, in this process or another, with any worker count."""
        return self._save(lib.i2d_world_get_snapshot_size, lib.i2d_world_save_snapshot)

    @classmethod
    def from_snapshot(cls, data: Bytes, **runtime: Any) -> "World":
        """A new world from save_snapshot's bytes. runtime is the host's wiring:
        worker_count, simd_path, enable_profile (the defaults otherwise); what the world
        simulates, gravity included, is the snapshot's. Ids keep their index and
        generation: world.body(old_id) gives the body of an id saved with the snapshot.
        Raises InvalidSnapshot, with the library's message, for bytes it refuses."""
        unknown = sorted(set(runtime) - set(_RUNTIME_SETTINGS))
        if unknown:
            raise TypeError(
                "World.from_snapshot takes the host's wiring only (%s), not %s: the snapshot holds "
                "what the world simulates" % (", ".join(_RUNTIME_SETTINGS), ", ".join(unknown))
            )
        data = _as_bytes(data, "from_snapshot", "save_snapshot")
        world_def = lib.i2d_default_world_def()
        apply_settings(world_def, runtime, "world")
        world_id = lib.i2d_world_create_from_snapshot(data, len(data), C.byref(world_def))
        if not world_id:
            check_last()
        world = cls.__new__(cls)
        world._id = world_id
        world._user_data = {}
        world._runtime = dict(runtime)
        return world

    def restore_snapshot(self, data: Bytes) -> None:
        """Brings the world back to a snapshot (of this world or any other). The world keeps
        its id and wiring; ids of what existed at the save are valid again, later ones are
        stale (their user data is dropped). InvalidSnapshot, world unchanged, for bytes
        the library refuses."""
        data = _as_bytes(data, "restore_snapshot", "save_snapshot")
        check(lib.i2d_world_restore_snapshot(self._id, data, len(data)))
        self._user_data = {i: v for i, v in self._user_data.items() if lib.i2d_body_is_valid(i)}

    def save_state(self) -> bytes:
        """A rollback state: what a step changes (poses, velocities, contacts, sleep), for
        restore_state into this world while its bodies, shapes, joints and settings stay
        as they are. Smaller and faster than a snapshot; not portable."""
        return self._save(lib.i2d_world_get_state_size, lib.i2d_world_save_state)

    def restore_state(self, data: Bytes) -> None:
        """Brings the world back to a state save_state took from it; stepping then gives
        the same bits as stepping from the moment it was saved. InvalidSnapshot, world
        unchanged, for another world's state, one saved before a body, shape, joint or
        setting changed, or truncated or corrupted bytes."""
        data = _as_bytes(data, "restore_state", "save_state")
        check(lib.i2d_world_restore_state(self._id, data, len(data)))

    def start_recording(self, write: Callable[[bytes], Any]) -> None:
        """Streams a recording of this world to write (file.write, bytearray.extend or any
        callable taking bytes): at once a header and a snapshot, then every change and
        every step with the hash it produced, as they happen. impulse2d.Replay replays it
        and names the first step whose hash differs. An exception write raises is kept
        and raised by stop_recording (the library cannot take it mid-call)."""
        self._recording_error: Optional[BaseException] = None

        def on_bytes(data: int, size: int, _context: int) -> None:
            if self._recording_error is None:
                try:
                    write(C.string_at(data, size))
                except BaseException as error:  # kept for stop_recording
                    self._recording_error = error

        callback = _WRITE_FN(on_bytes)
        check(lib.i2d_world_start_recording(self._id, callback, None))
        self._recording_callback = callback  # the library calls it until stop_recording

    def stop_recording(self) -> None:
        """Stops recording; raises what write raised while recording, if anything."""
        check(lib.i2d_world_stop_recording(self._id))
        self._recording_callback = None
        error, self._recording_error = getattr(self, "_recording_error", None), None
        if error is not None:
            raise error

    def _runtime_of(self) -> Dict[str, Any]:
        """The wiring a copy of this world gets: its worker count and what else it was
        created with."""
        workers = lib.i2d_world_get_worker_count(self._id)
        if not workers:
            check_last()
        return dict(self._runtime, worker_count=workers)

    def __reduce__(self) -> Tuple[Any, ...]:
        # pickle and copy.deepcopy: a snapshot and the wiring, then the user data as state
        # (after the world exists, so user data may hold the world's own bodies).
        user_data = {i: v for i, v in self._user_data.items() if lib.i2d_body_is_valid(i)}
        state = {"user_data": user_data, "world_user_data": self.user_data}
        return (_unpickle, (self.save_snapshot(), self._runtime_of()), state)

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self._world_user_data = state.get("world_user_data")
        for old_id, value in state.get("user_data", {}).items():
            body_id = lib.i2d_body_in_world(old_id, self._id)
            if body_id:
                self._user_data[body_id] = value

    def _in_world(self, function: Any, item: Any, cls: Any, kind: str) -> int:
        old_id = item.id if isinstance(item, cls) else int(item)
        new_id = function(old_id, self._id)
        if not new_id:
            check_last()
            raise InvalidHandle("World.%s: %r has no %s with the index and generation of 0x%016x"
                                % (kind, self, kind, old_id))
        return new_id

    def body(self, body: Union[Body, int]) -> Body:
        """The Body of this world with the index and generation of body (a Body or an id),
        for ids of the world a snapshot or pickle of this one came from
        (i2d_body_in_world). InvalidHandle when this world has no such body."""
        return Body(self, self._in_world(lib.i2d_body_in_world, body, Body, "body"))

    def shape(self, shape: Union[Shape, int]) -> Shape:
        """As body(), for a shape."""
        return Shape(self, self._in_world(lib.i2d_shape_in_world, shape, Shape, "shape"))

    def joint(self, joint: Union[Joint, int]) -> Joint:
        """As body(), for a joint."""
        return Joint(self, self._in_world(lib.i2d_joint_in_world, joint, Joint, "joint"))

    # ---- Bodies ----------------------------------------------------------------------------

    def create_body(
        self,
        type: BodyType = BodyType.DYNAMIC,
        position: Sequence[float] = (0.0, 0.0),
        angle: float = 0.0,
        **settings: Any,
    ) -> Body:
        """Creates a body (dynamic unless type says otherwise) at position, turned by
        angle (radians). Settings are the body def's fields: linear_velocity,
        angular_velocity, linear_damping, angular_damping, gravity_scale,
        fixed_rotation, enable_sleep, is_bullet."""
        body_def = lib.i2d_default_body_def()
        apply_settings(body_def, dict(settings, type=int(type), position=position, rotation=angle), "body")
        body_id = lib.i2d_body_create(self._id, C.byref(body_def))
        if not body_id:
            check_last()
        return Body(self, body_id)

    # ---- Joints ----------------------------------------------------------------------------

    def create_joint(self, kind: str, body_a: Body, body_b: Body, **settings: Any) -> Joint:
        """Creates a joint of kind "revolute", "prismatic", "distance", "weld", "wheel",
        "motor", "mouse" or "filter" between two bodies of this world. Settings are the
        kind's C def fields (include/impulse2d/joint.h) and the shared local_anchor_a,
        local_anchor_b, collide_connected, force_threshold and torque_threshold."""
        return _joint.create(self, kind, body_a, body_b, dict(settings))

    def joint_events(self) -> List[Joint]:
        """The joints whose reaction force or torque passed its threshold in the last step."""
        return list(_joint.joint_events(self))

    @property
    def joint_count(self) -> int:
        return _joint.joint_count(self)

    # ---- Events ----------------------------------------------------------------------------

    def _shape(self, shape_id: int) -> Shape:
        return Shape(self, shape_id)

    def contact_events(self) -> Tuple[List[ContactBegin], List[ContactEnd]]:
        """(begin, end) events of the last step."""
        e = lib.i2d_world_get_contact_events(self._id)
        check_last()
        begin = [ContactBegin(self._shape(b.shape_a), self._shape(b.shape_b)) for b in e.begin_events[: e.begin_count]]
        end = [ContactEnd(self._shape(n.shape_a), self._shape(n.shape_b)) for n in e.end_events[: e.end_count]]
        return begin, end

    def sensor_events(self) -> Tuple[List[SensorBegin], List[SensorEnd]]:
        """(begin, end) sensor events of the last step."""
        e = lib.i2d_world_get_sensor_events(self._id)
        check_last()
        begin = [SensorBegin(self._shape(b.sensor_shape), self._shape(b.visitor_shape)) for b in e.begin_events[: e.begin_count]]
        end = [SensorEnd(self._shape(n.sensor_shape), self._shape(n.visitor_shape)) for n in e.end_events[: e.end_count]]
        return begin, end

    def body_events(self) -> List[BodyMove]:
        """Every body that moved during the last step."""
        e = lib.i2d_world_get_body_events(self._id)
        check_last()
        moves = []
        for i in range(e.move_count):
            m = e.move_events[i]
            xf = m.transform
            moves.append(BodyMove(Body(self, m.body), (xf.p.x, xf.p.y), (xf.q.c, xf.q.s), bool(m.fell_asleep)))
        return moves

    def quarantine_events(self) -> List[BodyQuarantine]:
        """Every body the last step quarantined (its state went non-finite). A world fed
        only finite values should never have one; see i2d_body_quarantine_event."""
        e = lib.i2d_world_get_body_events(self._id)
        check_last()
        frozen = []
        for i in range(e.quarantine_count):
            q = e.quarantine_events[i]
            xf = q.transform
            frozen.append(
                BodyQuarantine(Body(self, q.body), (xf.p.x, xf.p.y), (xf.q.c, xf.q.s), BodyType(q.former_type))
            )
        return frozen

    # ---- Contact hooks and explosions (include/impulse2d/toolkit.h) ------------------------

    def _contact_hooks(self) -> Hooks:
        hooks = getattr(self, "_hooks", None)
        if hooks is None:
            hooks = self._hooks = Hooks(self)
            World._hooks_ever_set = True
        return hooks

    def set_custom_filter(self, fn: Optional[Callable[[Shape, Shape], bool]]) -> None:
        """fn(shape_a, shape_b) decides whether two shapes may ever touch (false: they pass
        through each other), or None clears it. It is asked when the pair is found (their
        bounds meet), only for pairs where either shape was created with
        enable_custom_filtering=True; pairs already in contact keep it until their bounds
        part. See set_pre_solve for when it runs and what it may do."""
        self._contact_hooks().set_custom_filter(fn)

    def set_pre_solve(self, fn: Optional[Callable[[Shape, Shape, Manifold], bool]]) -> None:
        """fn(shape_a, shape_b, manifold) decides whether a touching contact takes part in
        this step (false: no impulse, no begin event this step), or None clears it. It is
        asked every step the pair touches, after the narrowphase, only for pairs where
        either shape has pre_solve_events_enabled (enable_pre_solve_events=True); manifold
        is a Manifold whose normal points from shape_a to shape_b.

        Both hooks run inside step(), one Python call per pair asked, on the library's
        worker threads when it has several: each call takes the GIL, so they run one at a
        time, and what they cost adds to the step's time. The answer is fn's truth value.
        The world is locked while they run: any call on it raises WorldLocked. An
        exception fn raises gives the pair the answer True and is raised by step() once
        the step is done (the first one, if several were). Restoring a snapshot or state
        in place keeps the hooks; a copy (from_snapshot, pickle, deepcopy) or a Replay has
        the shapes' opt-ins but no hooks."""
        self._contact_hooks().set_pre_solve(fn)

    def explode(
        self,
        position: Sequence[float],
        radius: float = 1.0,
        falloff: float = 0.0,
        impulse_per_length: float = 1.0,
        mask_bits: int = _ALL_BITS,
    ) -> None:
        """Pushes every dynamic body with a shape (whose category_bits meet mask_bits)
        within radius + falloff of position, away from it, and wakes it: impulse_per_length
        N s per length of the shape's outline that faces the blast, at full strength within
        radius and fading linearly to nothing over falloff (measured to the shape's closest
        point). A disc of radius r and mass m within radius leaves at
        impulse_per_length * 2r / m. Negative impulse_per_length pulls. Sensors are not
        pushed. InvalidArgument for a position that is not finite, a radius or falloff
        outside [0, 1e6] or an impulse_per_length outside [-1e6, 1e6] (NaN included)."""
        blast = lib.i2d_default_explosion_def()
        blast.position = vec2(position)
        blast.radius, blast.falloff, blast.impulse_per_length = radius, falloff, impulse_per_length
        blast.mask_bits = mask_bits
        check(lib.i2d_world_explode(self._id, C.byref(blast)))

    # ---- The character mover (include/impulse2d/toolkit.h) ---------------------------------

    def move_character(
        self,
        capsule: CapsuleLike,
        position: Sequence[float],
        velocity: Sequence[float],
        time_step: float,
        *,
        max_slope_angle: Optional[float] = None,
        step_height: Optional[float] = None,
        snap_distance: Optional[float] = None,
        skin: Optional[float] = None,
        max_iterations: Optional[int] = None,
        push_mass: Optional[float] = None,
        filter: Any = None,
    ) -> CharacterResult:
        """Moves a character's capsule ((center1, center2, radius) in the character's frame,
        as Shape.geometry() gives a capsule) from position by velocity * time_step:
        cast-and-slide against the shapes the filter sees, keeping skin from every surface,
        walking up ground no steeper than max_slope_angle, stepping onto ledges up to
        step_height and snapping down to ground within snap_distance. It never passes
        through a shape. Returns a CharacterResult (position, clipped velocity, on_ground,
        ground_normal, ground_shape, ground_velocity, hit_count); add ground_velocity to the
        next move's velocity to ride a moving platform.

        Settings left None take i2d_default_character_def()'s values: max_slope_angle
        0.7854 rad (45 degrees, in [0, pi/2)), step_height 0.25, snap_distance 0.2, skin 0.01
        (> 0), max_iterations 5 (in [1, 64]), push_mass 80 kg (each dynamic body it moves
        into gets an impulse as from that mass; 0 pushes nothing and makes the move a pure
        query). filter is (category_bits, mask_bits), default every shape; sensors are
        never seen. docs/character_mover.md describes a move.

        InvalidArgument, with the library's message and the world untouched, for NaN or
        infinite values, a negative time step, a move longer than 1e9, settings out of
        their ranges or a capsule radius outside [1e-4, 1e5]; WorldLocked for a move that
        pushes, inside a query or draw callback."""
        settings = dict(max_slope_angle=max_slope_angle, step_height=step_height, snap_distance=snap_distance,
                        skin=skin, max_iterations=max_iterations, push_mass=push_mass)
        d = _mover.character_def(settings, filter)
        return _mover.move_character(self, d, capsule, position, velocity, time_step)

    def cast_mover(self, capsule: CapsuleLike, translation: Sequence[float], filter: Any = None) -> float:
        """The fraction of translation, in [0, 1], that the capsule ((center1, center2,
        radius) in world coordinates) can move before it comes within the world's contact
        slop of a shape the filter ((category_bits, mask_bits), default every shape) sees:
        1 the whole way. It stops at a gap of a half to three quarters of the slop, and at
        once (0) when moving deeper into a shape it already touches; it never passes through
        one. Sensors are not seen. A query: allowed inside query and draw callbacks."""
        return _mover.cast_mover(self, capsule, translation, filter)

    def collide_mover(self, capsule: CapsuleLike, filter: Any = None) -> List[CollisionPlane]:
        """A CollisionPlane per shape within the contact slop of the capsule (world
        coordinates): its normal from the shape toward the capsule, its offset the signed
        separation (negative when overlapping), push_limit inf (rigid), clip_velocity True;
        in a fixed order for the same world. Feed them to solve_planes and clip_vector to
        build a mover of your own. Filter and sensors as for cast_mover."""
        return _mover.collide_mover(self, capsule, filter)

    # ---- Debug drawing (include/impulse2d/toolkit.h) ---------------------------------------

    def draw(
        self,
        drawer: Any,
        *,
        shapes: bool = True,
        joints: bool = True,
        joint_extras: bool = False,
        bounds: bool = False,
        mass: bool = False,
        contacts: bool = False,
        contact_normals: bool = False,
        contact_impulses: bool = False,
        friction_impulses: bool = False,
        graph_colors: bool = False,
        islands: bool = False,
        bounds_box: Optional[Sequence[Sequence[float]]] = None,
    ) -> None:
        """Draws the world through the drawer's methods, before returning (i2d_world_draw):
        draw_polygon(vertices, color), draw_solid_polygon(transform, vertices, radius,
        color), draw_circle(center, radius, color), draw_solid_circle(transform, radius,
        color), draw_solid_capsule(p1, p2, radius, color), draw_segment(p1, p2, color),
        draw_transform(transform), draw_point(p, size, color), draw_string(p, text, color).
        Points are (x, y) tuples in world units (a solid polygon's vertices are local:
        transform.apply places them); transform is a Transform(position, rotation); color an
        int 0xRRGGBB, one of the COLOR_* constants (a shape's says its body's state). What
        the drawer has no method for is not drawn.

        The flags choose what is drawn: shapes, joints (on by default), joint_extras
        (limits, motors, springs), bounds (shapes' fattened boxes), mass (centres of mass
        and mass as text), contacts (points), contact_normals, contact_impulses,
        friction_impulses, graph_colors (contact points in their solver colour), islands
        (awake islands' boxes). bounds_box ((min_x, min_y), (max_x, max_y)) draws only the
        shapes whose bounds overlap it, and their bodies' joints, contacts and the rest.

        The world is locked while the methods run: calls that change it raise WorldLocked
        there; getters, queries and draw work. The first exception a method raises ends
        the drawer's part (the library finishes its pass without calling the drawer again)
        and is raised here. InvalidArgument for a bounds_box that is not finite or is
        inverted; InvalidHandle for a destroyed world. Each picture costs a Python call,
        see bindings/python/README.md."""
        flags = dict(draw_shapes=shapes, draw_joints=joints, draw_joint_extras=joint_extras, draw_bounds=bounds,
                     draw_mass=mass, draw_contacts=contacts, draw_contact_normals=contact_normals,
                     draw_contact_impulses=contact_impulses, draw_friction_impulses=friction_impulses,
                     draw_graph_colors=graph_colors, draw_islands=islands)
        _draw.draw(self, drawer, flags, bounds_box)

    # ---- Queries ---------------------------------------------------------------------------

    def overlap_aabb(
        self,
        lower: Sequence[float],
        upper: Sequence[float],
        category_bits: int = _ALL_BITS,
        mask_bits: int = _ALL_BITS,
    ) -> List[Shape]:
        """Every shape whose geometry overlaps the box from lower to upper."""
        box = AABB(min=vec2(lower), max=vec2(upper))
        qf = _query_filter(category_bits, mask_bits)
        capacity = 64
        while True:
            ids = (C.c_uint64 * capacity)()
            total = lib.i2d_world_overlap_aabb_ids(self._id, box, qf, C.addressof(ids), capacity)
            if total < 0:
                check_last()
            if total <= capacity:
                return [self._shape(ids[i]) for i in range(total)]
            capacity = total

    def overlap_point(
        self,
        point: Sequence[float],
        category_bits: int = _ALL_BITS,
        mask_bits: int = _ALL_BITS,
        visit: Optional[Callable[[Shape], bool]] = None,
    ) -> List[Shape]:
        """Every shape that contains the point. With visit, each is passed to it as it
        is found (the world is locked meanwhile: changing it raises WorldLocked) and a
        False return stops the query; an exception raised by visit stops it and is
        raised again here."""
        found: List[Shape] = []
        raised: List[BaseException] = []

        def collect(shape_id: int, _context: Any) -> bool:
            shape = self._shape(shape_id)
            found.append(shape)
            if visit is None:
                return True
            try:
                return visit(shape) is not False
            except BaseException as error:  # never let Python unwind through C
                raised.append(error)
                return False

        callback = _OVERLAP_FN(collect)
        check(lib.i2d_world_overlap_point(self._id, vec2(point), _query_filter(category_bits, mask_bits), callback, None))
        if raised:
            raise raised[0]
        return found

    def cast_ray(
        self,
        origin: Sequence[float],
        translation: Sequence[float],
        category_bits: int = _ALL_BITS,
        mask_bits: int = _ALL_BITS,
    ) -> Optional[RayHit]:
        """The first shape along origin + t * translation, t in [0, 1], or None."""
        r = lib.i2d_world_cast_ray_closest(
            self._id, vec2(origin), vec2(translation), _query_filter(category_bits, mask_bits)
        )
        check_last()
        if not r.hit:
            return None
        return RayHit(self._shape(r.shape), pair(r.point), pair(r.normal), r.fraction)

    # ---- Bulk state: NumPy arrays, one call for many bodies -------------------------------

    def body_ids(self, bodies: BodyList) -> "np.ndarray":
        """The ids of bodies as a uint64 array. Build it once and pass it to the bulk
        calls: they then cost nanoseconds per body instead of a Python loop."""
        numpy = _numpy()
        if isinstance(bodies, numpy.ndarray):
            if bodies.dtype != numpy.uint64 or bodies.ndim != 1:
                raise TypeError("body id arrays must be one-dimensional uint64 (world.body_ids(bodies))")
            return numpy.ascontiguousarray(bodies)
        return numpy.fromiter((b._id for b in bodies), dtype=numpy.uint64, count=len(bodies))

    @staticmethod
    def _output(numpy: Any, out: Optional["np.ndarray"], shape: Tuple[int, ...], name: str) -> "np.ndarray":
        if out is None:
            return numpy.empty(shape, dtype=numpy.float32)
        if out.shape != shape or out.dtype != numpy.float32 or not out.flags.c_contiguous or not out.flags.writeable:
            raise ValueError("%s must be a writable C-contiguous float32 array of shape %s" % (name, shape))
        return out

    @staticmethod
    def _input(numpy: Any, values: Any, shape: Tuple[int, ...], name: str) -> "np.ndarray":
        array = numpy.ascontiguousarray(values, dtype=numpy.float32)
        if array.shape != shape:
            raise ValueError("%s has shape %s; expected %s" % (name, array.shape, shape))
        return array

    def transforms(self, bodies: BodyList, out: Optional["np.ndarray"] = None) -> "np.ndarray":
        """The transforms of bodies as an (n, 4) float32 array of rows [x, y, c, s]
        (origin, cosine and sine of the angle). out, if given, is filled instead."""
        numpy = _numpy()
        ids = self.body_ids(bodies)
        result = self._output(numpy, out, (len(ids), 4), "out")
        check(lib.i2d_world_get_body_transforms(self._id, ids.ctypes.data, len(ids), result.ctypes.data))
        return result

    def velocities(
        self, bodies: BodyList, linear_out: Optional["np.ndarray"] = None, angular_out: Optional["np.ndarray"] = None
    ) -> Tuple["np.ndarray", "np.ndarray"]:
        """(linear, angular): an (n, 2) float32 array of m/s and an (n,) float32 array
        of rad/s."""
        numpy = _numpy()
        ids = self.body_ids(bodies)
        linear = self._output(numpy, linear_out, (len(ids), 2), "linear_out")
        angular = self._output(numpy, angular_out, (len(ids),), "angular_out")
        check(
            lib.i2d_world_get_body_velocities(
                self._id, ids.ctypes.data, len(ids), linear.ctypes.data, angular.ctypes.data
            )
        )
        return linear, angular

    def set_transforms(self, bodies: BodyList, transforms: Any) -> None:
        """Teleports bodies to the rows [x, y, c, s] of an (n, 4) array (rotations
        normalised within 1e-3). All rows are checked before any body moves."""
        numpy = _numpy()
        ids = self.body_ids(bodies)
        array = self._input(numpy, transforms, (len(ids), 4), "transforms")
        check(lib.i2d_world_set_body_transforms(self._id, ids.ctypes.data, len(ids), array.ctypes.data))

    def set_velocities(self, bodies: BodyList, linear: Any = None, angular: Any = None) -> None:
        """Sets linear ((n, 2), m/s) and/or angular ((n,), rad/s) velocities, as the
        per-body setters do (static bodies ignore them, non-zero values wake)."""
        numpy = _numpy()
        ids = self.body_ids(bodies)
        lin = None if linear is None else self._input(numpy, linear, (len(ids), 2), "linear")
        ang = None if angular is None else self._input(numpy, angular, (len(ids),), "angular")
        check(
            lib.i2d_world_set_body_velocities(
                self._id,
                ids.ctypes.data,
                len(ids),
                None if lin is None else lin.ctypes.data,
                None if ang is None else ang.ctypes.data,
            )
        )
