# SPDX-License-Identifier: MIT
"""The game toolkit from Python: contact hooks (a one-way platform, ghosts) and explosions,
as tests/physics/test_contact_hooks.cpp and test_explosion.cpp check them in C. Each hook
scene also runs without its hook, as the control that must fail the same check."""

import gc
import math
import threading
import time

import pytest

import impulse2d
from conftest import make_ground

STEP = 1 / 60

# The one-way platform: a thin static box whose top is at 3 m; a crate of half size 0.25.
PLATFORM_TOP = 3.0
PLATFORM_HALF_HEIGHT = 0.1
CRATE_HALF = 0.25
REST_HEIGHT = PLATFORM_TOP + CRATE_HALF
REST_TOLERANCE = 0.01  # m, the contact slop's order


def steps(world, seconds):
    for _ in range(round(seconds / STEP)):
        world.step(STEP, 4)


def one_way_platform(world, **opt_in):
    """The platform on a ground; opt_in are its shape settings (the hook's opt-in)."""
    make_ground(world)
    body = world.create_body(impulse2d.STATIC, position=(0.0, PLATFORM_TOP - PLATFORM_HALF_HEIGHT))
    return body.create_box(2.0, PLATFORM_HALF_HEIGHT, **opt_in)


def lands_from_above(platform):
    """The pre-solve hook of a one-way platform: the contact acts only when it pushes the
    other shape up (the normal points from shape A to shape B)."""

    def hook(shape_a, shape_b, manifold):
        sign = 1.0 if shape_a == platform else -1.0 if shape_b == platform else 0.0
        return sign * manifold.normal[1] > 0.95

    return hook


def jump(world, speed=9.0, seconds=3.0):
    """A crate launched up from the ground at speed (9 m/s rises 4.05 m: past the platform);
    returns it and the highest its centre rose."""
    crate = world.create_body(position=(0.0, CRATE_HALF), linear_velocity=(0.0, speed))
    crate.create_box(CRATE_HALF, CRATE_HALF)
    highest = -math.inf
    for _ in range(round(seconds / STEP)):
        world.step(STEP, 4)
        highest = max(highest, crate.position[1])
    return crate, highest


def test_one_way_platform_lets_a_crate_up_through_and_holds_it_on_top(world):
    platform = one_way_platform(world, enable_pre_solve_events=True)
    assert platform.pre_solve_events_enabled
    asked = []
    landing = lands_from_above(platform)

    def hook(shape_a, shape_b, manifold):
        asked.append((shape_a, shape_b, manifold))
        return landing(shape_a, shape_b, manifold)

    world.set_pre_solve(hook)
    crate, highest = jump(world)
    assert highest > REST_HEIGHT + 0.5
    assert crate.position[1] == pytest.approx(REST_HEIGHT, abs=REST_TOLERANCE)
    assert math.hypot(*crate.linear_velocity) < 0.01
    # The hook saw the package's objects: Shapes of this world and a Manifold.
    shape_a, shape_b, manifold = asked[-1]
    assert {shape_a, shape_b} == {platform, crate.shapes[0]}
    assert isinstance(manifold, impulse2d.Manifold) and 1 <= len(manifold.points) <= 2
    assert isinstance(manifold.points[0], impulse2d.ManifoldPoint)
    assert math.hypot(*manifold.normal) == pytest.approx(1.0, abs=1e-5)


def test_without_the_hook_the_crate_is_stopped_beneath_the_platform(world):
    one_way_platform(world, enable_pre_solve_events=True)
    _crate, highest = jump(world)
    assert highest < PLATFORM_TOP - 2 * PLATFORM_HALF_HEIGHT


def test_the_pre_solve_opt_in_changes_after_creation_and_clearing_the_hook_stops_it(world):
    platform = one_way_platform(world)  # not opted in: the hook is never asked
    assert platform.pre_solve_events_enabled is False
    asked = []
    world.set_pre_solve(lambda a, b, m: asked.append(1) or lands_from_above(platform)(a, b, m))
    _crate, highest = jump(world, seconds=1.5)
    assert asked == [] and highest < PLATFORM_TOP
    platform.pre_solve_events_enabled = True
    assert platform.pre_solve_events_enabled is True
    with impulse2d.World() as other:  # the same jump in a world where it was on from the start
        other_platform = one_way_platform(other)
        other_platform.pre_solve_events_enabled = True
        other.set_pre_solve(lands_from_above(other_platform))
        crate, _highest = jump(other)
        assert crate.position[1] == pytest.approx(REST_HEIGHT, abs=REST_TOLERANCE)
    # Cleared: the opted-in platform holds the crate from below again.
    world.set_pre_solve(None)
    del asked[:]
    _crate, highest = jump(world, seconds=1.5)
    assert asked == [] and highest < PLATFORM_TOP


