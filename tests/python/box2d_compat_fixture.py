# SPDX-License-Identifier: MIT
"""Shared by the test_box2d_compat_*.py files: puts bindings/box2d-compat on sys.path
(and bindings/python, which conftest.py also adds) and holds the small helpers they share."""

import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))
for _part in ("python", "box2d-compat"):  # the impulse2d package too, for scripts run outside pytest
    _path = os.path.normpath(os.path.join(_HERE, "..", "..", "bindings", _part))
    if _path not in sys.path:
        sys.path.insert(0, _path)

import Box2D  # noqa: E402
from Box2D import b2  # noqa: E402

FPS = 60.0


def step(world, seconds, fps=FPS):
    """Steps world for seconds at fps, as the environments do (their iteration counts)."""
    for _ in range(int(round(seconds * fps))):
        world.Step(1.0 / fps, 6 * 30, 2 * 30)


def ground(world, half_width=50.0, y=0.0, **fixture):
    """A static edge from -half_width to half_width at height y."""
    body = world.CreateStaticBody()
    body.CreateEdgeFixture(vertices=[(-half_width, y), (half_width, y)], **fixture)
    return body


class Recorder(b2.contactListener):
    """A listener that records ('begin' | 'end', body userData A, body userData B,
    sensor) per call, the pair ordered by name so that tests need not know A from B."""

    def __init__(self):
        b2.contactListener.__init__(self)
        self.calls = []

    def _record(self, kind, contact):
        names = sorted(str(f.body.userData) for f in (contact.fixtureA, contact.fixtureB))
        self.calls.append((kind, names[0], names[1], contact.fixtureA.sensor or contact.fixtureB.sensor))

    def BeginContact(self, contact):
        self._record("begin", contact)

    def EndContact(self, contact):
        self._record("end", contact)
