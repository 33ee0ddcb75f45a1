# SPDX-License-Identifier: MIT
"""Shape descriptions (polygonShape, circleShape, edgeShape), fixtureDef and b2Filter.

A shape here is a plain description in the body frame, as Box2D's b2Shape is before it
is attached: fixtureDefs and their shapes are reused across bodies and edited between
uses, and each fixture keeps a copy of the shape it was made from."""

import math

from impulse2d.errors import InvalidArgument

from ._native import C, check, lib, structs
from ._vec import b2Vec2, as_pair

Vec2 = structs.Vec2


class b2Shape(object):
    e_circle, e_edge, e_polygon, e_chain, e_typeCount = 0, 1, 2, 3, 4

    def __init__(self, **kwargs):
        for key, value in kwargs.items():
            if not hasattr(type(self), key):
                raise AttributeError('Invalid keyword argument "%s" for %s' % (key, type(self).__name__))
            setattr(self, key, value)

    def __copy__(self):
        # Shallow is enough: setters replace the vertex lists and arrays, never edit them.
        other = type(self).__new__(type(self))
        other.__dict__ = self.__dict__.copy()
        return other

    copy = __copy__


class b2CircleShape(b2Shape):
    """A disc of radius about pos (body frame)."""

    type = b2Shape.e_circle
    radius = 0.0

    def __init__(self, **kwargs):
        self._pos = (0.0, 0.0)
        b2Shape.__init__(self, **kwargs)

    @property
    def pos(self):
        return b2Vec2(*self._pos)

    @pos.setter
    def pos(self, value):
        self._pos = as_pair(value)

    p = pos

    @property
    def childCount(self):
        return 1

    def _create(self, body_id, shape_def):
        circle = structs.Circle(center=Vec2(*self._pos), radius=self.radius)
        return lib.i2d_shape_create_circle(body_id, C.byref(shape_def), C.byref(circle))

    def __repr__(self):
        return "b2CircleShape(radius=%g, pos=%r)" % (self.radius, self._pos)


class b2PolygonShape(b2Shape):
    """A convex polygon of 3 to 8 vertices (body frame). Setting vertices makes their
    convex hull with the library (i2d_make_polygon), so a bad polygon raises the
    library's InvalidArgument at once, as Box2D asserts in Set."""

    type = b2Shape.e_polygon
    radius = 0.0  # impulse2d polygons are sharp; Box2D's carry a 0.01 m skin

    def __init__(self, **kwargs):
        self._vertices = []
        self._points = None
        b2Shape.__init__(self, **kwargs)

    @property
    def vertices(self):
        """The hull's vertices, counter-clockwise, as (x, y) tuples."""
        return list(self._vertices)

    @vertices.setter
    def vertices(self, points):
        pts = [as_pair(p) for p in points]
        array = (Vec2 * max(len(pts), 1))(*[Vec2(x, y) for x, y in pts])
        polygon = structs.Polygon()
        check(lib.i2d_make_polygon(array, len(pts), 0.0, C.byref(polygon)))
        hull = [(polygon.vertices[i].x, polygon.vertices[i].y) for i in range(polygon.count)]
        self._vertices = hull
        self._points = (Vec2 * len(hull))(*[Vec2(x, y) for x, y in hull])

    @property
    def vertexCount(self):
        return len(self._vertices)

    def __len__(self):
        return len(self._vertices)

    def __getitem__(self, i):
        return self._vertices[i]

    @property
    def box(self):
        raise AttributeError("box is write-only (as in pybox2d)")

    @box.setter
    def box(self, value):
        self.SetAsBox(*value)

    def SetAsBox(self, hx, hy, center=None, angle=0.0):
        corners = [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]
        if center is not None or angle:
            cx, cy = as_pair(center) if center is not None else (0.0, 0.0)
            c, s = math.cos(angle), math.sin(angle)
            corners = [(c * x - s * y + cx, s * x + c * y + cy) for x, y in corners]
        self.vertices = corners

    @property
    def valid(self):
        return len(self._vertices) >= 3

    @property
    def centroid(self):
        return b2Vec2(*_centroid(self._vertices))

    @property
    def childCount(self):
        return 1

    def _create(self, body_id, shape_def):
        if self._points is None:
            raise InvalidArgument("polygonShape has no vertices: set vertices= or box= first")
        return lib.i2d_shape_create_polygon(body_id, C.byref(shape_def), self._points, len(self._vertices))

    def __repr__(self):
        return "b2PolygonShape(vertices=%r)" % (self._vertices,)


