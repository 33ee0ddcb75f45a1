#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the fuzzer's seed corpus: small call programs in fuzz_api.cpp's encoding that
build scenes worth mutating (a pile on a floor, queries with callbacks, pure functions).
Run from this directory after changing the encoding: python3 make_seeds.py
The corpus also holds the inputs of past findings (finding_*), kept as regressions."""
import os


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
}
here = os.path.dirname(os.path.abspath(__file__))
for name, program in seeds.items():
    with open(os.path.join(here, "corpus", name), "wb") as f:
        f.write(bytes(program))
