# SPDX-License-Identifier: MIT
"""Bundles the native library into the package, building it with CMake when needed, so
that ``pip install --no-build-isolation --no-index bindings/python`` on a fresh clone
gives an ``import impulse2d`` that works from anywhere.

Which library is bundled (the first that applies):

1. the file named by IMPULSE2D_LIBRARY;
2. build/capi/libimpulse2d.so of this source tree (the README's build), unless
   IMPULSE2D_BUNDLE=source;
3. otherwise a fresh Release build of the shared library alone (no tests, bench or
   examples) with the cmake on PATH, in setuptools' build_temp, honouring CMAKE_ARGS
   and CMAKE_BUILD_PARALLEL_LEVEL.

Other build*/ directories (sanitizer, cross, clang builds) are never picked up
silently: name one with IMPULSE2D_LIBRARY. IMPULSE2D_BUNDLE=none bundles nothing; the
package then finds the library at import time (IMPULSE2D_LIBRARY, or where
``cmake --install`` put it).

The wheel is tagged py3-none-<platform>: it carries a native library but no Python
extension module, so it fits every Python 3 on that platform.
"""

import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

try:  # setuptools >= 70.1 has its own; Debian 12's setuptools 66 uses the wheel package's.
    from setuptools.command.bdist_wheel import bdist_wheel
except ImportError:
    try:
        from wheel.bdist_wheel import bdist_wheel
    except ImportError:  # no wheel package: `setup.py install` still works, untagged
        bdist_wheel = None

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LIBRARY_NAMES = ("libimpulse2d.so", "libimpulse2d.dylib")
BUNDLE_CHOICES = ("auto", "source", "none")


class BuildError(Exception):
    """A reason the library cannot be bundled, worded for the person running pip."""


def requested_bundle_mode():
    return os.environ.get("IMPULSE2D_BUNDLE", "").strip().lower() or "auto"


def bundle_mode():
    mode = requested_bundle_mode()
    if mode not in BUNDLE_CHOICES:
        raise BuildError("IMPULSE2D_BUNDLE=%s: expected one of %s" % (mode, ", ".join(BUNDLE_CHOICES)))
    return mode


def bundles_a_library():
    # Unchecked: setuptools asks before build_py can report a bad value properly.
    return requested_bundle_mode() != "none"


def library_from_environment():
    path = os.environ.get("IMPULSE2D_LIBRARY")
    if path and not os.path.isfile(path):
        raise BuildError("IMPULSE2D_LIBRARY=%s: no such file" % path)
    return path or None


def library_in_readme_build():
    for name in LIBRARY_NAMES:
        path = os.path.join(ROOT, "build", "capi", name)
        if os.path.exists(path):
            return path
    return None


def cmake_program():
    cmake = shutil.which("cmake")
    if cmake is None:
        raise BuildError(
            "building libimpulse2d from source needs the cmake program on PATH "
            "(Debian: apt-get install cmake g++), or set IMPULSE2D_LIBRARY to a built library"
        )
    return cmake


def cmake_configure_arguments(build_dir):
    # Only the shared library: the tests, bench and examples would triple the build time.
    arguments = [
        "-S", ROOT, "-B", build_dir,
        "-DCMAKE_BUILD_TYPE=Release",
        "-DI2D_BUILD_SHARED=ON",
        "-DI2D_BUILD_STATIC_TOO=OFF",
        "-DI2D_BUILD_TESTS=OFF",
        "-DI2D_BUILD_BENCH=OFF",
        "-DI2D_BUILD_EXAMPLES=OFF",
        "-DI2D_FUZZ=OFF",
    ]
    # The user's own arguments come last, so they win.
    return arguments + shlex.split(os.environ.get("CMAKE_ARGS", ""))


def cmake_build_arguments(build_dir):
    arguments = ["--build", build_dir, "--target", "impulse2d"]
    # cmake reads CMAKE_BUILD_PARALLEL_LEVEL itself when no --parallel is given.
    if not os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL"):
        arguments += ["--parallel", str(available_cores())]
    return arguments


def available_cores():
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def run(command):
    print("impulse2d: " + " ".join(shlex.quote(part) for part in command), flush=True)
    subprocess.run(command, check=True)


def build_library_from_source(build_temp):
    if not os.path.isfile(os.path.join(ROOT, "CMakeLists.txt")):
        raise BuildError(
            "no C++ sources at %s (this package builds from a source tree of impulse2d, "
            "not from an sdist); set IMPULSE2D_LIBRARY to a built library" % ROOT
        )
    cmake = cmake_program()
    build_dir = os.path.join(os.path.abspath(build_temp), "cmake")
    print("impulse2d: building libimpulse2d from source with CMake in " + build_dir)
    try:
        run([cmake] + cmake_configure_arguments(build_dir))
        run([cmake] + cmake_build_arguments(build_dir))
    except subprocess.CalledProcessError as error:
        raise BuildError("the CMake build of libimpulse2d failed (%s); see its output above" % error)
    for name in LIBRARY_NAMES:
        path = os.path.join(build_dir, "capi", name)
        if os.path.exists(path):
            return path
    raise BuildError("the CMake build finished but made no libimpulse2d in %s/capi" % build_dir)


def library_to_bundle(build_temp):
    """The library to copy into the package (the rule in the module docstring), or None."""
    mode = bundle_mode()
    if mode == "none":
        return None
    from_environment = library_from_environment()
    if from_environment:
        return from_environment
    if mode == "auto" and library_in_readme_build():
        return library_in_readme_build()
    return build_library_from_source(build_temp)


def remove_stale_libraries(package_dir):
    # build_lib outlives a pip run (pip builds in the source tree): a library an earlier
    # run copied there would otherwise land in this wheel too.
    for name in os.listdir(package_dir):
        if name.startswith("libimpulse2d") or name == "impulse2d.dll":
            os.remove(os.path.join(package_dir, name))


class BuildPyWithLibrary(build_py):
    def run(self):
        super().run()
        build_temp = self.get_finalized_command("build").build_temp
        try:
            library = library_to_bundle(build_temp)
        except BuildError as error:
            sys.exit("impulse2d: error: %s" % error)
        if getattr(self, "editable_mode", False):
            # `pip install -e` imports the package from the source tree, not build_lib
            # (bindings/python/.gitignore ignores the copy).
            package_dir = os.path.join(HERE, "impulse2d")
        else:
            package_dir = os.path.join(self.build_lib, "impulse2d")
            remove_stale_libraries(package_dir)
        if library is None:
            print("impulse2d: IMPULSE2D_BUNDLE=none; the package will look for the library at import time")
            return
        target = os.path.join(package_dir, os.path.basename(library))
        # Copy the file the symlink chain ends at, under the unversioned name.
        shutil.copyfile(os.path.realpath(library), target)
        print("impulse2d: bundled %s" % library)


class DistributionWithLibrary(Distribution):
    """Says it has extension modules when it bundles the library, so that setuptools
    builds into a platform directory and bdist_wheel makes a platform wheel."""

    def has_ext_modules(self):
        return bundles_a_library()


commands = {"build_py": BuildPyWithLibrary}

if bdist_wheel is not None:

    class PlatformWheel(bdist_wheel):
        """Tags the wheel for this platform (it holds a native library) but for any
        Python 3 (the library is loaded through ctypes, not as an extension module)."""

        def get_tag(self):
            python, abi, platform = super().get_tag()
            return (python, abi, platform) if self.root_is_pure else ("py3", "none", platform)

    commands["bdist_wheel"] = PlatformWheel

setup(cmdclass=commands, distclass=DistributionWithLibrary)
