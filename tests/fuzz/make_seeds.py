#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the fuzzer's seed corpus: small call programs in fuzz_api.cpp's encoding that
build scenes worth mutating (a pile on a floor, queries with callbacks, pure functions).
Run from this directory after changing the encoding: python3 make_seeds.py
The corpus also holds the inputs of past findings (finding_*), kept as regressions; those
of issue 44 (far joint angles, a cast starting inside, a cast past 1e9 m) are written here."""
import os
import struct


def raw_real(v):
    """real() operand for any float: kind byte 160 and up, then its bits, big-endian."""
    return [160] + list(struct.pack(">f", v))


def special(index):
    """real() operand for FuzzInput::special's value at index (0.0 is 8, 1e-30 is 10,
    1e9 is 14)."""
    return [96 + index]


def small(v):
    """small_real()/real() operand for v in [-4, 1.9]: kind byte, fraction byte."""
    kind = int(round(v * 16)) + 64
    assert 0 <= kind < 96
    return [kind, 0]


def world_create():
    return [0, 0, 0, 0]  # op, no edits, def not null, table slot


def world_create_workers(workers, who):
    """One edit: the worker edit byte (248 and up), the count, who runs the tasks (0 at
    once, 1 at finish, 2 newest first, 3 intruding, 6 the built-in threads)."""
    return [0, 1, 248, workers - 1, who, 0, 0]


def body_create(body_type, x, y):
    return [1, 0, body_type] + small(x) + small(y) + [0, 0, 0]


def box(body, hw, hh=None):
    hh = hw if hh is None else hh
    return [9, body, 0, 0] + small(hw) + small(hh) + [0]


def circle(body, r):
    return [3, body, 0, 0] + small(0) + small(0) + small(r) + [0, 0]


def capsule(body, r):
    # op 5 = 3 + 6*5 ... sub 5: capsule or segment; flag byte odd = capsule
    return [33, body, 0, 0] + small(-0.5) + small(0) + small(0.5) + small(0) + [1] + small(r) + [0]


def step(count):
    return [12, 0, 0, 0] * count


def overlap_query():
    # group 4, sub 0: world, aabb (4 reals), query filter flag, callback not null
    return [4, 0] + small(-4) + small(-4) + small(1.5) + small(1.5) + [0, 0] + [5, 100] * 8


def ray_query():
    return [4 + 6 * 4, 0] + small(-4) + small(-4) + small(1.5) + small(1.5) + small(-3) + small(1) + small(1.9) + small(0) + [0, 0] + [7, 2] * 8


def pile(world=None):
    p = (world or world_create()) + body_create(0, 0, -1) + box(0, 1.9, 0.25)
    for i in range(4):
        p += body_create(2, -1 + 0.6 * i, 0.5 * i)
        p += [box, circle, capsule, box][i](i + 1, 0.25)
    return p


def joint_op(k):
    """Joint call k: the body group's second alias from sub 30 on (fuzz_api.cpp)."""
    return 2 + 6 * (30 + k)


def joint(kind, body_a, body_b, anchors=None):
    # op, world, kind (i2d_joint_type), bodies, edits, def not null, table slot
    if anchors is None:
        return [joint_op(0), 0, kind, body_a, body_b, 0, 0, 0]
    (ax, ay), (bx, by) = anchors
    return [joint_op(0), 0, kind, body_a, body_b, 1, 0] + small(ax) + small(ay) + small(bx) + small(by) + [0, 0]


def joints():
    # revolute to the floor, a distance rope, a weld and a wheel down the pile
    p = joint(5, 0, 1, ((-1, 0.5), (0, 0))) + joint(0, 1, 2) + joint(6, 2, 3) + joint(7, 3, 4)
    p += [joint_op(3), 0, 5] + small(1.5)   # revolute motor speed
    p += [joint_op(5), 0, 2, 1]              # revolute motor on
    p += [joint_op(3), 0, 6] + small(1.9)   # max motor torque
    return p