# Ghosts: shapes in groups; two different groups pass through each other, a group meets
# itself and everything in no group (the ground). The hook may not call the world, so the
# groups are a table of its own.


def drop_ghosts(world, with_filter):
    """A crate of group 1 dropped on one of group 2, and one of group 1 on one of group 1;
    their heights after 3 s."""
    make_ground(world)
    group_of = {}

    def tagged(x, y, group):
        body = world.create_body(position=(x, y))
        group_of[body.create_box(0.5, 0.5, enable_custom_filtering=True)] = group
        return body

    def same_group(shape_a, shape_b):
        ga, gb = group_of.get(shape_a, 0), group_of.get(shape_b, 0)
        return ga == 0 or gb == 0 or ga == gb

    if with_filter:
        world.set_custom_filter(same_group)
    tagged(-3.0, 0.5, 2)
    fallen = tagged(-3.0, 3.0, 1)
    tagged(3.0, 0.5, 1)
    stacked = tagged(3.0, 3.0, 1)
    steps(world, 3.0)
    return fallen.position[1], stacked.position[1]


def test_custom_filter_lets_two_groups_pass_through_each_other(world):
    fallen, stacked = drop_ghosts(world, with_filter=True)
    assert fallen == pytest.approx(0.5, abs=REST_TOLERANCE)  # through the other group, on the ground
    assert stacked == pytest.approx(1.5, abs=REST_TOLERANCE)  # on its own group's crate


def test_without_the_filter_the_ghosts_stack(world):
    fallen, stacked = drop_ghosts(world, with_filter=False)
    assert fallen == pytest.approx(1.5, abs=REST_TOLERANCE)
    assert stacked == pytest.approx(1.5, abs=REST_TOLERANCE)


