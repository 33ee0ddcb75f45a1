# SPDX-License-Identifier: MIT
"""The classes a program subclasses (contactListener, rayCastCallback, QueryCallback)
and what the world hands them (b2Contact)."""


class b2ContactListener(object):
    """Subclass and override BeginContact / EndContact (PreSolve and PostSolve are never
    called: impulse2d reports contacts after the step, not during it)."""

    def __init__(self, **kwargs):
        for key, value in kwargs.items():
            setattr(self, key, value)

    def BeginContact(self, contact):
        pass

    def EndContact(self, contact):
        pass

    def PreSolve(self, contact, oldManifold):
        pass

    def PostSolve(self, contact, impulse):
        pass


class b2RayCastCallback(object):
    """ReportFixture(fixture, point, normal, fraction) returns -1 to ignore the fixture,
    0 to stop, fraction to clip the ray there, 1 to go on."""

    def __init__(self, **kwargs):
        for key, value in kwargs.items():
            setattr(self, key, value)

    def ReportFixture(self, fixture, point, normal, fraction):
        return 1.0


class b2QueryCallback(object):
    """ReportFixture(fixture) returns False to stop the query."""

    def __init__(self, **kwargs):
        for key, value in kwargs.items():
            setattr(self, key, value)

    def ReportFixture(self, fixture):
        return True


class b2DestructionListener(object):
    def SayGoodbye(self, obj):
        pass


class b2ContactFilter(object):
    """Accepted for compatibility; impulse2d filters pairs by categoryBits, maskBits and
    groupIndex only, so ShouldCollide is never asked."""

    def ShouldCollide(self, fixtureA, fixtureB):
        return True


class b2Contact(object):
    """A touching pair (or a sensor and a shape inside it), as the listener gets it."""

    __slots__ = ("fixtureA", "fixtureB", "touching", "enabled")

    def __init__(self, fixtureA, fixtureB, touching=True):
        self.fixtureA, self.fixtureB = fixtureA, fixtureB
        self.touching = touching
        self.enabled = True

    @property
    def sensor(self):
        return self.fixtureA.sensor or self.fixtureB.sensor

    @property
    def childIndexA(self):
        return 0

    @property
    def childIndexB(self):
        return 0

    def __repr__(self):
        return "b2Contact(fixtureA=%r, fixtureB=%r, touching=%s)" % (self.fixtureA, self.fixtureB, self.touching)


class b2ContactEdge(object):
    __slots__ = ("contact", "other")

    def __init__(self, contact, other):
        self.contact, self.other = contact, other
