# SPDX-License-Identifier: MIT
"""World.draw through recording drawers, as tests/api/test_api_debug_draw.c checks
i2d_world_draw in C: each shape once through its method in its body's colour, the flags,
culling, drawers lacking methods, exceptions raised after the pass, the world locked while
the drawer runs, refusals, and the COLOR_* constants against the header."""

import gc
import math
import os
import re
import weakref
from typing import Any, NamedTuple, Tuple

import pytest

import impulse2d

HEADER = os.path.join(os.path.dirname(__file__), "..", "..", "include", "impulse2d", "toolkit.h")


class Call(NamedTuple):
    kind: str  # the method's name without draw_
    color: Any  # None for draw_transform, which has none
    where: Tuple[float, float]  # a point that places it (first vertex, centre, first end)
    args: Tuple[Any, ...]  # everything the method was given


class Recorder:
    """A drawer with every method, keeping each call."""

    def __init__(self):
        self.calls = []

    def _add(self, kind, color, where, *args):
        self.calls.append(Call(kind, color, where, args))

    def draw_polygon(self, vertices, color):
        self._add("polygon", color, vertices[0], vertices)

    def draw_solid_polygon(self, transform, vertices, radius, color):
        self._add("solid_polygon", color, transform.position, transform, vertices, radius)

    def draw_circle(self, center, radius, color):
        self._add("circle", color, center, radius)

    def draw_solid_circle(self, transform, radius, color):
        self._add("solid_circle", color, transform.position, transform, radius)

    def draw_solid_capsule(self, p1, p2, radius, color):
        self._add("solid_capsule", color, p1, p2, radius)

    def draw_segment(self, p1, p2, color):
        self._add("segment", color, p1, p2)

    def draw_transform(self, transform):
        self._add("transform", None, transform.position, transform)

    def draw_point(self, p, size, color):
        self._add("point", color, p, size)

    def draw_string(self, p, text, color):
        self._add("string", color, p, text)

    def of(self, kind, color=None):
        return [c for c in self.calls if c.kind == kind and (color is None or c.color == color)]

    def at(self, kind, point, color):
        """The calls of a kind in a colour placed at point (within 1e-4)."""
        return [c for c in self.of(kind, color) if math.dist(c.where, point) < 1e-4]


def drawn(world, **flags):
    recorder = Recorder()
    world.draw(recorder, **flags)
    return recorder


def body_at(world, x, y=0.0, kind=impulse2d.DYNAMIC, **settings):
    return world.create_body(kind, position=(x, y), **settings)


def bodies_in_every_state(world):
    """A body of each state at its own x (as the C test's scene, without the chain)."""
    ground = body_at(world, 0.0, kind=impulse2d.STATIC)
    ground.create_box(1.0, 1.0)
    ground.create_segment((-2.0, 2.0), (2.0, 2.0))
    body_at(world, 10.0, kind=impulse2d.KINEMATIC).create_capsule((-0.5, 0.0), (0.5, 0.0), 0.25)
    body_at(world, 20.0).create_circle(0.5)
    asleep = body_at(world, 30.0)
    asleep.create_box(0.5, 0.5)
    asleep.awake = False
    bullet = body_at(world, 40.0)
    bullet.create_circle(0.1)
    bullet.bullet = True
    sensor = body_at(world, 50.0)
    sensor.create_circle(0.5, is_sensor=True)
    sensor.create_box(0.25, 0.25)  # a solid shape on the sensor's body: drawn awake
    disabled = body_at(world, 60.0)
    disabled.create_box(0.5, 0.5)
    disabled.disable()
    return bullet


