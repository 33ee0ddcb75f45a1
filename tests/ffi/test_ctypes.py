#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The C API through Python ctypes, as a binding would use it (standard library only).

Usage: test_ctypes.py path/to/libimpulse2d.so

Builds the public structs from the library's description of them (i2d_get_field_infos,
through bindings/python/impulse2d/_layout.py) and checks the fields it uses are there,
declares the signature of every function it calls, checks the library version against
include/impulse2d/base.h, builds a small scene, steps it and compares the resting
positions with closed form, runs the FFI-friendly queries, and checks that errors come
back across the boundary as status codes with messages.
Exits 0 when every check passes; prints "N passed, M failed" last.
"""

import ctypes as C
import importlib.util
import math
import os
import re
import sys

# ---- Public types: built from the library's own description ------------------------------
# No struct is declared here: bindings/python/impulse2d/_layout.py (standard library only,
# loaded by path, without the package's wrappers) reads i2d_get_struct_infos and
# i2d_get_field_infos and makes a ctypes class per struct, checking that ctypes lays each
# out as the library says. Ids stay structs here ({bits}), as a C caller sees them.


def load_layout_module(script_dir):
    path = os.path.join(script_dir, "..", "..", "bindings", "python", "impulse2d", "_layout.py")
    spec = importlib.util.spec_from_file_location("i2d_layout", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# The classes the checks below construct, set by load().
Vec2 = AABB = Circle = BodyId = ShapeId = ShapeDef = None

# i2d_body_type
BODY_STATIC, BODY_KINEMATIC, BODY_DYNAMIC = 0, 1, 2

# The fields this script reads or writes, as it uses them (see _layout.usage_problems).
USES = {
    "i2d_vec2": {"x": "float", "y": "float"},
    "i2d_aabb": {"min": "i2d_vec2", "max": "i2d_vec2"},
    "i2d_world_id": {"bits": "uint64"},
    "i2d_body_id": {"bits": "uint64"},
    "i2d_shape_id": {"bits": "uint64"},
    "i2d_world_def": {"gravity": "i2d_vec2", "contact_slop": "float"},
    "i2d_body_def": {"type": "int32", "position": "i2d_vec2"},
    "i2d_shape_def": {"density": "float"},
    "i2d_circle": {"center": "i2d_vec2", "radius": "float"},
    "i2d_manifold_point": {"point": "i2d_vec2", "penetration": "float"},
    "i2d_manifold": {"normal": "i2d_vec2", "point_count": "int32", "points": "i2d_manifold_point[2]"},
    "i2d_ray_result": {"shape": "i2d_shape_id", "point": "i2d_vec2", "normal": "i2d_vec2", "fraction": "float",
                       "hit": "bool"},
}

# i2d_status
OK, ERR_INVALID_ARGUMENT, ERR_INVALID_HANDLE = 0, 1, 2

# ---- Signatures: restype and argtypes for every function used ---------------------------


def signatures(S):
    """restype and argtypes of every function this script calls, with the classes S (by
    C name) built from the library."""
    Vec2, AABB, Circle, Manifold = S["i2d_vec2"], S["i2d_aabb"], S["i2d_circle"], S["i2d_manifold"]
    WorldId, BodyId, ShapeId = S["i2d_world_id"], S["i2d_body_id"], S["i2d_shape_id"]
    WorldDef, BodyDef, ShapeDef = S["i2d_world_def"], S["i2d_body_def"], S["i2d_shape_def"]
    QueryFilter, RayResult = S["i2d_query_filter"], S["i2d_ray_result"]
    return {
        "i2d_version": (C.c_uint32, []),
        "i2d_status_string": (C.c_char_p, [C.c_int]),
        "i2d_last_status": (C.c_int, []),
        "i2d_last_error_message": (C.c_char_p, []),
        "i2d_default_world_def": (WorldDef, []),
        "i2d_default_body_def": (BodyDef, []),
        "i2d_default_shape_def": (ShapeDef, []),
        "i2d_default_query_filter": (QueryFilter, []),
        "i2d_world_create": (WorldId, [C.POINTER(WorldDef)]),
        "i2d_world_destroy": (C.c_int, [WorldId]),
        "i2d_world_is_valid": (C.c_bool, [WorldId]),
        "i2d_world_step": (C.c_int, [WorldId, C.c_float, C.c_int32]),
        "i2d_body_create": (BodyId, [WorldId, C.POINTER(BodyDef)]),
        "i2d_body_destroy": (C.c_int, [BodyId]),
        "i2d_body_is_valid": (C.c_bool, [BodyId]),
        "i2d_body_get_position": (Vec2, [BodyId]),
        "i2d_body_get_linear_velocity": (Vec2, [BodyId]),
        "i2d_body_set_linear_velocity": (C.c_int, [BodyId, Vec2]),
        "i2d_body_get_mass": (C.c_float, [BodyId]),
        "i2d_body_get_shape_count": (C.c_int32, [BodyId]),
        "i2d_shape_create_circle": (ShapeId, [BodyId, C.POINTER(ShapeDef), C.POINTER(Circle)]),
        "i2d_shape_create_box": (ShapeId, [BodyId, C.POINTER(ShapeDef), C.c_float, C.c_float]),
        "i2d_shape_get_body": (BodyId, [ShapeId]),
        "i2d_world_overlap_aabb_ids": (C.c_int32, [WorldId, AABB, QueryFilter, C.POINTER(ShapeId), C.c_int32]),
        "i2d_world_cast_ray_closest": (RayResult, [WorldId, Vec2, Vec2, QueryFilter]),
        "i2d_collide_circles": (Manifold, [Circle, Circle]),
    }


def load(path, layout):
    """The library with every function declared, and the problems found building its
    structs (which are then missing from the module's names)."""
    lib = C.CDLL(path)
    description = layout.describe(lib)
    classes, problems = layout.build_structs(description)
    problems += layout.usage_problems(description, USES)
    if problems:
        return lib, problems
    # Vec2(x, y) is built positionally below.
    if [f.name for f in description["i2d_vec2"].fields[:2]] != ["x", "y"]:
        return lib, ["i2d_vec2 no longer begins with x, y"]
    global Vec2, AABB, Circle, BodyId, ShapeId, ShapeDef
    Vec2, AABB, Circle = classes["i2d_vec2"], classes["i2d_aabb"], classes["i2d_circle"]
    BodyId, ShapeId, ShapeDef = classes["i2d_body_id"], classes["i2d_shape_id"], classes["i2d_shape_def"]
    for name, (restype, argtypes) in signatures(classes).items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes
    return lib, []


# ---- A minimal check harness ---------------------------------------------------------------

passed = 0
failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + what, file=sys.stderr)
    return cond


