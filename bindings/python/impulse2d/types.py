# SPDX-License-Identifier: MIT
"""Enumerations and the named tuples that events and queries return."""

import enum
from typing import NamedTuple, Optional, Tuple, TYPE_CHECKING

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


class MassData(NamedTuple):
    """A body's mass properties (i2d_mass_data). Body.mass_data gives one; setting it
    takes one or any (mass, center, rotational_inertia) tuple."""

    mass: float  #: kg
    center: Vec  #: centre of mass in the body frame
    rotational_inertia: float  #: kg m^2 about the centre of mass


class SurfaceMaterial(NamedTuple):
    """A shape's surface (i2d_surface_material), as Shape.material gives and takes it."""

    friction: float  #: [0, inf)
    restitution: float  #: [0, 100]
    rolling_resistance: float  #: [0, 1e5]
    tangent_speed: float  #: length units per second, |speed| <= 1e5


class ManifoldPoint(NamedTuple):
    """One point of a contact manifold (i2d_manifold_point)."""

    point: Vec  #: world point midway between the two surfaces
    penetration: float  #: > 0 overlapping, 0 touching, < 0 speculative
    id: int  #: feature key, stable from step to step for the same features


class Manifold(NamedTuple):
    """A contact's manifold as the pre-solve hook sees it (i2d_manifold): the unit normal
    from shape A to shape B and the touching points, one to two."""

    normal: Vec
    points: Tuple[ManifoldPoint, ...]


class ContactData(NamedTuple):
    """A touching contact as the last step left it (i2d_contact_data): its shapes (in the
    order contact events name them), the unit normal from A to B, its manifold points and
    the last substep's impulses at each point (N s; divided by time_step / substeps, the
    contact's force). points, normal_impulses and tangent_impulses have one entry per
    manifold point."""

    shape_a: "Shape"
    shape_b: "Shape"
    normal: Vec
    points: Tuple[ManifoldPoint, ...]
    normal_impulses: Tuple[float, ...]
    tangent_impulses: Tuple[float, ...]


class DistanceResult(NamedTuple):
    """The closest points of two convex shapes (i2d_distance_result), from
    impulse2d.shape_distance."""

    point_a: Vec  #: on A's surface
    point_b: Vec  #: on B's surface
    normal: Vec  #: unit, from A towards B; (0, 0) when they overlap
    distance: float  #: between the surfaces; 0 when they touch or overlap


class Transform(NamedTuple):
    """A position and rotation, as the debug drawer's callbacks receive them
    (i2d_transform): apply() places a point given in its frame."""

    position: Vec
    rotation: Vec  #: (cosine, sine)

    def apply(self, point: Vec) -> Vec:
        """point (in this frame) in world coordinates."""
        (px, py), (c, s), (x, y) = self.position, self.rotation, point
        return (c * x - s * y + px, s * x + c * y + py)


class CollisionPlane(NamedTuple):
    """A plane the character mover touches or is kept from (i2d_collision_plane): the
    points x with dot(normal, x) = offset, normal unit. As World.collide_mover reports
    one, the normal points from the shape toward the mover and offset is the mover's
    signed separation (negative when overlapping); moved by d, the mover keeps clear
    while offset + dot(normal, d) >= 0. A tuple (normal, offset) works wherever a plane
    is taken."""

    normal: Vec
    offset: float
    #: How far the plane may push the mover (solve_planes); math.inf for a rigid plane
    #: (the C API's FLT_MAX, which is what it is given).
    push_limit: float = float("inf")
    #: How far solve_planes found it pushed; 0 in what collide_mover reports.
    push: float = 0.0
    #: Whether clip_vector clips against it.
    clip_velocity: bool = True


class PlaneResult(NamedTuple):
    """What solve_planes found (i2d_plane_result, plus each plane's push)."""

    translation: Vec  #: the move that keeps every rigid plane's separation >= 0
    iteration_count: int  #: sweeps it took (at most 32; 0 without planes)
    pushes: Tuple[float, ...]  #: how far each plane pushed, in the order given


class CharacterResult(NamedTuple):
    """Where World.move_character left the character (i2d_character_result)."""

    position: Vec  #: where the capsule's local origin ends
    #: The velocity asked for, less what runs into walls and ceilings and the downward part
    #: the ground takes; without ground_velocity (add that to ride a platform).
    velocity: Vec
    on_ground: bool  #: standing on ground within max_slope_angle of up
    ground_normal: Vec  #: (0, 0) when not on the ground
    ground_shape: Optional["Shape"]  #: the shape stood on, or None
    ground_velocity: Vec  #: the velocity of the ground's body at the feet
    hit_count: int  #: distinct shapes the move touched (counted up to 64)