def test_each_shape_is_drawn_once_through_its_method_in_its_bodys_colour():
    with impulse2d.World(gravity=(0, 0)) as world:
        bullet = bodies_in_every_state(world)
        r = drawn(world)
        kinds = sorted(c.kind for c in r.calls)
        assert kinds == ["segment"] + ["solid_capsule"] + ["solid_circle"] * 3 + ["solid_polygon"] * 4
        assert len(r.at("solid_polygon", (0.0, 0.0), impulse2d.COLOR_STATIC)) == 1
        assert len(r.at("segment", (-2.0, 2.0), impulse2d.COLOR_STATIC)) == 1
        assert len(r.at("solid_capsule", (9.5, 0.0), impulse2d.COLOR_KINEMATIC)) == 1
        assert len(r.at("solid_circle", (20.0, 0.0), impulse2d.COLOR_AWAKE)) == 1
        assert len(r.at("solid_polygon", (30.0, 0.0), impulse2d.COLOR_ASLEEP)) == 1
        assert len(r.at("solid_circle", (40.0, 0.0), impulse2d.COLOR_BULLET)) == 1
        assert len(r.at("solid_circle", (50.0, 0.0), impulse2d.COLOR_SENSOR)) == 1
        assert len(r.at("solid_polygon", (50.0, 0.0), impulse2d.COLOR_AWAKE)) == 1
        assert len(r.at("solid_polygon", (60.0, 0.0), impulse2d.COLOR_DISABLED)) == 1
        # What each method gets: local vertices and radius, a capsule's ends and radius.
        ground = r.at("solid_polygon", (0.0, 0.0), impulse2d.COLOR_STATIC)[0]
        assert ground.args[1] == [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] and ground.args[2] == 0.0
        assert r.of("solid_capsule")[0].args == ((10.5, 0.0), 0.25)
        assert r.at("solid_circle", (40.0, 0.0), impulse2d.COLOR_BULLET)[0].args[1] == pytest.approx(0.1)
        # A bullet asleep is drawn asleep.
        bullet.awake = False
        assert len(drawn(world).at("solid_circle", (40.0, 0.0), impulse2d.COLOR_ASLEEP)) == 1
        assert drawn(world, shapes=False).calls == []


def test_a_transform_places_a_turned_bodys_local_vertices(world):
    angle = 0.5
    body = body_at(world, 2.0, 3.0, angle=angle, gravity_scale=0.0)
    body.create_box(1.0, 0.5)
    wheel = body_at(world, -4.0, 1.0, angle=angle, gravity_scale=0.0)
    wheel.create_circle(0.5)
    r = drawn(world)
    (box,) = r.of("solid_polygon")
    transform, vertices = box.args[0], box.args[1]
    assert isinstance(transform, impulse2d.Transform)
    assert transform.rotation == pytest.approx((math.cos(angle), math.sin(angle)))
    c, s = math.cos(angle), math.sin(angle)
    expected = [(2.0 + c * x - s * y, 3.0 + s * x + c * y) for x, y in ((-1, -0.5), (1, -0.5), (1, 0.5), (-1, 0.5))]
    assert [transform.apply(v) for v in vertices] == [pytest.approx(p, abs=1e-5) for p in expected]
    (disc,) = r.of("solid_circle")
    assert disc.args[0].rotation == pytest.approx((c, s)) and disc.where == pytest.approx((-4.0, 1.0))


def jointed_scene(world):
    """A box on a revolute joint (limit and motor) to a static box, and a ball; returns
    (ground, arm, ball)."""
    ground = body_at(world, 0.0, kind=impulse2d.STATIC)
    ground.create_box(0.5, 0.5)
    arm = body_at(world, 2.0)
    arm.create_box(0.5, 0.5)
    ball = body_at(world, 10.0)
    ball.create_circle(0.5)
    world.create_joint("revolute", ground, arm, local_anchor_a=(1.0, 0.0), local_anchor_b=(-1.0, 0.0),
                       enable_limit=True, lower_angle=-0.5, upper_angle=0.5, enable_motor=True)
    return ground, arm, ball


def test_joints_are_drawn_by_default_and_their_extras_when_asked(world):
    jointed_scene(world)
    r = drawn(world)
    assert len(r.of("segment")) == len(r.of("segment", impulse2d.COLOR_JOINT)) == 3
    assert len(r.at("point", (1.0, 0.0), impulse2d.COLOR_JOINT_ANCHOR)) == 2  # both anchors at (1, 0)
    assert r.of("polygon") == r.of("transform") == r.of("circle") == []
    r = drawn(world, joint_extras=True)
    assert len(r.of("segment", impulse2d.COLOR_JOINT_LIMIT)) == 2
    assert len(r.of("circle", impulse2d.COLOR_JOINT_MOTOR)) == 1
    r = drawn(world, joints=False)
    assert r.of("segment") == r.of("point") == []
    assert len(r.of("solid_polygon")) == 2 and len(r.of("solid_circle")) == 1