def near(actual, expected, tol, what):
    ok = not math.isnan(actual) and abs(actual - expected) <= tol
    return check(ok, "%s = %.9g, expected %.9g within %.3g" % (what, actual, expected, tol))


def header_version(script_dir):
    """(major, minor, patch) parsed from include/impulse2d/base.h next to the tests."""
    path = os.path.join(script_dir, "..", "..", "include", "impulse2d", "base.h")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    parts = []
    for part in ("MAJOR", "MINOR", "PATCH"):
        m = re.search(r"^#define\s+I2D_VERSION_%s\s+(\d+)" % part, text, re.MULTILINE)
        if not m:
            raise RuntimeError("I2D_VERSION_%s not found in %s" % (part, path))
        parts.append(int(m.group(1)))
    return tuple(parts)


# ---- The checks ------------------------------------------------------------------------------

TIME_STEP = 1.0 / 60.0
SUBSTEPS = 4


def check_version(lib, script_dir):
    major, minor, patch = header_version(script_dir)
    packed = (major << 16) | (minor << 8) | patch
    check(lib.i2d_version() == packed,
          "i2d_version() = 0x%06x, header says %d.%d.%d" % (lib.i2d_version(), major, minor, patch))


def check_struct_passing(lib):
    # Structs by value in both directions: two circles overlapping by 0.5 along +x.
    m = lib.i2d_collide_circles(Circle(center=Vec2(0, 0), radius=1.0), Circle(center=Vec2(1.5, 0), radius=1.0))
    check(m.point_count == 1, "collide_circles point_count %d, expected 1" % m.point_count)
    near(m.normal.x, 1.0, 1e-6, "collide_circles normal.x")
    near(m.normal.y, 0.0, 1e-6, "collide_circles normal.y")
    near(m.points[0].penetration, 0.5, 1e-6, "collide_circles penetration")
    near(m.points[0].point.x, 0.75, 1e-6, "collide_circles point.x")


