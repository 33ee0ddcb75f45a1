# SPDX-License-Identifier: MIT
"""The character mover from Python (World.move_character, cast_mover, collide_mover,
solve_planes, clip_vector), against the closed forms tests/physics/test_character_mover.cpp
checks in C: distances walked, the gap kept to a wall, ledges within and beyond the step
height, a platform ridden, pushes, filters, refusals with the library's message, and the
plane solver on planes worked out by hand.

The character is a capsule 1.8 m tall of radius 0.3 m with its origin at its feet, moved
as a game does at 60 Hz: the input sets the level speed, gravity is added while it is in
the air and the velocity a move returns is fed back."""

import math

import pytest

import impulse2d
from conftest import make_ground

STEP = 1 / 60
GRAVITY = 10.0
RADIUS = 0.3
HEIGHT = 1.8
CAPSULE = ((0.0, RADIUS), (0.0, HEIGHT - RADIUS), RADIUS)
SKIN = 0.01  # the default def's gap to surfaces, m
SLOP = 0.005  # the default world's contact slop, m
# Where a character rests above what it stands on: the skin and 7/8 of the slop, beyond the
# band its casts stop in (a half to three quarters of the slop).
REST_GAP = SKIN + 0.875 * SLOP
ALL_BITS = 0xFFFFFFFFFFFFFFFF


def frames(seconds):
    return round(seconds / STEP)


class Character:
    """A character moved frame by frame with the given move_character settings."""

    def __init__(self, world, position, **settings):
        self.world, self.position, self.settings = world, position, settings
        self.velocity = (0.0, 0.0)
        self.last = None

    def move(self, velocity):
        self.last = self.world.move_character(CAPSULE, self.position, velocity, STEP, **self.settings)
        self.position = self.last.position
        return self.last

    def frame(self, input_x):
        """One game frame: the input sets the level speed, gravity pulls while airborne."""
        vy = self.velocity[1]
        if self.last is None or not self.last.on_ground:
            vy -= GRAVITY * STEP
        self.move((input_x, vy))
        self.velocity = self.last.velocity
        return self.last


def static_block(world, x0, y0, x1, y1, **shape_settings):
    """A static box whose corners are (x0, y0) and (x1, y1); returns its shape."""
    body = world.create_body(impulse2d.STATIC, position=(0.5 * (x0 + x1), 0.5 * (y0 + y1)))
    return body.create_box(0.5 * (x1 - x0), 0.5 * (y1 - y0), **shape_settings)


# ---- World.move_character --------------------------------------------------------------


def test_walks_8_m_in_2_s_on_flat_ground_at_the_rest_gap(world):
    ground = make_ground(world)
    c = Character(world, (0.0, REST_GAP))
    for _ in range(frames(2.0)):
        world.step(STEP, 4)
        r = c.frame(4.0)
        assert r.on_ground
        assert c.position[1] == pytest.approx(REST_GAP, abs=0.25 * SLOP)
    assert c.position[0] == pytest.approx(8.0, rel=0.01)
    assert isinstance(r, impulse2d.CharacterResult)
    assert r.velocity[0] == pytest.approx(4.0, abs=1e-6) and r.velocity[1] == pytest.approx(0.0, abs=1e-4)
    # From closest points on a 100 m edge, which round to a few 1e-6 m.
    assert r.ground_normal == pytest.approx((0.0, 1.0), abs=1e-5)
    assert r.ground_shape == ground.shapes[0] and isinstance(r.ground_shape, impulse2d.Shape)
    assert r.ground_velocity == (0.0, 0.0)
    assert r.hit_count == 1


def test_in_the_air_it_has_no_ground():
    with impulse2d.World() as world:
        r = world.move_character(CAPSULE, (0.0, 5.0), (0.0, -1.0), STEP)
        assert not r.on_ground and r.ground_shape is None and r.ground_normal == (0.0, 0.0)
        assert r.hit_count == 0
        assert r.position == pytest.approx((0.0, 5.0 - STEP), abs=1e-6)


def test_stops_at_a_wall_within_the_skin(world):
    make_ground(world)
    static_block(world, 3.0, 0.0, 4.0, 3.0)
    c = Character(world, (0.0, REST_GAP))
    for _ in range(frames(2.0)):
        c.frame(4.0)
    gap = 3.0 - (c.position[0] + RADIUS)
    assert SKIN - 1e-5 <= gap <= SKIN + SLOP
    assert c.velocity[0] == pytest.approx(0.0, abs=1e-6)
    assert c.last.on_ground and c.last.hit_count == 2