def test_bounds_mass_and_islands_only_when_asked(world):
    ground, arm, ball = jointed_scene(world)
    r = drawn(world, bounds=True)
    boxes = r.of("polygon", impulse2d.COLOR_BOUNDS)
    assert len(boxes) == len(r.of("polygon")) == 3
    for body in (ground, arm, ball):
        (lo_x, lo_y), (hi_x, hi_y) = body.shapes[0].aabb
        holding = [b for b in boxes if min(v[0] for v in b.args[0]) <= lo_x and min(v[1] for v in b.args[0]) <= lo_y
                   and max(v[0] for v in b.args[0]) >= hi_x and max(v[1] for v in b.args[0]) >= hi_y]
        assert len(holding) == 1
    r = drawn(world, mass=True)
    assert len(r.of("transform")) == len(r.of("string", impulse2d.COLOR_MASS)) == 2
    for body in (arm, ball):
        (frame,) = r.at("transform", body.world_center_of_mass, None)
        (text,) = r.at("string", body.world_center_of_mass, impulse2d.COLOR_MASS)
        assert float(text.args[0].split()[0]) == pytest.approx(body.mass, abs=0.01)
    assert r.of("polygon") == []
    r = drawn(world, islands=True)
    assert len(r.of("polygon", impulse2d.COLOR_ISLAND)) == 2  # the arm's and the ball's
    ball.awake = False
    assert len(drawn(world, islands=True).of("polygon", impulse2d.COLOR_ISLAND)) == 1


def test_contacts_their_normals_impulses_and_graph_colours_when_asked(world):
    body_at(world, 0.0, -0.5, kind=impulse2d.STATIC).create_box(5.0, 0.5)
    body_at(world, 0.0, 0.5).create_box(0.5, 0.5)
    for _ in range(20):
        world.step()  # resting, still awake
    assert drawn(world, shapes=False, joints=False).calls == []
    points = drawn(world, shapes=False, contacts=True).of("point", impulse2d.COLOR_CONTACT)
    assert len(points) == 2 and all(abs(p.where[1]) < 0.01 for p in points)  # on the ground's top
    for flag, color in (("contact_normals", impulse2d.COLOR_CONTACT_NORMAL),
                        ("contact_impulses", impulse2d.COLOR_CONTACT_IMPULSE),
                        ("friction_impulses", impulse2d.COLOR_FRICTION_IMPULSE)):
        r = drawn(world, shapes=False, **{flag: True})
        assert len(r.of("segment", color)) == len(r.calls) == 2, flag
    normal = drawn(world, shapes=False, contact_normals=True).of("segment")[0]
    assert normal.args[0][1] - normal.where[1] == pytest.approx(0.3, abs=1e-4)  # 0.3 m up, from ground to box
    colored = drawn(world, shapes=False, graph_colors=True).of("point")
    palette = impulse2d.GRAPH_COLORS + (impulse2d.COLOR_GRAPH_OVERFLOW,)
    assert len(colored) == 2 and all(p.color in palette for p in colored)


def test_bounds_box_culls_to_the_shapes_it_overlaps():
    with impulse2d.World(gravity=(0, 0)) as world:
        for x in (0.0, 20.0, 40.0):
            body_at(world, x).create_circle(0.5)
        r = drawn(world, bounds_box=((15.0, -5.0), (25.0, 5.0)))
        assert [c.where for c in r.calls] == [(20.0, 0.0)]
        assert drawn(world, bounds_box=((100.0, 100.0), (101.0, 101.0))).calls == []
        assert len(drawn(world).calls) == 3  # the whole world again without it


def test_a_drawer_lacking_methods_gets_what_it_has():
    class OnlyCircles:
        def __init__(self):
            self.centres = []

        def draw_solid_circle(self, transform, radius, color):
            self.centres.append(transform.position)

    class NoPoints(Recorder):
        draw_point = None  # None: not drawn, as if absent

    with impulse2d.World(gravity=(0, 0)) as world:
        jointed_scene(world)
        circles = OnlyCircles()
        world.draw(circles, joint_extras=True, bounds=True, mass=True)
        assert circles.centres == [(10.0, 0.0)]
        world.draw(object(), mass=True)  # nothing to call: nothing happens
        no_points = NoPoints()
        world.draw(no_points)
        assert no_points.of("point") == [] and len(no_points.of("segment")) == 3

        class Broken:
            draw_point = 42

        with pytest.raises(TypeError, match="draw_point"):
            world.draw(Broken())