def joint_with_setting(kind, body_b, anchor_a, setting, value):
    """A joint from the static body 0 to body_b, anchored at anchor_a and at B's (-1, 0),
    with its def's float k_def_floats[setting] (../api/any_joint_def.h) set to value."""
    (ax, ay) = anchor_a
    return ([joint_op(0), 0, kind, 0, body_b, 2, 0] + small(ax) + small(ay) + small(-1) + small(0) +
            [4, setting] + raw_real(value) + [0, 0])


def float_setter(joint, setter, value):
    """joint_float_setters[setter] (fuzz_api.cpp) of the joint-th held joint."""
    return [joint_op(3), joint, setter] + raw_real(value)


def read_joints(count):
    return sum(([joint_op(11), k] for k in range(count)), [])


def far_joint_angles():
    """Issue 44, defect 1: joint angles turns from zero, which the solver wound back once
    only. Four bars held by their left ends to a static body: by def a revolute reference
    of 100 rad, a prismatic one of -7, a weld one of -1e4 and a motor offset of -100; by
    setter the revolute's target 1e4, its limit on, and the motor's offset 7 (setters 9
    and 29, flag setter 1). Read, stepped, read again: the harness checks every angle."""
    p = world_create() + body_create(0, 0, 0)
    for i, y in enumerate([-3, -1.5, 0, 1.5]):
        p += body_create(2, 1, y) + box(i + 1, 0.5, 0.125)
    p += joint_with_setting(5, 1, (0, -3), 0, 100.0)     # revolute reference_angle
    p += joint_with_setting(4, 2, (0, -1.5), 10, -7.0)   # prismatic reference_angle
    p += joint_with_setting(6, 3, (0, 0), 25, -1.0e4)    # weld reference_angle
    p += joint_with_setting(2, 4, (0, 1.5), 40, -100.0)  # motor angular_offset
    p += read_joints(4)
    p += [joint_op(5), 0, 1, 1]                          # revolute enable_limit
    p += float_setter(0, 9, 1.0e4)                       # revolute target_angle
    p += float_setter(3, 29, 7.0)                        # motor angular_offset
    return p + step(30) + read_joints(4)


def proxy_cast(points, radius, translation, hits):
    """Query 5: a proxy of the points (world space) and radius, cast by translation (real()
    operands) with i2d_world_cast_shape_closest and then i2d_world_cast_shape, whose
    callback, when the cast hits, sets user data and goes on."""
    p = [4 + 6 * 5, 0] + small(0) * 4                  # world, an unused box
    for i in range(9):
        x, y = points[i] if i < len(points) else (0, 0)
        p += [1] + small(x) + small(y)                  # small points
    p += [1, len(points), 0] + small(radius) + [0]      # count, not NULL, radius, not hand-made
    p += [1] + translation + [0]                        # cast_shape_closest, default filter
    return p + translation + [0, 0] + ([5, 3] if hits else [])  # cast_shape, callback


def cast_starting_inside():
    """Issue 44, defect 2: a disc proxy inside a box, cast by (1e-30, 0): the hit at
    fraction 0 had the normal (0, 0)."""
    box_world = world_create() + body_create(0, 0, 0) + box(0, 1.5, 1)
    return box_world + proxy_cast([(0.5, 0.25)], 0.25, special(10) + special(8), True)


def cast_past_the_bound():
    """Issue 44, defect 3: a shape cast and a ray cast by (1e9, 1e9), 1.41e9 m long, were
    accepted (each component was bounded by 1e9 m, not the length)."""
    p = world_create() + body_create(0, 0, 0) + box(0, 1.5, 1)
    p += proxy_cast([(0.5, 1.5)], 0.25, special(14) * 2, False)
    # query 3: i2d_world_cast_ray_closest from (0, 1.5) by (1e9, 1e9), default filter
    return p + [4 + 6 * 3, 0] + small(0) * 4 + small(0) + small(1.5) + special(14) * 2 + [0]