def make_body(lib, world, body_type, x, y):
    bd = lib.i2d_default_body_def()
    bd.type = body_type
    bd.position = Vec2(x, y)
    body = lib.i2d_body_create(world, C.byref(bd))
    check(body.bits != 0, "i2d_body_create at (%g, %g): %s" % (x, y, lib.i2d_last_error_message()))
    return body


def run_scene(lib):
    wd = lib.i2d_default_world_def()
    near(wd.gravity.y, -10.0, 0.0, "default gravity.y")
    slop = wd.contact_slop
    world = lib.i2d_world_create(C.byref(wd))
    if not check(world.bits != 0 and lib.i2d_world_is_valid(world), "i2d_world_create"):
        return None
    sd = lib.i2d_default_shape_def()

    # Static ground: a 40 x 2 m box centred at (0, -1), top face at y = 0.
    ground = make_body(lib, world, BODY_STATIC, 0.0, -1.0)
    ground_shape = lib.i2d_shape_create_box(ground, C.byref(sd), 20.0, 1.0)
    check(ground_shape.bits != 0, "ground box")

    # Dynamic bodies dropped from different heights: (x, y0, kind, size). Each comes to
    # rest on the ground: a circle at y = r, a box at y = half height.
    specs = [(-6.0, 2.0, "circle", 0.5), (-3.0, 4.0, "circle", 0.25),
             (3.0, 3.0, "box", (0.5, 0.5)), (6.0, 5.0, "box", (0.75, 0.25))]
    bodies = []
    for x, y0, kind, size in specs:
        body = make_body(lib, world, BODY_DYNAMIC, x, y0)
        if kind == "circle":
            circle = Circle(center=Vec2(0.0, 0.0), radius=size)
            shape = lib.i2d_shape_create_circle(body, C.byref(sd), C.byref(circle))
            rest_y = size
            mass = math.pi * size * size * sd.density
        else:
            shape = lib.i2d_shape_create_box(body, C.byref(sd), size[0], size[1])
            rest_y = size[1]
            mass = 4.0 * size[0] * size[1] * sd.density
        check(shape.bits != 0, "%s shape: %s" % (kind, lib.i2d_last_error_message()))
        check(lib.i2d_shape_get_body(shape).bits == body.bits, "shape_get_body")
        near(lib.i2d_body_get_mass(body), mass, 1e-5, "mass of %s at x = %g" % (kind, x))
        bodies.append((body, shape, x, rest_y, kind))

    # 2 s at 1/60 s with 4 substeps: the highest body lands after about 0.95 s.
    for _ in range(120):
        status = lib.i2d_world_step(world, TIME_STEP, SUBSTEPS)
        if not check(status == OK, "i2d_world_step returned %d" % status):
            break

    # At rest on the ground: at most one slop deep, not hovering, x unchanged, still.
    for body, _, x, rest_y, kind in bodies:
        p = lib.i2d_body_get_position(body)
        v = lib.i2d_body_get_linear_velocity(body)
        what = "%s from x = %g" % (kind, x)
        check(rest_y - slop - 1e-3 <= p.y <= rest_y + 1e-3,
              "%s rests at y = %.6f, expected %.6f (slop %.4f)" % (what, p.y, rest_y, slop))
        near(p.x, x, 1e-4, what + " x")
        check(math.hypot(v.x, v.y) < 1e-2, "%s still moving at (%g, %g)" % (what, v.x, v.y))
    ground_p = lib.i2d_body_get_position(ground)
    check(ground_p.x == 0.0 and ground_p.y == -1.0, "static ground moved to (%g, %g)" % (ground_p.x, ground_p.y))
    return world, ground, ground_shape, bodies


