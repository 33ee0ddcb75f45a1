#!/usr/bin/env bash
# How fast each CPU of this machine steps the same scene with 1 worker, pinned to it.
#
# usage: bench/cpu_speeds.sh [BUILD_DIR] [SCENE] [ROUNDS]   (defaults: build, large_pyramid, 3)
#
# A 2-worker step is no faster than its slower core allows. On a shared virtual machine
# one vCPU can run a third slower than the other for minutes at a time (its physical core
# busy with another guest), and which one changes; a speed-up read from a side-by-side run
# means little without this figure taken next to it. Rounds alternate the CPUs so that a
# change in the machine falls on all of them alike. Then bench/core_round_trip (Linux) gives
# how long a cache line takes between the first two CPUs and back: a shared step pays that
# at every stage boundary, and on a VM it changes with where the host put the vCPUs (120 or
# 480 ns on this one). Needs taskset (util-linux).
set -euo pipefail
build=${1:-build}; scene=${2:-large_pyramid}; rounds=${3:-3}
bench=$build/bench/impulse2d_bench
[ -x "$bench" ] || { echo "no $bench: build this project in Release first"; exit 2; }
command -v taskset >/dev/null || { echo "needs taskset (util-linux)"; exit 2; }
cpus=$(taskset -pc $$ | sed 's/.*: //' | tr ',' ' ')
expanded=()
for part in $cpus; do
  if [[ $part == *-* ]]; then expanded+=($(seq "${part%-*}" "${part#*-}")); else expanded+=("$part"); fi
done
raw=$(mktemp); trap 'rm -f "$raw"' EXIT
for r in $(seq "$rounds"); do
  for cpu in "${expanded[@]}"; do
    ms=$(taskset -c "$cpu" "$bench" --scene "$scene" --repeat 1 --csv 2>/dev/null |
         python3 -c "
import csv, sys
rows = [r for r in csv.reader(l for l in sys.stdin if not l.startswith('#'))]
head = rows[0]
print(next(r[head.index('median_ms')] for r in rows[1:] if r and r[0] == '$scene'))")
    echo "$cpu,$ms" >>"$raw"
  done
done
python3 - "$raw" "$scene" "$rounds" <<'PY'
import statistics, sys
by_cpu = {}
for line in open(sys.argv[1]):
    cpu, ms = line.strip().split(',')
    by_cpu.setdefault(int(cpu), []).append(float(ms))
medians = {cpu: statistics.median(v) for cpu, v in sorted(by_cpu.items())}
print(f"{sys.argv[2]}, 1 worker pinned, median of {sys.argv[3]} alternating runs (ms per step):")
for cpu, ms in medians.items():
    print(f"  cpu {cpu}: {ms:.3f}   (runs: {', '.join(f'{x:.3f}' for x in by_cpu[cpu])})")
fast, slow = min(medians.values()), max(medians.values())
print(f"slowest / fastest: {slow / fast:.2f}; a 2-worker speed-up over the faster CPU is at most "
      f"{1 + fast / slow:.2f} even with no cost of sharing the work")
PY
# The other half of what a shared step costs: how far apart the host put the two vCPUs.
trip=$build/bench/core_round_trip
if [ -x "$trip" ]; then "$trip"; fi
