#!/usr/bin/env bash
# Two or more builds of the library against each other on one scene: the same
# impulse2d_bench binary run against each library in turn, pinned to one CPU.
#
# usage: bench/ab_libraries.sh [-b BUILD_DIR] [-s SCENE] [-w WORKERS] [-r ROUNDS] [-c CPUS] LIBDIR LIBDIR...
#   (defaults: build, large_pyramid, 1, 8, 0; each LIBDIR holds a libimpulse2d.so.0, e.g. a
#   copy of BUILD_DIR/capi/ taken before a change)
#
# On a shared virtual machine a whole run can land a third or more slower than the one
# before it (the vCPU's physical core busy with another guest; bench/cpu_speeds.sh shows
# it per vCPU), and runs taken in a fixed order A, B, A, B can fall in step with those
# spells: a change that made large_pyramid 6 % slower once read as 24 % faster that way.
# So every run is pinned to the same CPUs (taskset), each round takes the libraries in a
# new random order, and the report splits the runs into the machine's fast and slow
# spells (runs more than 20 % above the fastest are counted slow) before comparing means
# within the fast one. Prints ms per step; times are never asserted on. Needs taskset
# (util-linux), shuf (coreutils) and python3.
set -euo pipefail
build=build; scene=large_pyramid; workers=1; rounds=8; cpus=0
while getopts "b:s:w:r:c:" option; do
  case $option in
    b) build=$OPTARG ;;
    s) scene=$OPTARG ;;
    w) workers=$OPTARG ;;
    r) rounds=$OPTARG ;;
    c) cpus=$OPTARG ;;
    *) sed -n '2,7p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 2 ] || { sed -n '2,7p' "$0"; exit 2; }
bench=$build/bench/impulse2d_bench
[ -x "$bench" ] || { echo "no $bench: build this project in Release first"; exit 2; }
for tool in taskset shuf python3; do
  command -v $tool >/dev/null || { echo "needs $tool"; exit 2; }
done
for lib in "$@"; do
  [ -e "$lib/libimpulse2d.so.0" ] || { echo "no $lib/libimpulse2d.so.0"; exit 2; }
done
raw=$(mktemp); trap 'rm -f "$raw"' EXIT
for _ in $(seq "$rounds"); do
  for lib in $(printf '%s\n' "$@" | shuf); do
    ms=$(LD_LIBRARY_PATH=$lib taskset -c "$cpus" "$bench" --scene "$scene" --workers "$workers" --repeat 1 --csv \
           2>/dev/null |
         python3 -c "
import csv, sys
rows = [r for r in csv.reader(l for l in sys.stdin if not l.startswith('#'))]
print(rows[1][rows[0].index('median_ms')])")
    echo "$lib $ms" >>"$raw"
  done
done
python3 - "$raw" "$scene" "$workers" "$cpus" "$@" <<'EOF'
import statistics, sys
raw, scene, workers, cpus = sys.argv[1:5]
libs = list(dict.fromkeys(sys.argv[5:]))  # a library named twice is one library
runs = {lib: [] for lib in libs}
for line in open(raw):
    lib, ms = line.split()
    runs[lib].append(float(ms))
fastest = min(min(v) for v in runs.values())
slow_above = 1.2 * fastest  # a run this far above the fastest fell in a slow spell
print(f"{scene}, {workers} worker(s) pinned to cpu {cpus}, ms per step; runs above {slow_above:.3f} counted slow")
base = None
for lib in libs:
    fast = [ms for ms in runs[lib] if ms <= slow_above]
    slow = len(runs[lib]) - len(fast)
    mean = statistics.mean(fast) if fast else float("nan")
    base = base if base is not None else mean
    spread = f"{min(fast):.3f}-{max(fast):.3f}" if fast else "-"
    print(f"  {lib}: {mean:.3f} ({mean / base:.3f})  fast runs {len(fast)} ({spread}), slow {slow}")
EOF