def ghost_pile(workers):
    """100 touching crates in two ghost groups (odd and even), stepped 1 s with both hooks
    set: the state hash, and the threads the hooks ran on."""
    threads = set()
    with impulse2d.World(worker_count=workers) as world:
        make_ground(world)
        odd = set()
        for i in range(100):
            body = world.create_body(position=(-10.0 + (i % 20), 0.5 + (i // 20)))
            shape = body.create_box(0.5, 0.5, enable_custom_filtering=True, enable_pre_solve_events=True)
            if i % 2:
                odd.add(shape)

        def same_group(shape_a, shape_b, _manifold=None):
            threads.add(threading.get_ident())
            if workers > 1 and len(threads) == 1:
                # Holds its thread (without the GIL) a moment, so that the step's other
                # threads take part of the work even when the machine is slow to wake them.
                time.sleep(0.0002)
            return (shape_a in odd) == (shape_b in odd)

        world.set_custom_filter(same_group)
        world.set_pre_solve(same_group)
        steps(world, 1.0)
        return world.state_hash, threads


def test_hooks_called_from_worker_threads_give_the_same_bits_as_one_thread():
    # With 4 workers the library finds this many new pairs on several threads at once, and
    # ctypes takes the GIL for each call; the answers depend only on the arguments, so the
    # bits must be those of one thread. Which threads get work is the scheduler's choice
    # (the hook waits a little while it has seen one thread only, to let the others in),
    # so a few tries make sure the hooks ran on more than one.
    reference, threads = ghost_pile(1)
    assert len(threads) == 1
    for _attempt in range(5):
        digest, threads = ghost_pile(4)
        assert digest == reference
        if len(threads) > 1:
            break
    assert len(threads) > 1


def test_an_exception_in_a_hook_is_raised_by_step_and_the_pair_gets_true(world):
    make_ground(world)
    crate = world.create_body(position=(0.0, 0.5), enable_sleep=False)  # touching: asked every step
    crate.create_box(0.5, 0.5, enable_pre_solve_events=True)
    falling = world.create_body(position=(10.0, 20.0))  # shows that each step was done
    falling.create_circle(0.5)

    class Boom(Exception):
        pass

    def hook(shape_a, shape_b, manifold):
        raise Boom("from the hook")

    world.set_pre_solve(hook)
    for _ in range(60):
        height = falling.position[1]
        with pytest.raises(Boom, match="from the hook"):
            world.step(STEP, 4)
        assert falling.position[1] < height
    # True for every pair meanwhile: the crate rests on the ground.
    assert crate.position[1] == pytest.approx(0.5, abs=REST_TOLERANCE)
    world.set_pre_solve(None)
    world.step(STEP, 4)  # nothing left over to raise


def test_a_hook_answering_false_drops_the_crate_through_the_ground(world):
    # The control of the test above: the same hook answering False is what the crate
    # would do had the exception turned the pair off.
    make_ground(world)
    crate = world.create_body(position=(0.0, 0.5))
    crate.create_box(0.5, 0.5, enable_pre_solve_events=True)
    world.set_pre_solve(lambda a, b, m: False)
    steps(world, 1.0)
    assert crate.position[1] < -1.0


def test_a_hook_calling_its_world_gets_world_locked(world):
    platform = one_way_platform(world, enable_pre_solve_events=True)
    seen = []

    def hook(shape_a, shape_b, manifold):
        if not seen:
            calls = (lambda: world.step(), lambda: shape_b.aabb, lambda: world.explode((0, 0)),
                     lambda: world.set_pre_solve(None))
            for call in calls:
                try:
                    call()
                    seen.append(None)
                except impulse2d.WorldLocked as error:
                    seen.append(error)
        return lands_from_above(platform)(shape_a, shape_b, manifold)

    world.set_pre_solve(hook)
    crate, _highest = jump(world)
    assert len(seen) == 4 and all(isinstance(e, impulse2d.WorldLocked) for e in seen), seen
    assert str(seen[0]).startswith("i2d_world_step: called from inside the world's step")
    # Refused inside (the hook stayed set), the step went on as ever: the crate is on the
    # platform.
    assert crate.position[1] == pytest.approx(REST_HEIGHT, abs=REST_TOLERANCE)


def test_a_hook_that_lets_world_locked_escape_has_it_raised_by_step(world):
    make_ground(world)
    world.create_body(position=(0.0, 0.5)).create_box(0.5, 0.5, enable_custom_filtering=True)
    world.set_custom_filter(lambda a, b: world.step())
    with pytest.raises(impulse2d.WorldLocked):
        world.step()
    world.set_custom_filter(None)
    world.step()  # nothing left to raise


def test_hook_setters_refuse_what_is_not_callable_and_a_destroyed_world(world):
    with pytest.raises(TypeError, match="callable"):
        world.set_pre_solve(42)
    with pytest.raises(TypeError, match="callable"):
        world.set_custom_filter("yes")
    shape = world.create_body().create_circle(1.0)
    world.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        world.set_pre_solve(lambda a, b, m: True)
    with pytest.raises(impulse2d.InvalidHandle):
        world.set_custom_filter(None)
    with pytest.raises(impulse2d.InvalidHandle):
        shape.pre_solve_events_enabled = True
    with pytest.raises(impulse2d.InvalidHandle):
        shape.pre_solve_events_enabled


# ---- Explosions: a disc of radius r and mass m whose closest point is within the radius
# leaves at impulse_per_length * 2r / m, straight away from the blast; the speed falls
# linearly to 0 over the falloff.

DISC_RADIUS = 0.25


def disc_at(world, gap, angle):
    """A disc whose closest point is gap from the origin, in direction angle."""
    d = gap + DISC_RADIUS
    body = world.create_body(position=(d * math.cos(angle), d * math.sin(angle)))
    body.create_circle(DISC_RADIUS)
    return body


def full_speed(impulse_per_length, body):
    return impulse_per_length * 2 * DISC_RADIUS / body.mass


def test_explosion_gives_discs_the_closed_form_speed_away_from_the_blast():
    with impulse2d.World(gravity=(0, 0)) as world:
        discs = [disc_at(world, 1.5, 2 * math.pi * k / 8) for k in range(8)]
        world.explode((0.0, 0.0), radius=2.0, impulse_per_length=3.0)
        for disc in discs:
            (vx, vy), (px, py) = disc.linear_velocity, disc.position
            assert math.hypot(vx, vy) == pytest.approx(full_speed(3.0, disc), rel=1e-5)
            assert vx * px + vy * py > 0  # away from the blast
            assert abs(vx * py - vy * px) < 1e-5 * math.hypot(vx, vy) * math.hypot(px, py)  # along the line


def test_explosion_fades_over_the_falloff_and_stops_beyond_it():
    with impulse2d.World(gravity=(0, 0)) as world:
        inside = disc_at(world, 0.5, 0.0)
        halfway = disc_at(world, 2.0, math.pi / 2)  # radius + falloff / 2
        beyond = disc_at(world, 3.2, math.pi)  # past radius + falloff
        world.explode((0.0, 0.0), radius=1.0, falloff=2.0)
        assert math.hypot(*inside.linear_velocity) == pytest.approx(full_speed(1.0, inside), rel=1e-5)
        assert math.hypot(*halfway.linear_velocity) == pytest.approx(0.5 * full_speed(1.0, halfway), rel=1e-5)
        assert beyond.linear_velocity == (0.0, 0.0)


def test_explosion_defaults_mask_and_pull():
    with impulse2d.World(gravity=(0, 0)) as world:
        pushed = disc_at(world, 0.5, 0.0)
        masked = world.create_body(position=(-0.75, 0.0))
        masked.create_circle(DISC_RADIUS, filter=(2, 0xFFFF))
        world.explode((0.0, 0.0), mask_bits=1)  # radius 1, impulse 1 per length
        assert math.hypot(*pushed.linear_velocity) == pytest.approx(full_speed(1.0, pushed), rel=1e-5)
        assert masked.linear_velocity == (0.0, 0.0)
        world.explode((0.0, 0.0), mask_bits=2, impulse_per_length=-1.0)
        assert masked.linear_velocity[0] > 0  # pulled toward the blast at x = 0


def test_explosion_refuses_bad_values_and_changes_nothing():
    with impulse2d.World(gravity=(0, 0)) as world:
        disc = disc_at(world, 0.5, 0.0)
        bad = [
            (dict(position=(math.nan, 0.0)), "position.x is NaN"),
            (dict(position=(0.0, math.inf)), "position.y"),
            (dict(position=(0.0, 0.0), radius=-1.0), "radius"),
            (dict(position=(0.0, 0.0), falloff=math.nan), "falloff"),
            (dict(position=(0.0, 0.0), impulse_per_length=math.inf), "impulse_per_length"),
        ]
        for kwargs, message in bad:
            with pytest.raises(impulse2d.InvalidArgument, match="i2d_world_explode: " + message):
                world.explode(**kwargs)
        assert disc.linear_velocity == (0.0, 0.0)
        world.destroy()
        with pytest.raises(impulse2d.InvalidHandle):
            world.explode((0.0, 0.0))


def test_a_dropped_world_with_hooks_is_destroyed_at_once():
    # The hooks keep no reference cycle through their World: dropping it destroys the C
    # world there and then, as for a World without hooks (the library no longer calls them).
    from impulse2d import _native

    world = impulse2d.World()
    world.set_custom_filter(lambda a, b: True)
    world.set_pre_solve(lambda a, b, m: True)
    world_id = world.id
    gc.disable()
    try:
        del world
        assert not _native.lib.i2d_world_is_valid(world_id)
    finally:
        gc.enable()


def test_restoring_in_place_keeps_the_hooks_and_a_copy_has_none(world):
    make_ground(world)
    crate = world.create_body(position=(0.0, 0.5), enable_sleep=False)
    shape = crate.create_box(0.5, 0.5, enable_pre_solve_events=True)
    asked = []
    world.set_pre_solve(lambda a, b, m: asked.append(a) is None)
    data = world.save_snapshot()
    world.restore_snapshot(data)
    world.step()
    assert len(asked) == 1
    with impulse2d.World.from_snapshot(data) as copy:
        assert copy.shape(shape).pre_solve_events_enabled  # the opt-in travels
        copy.step()
        assert len(asked) == 1  # the hook does not