def draw(variant, flags=None, culled_half=None):
    """Group 4, sub 24 + variant (fuzz_draw_calls.inl): i2d_world_draw of the first world with
    every callback set; variants 0 and 1 draw everything, 9 culls to a box of half size
    culled_half around the first body; others take two flag bytes and unused bounds. Then
    the callbacks' bytes: a few calls back in (a step, a destroy, a create, a body change, a
    getter, a query, a nested draw, a gravity change), the rest just check."""
    p = [4 + 6 * (24 + variant), 0, 0xFF, 0x01]
    if variant >= 2:
        p += [flags & 0xFF, flags >> 8]
    if variant == 9:
        p += [0] + small(culled_half)
    elif variant >= 2:
        p += [0] + small(-1) + small(-1) + small(1) + small(1)
    p += [0]  # the def initialised
    pokes = [200, 0, 200, 1, 200, 2, 200, 3, 0] + small(1) + small(0) + [200, 4, 200, 5] + small(-2) + small(-2)
    pokes += small(1.5) + small(1.5) + [200, 6, 0x0F, 0x00, 0, 0, 200, 7] + small(0) + small(1)
    return p + pokes


def mover_op(sub):
    """A mover call (fuzz_mover_calls.inl): group 4, subs 14 to 23; sub % 6 picks the call."""
    return 4 + 6 * sub


def mover_capsule():
    # flag (small values), centres (0, 0.3) and (0, 1.5), radius 0.3
    return [1] + small(0) + small(0.3) + small(0) + small(1.5) + small(0.3)


def mover_plane(angle, offset):
    # a unit normal at angle, offset, rigid (FLT_MAX), push left 0, clipping
    return [0] + small(angle) + small(offset) + [1] + small(0) + [1]


def mover_calls():
    """A character walked at 4 m/s from the floor's left end into the pile (pushing it),
    with a cast, a collide, the plane calls on a floor and a wall, and a pushing move
    tried inside a query callback."""
    p = [mover_op(18), 0] + mover_capsule() + [1] + small(1) + small(0) + [0, 0]      # cast
    p += [mover_op(19), 0] + mover_capsule() + [1, 4, 0, 0]                          # collide
    planes = [3, 2] + mover_plane(1.5708, 0) + mover_plane(3.1416 - 4, 0.05)
    p += [mover_op(20), 0] + planes + [1] + small(0.3) + small(-0.2)                  # solve
    p += [mover_op(21), 0] + planes + [1] + small(1.5) + small(-1.5)                  # clip
    for _ in range(20):                                                             # moves
        p += [mover_op(23), 0, 0, 0] + mover_capsule() + [1] + small(-1.8) + small(-0.73)
        p += [1] + small(0.5) + small(0) + [1, 0, 0, 0]
    p += [mover_op(22), 0] + small(-2) + small(-1) + small(1) + small(1.5)          # in a query
    p += [0] + small(-1.8) + small(-0.73) + small(0.5) + small(0) + [200]           # pushing; stop
    return p


seeds = {
    "pile_steps": pile() + step(30),
    "pile_queries": pile() + step(10) + overlap_query() + ray_query() + step(5),
    "pile_destroy": pile() + step(5) + [7, 2] + step(5) + [1 + 6 * 1, 3] + step(5),
    "pile_joints": pile() + joints() + step(20) + [joint_op(10), 0, 0] + [joint_op(11), 0] + [joint_op(2), 1] + step(10),
    "pure_calls": [5 + 6 * k for k in range(20)] * 2,
    "pile_workers_inline": pile(world_create_workers(8, 0)) + step(10),
    "pile_workers_at_finish": pile(world_create_workers(3, 1)) + joints() + step(10),
    "pile_workers_newest_first": pile(world_create_workers(4, 2)) + step(10),
    "pile_workers_intruding": pile(world_create_workers(2, 3)) + step(10),
    "pile_workers_built_in": pile(world_create_workers(2, 6)) + step(10),
    "pile_draws": pile() + joints() + step(10) + draw(0),
    "pile_draw_culled": pile() + joints() + step(10) + draw(9, flags=0x07FF, culled_half=1.5),
    "finding_joint_far_angles": far_joint_angles(),
    "finding_cast_starting_inside": cast_starting_inside(),
    "finding_cast_past_the_bound": cast_past_the_bound(),
    "pile_mover": pile() + step(10) + mover_calls() + step(5),
}
here = os.path.dirname(os.path.abspath(__file__))
for name, program in seeds.items():
    with open(os.path.join(here, "corpus", name), "wb") as f:
        f.write(bytes(program))
