# SPDX-License-Identifier: MIT
"""The compat package's one compiled part: Box2D._raycast, b2World.RayCast's loop in C
(BipedalWalker's ten lidar rays a frame cost half as much). It is built where a C
compiler and Python's headers are (Debian: python3-dev), with the headers of this source
tree's include/; it is optional: without them pip installs the package with the same
loop in Python. Everything else is in pyproject.toml."""

import os

from setuptools import Extension, setup

HERE = os.path.dirname(os.path.abspath(__file__))
INCLUDE = os.path.normpath(os.path.join(HERE, "..", "..", "include"))

setup(ext_modules=[Extension("Box2D._raycast", sources=["Box2D/_raycast.c"], include_dirs=[INCLUDE],
                             optional=True)])
