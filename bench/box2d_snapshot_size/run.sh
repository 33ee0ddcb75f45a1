#!/usr/bin/env bash
# Snapshot sizes of Box2D v3 (b2World_Snapshot) beside impulse2d's on the same scenes at the
# same step: builds box2d_snapshot_size.c against a Box2D v3 checkout and runs it; with an
# impulse2d build, also runs impulse2d_snapshot_bench --csv and prints the two side by side.
# Not part of impulse2d's build or CI: Box2D is only run here, never copied into the project.
#
# usage: run.sh BOX2D [IMPULSE2D_BUILD_DIR]
#   BOX2D                a git directory of erincatto/box2d (what the search tool's fetch returns)
#                        or a source checkout (the folder holding include/box2d/box2d.h)
#   IMPULSE2D_BUILD_DIR  a build of this project holding bench/impulse2d_snapshot_bench
#
# A git directory is checked out and built where the side-by-side tool builds it,
# ${TMPDIR:-/tmp}/box2d-v3-<commit> (Release, AVX2, benchmarks on), and a build already there is
# reused. A source checkout is built in ${TMPDIR:-/tmp}/box2d-snapshot-size-build.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 1 ] || { sed -n 2,14p "$0"; exit 2; }
box2d=$1
i2d_build=${2:-}

if [ -f "$box2d/HEAD" ] && [ -d "$box2d/objects" ]; then
  commit=$(git --git-dir="$box2d" rev-parse --short HEAD)
  root=${TMPDIR:-/tmp}/box2d-v3-$commit
  src=$root/src
  build=$root/build
  if [ ! -f "$build/src/libbox2d.a" ] || [ ! -f "$build/shared/libshared.a" ]; then
    echo "building Box2D v3 $commit in $root (once)" >&2
    rm -rf "$root"; mkdir -p "$src"
    git --git-dir="$box2d" --work-tree="$src" checkout -f HEAD -- .
  fi
elif [ -f "$box2d/include/box2d/box2d.h" ]; then
  src=$(cd "$box2d" && pwd)
  commit=$(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo "unknown commit")
  build=${TMPDIR:-/tmp}/box2d-snapshot-size-build
else
  echo "run.sh: $box2d is neither a git directory nor a Box2D source checkout" >&2
  exit 2
fi
if ! grep -q "b2World_Snapshot" "$src/include/box2d/box2d.h"; then
  echo "Box2D $commit has no b2World_Snapshot" >&2
  exit 1
fi
if [ ! -f "$build/src/libbox2d.a" ] || [ ! -f "$build/shared/libshared.a" ]; then
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBOX2D_SAMPLES=OFF -DBOX2D_BENCHMARKS=ON \
    -DBOX2D_UNIT_TESTS=OFF -DBOX2D_AVX2=ON >"$build.configure.log" 2>&1
  cmake --build "$build" -j2 >"$build.build.log" 2>&1
fi

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cc -O2 -std=c17 -Wall -Wextra -I"$src/include" -I"$src/shared" "$here/box2d_snapshot_size.c" \
  "$build/shared/libshared.a" "$build/src/libbox2d.a" -lm -lpthread -o "$tmp/box2d_snapshot_size"
echo "Box2D v3 $commit" >&2
"$tmp/box2d_snapshot_size" >"$tmp/box2d.csv"
if [ -z "$i2d_build" ]; then
  cat "$tmp/box2d.csv"
  exit 0
fi
"$i2d_build/bench/impulse2d_snapshot_bench" --csv --scene large_pyramid,rain,joint_grid,many_pyramids \
  >"$tmp/impulse2d.csv"
python3 - "$tmp/box2d.csv" "$tmp/impulse2d.csv" "$commit" <<'PY'
import csv, sys
b2 = {r["scene"]: r for r in csv.DictReader(open(sys.argv[1]))}
i2d = {r["scene"]: r for r in csv.DictReader(open(sys.argv[2]))}
print(f"Full snapshot bytes, impulse2d against Box2D v3 {sys.argv[3]} (b2World_Snapshot), same scene, same step")
print(f"{'scene':14s} {'steps':>5s} {'bodies i2d/b2':>13s} {'points i2d/b2':>15s} {'impulse2d B':>12s} "
      f"{'Box2D B':>12s} {'ratio':>6s} {'i2d state B':>12s} {'state/Box2D':>11s}")
for s, b in b2.items():
    i = i2d.get(s)
    if i is None:
        continue
    steps = i["steps"] if i["steps"] == b["steps"] else f"{i['steps']}/{b['steps']}"
    ratio = int(i["snapshot_bytes"]) / int(b["snapshot_bytes"])
    state = int(i["state_bytes"]) / int(b["snapshot_bytes"])
    print(f"{s:14s} {steps:>5s} {i['dynamic_bodies'] + '/' + b['dynamic_bodies']:>13s} "
          f"{i['touching_points'] + '/' + b['touching_points']:>15s} {int(i['snapshot_bytes']):12d} "
          f"{int(b['snapshot_bytes']):12d} {ratio:6.3f} {int(i['state_bytes']):12d} {state:11.3f}")
print("ratio: impulse2d's full snapshot over Box2D's (<= 1 meets issue 38); state/Box2D: impulse2d's rollback")
print("state over Box2D's snapshot (Box2D has no smaller rollback image).")
PY
