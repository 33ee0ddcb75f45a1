# SPDX-License-Identifier: MIT
"""impulse2d: a 2D rigid-body physics engine, through its C library.

    import impulse2d

    with impulse2d.World(gravity=(0, -10)) as world:
        ground = world.create_body(impulse2d.BodyType.STATIC, position=(0, -1))
        ground.create_box(50, 1)
        ball = world.create_body(position=(0, 4))
        ball.create_circle(0.5, restitution=0.5)
        for _ in range(120):
            world.step(1 / 60, 4)
        print(ball.position)

Objects: World (owns everything; a context manager), Body, Shape and Joint (value
handles; World.create_joint joins two bodies). Bodies and shapes change at run time
through properties (Body.mass_data, gravity_scale, fixed_rotation, Shape.material, ...)
and methods (Body.disable, Shape.set_circle, ...); Body.contact_data and
Shape.contact_data give what touches them now. shape_distance measures two convex
shapes without a world. World(length_units_per_meter=50) counts lengths in pixels.
Errors come back as exceptions carrying the library's message: InvalidArgument,
InvalidHandle, WorldLocked, CapacityError, OutOfMemory, InvalidSnapshot (all
Impulse2DError).
Bulk state (World.transforms, velocities, set_transforms, set_velocities) reads and
writes many bodies per call through NumPy arrays.
Snapshots (World.save_snapshot, from_snapshot, restore_snapshot) and rollback states
(save_state, restore_state) bring a world back bit for bit; a World pickles and
deep-copies through a snapshot. World.start_recording streams every change and step;
Replay replays such a recording and names the first step whose hash differs.
Contact hooks (World.set_custom_filter, World.set_pre_solve) decide pair by pair whether
shapes touch: one-way platforms, ghosts; World.explode pushes what is near a blast.
World.move_character moves a game character's capsule (walks, slides, climbs steps,
rides platforms); World.cast_mover, World.collide_mover, solve_planes and clip_vector are
the pieces for movers of one's own. World.draw hands the world to a drawer's draw_*
methods, in the COLOR_* colours.

The native library is found through IMPULSE2D_LIBRARY, next to this package, in the
source tree's build directories or where ``cmake --install`` put it; its struct layouts
are checked at import, and a mismatched library is refused (LayoutMismatch).
"""

from ._native import lib as _lib
from ._library import ENVIRONMENT_VARIABLE, version_string as _version_string
from .body import Body
from .errors import (
    CapacityError,
    Impulse2DError,
    InvalidArgument,
    InvalidHandle,
    InvalidSnapshot,
    LayoutMismatch,
    LibraryError,
    OutOfMemory,
    WorldLocked,
)
from .joint import Joint
from ._draw import (
    COLOR_ASLEEP,
    COLOR_AWAKE,
    COLOR_BOUNDS,
    COLOR_BULLET,
    COLOR_CONTACT,
    COLOR_CONTACT_IMPULSE,
    COLOR_CONTACT_NORMAL,
    COLOR_DISABLED,
    COLOR_FRICTION_IMPULSE,
    COLOR_GRAPH_OVERFLOW,
    COLOR_ISLAND,
    COLOR_JOINT,
    COLOR_JOINT_ANCHOR,
    COLOR_JOINT_LIMIT,
    COLOR_JOINT_MOTOR,
    COLOR_JOINT_SPRING,
    COLOR_KINEMATIC,
    COLOR_MASS,
    COLOR_QUARANTINED,
    COLOR_SENSOR,
    COLOR_SPECULATIVE,
    COLOR_STATIC,
    GRAPH_COLORS,
)
from ._mover import clip_vector, solve_planes
from .shape import Shape, shape_distance
from .types import (
    BodyMove,
    BodyQuarantine,
    BodyType,
    CharacterResult,
    CollisionPlane,
    ContactBegin,
    ContactData,
    ContactEnd,
    Counters,
    DistanceResult,
    Manifold,
    ManifoldPoint,
    MassData,
    PlaneResult,
    RayHit,
    SensorBegin,
    SensorEnd,
    ShapeType,
    SurfaceMaterial,
    Transform,
)
from .world import World
from .batch import WorldBatch, step_worlds
from .replay import Replay

__version__ = "0.2.0"
#: The version of the loaded native library, "major.minor.patch".
library_version: str = _version_string(_lib)
#: Path of the loaded native library.
library_path: str = _lib._impulse2d_path

STATIC, KINEMATIC, DYNAMIC = BodyType.STATIC, BodyType.KINEMATIC, BodyType.DYNAMIC

__all__ = [
    "World",
    "WorldBatch",
    "step_worlds",
    "Replay",
    "Body",
    "Shape",
    "Joint",
    "BodyType",
    "ShapeType",
    "STATIC",
    "KINEMATIC",
    "DYNAMIC",
    "ContactBegin",
    "ContactEnd",
    "SensorBegin",
    "SensorEnd",
    "BodyMove",
    "BodyQuarantine",
    "RayHit",
    "Counters",
    "MassData",
    "SurfaceMaterial",
    "Manifold",
    "ManifoldPoint",
    "ContactData",
    "DistanceResult",
    "shape_distance",
    "CharacterResult",
    "CollisionPlane",
    "PlaneResult",
    "solve_planes",
    "clip_vector",
    "Transform",
    "GRAPH_COLORS",
    "COLOR_ASLEEP",
    "COLOR_AWAKE",
    "COLOR_BOUNDS",
    "COLOR_BULLET",
    "COLOR_CONTACT",
    "COLOR_CONTACT_IMPULSE",
    "COLOR_CONTACT_NORMAL",
    "COLOR_DISABLED",
    "COLOR_FRICTION_IMPULSE",
    "COLOR_GRAPH_OVERFLOW",
    "COLOR_ISLAND",
    "COLOR_JOINT",
    "COLOR_JOINT_ANCHOR",
    "COLOR_JOINT_LIMIT",
    "COLOR_JOINT_MOTOR",
    "COLOR_JOINT_SPRING",
    "COLOR_KINEMATIC",
    "COLOR_MASS",
    "COLOR_QUARANTINED",
    "COLOR_SENSOR",
    "COLOR_SPECULATIVE",
    "COLOR_STATIC",
    "Impulse2DError",
    "InvalidArgument",
    "InvalidHandle",
    "WorldLocked",
    "CapacityError",
    "OutOfMemory",
    "InvalidSnapshot",
    "LibraryError",
    "LayoutMismatch",
    "ENVIRONMENT_VARIABLE",
    "library_version",
    "library_path",
]
