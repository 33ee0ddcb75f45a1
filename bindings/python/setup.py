# SPDX-License-Identifier: MIT
"""Copies the built native library into the installed package, so that
``pip install --no-build-isolation bindings/python`` after the README's build gives an
``import impulse2d`` that works from anywhere.

The library is taken from IMPULSE2D_LIBRARY if set, else from build/capi/ (the README's
build), else from the newest other build*/capi/ of this source tree. Sanitizer and
cross builds sit beside it there: name the library when several exist. Without one the package installs alone and finds the
library at import time (IMPULSE2D_LIBRARY, or where ``cmake --install`` put it).
"""

import glob
import os
import shutil

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def built_library():
    from_env = os.environ.get("IMPULSE2D_LIBRARY")
    if from_env:
        return from_env
    for name in ("libimpulse2d.so", "libimpulse2d.dylib"):
        readme_build = os.path.join(ROOT, "build", "capi", name)
        if os.path.exists(readme_build):
            return readme_build
    candidates = glob.glob(os.path.join(ROOT, "build*", "capi", "libimpulse2d.so")) + glob.glob(
        os.path.join(ROOT, "build*", "capi", "libimpulse2d.dylib")
    )
    return max(candidates, key=os.path.getmtime) if candidates else None


class BuildPyWithLibrary(build_py):
    def run(self):
        super().run()
        library = built_library()
        if library is None:
            print("impulse2d: no built libimpulse2d found; the package will look for it at import time")
            return
        target = os.path.join(self.build_lib, "impulse2d", os.path.basename(library))
        # Copy the file the symlink chain ends at, under the unversioned name.
        shutil.copyfile(os.path.realpath(library), target)
        print("impulse2d: bundled %s" % library)


setup(cmdclass={"build_py": BuildPyWithLibrary})
