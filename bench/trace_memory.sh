#!/usr/bin/env bash
# bench/trace_memory.sh: trace's peak resident memory against the size of its cube.
# The hawkeye scene's nadir view (data/scenes/hawkeye) at N x N pixels for N in SIZES,
# with the scene's 3 bands and with 100 bands of 5 spectral samples each over the same
# 0.40-0.69 um (BANDS), one primary and one hemisphere ray per pixel and no bounce
# (memory does not depend on the sampling); GNU time's peak RSS (%M) for each, beside
# the cube's size (4 bytes per pixel and spectral sample), and per band count the
# least-squares line peak = a + b x cube.
#
#   [TRACE=PROGRAM] [SIZES="256 512 1024 2048 4096"] [BANDS="3 100"] [FORMAT=img|tif]
#   [MAX_CUBE_GIB=8] bench/trace_memory.sh [BUILD]
#
# BUILD (default build/) gives the tools that make the inputs (hawkeye_scene,
# build_radiance, ...) and the trace measured, unless TRACE names another (an older
# build's, for a before/after table). Renders whose cube would exceed MAX_CUBE_GIB
# GiB are skipped (a 4096 x 4096 x 500 cube is 32 GiB of disk). Needs GNU time.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$SRC/build}" && pwd)
BIN=$BUILD/bin
TRACE=$(realpath "${TRACE:-$BIN/trace}")
SIZES=${SIZES:-256 512 1024 2048 4096}
BANDS=${BANDS:-3 100}
FORMAT=${FORMAT:-img}
MAX_CUBE_GIB=${MAX_CUBE_GIB:-8}
[ -x /usr/bin/time ] || { echo "trace_memory.sh: needs GNU time (apt-get install time)" >&2; exit 2; }
H=$SRC/data/scenes/hawkeye
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT

# The scene node with `bands` bands: the scene's own (3), or its 14400-25000 cm-1
# split into equal bands of 5 samples.
snd() {
    if [ "$1" = 3 ]; then cat "$H/hawkeye.snd"; return; fi
    awk -v n="$1" '
        /^[ \t]*#/ { print; next }
        { ++k }
        k == 2 { print n "\t# number of spectral bands"; next }
        k == 3 { w = (25000 - 14400) / n
                 for (i = 0; i < n; i++)
                     printf "%.4f %.4f %.4f\t# band %d\n", 14400 + i * w, 14400 + (i + 1) * w, w / 4, i + 1
                 next }
        k == 4 || k == 5 { next }
        { print }' "$H/hawkeye.snd"
}

printf 'trace peak memory against cube size: hawkeye nadir, %s, %s\n' "$FORMAT" "$TRACE"
printf '%6s %8s %10s %10s %10s %10s %9s %5s\n' bands samples pixels "cube MiB" "peak MiB" \
    peak/cube seconds exit
for b in $BANDS; do
    out=$W/b$b
    mkdir -p "$out"
    snd "$b" > "$out/hawkeye.snd"
    make -s -C "$H" OUT="$out/nadir" SND="$out/hawkeye.snd" SCENE_DIR="$W/scene-4" \
        SIGCHAIN_BIN="$BIN" HAWKEYE_SCENE="$BIN/hawkeye_scene" BUILD_RADIANCE_FLAGS=-q \
        rad view > "$out/make.log" 2>&1 || { cat "$out/make.log" >&2; exit 1; }
    rads=()
    for k in $(seq 1 "$b"); do rads+=("$out/nadir/hawkeye-$k.rad"); done
    samples=$(( $(awk '!/^[ \t]*(#|$)/ { if (++n == 3) { print int(($2 - $1) / $3 + 1.5); exit } }' \
        "$out/hawkeye.snd") * b ))
    for n in $SIZES; do
        cube=$(awk -v n="$n" -v s="$samples" 'BEGIN { printf "%.1f", n * n * s * 4 / 1048576 }')
        if awk -v c="$cube" -v m="$MAX_CUBE_GIB" 'BEGIN { exit !(c > m * 1024) }'; then continue; fi
        # The nadir view at n x n pixels over the same ground (pitch scaled), 1 sample.
        sed "s/^512 512\t/$n $n\t/; s/^pixel_pitch_um = 21.5/pixel_pitch_um = $(awk -v n="$n" \
            'BEGIN { printf "%.9g", 21.5 * 512 / n }')/" "$H/nadir.adv" > "$out/n.adv"
        status=0
        (cd "$H" && /usr/bin/time -f '%M %e' -o "$out/time" "$TRACE" -q --samples-per-pixel 1 \
            --sampling montecarlo --hemisphere-samples 1 --bounces 0 --no-adjacency \
            "$out/n.adv" "$out/nadir/hawkeye.snd" "$W/scene-4/hawkeye.odb" hawkeye.mat \
            "${rads[@]}" -o "$out/cube.$FORMAT") 2> "$out/err" || status=$?
        read -r kib seconds < <(tail -n 1 "$out/time")
        rm -f "$out"/cube.* "$out"/cube.geoloc.tif
        echo "$b $samples $n $cube $kib $seconds $status" >> "$W/rows"
        awk -v b="$b" -v s="$samples" -v n="$n" -v c="$cube" -v k="$kib" -v t="$seconds" -v x="$status" \
            'BEGIN { printf "%6d %8d %10s %10.1f %10.1f %10.2f %9.1f %5d\n", b, s, n "^2", c, k / 1024, k / 1024 / c, t, x }'
        [ "$status" = 0 ] || sed 's/^/    /' "$out/err"
    done
done
# peak = a + b x cube per band count (least squares over its renders).
awk '{ n[$1]++; x = $4; y = $5 / 1024; sx[$1] += x; sy[$1] += y; sxx[$1] += x * x; sxy[$1] += x * y }
     END { for (b in n) if (n[b] > 1) {
               d = n[b] * sxx[b] - sx[b] * sx[b]
               s = d ? (n[b] * sxy[b] - sx[b] * sy[b]) / d : 0
               printf "%d bands: peak = %.0f MiB + %.3f x cube\n", b, (sy[b] - s * sx[b]) / n[b], s } }' \
    "$W/rows" | sort -n
