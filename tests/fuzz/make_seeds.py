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


def pile():
    p = world_create() + body_create(0, 0, -1) + box(0, 1.9, 0.25)
    for i in range(4):
        p += body_create(2, -1 + 0.6 * i, 0.5 * i)
        p += [box, circle, capsule, box][i](i + 1, 0.25)
    return p


seeds = {
    "pile_steps": pile() + step(30),
    "pile_queries": pile() + step(10) + overlap_query() + ray_query() + step(5),
    "pile_destroy": pile() + step(5) + [7, 2] + step(5) + [1 + 6 * 1, 3] + step(5),
    "pure_calls": [5 + 6 * k for k in range(20)] * 2,
}
here = os.path.dirname(os.path.abspath(__file__))
for name, program in seeds.items():
    with open(os.path.join(here, "corpus", name), "wb") as f:
        f.write(bytes(program))
