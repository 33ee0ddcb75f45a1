# SPDX-License-Identifier: MIT
"""b2Fixture: a shape attached to a body, over one impulse2d shape id."""

import impulse2d

from ._native import check, check_last, lib, structs
from ._shapes import b2Filter, b2FixtureDef, shape_def


class b2Fixture(object):
    """Keeps the shape description it was made from (its vertices are what a renderer
    reads every frame, so they are never fetched from C), the def's values (to make the
    shape again as a sensor) and the Python userData."""

    def __init__(self, body, fd):
        if fd.shape is None:
            raise impulse2d.InvalidArgument("fixtureDef has no shape")
        self._body = body
        self._shape = fd.shape.__copy__()
        f = fd.filter
        self._filter = (f.categoryBits, f.maskBits, f.groupIndex)
        self._density, self._friction, self._restitution = fd.density, fd.friction, fd.restitution
        self.userData = fd.userData
        self._sensor = bool(fd.isSensor)
        self._filter_view = None
        self._id = self._make(self._sensor)

    def _make(self, is_sensor):
        d = shape_def(self._density, self._friction, self._restitution, is_sensor, self._filter)
        shape_id = self._shape._create(self._body._id, d)
        if not shape_id:
            check_last()
        self._sensor = is_sensor
        world = self._body._world
        world._fixtures[shape_id] = self
        world._sensor_count += is_sensor
        return shape_id

    def _forget(self):
        """Drops the world's entries for the shape (destroyed, or about to be)."""
        world = self._body._world
        del world._fixtures[self._id]
        world._sensor_count -= self._sensor

    @property
    def body(self):
        return self._body

    @property
    def shape(self):
        return self._shape

    @property
    def type(self):
        return self._shape.type

    @property
    def sensor(self):
        return self._sensor

    @sensor.setter
    def sensor(self, value):
        # impulse2d fixes a shape's sensor flag at creation: the shape is made again,
        # behind this same fixture object, with the flag changed.
        value = bool(value)
        if value == self._sensor:
            return
        world = self._body._world
        world._fixture_ending(self)
        check(lib.i2d_shape_destroy(self._id))
        self._forget()
        self._id = self._make(value)

    isSensor = sensor

    @property
    def density(self):
        return self._density

    @density.setter
    def density(self, value):
        check(lib.i2d_shape_set_density(self._id, value, True))
        self._density = value

    @property
    def friction(self):
        return lib.i2d_shape_get_friction(self._id) if self._check() else 0.0

    @friction.setter
    def friction(self, value):
        check(lib.i2d_shape_set_friction(self._id, value))
        self._friction = value

    @property
    def restitution(self):
        return lib.i2d_shape_get_restitution(self._id) if self._check() else 0.0

    @restitution.setter
    def restitution(self, value):
        check(lib.i2d_shape_set_restitution(self._id, value))
        self._restitution = value

    @property
    def filterData(self):
        """The fixture's filter as one object kept by the fixture (a lidar callback reads
        it per hit): changing a field of it refilters the fixture at once."""
        view = self._filter_view
        if view is None:
            view = self._filter_view = _FilterView(self)
        return view

    @filterData.setter
    def filterData(self, value):
        bits = (value.categoryBits, value.maskBits, value.groupIndex)
        f = structs.Filter(category_bits=bits[0], mask_bits=bits[1], group_index=bits[2])
        check(lib.i2d_shape_set_filter(self._id, f))
        self._filter = bits

    def _check(self):
        if not lib.i2d_shape_is_valid(self._id):
            raise impulse2d.InvalidHandle("fixture's shape 0x%016x was destroyed" % self._id)
        return True

    def _handle(self):
        return impulse2d.Shape(self._body._world._w, self._id)

    def TestPoint(self, point):
        """Whether the world point lies in the fixture (its outline included)."""
        x, y = point
        cx, cy = self._handle().closest_point((x, y))
        return abs(cx - x) < 1e-6 and abs(cy - y) < 1e-6

    @property
    def aabb(self):
        from ._world import b2AABB

        lo, hi = self._handle().aabb
        return b2AABB(lowerBound=lo, upperBound=hi)

    def GetAABB(self, childIndex=0):
        return self.aabb

    def __repr__(self):
        return "b2Fixture(shape=%r, sensor=%s)" % (self._shape, self._sensor)


class _FilterView(b2Filter):
    """b2Filter whose fields are its fixture's: reading costs no allocation, writing
    sets the fixture's filter (pybox2d hands out a copy, which a write leaves alone)."""

    __slots__ = ("_fixture",)

    def __init__(self, fixture):
        object.__setattr__(self, "_fixture", fixture)

    categoryBits = property(lambda self: self._fixture._filter[0], lambda self, v: self._set(0, v))
    maskBits = property(lambda self: self._fixture._filter[1], lambda self, v: self._set(1, v))
    groupIndex = property(lambda self: self._fixture._filter[2], lambda self, v: self._set(2, v))

    def _set(self, index, value):
        bits = list(self._fixture._filter)
        bits[index] = value
        self._fixture.filterData = b2Filter(*bits)


def fixture_def_from(kwargs, shape_cls=None):
    """A b2FixtureDef from CreateFixture-style keywords: the def's own fields, and for
    Create*Fixture the shape's (radius=, pos=, vertices=, box=)."""
    fd = b2FixtureDef()
    shape_kwargs = {}
    for key, value in kwargs.items():
        if key in ("shape", "density", "friction", "restitution", "isSensor", "userData",
                   "categoryBits", "maskBits", "groupIndex", "filter"):
            setattr(fd, key, value)
        elif shape_cls is not None:
            shape_kwargs[key] = value
        else:
            raise AttributeError('Invalid keyword argument "%s" for CreateFixture' % key)
    if shape_cls is not None:
        fd.shape = shape_cls(**shape_kwargs)
    return fd
