#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Proves that pip builds libimpulse2d from source when no built library is given: on a copy
# of the source tree without any build*/ directory (as a fresh clone is), offline,
#   1. `pip wheel` makes one py3-none-<platform> wheel holding impulse2d/libimpulse2d.so;
#   2. that wheel, installed with --target, imports from elsewhere, loads its bundled
#      library and drops a ball as v = g t says;
#   3. `pip install` of the source directory does the same, together with
#      bindings/box2d-compat in the same command, whose Box2D module (with its compiled
#      ray cast loop) then drops a body.
# Compiling the library twice takes most of the time (about half a minute each on 2 cores).
# Needs cmake, a C++ compiler, and a Python with pip, setuptools, wheel and its headers
# (Debian: cmake g++ python3-pip python3-setuptools python3-wheel python3-dev); no network.
#
# usage: tests/tools/check_pip_build.sh      (PYTHON=/usr/bin/python3 to choose the Python)
set -euo pipefail

python=${PYTHON:-python3}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A built library named here would be bundled instead of the one this checks.
unset IMPULSE2D_LIBRARY IMPULSE2D_BUNDLE

# Offline: no index, and the build runs in this Python (its setuptools and wheel), as
# there is no index to fill an isolated build environment from.
pip() {
  PIP_ROOT_USER_ACTION=ignore "$python" -m pip "$@" --no-build-isolation --no-index --disable-pip-version-check
}

# The tracked and new (not ignored) files only: no build*/, as in a fresh clone. Outside
# git, everything but build*/ and .git.
copy_source_tree() {
  local target=$1
  mkdir -p "$target"
  if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    (cd "$root" && git ls-files -z --cached --others --exclude-standard |
      tar --null --ignore-failed-read -T - -cf -) 2>/dev/null | tar -C "$target" -xf -
  else
    tar -C "$root" --exclude='./build*' --exclude=./.git -cf - . | tar -C "$target" -xf -
  fi
  if compgen -G "$target/build*" >/dev/null; then
    echo "FAIL: the copy of the source tree has a build directory" >&2
    exit 1
  fi
}

# Runs pip verbosely into a log, shown only on failure; the log must say the library was
# built from source (not taken from somewhere else).
pip_from_source() {
  local log=$1
  shift
  if ! pip "$@" -v >"$log" 2>&1; then
    cat "$log" >&2
    echo "FAIL: pip $*" >&2
    exit 1
  fi
  if ! grep -q "impulse2d: building libimpulse2d from source with CMake" "$log"; then
    grep "impulse2d:" "$log" >&2 || true
    echo "FAIL: pip $* did not build the library from source" >&2
    exit 1
  fi
}

check_wheel() {
  local dist=$1
  "$python" - "$dist" <<'EOF'
import glob, os, sys, sysconfig, zipfile

dist = sys.argv[1]
wheels = glob.glob(os.path.join(dist, "*.whl"))
assert len(wheels) == 1, "expected one wheel, got %s" % wheels
platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
expected = "impulse2d-0.2.0-py3-none-%s.whl" % platform
name = os.path.basename(wheels[0])
assert name == expected, "wheel %s, expected %s" % (name, expected)
with zipfile.ZipFile(wheels[0]) as wheel:
    files = wheel.namelist()
for needed in ("impulse2d/libimpulse2d.so", "impulse2d/gym/__init__.py"):
    assert needed in files, "no %s in %s" % (needed, files)
print("wheel:", name, "holds impulse2d/libimpulse2d.so and impulse2d.gym")
EOF
}

# Imports the installed package from / (so no source tree is near) and drops a ball.
check_installed() {
  local target=$1
  (cd / && PYTHONPATH="$target" "$python" - "$target" <<'EOF'
import os, sys
import impulse2d
import impulse2d.gym

target = os.path.realpath(sys.argv[1])
loaded = os.path.realpath(impulse2d.library_path)
assert loaded == os.path.join(target, "impulse2d", "libimpulse2d.so"), "loaded %s" % loaded

g, dt, steps = 10.0, 1.0 / 60.0, 30
with impulse2d.World(gravity=(0, -g)) as world:
    ball = world.create_body(position=(0, 10))
    ball.create_circle(0.5)
    for _ in range(steps):
        world.step(dt, 4)
    vy = ball.linear_velocity[1]
expected = -g * dt * steps  # no damping, no contact: v = g t
assert abs(vy - expected) < 1e-4 * g, "ball velocity %r, expected %r" % (vy, expected)
print("import from /: loads", loaded, "- ball falls at %.4f m/s after %.2f s" % (vy, dt * steps))
EOF
  )
}

# The compat package's Box2D, installed beside impulse2d: a body falls under b2World's
# default gravity of (0, -10) as v = g t.
check_box2d_compat() {
  local target=$1
  (cd / && PYTHONPATH="$target" "$python" - <<'EOF'
import Box2D
import Box2D._world

# pip built the compiled ray cast loop (Python's headers are a prerequisite here).
assert Box2D._world._ray_cast is not None, "pip installed Box2D without Box2D._raycast"
world = Box2D.b2World()
body = world.CreateDynamicBody(position=(0, 10))
body.CreateCircleFixture(radius=0.5, density=1.0)
for _ in range(30):
    world.Step(1.0 / 60.0, 6, 2)
vy = body.linearVelocity[1]
assert abs(vy + 5.0) < 1e-3, "Box2D body velocity %r, expected -5" % vy
print("Box2D from", Box2D.__file__, "- a body falls at %.4f m/s after 0.5 s; RayCast compiled" % vy)
EOF
  )
}

timed() {
  local start=$SECONDS
  "$@"
  echo "  ($((SECONDS - start)) s)"
}

# Says what is missing instead of letting pip fail deep in its output.
check_prerequisites() {
  command -v cmake >/dev/null || { echo "FAIL: no cmake on PATH (apt-get install cmake)" >&2; exit 1; }
  if ! "$python" -c "import setuptools, wheel" 2>/dev/null; then
    echo "FAIL: $python lacks setuptools or wheel (apt-get install python3-setuptools python3-wheel," \
      "and PYTHON=/usr/bin/python3)" >&2
    exit 1
  fi
  if ! "$python" -c "import os, sysconfig; assert os.path.exists(sysconfig.get_paths()['include'] + '/Python.h')" \
    2>/dev/null; then
    echo "FAIL: $python has no headers to build Box2D._raycast with (apt-get install python3-dev)" >&2
    exit 1
  fi
}

check_prerequisites
copy_source_tree "$work/src"
package="$work/src/bindings/python"

echo "== pip wheel from source"
timed pip_from_source "$work/wheel.log" wheel "$package" -w "$work/dist"
check_wheel "$work/dist"
pip install -q --target "$work/from_wheel" "$work"/dist/*.whl
check_installed "$work/from_wheel"

# From scratch again: without the wheel step's build directory (setuptools' build_temp in
# bindings/python/build), which pip would otherwise reuse.
rm -rf "$package/build"
echo "== pip install of the source directory, with the Box2D compat package"
timed pip_from_source "$work/install.log" install --target "$work/from_source" "$package" \
  "$work/src/bindings/box2d-compat"
check_installed "$work/from_source"
check_box2d_compat "$work/from_source"

echo "pip build from source: OK"
