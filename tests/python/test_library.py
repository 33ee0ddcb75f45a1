# SPDX-License-Identifier: MIT
"""Loading the library: the layout check refuses a mismatched library; the search order."""

import glob
import os
import re
import subprocess
import sys

import pytest

import impulse2d
from impulse2d import _layout, _library

HEADERS = os.path.join(os.path.dirname(__file__), "..", "..", "include", "impulse2d")


def real_infos():
    return _layout.read_struct_infos(_library.load(impulse2d.library_path))


def test_the_library_describes_every_public_struct():
    infos = real_infos()
    names = set()
    for header in glob.glob(os.path.join(HEADERS, "*.h")):
        with open(header) as f:
            names.update(re.findall(r"typedef struct (i2d_\w+)", f.read()))
    assert len(names) >= 30
    assert sorted(names - set(infos)) == []
    assert all(size > 0 and align > 0 for size, align in infos.values())


def test_a_struct_of_another_size_is_refused():
    infos = real_infos()
    size, align = infos["i2d_body_def"]
    infos["i2d_body_def"] = (size + 8, align)
    with pytest.raises(impulse2d.LayoutMismatch) as caught:
        _library.load(impulse2d.library_path, layouts=infos)
    message = str(caught.value)
    assert "i2d_body_def: library has size %d" % (size + 8) in message
    assert "this package expects size %d" % size in message
    assert isinstance(caught.value, ImportError)


def test_another_alignment_or_a_missing_struct_is_refused():
    infos = real_infos()
    infos["i2d_filter"] = (infos["i2d_filter"][0], 4)
    del infos["i2d_transform"]
    with pytest.raises(impulse2d.LayoutMismatch) as caught:
        _library.load(impulse2d.library_path, layouts=infos)
    assert "i2d_filter" in str(caught.value) and "i2d_transform: not described by the library" in str(caught.value)
    infos = real_infos()
    infos["i2d_some_future_struct"] = (1, 1)  # structs the package does not use are fine
    assert _library.load(impulse2d.library_path, layouts=infos) is not None


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