def walk_at_ledge(height, **settings):
    """A character walked at 2 m/s for 2 s toward a ledge `height` high from x = 2 to 8;
    its last result."""
    with impulse2d.World() as world:
        make_ground(world)
        static_block(world, 2.0, 0.0, 8.0, height)
        c = Character(world, (0.0, REST_GAP), **settings)
        for _ in range(frames(2.0)):
            c.frame(2.0)
        return c.last


def test_steps_onto_a_0_2_m_ledge_but_not_a_0_4_m_one():
    low = walk_at_ledge(0.2, step_height=0.25)
    assert low.on_ground
    assert low.position[1] == pytest.approx(0.2 + REST_GAP, abs=0.25 * SLOP)
    assert 3.5 < low.position[0] < 4.0 + RADIUS  # walked along the ledge
    high = walk_at_ledge(0.4, step_height=0.25)
    assert high.on_ground
    assert high.position[1] == pytest.approx(REST_GAP, abs=0.25 * SLOP)
    assert high.position[0] + RADIUS == pytest.approx(2.0 - REST_GAP, abs=0.75 * SLOP)  # at its face


def test_step_height_is_the_callers_and_defaults_to_the_librarys():
    # A step of 0.1 m keeps it off the 0.2 m ledge: the setting reaches the library.
    stopped = walk_at_ledge(0.2, step_height=0.1)
    assert stopped.position[1] == pytest.approx(REST_GAP, abs=0.25 * SLOP)
    # Left out, the library's default (0.25 m) climbs it.
    climbed = walk_at_ledge(0.2)
    assert climbed.position[1] == pytest.approx(0.2 + REST_GAP, abs=0.25 * SLOP)


def test_rides_a_kinematic_platform_at_its_velocity(world):
    platform = world.create_body(impulse2d.KINEMATIC, position=(0.0, 1.0), linear_velocity=(2.0, 0.0))
    deck = platform.create_box(2.0, 0.25)
    c = Character(world, (0.0, 1.25 + REST_GAP))
    r = c.move((0.0, 0.0))
    assert r.on_ground and r.ground_shape == deck
    assert r.ground_velocity == pytest.approx((2.0, 0.0), abs=1e-6)
    offset = c.position[0] - platform.position[0]
    for _ in range(frames(1.0)):
        world.step(STEP, 4)
        r = c.move(r.ground_velocity)  # standing still on it: its velocity carries the character
        assert r.on_ground
        assert c.position[0] - platform.position[0] == pytest.approx(offset, abs=1e-4)
        assert c.position[1] == pytest.approx(1.25 + REST_GAP, abs=0.25 * SLOP)
    assert platform.position[0] == pytest.approx(2.0, abs=1e-3)


def test_pushes_a_crate_only_with_a_push_mass():
    with impulse2d.World(enable_sleep=False) as world:
        make_ground(world)
        crate = world.create_body(position=(2.0, 0.5))
        crate.create_box(0.5, 0.5, density=20.0)
        for _ in range(30):
            world.step(STEP, 4)  # the crate settles
        before = world.state_hash
        # push_mass 0: walked up against the crate, the move is a query and changes nothing.
        c = Character(world, (0.0, REST_GAP), push_mass=0.0)
        for _ in range(frames(1.0)):
            c.frame(2.0)
        assert c.position[0] + RADIUS == pytest.approx(1.5 - REST_GAP, abs=0.75 * SLOP)
        assert world.state_hash == before
        # The default 80 kg: one move into it is a plastic collision, slower than the walk.
        world.move_character(CAPSULE, c.position, (2.0, 0.0), STEP)
        vx = crate.linear_velocity[0]
        assert 0.0 < vx < 2.0
        assert crate.mass * vx <= 80.0 * 2.0


def test_the_filter_decides_what_the_character_meets(world):
    make_ground(world)
    static_block(world, 3.0, 0.0, 4.0, 3.0, filter=(2, ALL_BITS))  # a wall of category 2
    ghost = Character(world, (0.0, REST_GAP), filter=(1, 1))  # sees category 1 only
    for _ in range(frames(2.0)):
        ghost.frame(4.0)
    assert ghost.position[0] == pytest.approx(8.0, rel=0.01)  # through the wall
    assert ghost.last.on_ground  # and still on the ground, of category 1


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(velocity=(math.nan, 0.0)), "velocity.x is NaN"),
        (dict(time_step=-1.0), "time_step is -1"),
        (dict(position=(0.0, math.inf)), "position.y is +inf"),
        (dict(capsule=((0.0, 0.0), (0.0, 1.0), 0.0)), "capsule radius is 0"),
        (dict(skin=0.0), "def skin is 0; it must be in (0, "),
        (dict(max_iterations=0), "def max_iterations is 0; it must be in [1, 64]"),
        (dict(max_slope_angle=2.0), "def max_slope_angle is 2; it must be in [0, pi/2) rad"),
        (dict(step_height=-1.0), "def step_height is -1"),
        (dict(push_mass=-1.0), "def push_mass is -1"),
    ],
)
def test_refuses_bad_input_with_the_librarys_message_and_changes_nothing(change, message):
    with impulse2d.World() as world:
        make_ground(world)
        crate = world.create_body(position=(0.5, 0.5))
        crate.create_box(0.5, 0.5)
        before = world.state_hash
        args = dict(capsule=CAPSULE, position=(0.0, REST_GAP), velocity=(4.0, 0.0), time_step=STEP)
        args.update(change)
        with pytest.raises(impulse2d.InvalidArgument) as caught:
            world.move_character(**args)
        assert str(caught.value).startswith("i2d_world_move_character: " + message)
        assert world.state_hash == before and crate.linear_velocity == (0.0, 0.0)


