#!/usr/bin/env bash
# trace's set-up time on the hawkeye scene, two trace programs side by side in one run.
#   [THREADS=N] bench/trace_setup.sh TRACE_A TRACE_B [RUNS]
# Builds the hawkeye scene's inputs once (data/scenes/hawkeye, the nadir view at 8 x 8
# pixels, with the tools beside TRACE_B), then runs TRACE_A and TRACE_B in turn RUNS
# times (default 7) with -v and prints, per program, the median of trace -v's set-up,
# scene-files, Embree-build and render seconds and of the whole process's wall time, and
# the ratios A/B of the medians. The two cubes must be the same bytes (else exit 1).
# THREADS=N runs both with --threads N (default: trace's own default, all cores).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 TRACE_A TRACE_B [RUNS]" >&2; exit 2; }
A=$(realpath "$1") B=$(realpath "$2") RUNS=${3:-7} THREADS=${THREADS:-0}
SRC=$(cd "$(dirname "$0")/.." && pwd)
H=$SRC/data/scenes/hawkeye
BIN=$(dirname "$B")
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
sed 's/^512 512\t/8 8\t/; s/^pixel_pitch_um = 21.5/pixel_pitch_um = 1376/' "$H/nadir.adv" > "$W/nadir.adv"
make -s -C "$H" VIEW=nadir ADV="$W/nadir.adv" OUT="$W/out/nadir" SIGCHAIN_BIN="$BIN" \
    HAWKEYE_SCENE="$BIN/hawkeye_scene" > "$W/make.log" 2>&1 ||
    { cat "$W/make.log" >&2; exit 1; }
O=$W/out/nadir
args=("$W/nadir.adv" "$O/hawkeye.snd" "$W/out/scene-4/hawkeye.odb" hawkeye.mat
      "$O/hawkeye-1.rad" "$O/hawkeye-2.rad" "$O/hawkeye-3.rad")
run() {  # PROGRAM OUT.img -> "setup scene build render wall"
    local t0 t1 line
    t0=$(date +%s.%N)
    line=$(cd "$H" && "$1" -v --threads "$THREADS" "${args[@]}" -o "$2" 2>&1 | grep 'set-up ')
    t1=$(date +%s.%N)
    sed -E 's/.*set-up ([0-9.]+) s:.*scene files ([0-9.]+) s, Embree build ([0-9.]+) s.*render ([0-9.]+) s.*/\1 \2 \3 \4/' \
        <<< "$line" | tr -d '\n'
    echo " $(echo "$t1 - $t0" | bc)"
}
for ((i = 0; i < RUNS; i++)); do
    run "$A" "$W/a.img" >> "$W/a.txt"
    run "$B" "$W/b.img" >> "$W/b.txt"
done
cmp "$W/a.img" "$W/b.img" || { echo "$0: the two cubes differ" >&2; exit 1; }
median() {  # FILE COLUMN
    sort -g -k"$2","$2" "$1" | awk -v c="$2" '{ v[NR] = $c } END { print v[int((NR + 1) / 2)] }'
}
printf '%-10s %10s %12s %13s %10s %10s\n' "" set-up "scene files" "Embree build" render "wall"
for p in a b; do
    printf '%-10s' "$p"
    for c in 1 2 3 4 5; do printf ' %10.3f' "$(median "$W/$p.txt" $c)"; done
    echo
done
printf '%-10s' "A/B"
for c in 1 2 3 4 5; do
    printf ' %10.2f' "$(echo "$(median "$W/a.txt" $c) / $(median "$W/b.txt" $c)" | bc -l)"
done
echo
echo "($RUNS runs each, alternating, --threads $THREADS; seconds, medians; the cubes are identical)"