def check_overlap_ids(lib, world, ground_shape, bodies):
    qf = lib.i2d_default_query_filter()
    everything = AABB(min=Vec2(-30.0, -5.0), max=Vec2(30.0, 10.0))
    expected = {ground_shape.bits} | {shape.bits for _, shape, _, _, _ in bodies}

    # First ask for the count with no buffer, then fill a buffer of that size.
    total = lib.i2d_world_overlap_aabb_ids(world, everything, qf, None, 0)
    check(total == len(expected), "overlap count %d, expected %d" % (total, len(expected)))
    if total > 0:
        buf = (ShapeId * total)()
        n = lib.i2d_world_overlap_aabb_ids(world, everything, qf, buf, total)
        check(n == total, "overlap fill returned %d, expected %d" % (n, total))
        check({s.bits for s in buf} == expected, "overlap ids are the scene's shapes")

    # A buffer smaller than the result: filled up to capacity, the total still returned,
    # nothing written past the end.
    small = (ShapeId * 3)()
    small[2] = ShapeId(bits=0xDEADBEEF)
    n = lib.i2d_world_overlap_aabb_ids(world, everything, qf, small, 2)
    check(n == len(expected), "overlap with capacity 2 returned %d, expected %d" % (n, len(expected)))
    check(small[0].bits in expected and small[1].bits in expected and small[0].bits != small[1].bits,
          "overlap with capacity 2 filled two distinct scene shapes")
    check(small[2].bits == 0xDEADBEEF, "overlap wrote past capacity")

    # A box around the top of the first circle (resting at y = 0.5, radius 0.5) finds it
    # alone: the ground is 0.6 m below the query.
    first_shape = bodies[0][1]
    box = AABB(min=Vec2(-6.2, 0.6), max=Vec2(-5.8, 0.9))
    buf = (ShapeId * 4)()
    n = lib.i2d_world_overlap_aabb_ids(world, box, qf, buf, 4)
    check(n == 1 and buf[0].bits == first_shape.bits, "overlap around the first circle found %d shapes" % n)


def check_ray(lib, world, ground_shape, bodies):
    qf = lib.i2d_default_query_filter()
    # Straight down at x = 0 where nothing rests: the ground's top at y = 0 is half way.
    r = lib.i2d_world_cast_ray_closest(world, Vec2(0.0, 5.0), Vec2(0.0, -10.0), qf)
    if check(r.hit, "ray at x = 0 missed the ground"):
        near(r.fraction, 0.5, 1e-5, "ray fraction onto the ground")
        near(r.point.y, 0.0, 1e-5, "ray hit point y")
        near(r.normal.x, 0.0, 1e-6, "ray normal x")
        near(r.normal.y, 1.0, 1e-6, "ray normal y")
        check(r.shape.bits == ground_shape.bits, "ray hit the ground shape")
    # Down onto the resting unit box at x = 3: its top is at y = 1 (less at most a slop).
    _, box_shape, x, rest_y, _ = bodies[2]
    r = lib.i2d_world_cast_ray_closest(world, Vec2(x, 5.0), Vec2(0.0, -10.0), qf)
    if check(r.hit, "ray at x = 3 missed the box"):
        near(r.fraction, (5.0 - 2 * rest_y) / 10.0, 1e-3, "ray fraction onto the box")
        check(r.shape.bits == box_shape.bits, "ray hit the box shape")
    # Pointing up from above everything: no hit.
    r = lib.i2d_world_cast_ray_closest(world, Vec2(0.0, 20.0), Vec2(0.0, 10.0), qf)
    check(not r.hit, "ray into empty space reported a hit")


def message(lib):
    raw = lib.i2d_last_error_message()
    return raw.decode("utf-8", "replace") if raw else ""


