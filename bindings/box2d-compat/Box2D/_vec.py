# SPDX-License-Identifier: MIT
"""b2Vec2, b2Rot and b2Transform: plain Python values (no C calls)."""

import math


class b2Vec2(object):
    """A mutable 2D vector that is also a sequence of two floats, so that it goes
    wherever a tuple point does (pygame, NumPy, the impulse2d package)."""

    __slots__ = ("x", "y")

    def __init__(self, x=None, y=None):
        if x is None:
            x = y = 0.0
        elif y is None:
            if isinstance(x, (int, float)):
                raise TypeError("b2Vec2 takes two numbers or one pair, not %r" % (x,))
            x, y = x
        self.x = float(x)
        self.y = float(y)

    @classmethod
    def _raw(cls, x, y):
        """From two floats, unchecked: for the per-hit and per-step paths."""
        v = object.__new__(cls)
        v.x, v.y = x, y
        return v

    # ---- sequence protocol ---------------------------------------------------------
    def __len__(self):
        return 2

    def __getitem__(self, i):
        return (self.x, self.y)[i]

    def __setitem__(self, i, value):
        if i in (0, -2):
            self.x = float(value)
        elif i in (1, -1):
            self.y = float(value)
        else:
            raise IndexError("b2Vec2 index out of range")

    def __iter__(self):
        return iter((self.x, self.y))

    @property
    def tuple(self):
        return (self.x, self.y)

    def __repr__(self):
        return "b2Vec2(%g,%g)" % (self.x, self.y)

    def __eq__(self, other):
        try:
            ox, oy = other
        except (TypeError, ValueError):
            return NotImplemented
        return self.x == ox and self.y == oy

    def __ne__(self, other):
        result = self.__eq__(other)
        return result if result is NotImplemented else not result

    __hash__ = None  # mutable, as pybox2d's

    def copy(self):
        return b2Vec2(self.x, self.y)

    __copy__ = copy

    # ---- arithmetic ------------------------------------------------------------------
    def __add__(self, other):
        ox, oy = other
        return b2Vec2(self.x + ox, self.y + oy)

    __radd__ = __add__

    def __sub__(self, other):
        ox, oy = other
        return b2Vec2(self.x - ox, self.y - oy)

    def __rsub__(self, other):
        ox, oy = other
        return b2Vec2(ox - self.x, oy - self.y)

    def __mul__(self, a):
        return b2Vec2(self.x * a, self.y * a)

    __rmul__ = __mul__

    def __truediv__(self, a):
        return b2Vec2(self.x / a, self.y / a)

    __div__ = __truediv__

    def __neg__(self):
        return b2Vec2(-self.x, -self.y)

    def __pos__(self):
        return b2Vec2(self.x, self.y)

    def __abs__(self):
        return b2Vec2(abs(self.x), abs(self.y))

    def __iadd__(self, other):
        ox, oy = other
        self.x += ox
        self.y += oy
        return self

    def __isub__(self, other):
        ox, oy = other
        self.x -= ox
        self.y -= oy
        return self

    def __imul__(self, a):
        self.x *= a
        self.y *= a
        return self

    def __itruediv__(self, a):
        self.x /= a
        self.y /= a
        return self

    def __bool__(self):
        return self.x != 0.0 or self.y != 0.0

    # ---- Box2D's methods -------------------------------------------------------------
    @property
    def length(self):
        return math.hypot(self.x, self.y)

    @property
    def lengthSquared(self):
        return self.x * self.x + self.y * self.y

    def Normalize(self):
        """Makes the vector unit length and returns its old length (0 leaves it)."""
        n = math.hypot(self.x, self.y)
        if n < 1.1920929e-07:
            return 0.0
        self.x /= n
        self.y /= n
        return n

    def dot(self, other):
        ox, oy = other
        return self.x * ox + self.y * oy

    def cross(self, other):
        """With a vector: the scalar z of the 3D cross product; with a scalar s: the
        vector self x s (as Box2D's b2Cross(v, s))."""
        if isinstance(other, (int, float)):
            return b2Vec2(other * self.y, -other * self.x)
        ox, oy = other
        return self.x * oy - self.y * ox

    def skew(self):
        return b2Vec2(-self.y, self.x)

    def Set(self, x, y):
        self.x = float(x)
        self.y = float(y)

    def SetZero(self):
        self.x = self.y = 0.0

    def IsValid(self):
        return math.isfinite(self.x) and math.isfinite(self.y)

    @property
    def valid(self):
        return self.IsValid()


def as_pair(value):
    """(x, y) floats from a b2Vec2 or any pair."""
    x, y = value
    return (float(x), float(y))


class b2Rot(object):
    """A rotation as its sine and cosine."""

    __slots__ = ("s", "c")

    def __init__(self, angle=0.0):
        self.s = math.sin(angle)
        self.c = math.cos(angle)

    @property
    def angle(self):
        return math.atan2(self.s, self.c)

    @angle.setter
    def angle(self, value):
        self.s = math.sin(value)
        self.c = math.cos(value)

    def __mul__(self, v):
        x, y = v
        return b2Vec2(self.c * x - self.s * y, self.s * x + self.c * y)

    def __repr__(self):
        return "b2Rot(angle=%g)" % self.angle


class b2Transform(object):
    """A position and rotation; transform * point gives the point in world space."""

    __slots__ = ("_x", "_y", "_c", "_s")

    def __init__(self, position=(0.0, 0.0), angle=0.0):
        self._x, self._y = as_pair(position)
        self._c = math.cos(angle)
        self._s = math.sin(angle)

    @classmethod
    def _raw(cls, x, y, c, s):
        t = cls.__new__(cls)
        t._x, t._y, t._c, t._s = x, y, c, s
        return t

    @property
    def position(self):
        return b2Vec2(self._x, self._y)

    @position.setter
    def position(self, value):
        self._x, self._y = as_pair(value)

    @property
    def angle(self):
        return math.atan2(self._s, self._c)

    @angle.setter
    def angle(self, value):
        self._c = math.cos(value)
        self._s = math.sin(value)

    @property
    def q(self):
        r = b2Rot()
        r.c, r.s = self._c, self._s
        return r

    def __mul__(self, v):
        x, y = v
        c, s = self._c, self._s
        return b2Vec2(c * x - s * y + self._x, s * x + c * y + self._y)

    def apply_inverse(self, v):
        x, y = v
        dx, dy = x - self._x, y - self._y
        c, s = self._c, self._s
        return b2Vec2(c * dx + s * dy, -s * dx + c * dy)

    def __repr__(self):
        return "b2Transform(position=(%g,%g), angle=%g)" % (self._x, self._y, self.angle)
