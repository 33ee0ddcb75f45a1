# SPDX-License-Identifier: MIT
"""Fixtures shared by the Python package tests.

CTest runs each file with IMPULSE2D_LIBRARY naming the freshly built library and
bindings/python on PYTHONPATH, so these tests exercise the source tree's package."""

import math
import os
import sys

import pytest

sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "bindings", "python")))

import impulse2d  # noqa: E402


@pytest.fixture
def world():
    with impulse2d.World() as w:
        yield w


def make_ground(world, half_width=50.0):
    """A static box whose top face is at y = 0."""
    ground = world.create_body(impulse2d.STATIC, position=(0.0, -1.0))
    ground.create_box(half_width, 1.0)
    return ground


def make_pile(world, count=20, seed=3):
    """count dynamic bodies (boxes and circles, some turned) above a ground, as a list."""
    make_ground(world)
    bodies = []
    for i in range(count):
        body = world.create_body(position=((i % 5) * 1.1 - 2.2, 0.6 + 1.1 * (i // 5)), angle=0.1 * ((i * seed) % 7))
        if i % 2:
            body.create_circle(0.45)
        else:
            body.create_box(0.45, 0.45)
        bodies.append(body)
    return bodies


def close(a, b, tol=1e-5):
    return all(math.isclose(x, y, abs_tol=tol) for x, y in zip(a, b))