def test_an_exception_in_a_drawer_method_is_raised_after_the_pass_and_the_rest_skipped():
    class Boom(Exception):
        pass

    class Failing(Recorder):
        def draw_solid_polygon(self, transform, vertices, radius, color):
            super().draw_solid_polygon(transform, vertices, radius, color)
            raise Boom("from the drawer")

    with impulse2d.World(gravity=(0, 0)) as world:
        for x in (0.0, 5.0, 10.0):
            body_at(world, x).create_box(0.5, 0.5)
        body_at(world, 20.0).create_circle(0.5)
        failing = Failing()
        with pytest.raises(Boom, match="from the drawer"):
            world.draw(failing)
        assert len(failing.calls) == 1  # nothing after the first exception
        world.step()  # the world is unlocked and nothing is left over
        assert len(drawn(world).calls) == 4


def test_a_draw_keeps_no_reference_to_its_drawer():
    # Freed when the caller drops it, with the collector off: the pass leaves no cycle
    # through its callbacks or through an exception's traceback.
    class Failing(Recorder):
        def draw_solid_circle(self, transform, radius, color):
            raise ValueError("once")

    with impulse2d.World() as world:
        body_at(world, 0.0).create_circle(0.5)
        gc.disable()
        try:
            for make in (Recorder, Failing):
                drawer = make()
                ref = weakref.ref(drawer)
                try:
                    world.draw(drawer)
                except ValueError:
                    pass
                del drawer
                assert ref() is None
        finally:
            gc.enable()


def test_the_world_is_locked_for_changes_while_the_drawer_runs(world):
    ball = body_at(world, 0.0, 5.0)
    ball.create_circle(0.5)
    seen = []

    class Probe(Recorder):
        def draw_solid_circle(self, transform, radius, color):
            seen.append(ball.position)  # getters work
            seen.append(world.cast_ray((0.0, 10.0), (0.0, -10.0)).shape)  # queries too
            inner = Recorder()
            world.draw(inner)  # and drawing
            seen.append(len(inner.calls))
            try:
                world.step()
            except impulse2d.WorldLocked as error:
                seen.append(error)

    world.draw(Probe())
    assert seen[0] == (0.0, 5.0) and seen[1] == ball.shapes[0] and seen[2] == 1
    assert isinstance(seen[3], impulse2d.WorldLocked)

    class Escaping:
        def draw_solid_circle(self, transform, radius, color):
            ball.linear_velocity = (1.0, 0.0)

    with pytest.raises(impulse2d.WorldLocked):
        world.draw(Escaping())
    assert ball.linear_velocity == (0.0, 0.0)


def test_refusals_carry_the_librarys_message_and_call_nothing():
    with impulse2d.World() as world:
        body_at(world, 0.0).create_circle(0.5)
        r = Recorder()
        with pytest.raises(impulse2d.InvalidArgument, match=r"^i2d_world_draw: drawing_bounds\.x is NaN"):
            world.draw(r, bounds_box=((math.nan, 0.0), (1.0, 1.0)))
        with pytest.raises(impulse2d.InvalidArgument, match=r"^i2d_world_draw: drawing_bounds has min above"):
            world.draw(r, bounds_box=((1.0, 1.0), (0.0, 0.0)))
        world.destroy()
        with pytest.raises(impulse2d.InvalidHandle):
            world.draw(r)
        assert r.calls == []


def header_colors():
    """The header's I2D_COLOR_* values by name, and its graph palette."""
    with open(HEADER) as f:
        text = f.read()
    colors = {m.group(1): int(m.group(2), 16) for m in re.finditer(r"#define I2D_(COLOR_\w+) 0x([0-9A-Fa-f]+)u", text)}
    palette = re.search(r"#define I2D_GRAPH_COLORS\s*\\\s*\{([^}]*)\}", text).group(1)
    return colors, tuple(int(v, 16) for v in re.findall(r"0x([0-9A-Fa-f]+)u", palette))


def test_the_color_constants_are_the_headers():
    colors, palette = header_colors()
    assert len(colors) == 22 and len(palette) == 12
    for name, value in colors.items():
        assert getattr(impulse2d, name) == value, name
    assert impulse2d.GRAPH_COLORS == palette
    exported = {name for name in impulse2d.__all__ if name.startswith("COLOR_")}
    assert exported == set(colors)