def test_a_move_that_pushes_is_refused_inside_a_query_and_one_that_does_not_is_allowed(world):
    make_ground(world)
    seen = []

    def visit(_shape):
        try:
            world.move_character(CAPSULE, (0.0, REST_GAP), (1.0, 0.0), STEP)
        except impulse2d.WorldLocked as error:
            seen.append(str(error))
        seen.append(world.move_character(CAPSULE, (0.0, REST_GAP), (1.0, 0.0), STEP, push_mass=0.0))

    world.overlap_point((0.0, -0.5), visit=visit)
    assert seen[0].startswith("i2d_world_move_character: called from inside a query callback")
    assert seen[1].on_ground


def test_a_destroyed_world_refuses_the_mover_calls():
    world = impulse2d.World()
    world.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        world.move_character(CAPSULE, (0.0, 0.0), (1.0, 0.0), STEP)
    with pytest.raises(impulse2d.InvalidHandle):
        world.cast_mover(CAPSULE, (1.0, 0.0))
    with pytest.raises(impulse2d.InvalidHandle):
        world.collide_mover(CAPSULE)


# ---- World.cast_mover and World.collide_mover --------------------------------------------


def capsule_at(x, bottom, radius=RADIUS):
    """A standing capsule whose lowest point is at (x, bottom), in world coordinates."""
    return ((x, bottom + radius), (x, bottom + HEIGHT - radius), radius)


def test_cast_mover_stops_short_of_the_ground_within_the_slop(world):
    make_ground(world)
    fraction = world.cast_mover(capsule_at(0.0, 1.0), (0.0, -2.0))
    gap = 1.0 - 2.0 * fraction
    assert 0.5 * SLOP - 1e-6 <= gap <= 0.75 * SLOP + 1e-6
    assert world.cast_mover(capsule_at(0.0, 1.0), (0.0, 2.0)) == 1.0  # nothing above
    assert world.cast_mover(capsule_at(0.0, 1.0), (0.0, -2.0), filter=(2, 2)) == 1.0  # ground unseen
    with pytest.raises(impulse2d.InvalidArgument, match=r"^i2d_world_cast_mover: translation\.x is NaN"):
        world.cast_mover(capsule_at(0.0, 1.0), (math.nan, 0.0))


def test_collide_mover_gives_a_rigid_plane_per_shape_touched(world):
    make_ground(world)
    planes = world.collide_mover(capsule_at(0.0, 0.002))
    assert len(planes) == 1
    plane = planes[0]
    assert isinstance(plane, impulse2d.CollisionPlane)
    assert plane.normal == pytest.approx((0.0, 1.0), abs=1e-6)
    assert plane.offset == pytest.approx(0.002, abs=1e-5)
    assert plane.push_limit == math.inf and plane.push == 0.0 and plane.clip_velocity is True
    assert world.collide_mover(capsule_at(0.0, -0.01))[0].offset == pytest.approx(-0.01, abs=1e-5)
    assert world.collide_mover(capsule_at(0.0, 1.0)) == []
    assert world.collide_mover(capsule_at(0.0, 0.002), filter=(2, 2)) == []


def test_collide_mover_reports_more_planes_than_its_first_guess(world):
    # A lying capsule 6 m long across 0.25 m tiles touches 24 shapes at once.
    tile = 0.25
    for i in range(40):
        static_block(world, -5.0 + tile * i, -1.0, -5.0 + tile * (i + 1), 0.0)
    lying = ((-3.0, RADIUS + 0.002), (3.0, RADIUS + 0.002), RADIUS)
    planes = world.collide_mover(lying)
    assert len(planes) >= 24
    assert all(p.normal[1] > 0.99 and p.offset == pytest.approx(0.002, abs=1e-5) for p in planes)