class b2EdgeShape(b2Shape):
    """A two-sided segment (body frame)."""

    type = b2Shape.e_edge
    radius = 0.0

    def __init__(self, **kwargs):
        self._v1 = self._v2 = None
        b2Shape.__init__(self, **kwargs)

    @property
    def vertices(self):
        return [self._v1, self._v2] if self._v1 is not None else []

    @vertices.setter
    def vertices(self, points):
        points = [as_pair(p) for p in points]
        if len(points) != 2:
            raise InvalidArgument("edgeShape takes exactly 2 vertices, not %d" % len(points))
        self._v1, self._v2 = points

    @property
    def vertex1(self):
        return b2Vec2(*self._v1)

    @vertex1.setter
    def vertex1(self, value):
        self._v1 = as_pair(value)

    @property
    def vertex2(self):
        return b2Vec2(*self._v2)

    @vertex2.setter
    def vertex2(self, value):
        self._v2 = as_pair(value)

    @property
    def vertexCount(self):
        return 2

    @property
    def childCount(self):
        return 1

    def _create(self, body_id, shape_def):
        if self._v1 is None:
            raise InvalidArgument("edgeShape has no vertices: set vertices= first")
        return lib.i2d_shape_create_segment(body_id, C.byref(shape_def), Vec2(*self._v1), Vec2(*self._v2))

    def __repr__(self):
        return "b2EdgeShape(vertices=%r)" % (self.vertices,)


def _centroid(vertices):
    ax = ay = area = 0.0
    x0, y0 = vertices[0]
    for (x1, y1), (x2, y2) in zip(vertices[1:], vertices[2:]):
        a = 0.5 * ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0))
        area += a
        ax += a * (x0 + x1 + x2) / 3.0
        ay += a * (y0 + y1 + y2) / 3.0
    return (ax / area, ay / area) if area else (x0, y0)


class b2Filter(object):
    """Collision filtering: categoryBits, maskBits (Box2D's 16 bits) and groupIndex."""

    __slots__ = ("categoryBits", "maskBits", "groupIndex")

    def __init__(self, categoryBits=0x0001, maskBits=0xFFFF, groupIndex=0):
        self.categoryBits, self.maskBits, self.groupIndex = categoryBits, maskBits, groupIndex

    def __repr__(self):
        return "b2Filter(categoryBits=0x%x, maskBits=0x%x, groupIndex=%d)" % (
            self.categoryBits, self.maskBits, self.groupIndex)


class b2FixtureDef(object):
    """What a fixture is made from, with Box2D 2.3's defaults (density 0, friction 0.2)."""

    def __init__(self, **kwargs):
        self.shape = None
        self.density = 0.0
        self.friction = 0.2
        self.restitution = 0.0
        self.isSensor = False
        self.userData = None
        self.filter = b2Filter()
        for key, value in kwargs.items():
            if key in ("categoryBits", "maskBits", "groupIndex"):
                setattr(self.filter, key, value)
            elif key in self.__dict__:
                setattr(self, key, value)
            else:
                raise AttributeError('Invalid keyword argument "%s" for b2FixtureDef' % key)

    # pybox2d reaches the filter's fields from the def itself.
    categoryBits = property(lambda s: s.filter.categoryBits, lambda s, v: setattr(s.filter, "categoryBits", v))
    maskBits = property(lambda s: s.filter.maskBits, lambda s, v: setattr(s.filter, "maskBits", v))
    groupIndex = property(lambda s: s.filter.groupIndex, lambda s, v: setattr(s.filter, "groupIndex", v))

    def __repr__(self):
        return "b2FixtureDef(shape=%r, density=%g)" % (self.shape, self.density)


_SHAPE_DEF = lib.i2d_default_shape_def()
_ShapeDef = type(_SHAPE_DEF)


def shape_def(density, friction, restitution, is_sensor, filter_bits):
    """A C shape def (a copy of the library's default, which is cheaper than asking for
    one). Contact events stay on (the default) for every shape: the listener may be set
    at any time."""
    d = _ShapeDef.from_buffer_copy(_SHAPE_DEF)
    d.density, d.friction, d.restitution, d.is_sensor = density, friction, restitution, is_sensor
    f = d.filter
    f.category_bits, f.mask_bits, f.group_index = filter_bits
    return d