def check_errors(lib, world, bodies):
    # A null body id: a zero value and I2D_ERR_INVALID_HANDLE with a message.
    p = lib.i2d_body_get_position(BodyId(bits=0))
    check(p.x == 0.0 and p.y == 0.0, "position of a null body is zero")
    check(lib.i2d_last_status() == ERR_INVALID_HANDLE, "null body: last status %d" % lib.i2d_last_status())
    check(message(lib) != "", "null body: empty error message")
    status = lib.i2d_body_set_linear_velocity(BodyId(bits=0), Vec2(1.0, 0.0))
    check(status == ERR_INVALID_HANDLE, "set velocity on a null body returned %d" % status)
    check(message(lib) != "", "set velocity on a null body: empty error message")
    name = lib.i2d_status_string(ERR_INVALID_HANDLE)
    check(name == b"I2D_ERR_INVALID_HANDLE", "i2d_status_string: %r" % name)

    # A NaN radius: a null shape id, I2D_ERR_INVALID_ARGUMENT, and the body unchanged.
    body = bodies[0][0]
    sd = lib.i2d_default_shape_def()
    bad = Circle(center=Vec2(0.0, 0.0), radius=float("nan"))
    shape = lib.i2d_shape_create_circle(body, C.byref(sd), C.byref(bad))
    check(shape.bits == 0, "NaN radius created a shape")
    check(lib.i2d_last_status() == ERR_INVALID_ARGUMENT, "NaN radius: last status %d" % lib.i2d_last_status())
    check(message(lib) != "", "NaN radius: empty error message")
    check(lib.i2d_body_get_shape_count(body) == 1, "NaN radius changed the body's shape count")

    # A def that did not come from the default function (a zeroed ctypes struct, the
    # usual binding mistake) is refused.
    raw_def = ShapeDef()
    raw_def.density = 1.0
    good = Circle(center=Vec2(0.0, 0.0), radius=0.5)
    shape = lib.i2d_shape_create_circle(body, C.byref(raw_def), C.byref(good))
    check(shape.bits == 0 and lib.i2d_last_status() == ERR_INVALID_ARGUMENT,
          "shape def without the cookie: id %d, status %d" % (shape.bits, lib.i2d_last_status()))

    # A successful call clears the status and the message.
    lib.i2d_body_get_position(body)
    check(lib.i2d_last_status() == OK and message(lib) == "", "status after a successful call")

    # A destroyed body's id is stale.
    doomed = make_body(lib, world, BODY_DYNAMIC, 10.0, 10.0)
    check(lib.i2d_body_destroy(doomed) == OK, "i2d_body_destroy")
    check(not lib.i2d_body_is_valid(doomed), "destroyed body still valid")
    lib.i2d_body_get_position(doomed)
    check(lib.i2d_last_status() == ERR_INVALID_HANDLE, "stale body: last status %d" % lib.i2d_last_status())


def main():
    if len(sys.argv) != 2:
        print("usage: %s path/to/libimpulse2d.so" % sys.argv[0], file=sys.stderr)
        return 2
    script_dir = os.path.dirname(os.path.abspath(__file__))
    layout = load_layout_module(script_dir)
    try:
        lib, problems = load(sys.argv[1], layout)
    except (OSError, AttributeError, layout.LayoutError) as e:
        print("FAIL: cannot load %s: %s" % (sys.argv[1], e), file=sys.stderr)
        print("0 passed, 1 failed")
        return 1
    # The structs the library describes, built and laid out by ctypes as it says, with
    # every field this script uses.
    for problem in problems:
        check(False, "struct layout: " + problem)
    if problems:
        print("%d passed, %d failed" % (passed, failed))
        return 1

    check_version(lib, script_dir)
    check_struct_passing(lib)
    scene = run_scene(lib)
    if scene is not None:
        world, _, ground_shape, bodies = scene
        check_overlap_ids(lib, world, ground_shape, bodies)
        check_ray(lib, world, ground_shape, bodies)
        check_errors(lib, world, bodies)
        some_body = bodies[0][0]
        check(lib.i2d_world_destroy(world) == OK, "i2d_world_destroy")
        check(not lib.i2d_world_is_valid(world), "destroyed world still valid")
        check(not lib.i2d_body_is_valid(some_body), "body of a destroyed world still valid")
        check(lib.i2d_world_step(world, TIME_STEP, SUBSTEPS) == ERR_INVALID_HANDLE, "step on a destroyed world")

    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