# ---- solve_planes and clip_vector, on planes worked out by hand --------------------------


def test_solve_planes_on_a_floor_keeps_the_level_part():
    # A floor 0.1 below: (1, -0.3) keeps its level part and goes down 0.1; the floor pushes 0.2.
    r = impulse2d.solve_planes((1.0, -0.3), [impulse2d.CollisionPlane((0.0, 1.0), 0.1)])
    assert isinstance(r, impulse2d.PlaneResult)
    assert r.translation == pytest.approx((1.0, -0.1), abs=1e-6)
    assert r.pushes == pytest.approx((0.2,), abs=1e-6)
    assert r.iteration_count == 2


def test_solve_planes_in_a_corner_and_a_valley():
    # Floor touched, wall 5 cm to the right: (0.3, -0.2) ends at (0.05, 0).
    r = impulse2d.solve_planes((0.3, -0.2), [((0.0, 1.0), 0.0), ((-1.0, 0.0), 0.05)])
    assert r.translation == pytest.approx((0.05, 0.0), abs=1e-6)
    assert r.pushes == pytest.approx((0.2, 0.25), abs=1e-6)
    # A V of normals (-0.6, 0.8) and (0.6, 0.8): straight down stops at its bottom, each
    # side pushing p with 2 (0.8 p) = 1.
    r = impulse2d.solve_planes((0.0, -1.0), [((-0.6, 0.8), 0.0), ((0.6, 0.8), 0.0)])
    assert r.translation == pytest.approx((0.0, 0.0), abs=1e-5)
    assert r.pushes == pytest.approx((0.625, 0.625), abs=1e-5)
    assert 2 < r.iteration_count <= 32


def test_solve_planes_soft_rigid_and_none():
    # A soft plane 0.5 into the mover that may push 0.2 pushes 0.2; a rigid one (push_limit
    # inf, passed to C as FLT_MAX) all 0.5.
    soft = impulse2d.solve_planes((0.0, 0.0), [impulse2d.CollisionPlane((0.0, 1.0), -0.5, push_limit=0.2)])
    assert soft.translation == pytest.approx((0.0, 0.2), abs=1e-6) and soft.pushes == pytest.approx((0.2,))
    rigid = impulse2d.solve_planes((0.0, 0.0), [((0.0, 1.0), -0.5)])
    assert rigid.translation == pytest.approx((0.0, 0.5), abs=1e-6)
    none = impulse2d.solve_planes((0.25, -2.0), [])
    assert none == ((0.25, -2.0), 0, ())


def test_clip_vector_removes_what_runs_into_the_planes():
    floor = ((0.0, 1.0), 0.0)
    assert impulse2d.clip_vector((3.0, -4.0), [floor]) == (3.0, 0.0)
    assert impulse2d.clip_vector((3.0, 4.0), [floor]) == (3.0, 4.0)  # leaving: unchanged
    assert impulse2d.clip_vector((3.0, -4.0), [floor, ((-1.0, 0.0), 0.0)]) == (0.0, 0.0)  # a corner
    ignored = impulse2d.CollisionPlane((0.0, 1.0), 0.0, clip_velocity=False)
    assert impulse2d.clip_vector((3.0, -4.0), [ignored]) == (3.0, -4.0)
    s = math.sqrt(0.5)
    assert impulse2d.clip_vector((4.0, 0.0), [((-s, s), 0.0)]) == pytest.approx((2.0, 2.0), abs=1e-6)
    # A floor and a steep face: the nearest vector running into neither is zero.
    assert impulse2d.clip_vector((1.0, -1.0), [floor, ((-0.8, 0.6), 0.0)]) == (0.0, 0.0)


@pytest.mark.parametrize(
    "call",
    [impulse2d.solve_planes, impulse2d.clip_vector],
)
def test_plane_calls_refuse_bad_planes_with_the_librarys_message(call):
    name = "i2d_" + call.__name__
    first = "target_delta" if call is impulse2d.solve_planes else "vector"
    cases = [
        (((0.0, 0.0), [((2.0, 0.0), 0.0)]), "planes[0] normal (2, 0) is not unit length"),
        (((math.nan, 0.0), [((0.0, 1.0), 0.0)]), first + ".x is NaN"),
        (((0.0, 0.0), [((0.0, 1.0), 0.0), ((0.0, 1.0), 0.0, -1.0)]), "planes[1].push_limit is -1"),
        (((0.0, 0.0), [((0.0, 1.0), math.inf)]), "planes[0].plane.offset is +inf"),
    ]
    for args, message in cases:
        with pytest.raises(impulse2d.InvalidArgument) as caught:
            call(*args)
        assert str(caught.value).startswith(name + ": " + message)
