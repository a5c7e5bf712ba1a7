#!/bin/sh
# bench/thermal_settings.sh: what the Pennsylvania thermal band's default settings cost
# and lose. Runs `make thermal` in data/scenes/pennsylvania twice, side by side in one
# run: the Makefile's defaults (the shadow history with one point per facet every 30
# minutes, therm with 300 s steps) and the tools' finer settings (4 points per facet,
# 15-minute history, 60 s steps), each into its own folder (out/thermal_bench_coarse,
# out/thermal_bench_fine; the scene's other outputs are made once and shared), and
# prints each one's wall time, their ratio, and the largest difference of every
# score of out/thermal/score.txt between the two.
#
#   bench/thermal_settings.sh [BIN_DIR]    (default build/bin)
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$src/build/bin}" && pwd)
pa=$src/data/scenes/pennsylvania
out=out
make -s -C "$pa" -j 2 SIGCHAIN_BIN="$bin" "$out/july/classes.tif" "$out/atm/november/rad.stamp" \
    "$out/july/november.odb" "$out/july/terrain.tif" "$out/july/mask.tif" \
    "$out/july/points_held.cpt" > /dev/null
run() {  # run NAME SHADOW_FLAGS THERM_STEP: seconds of `make thermal` into out/thermal_bench_NAME
    rm -rf "$pa/$out/thermal_bench_$1"
    t0=$(date +%s.%N)
    make -s -C "$pa" SIGCHAIN_BIN="$bin" TH="$out/thermal_bench_$1" \
        THERMAL_SHADOW_FLAGS="$2" THERM_STEP="$3" "$out/thermal_bench_$1/score.txt" > /dev/null
    t1=$(date +%s.%N)
    echo "$t1 $t0" | awk '{ printf "%.1f", $1 - $2 }'
}
coarse=$(run coarse "--points-per-facet 1 --history-step-minutes 30" 300)
fine=$(run fine "--points-per-facet 4 --history-step-minutes 15" 60)
echo "thermal band, make thermal: defaults $coarse s, finer settings $fine s" \
    "($(echo "$fine $coarse" | awk '{ printf "%.1f", $1 / $2 }') x)"
awk 'FNR == NR { if (!/^#/) { roc[$1] = $4; rms[$1] = $5; bias[$1] = $6 } next }
    !/^#/ { d = $4 - roc[$1]; if (d < 0) d = -d; if (d > droc) droc = d
            d = $5 - rms[$1]; if (d < 0) d = -d; if (d > drms) drms = d
            d = $6 - bias[$1]; if (d < 0) d = -d; if (d > dbias) dbias = d }
    END { printf "largest difference, defaults against finer: ROC %.4f, RMS %.3f DN, bias %.3f DN\n",
          droc, drms, dbias }' \
    "$pa/$out/thermal_bench_fine/score.txt" "$pa/$out/thermal_bench_coarse/score.txt"
