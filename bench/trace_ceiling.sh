#!/usr/bin/env bash
# How close render() can come to the bare Embree loop: a perf profile of bench_trace,
# split by its phases, counting the samples inside Embree apart from the rest.
#   bench/trace_ceiling.sh BENCH_TRACE [VERTICES_PER_SIDE [TREES [IMAGE_SIDE]]]
# Runs BENCH_TRACE under `perf record -e task-clock -k CLOCK_MONOTONIC` with BENCH_PHASES
# set (bench_trace then prints each phase's start and end on that clock) and prints, per
# phase, the samples (1 ms of CPU each, both threads), those in libembree3 and the rest;
# then, for each render, its Embree samples over the bare golf-ball loop's (the same rays:
# above 1, Embree itself runs slower inside render than in the bare loop), and the ceiling
# bare / render-Embree: the ratio render / bare golf-ball would reach were all of render's
# own work (shading, the sky lookup, the Scene wrapper) free, and how many of its own
# samples a ratio of 0.9 would leave room for. Last, the non-Embree functions that take
# most of the first render's samples.
# Without perf (Debian's linux-perf) it says so and exits 0.
set -euo pipefail
usage="usage: $0 BENCH_TRACE [VERTICES_PER_SIDE [TREES [IMAGE_SIDE]]]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
command -v perf > /dev/null || { echo "$0: perf not installed (linux-perf): skipped"; exit 0; }
BENCH=$(realpath "$1")
shift
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
BENCH_PHASES=1 perf record -q -e task-clock -F 1000 -k CLOCK_MONOTONIC -o "$W/perf.data" \
    -- "$BENCH" "$@" > "$W/bench.txt" 2> "$W/phases.txt" ||
    { cat "$W/phases.txt" >&2; exit 1; }
grep -E '^ratio render / bare golf-ball  ' "$W/bench.txt"
perf script -i "$W/perf.data" -F time,ip,sym,dso 2> /dev/null > "$W/samples.txt"
python3 - "$W/phases.txt" "$W/samples.txt" << 'EOF'
import collections, re, sys

phases = []  # (name, start, end) in CLOCK_MONOTONIC seconds
for line in open(sys.argv[1]):
    f = line.split()
    if len(f) == 4 and f[0] == "phase":
        phases.append((f[1], float(f[2]), float(f[3])))
counts = [[0, 0] for _ in phases]  # samples, of which in Embree
own = collections.Counter()  # the first render's non-Embree samples by function
sample = re.compile(r"^\s*([0-9]+\.[0-9]+):\s+[0-9a-f]+\s+(.*)$")
for line in open(sys.argv[2]):
    m = sample.match(line)
    if not m:
        continue
    t, rest = float(m.group(1)), m.group(2)
    embree = "libembree" in rest
    for i, (name, t0, t1) in enumerate(phases):
        if t0 <= t <= t1:
            counts[i][0] += 1
            counts[i][1] += embree
            if i == 0 and not embree:
                own[re.sub(r"\s+\([/\[][^()]*\)$", "", rest).strip() or "?"] += 1
            break
print(f"{'phase':28s} {'samples':>8s} {'Embree':>8s} {'other':>8s}")
for (name, _, _), (total, embree) in zip(phases, counts):
    print(f"{name:28s} {total:8d} {embree:8d} {total - embree:8d}")
bare = [c[0] for (name, _, _), c in zip(phases, counts) if name == "bare-golfball"]
renders = [c for (name, _, _), c in zip(phases, counts) if name == "render"]
if bare and renders:
    best_bare = min(bare)
    for i, (total, embree) in enumerate(renders):
        if embree == 0:
            print(f"render {i + 1}: no samples in libembree (Embree linked otherwise?)")
            continue
        print(f"render {i + 1}: Embree inside render / whole bare golf-ball loop "
              f"{embree / best_bare:.2f}; ceiling with free shading {best_bare / embree:.2f}; "
              f"now {best_bare / total:.2f} (samples)")
        budget = best_bare / 0.9 - embree  # render's own samples that 0.9 leaves room for
        cut = (f"a cut of {(total - embree) / budget:.1f} times" if budget > 0
               else "out of reach even with free shading")
        print(f"  own work {total - embree}; 0.9 leaves room for {budget:.0f}: {cut}")
print("the first render's non-Embree samples, most first:")
for name, n in own.most_common(14):
    print(f"  {n:7d}  {name}")
EOF
