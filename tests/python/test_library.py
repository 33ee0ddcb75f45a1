# SPDX-License-Identifier: MIT
"""Loading the library: structs built from its description, the check that refuses a
mismatched library, the search order."""

import ctypes as C
import glob
import os
import re
import subprocess
import sys

import pytest

import impulse2d
from impulse2d import _layout, _library

HEADERS = os.path.join(os.path.dirname(__file__), "..", "..", "include", "impulse2d")


def real_description():
    return _layout.describe(_library.load(impulse2d.library_path))


def with_struct(description, name, **changes):
    """A copy of description with struct name changed (fields given as a list)."""
    doctored = dict(description)
    struct = doctored[name]
    if "fields" in changes:
        changes["fields"] = tuple(changes["fields"])
    doctored[name] = struct._replace(**changes)
    return doctored


def fields_of(description, name):
    return list(description[name].fields)


def test_the_library_describes_every_public_struct():
    description = real_description()
    names = set()
    for header in glob.glob(os.path.join(HEADERS, "*.h")):
        with open(header) as f:
            names.update(re.findall(r"typedef struct (i2d_\w+)", f.read()))
    assert len(names) >= 30
    assert sorted(names - set(description)) == []
    assert all(s.size > 0 and s.align > 0 and s.fields for s in description.values())
    # Every described struct became a class laid out as the library says.
    built = _library.load(impulse2d.library_path)._impulse2d_structs.by_c_name
    assert sorted(built) == sorted(description)
    assert _layout.layout_problems(description, built) == []


def test_the_classes_come_from_the_library():
    from impulse2d import _structs

    description = real_description()
    world_def = {f.name for f in description["i2d_world_def"].fields}
    assert {name for name, _ in _structs.WorldDef._fields_} == world_def
    assert _structs.AABB.__name__ == "AABB" and _structs.ContactBeginEvent.__name__ == "ContactBeginEvent"
    assert dict(_structs.Polygon._fields_)["vertices"]._length_ == _structs.MAX_POLYGON_VERTICES == 8
    assert dict(_structs.RayResult._fields_)["shape"] is C.c_uint64  # ids are integers
    assert dict(_structs.ContactEvents._fields_)["begin_events"]._type_ is _structs.ContactBeginEvent
    assert dict(_structs.WorldDef._fields_)["enqueue_task"] is C.c_void_p
    assert list(_structs.JOINT_DEFS) == ["distance", "filter", "motor", "mouse", "prismatic", "revolute", "weld",
                                         "wheel"]


def test_a_struct_of_another_size_is_refused():
    description = real_description()
    size = description["i2d_body_def"].size
    doctored = with_struct(description, "i2d_body_def", size=size + 8)
    with pytest.raises(impulse2d.LayoutMismatch) as caught:
        _library.load(impulse2d.library_path, description=doctored)
    message = str(caught.value)
    assert "i2d_body_def: the library has size %d" % (size + 8) in message
    assert "ctypes lays it out with size %d" % size in message
    assert isinstance(caught.value, ImportError)


def test_a_missing_field_another_kind_or_a_missing_struct_is_refused():
    description = real_description()
    transform = [f for f in fields_of(description, "i2d_transform") if f.name != "q"]
    doctored = with_struct(description, "i2d_transform", fields=transform)
    filter_fields = [f._replace(kind="float") if f.name == "group_index" else f for f in fields_of(description, "i2d_filter")]
    doctored = with_struct(doctored, "i2d_filter", fields=filter_fields)
    del doctored["i2d_ray_result"]
    with pytest.raises(impulse2d.LayoutMismatch) as caught:
        _library.load(impulse2d.library_path, description=doctored)
    message = str(caught.value)
    assert "i2d_transform.q: the library has no such field; this package uses it as i2d_rot" in message
    assert "i2d_filter.group_index: the library has float; this package uses it as int32" in message
    assert "i2d_ray_result: not described by the library" in message


def test_vectors_built_positionally_must_keep_their_order():
    description = real_description()
    doctored = with_struct(description, "i2d_vec2", fields=reversed(fields_of(description, "i2d_vec2")))
    with pytest.raises(impulse2d.LayoutMismatch) as caught:
        _library.load(impulse2d.library_path, description=doctored)
    assert "i2d_vec2: the package builds it as (x, y); the library's members begin (y, x)" in str(caught.value)


def test_fields_and_structs_the_package_does_not_use_are_fine():
    description = real_description()
    # A bool in the padding after enable_profile (57), and a struct of a newer library.
    world_def = fields_of(description, "i2d_world_def")
    at = next(i for i, f in enumerate(world_def) if f.name == "enable_profile") + 1
    world_def.insert(at, _layout.Field("enable_something", "bool", "bool", 58, 1, 1))
    doctored = with_struct(description, "i2d_world_def", fields=world_def)
    doctored["i2d_some_future_struct"] = _layout.Struct(
        "i2d_some_future_struct", 4, 4, (_layout.Field("value", "float", "float", 0, 4, 1),))
    lib = _library.load(impulse2d.library_path, description=doctored)
    assert "enable_something" in dict(lib._impulse2d_structs.WorldDef._fields_)
    assert lib._impulse2d_structs.SomeFutureStruct.value.offset == 0


def test_a_library_that_does_not_describe_itself_is_refused():
    class Old:
        i2d_get_struct_infos = None

    with pytest.raises(_layout.LayoutError, match="i2d_get_field_infos is missing"):
        _layout.describe(Old())


def run_python(code, **env):
    environment = dict(os.environ, **env)
    environment["PYTHONPATH"] = os.path.dirname(os.path.dirname(impulse2d.__file__))
    return subprocess.run([sys.executable, "-c", code], env=environment, capture_output=True, text=True)


def test_the_environment_variable_wins():
    done = run_python("import impulse2d; print(impulse2d.library_path)", IMPULSE2D_LIBRARY=impulse2d.library_path)
    assert done.returncode == 0 and done.stdout.strip() == impulse2d.library_path
    missing = run_python("import impulse2d", IMPULSE2D_LIBRARY="/nonexistent/libimpulse2d.so")
    assert missing.returncode != 0
    assert "impulse2d.errors.LibraryError" in missing.stderr and "IMPULSE2D_LIBRARY" in missing.stderr


def test_search_order_lists_the_package_dir_first():
    saved = os.environ.pop(_library.ENVIRONMENT_VARIABLE, None)
    try:
        paths = _library.candidate_paths()
    finally:
        if saved is not None:
            os.environ[_library.ENVIRONMENT_VARIABLE] = saved
    package_dir = os.path.dirname(os.path.abspath(impulse2d.__file__))
    assert os.path.dirname(paths[0]) == package_dir
    assert any("/usr/local/lib" in p for p in paths)
