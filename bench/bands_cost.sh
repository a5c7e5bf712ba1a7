#!/usr/bin/env bash
# The cost of each stage per spectral band, side by side in one run.
#   bench/bands_cost.sh BUILD [BANDS...]        (default BANDS: 3 30 100 200)
# Environment: ROUNDS [3] rounds over the band counts, SIZE [32] the image's lines and
# detectors, PER_BAND_MAX [100] the largest count also run as one build_radiance per
# band, OUT [none] a folder for the raw times (bands_cost.tsv, for `make chart`),
# TRACE_FLAGS [none] flags added to trace's command line (e.g. --open-sky sampled).
#
# The stages of data/scenes/hawkeye's imaging spectrometer (`make hyperspectral`:
# hyperspectral.mk, 5 spectral samples per band) with N of the 211 bands of
# hyperspectral.bands, spread evenly over 0.4-2.5 um (a band's cost depends on its
# wavelength: the water bands of the short-wave infrared take build_radiance several
# times a visible band's time, so the first N bands would mix count and region), the
# pushbroom at SIZE x SIZE pixels (the same swath, larger pixels): control7 (once; no bands), build_radiance (one run for the N bands, and, up
# to PER_BAND_MAX, one run per band as BUILD_RADIANCE_RUNS=band makes it), trace
# (with -v: its set-up, the .rad tables' share of it, its render) and sensorize
# (--float). The band counts alternate within each round, so that the machine's load
# falls on all of them alike; each figure is the median of the rounds, wall seconds
# (every stage uses all cores). Then, per stage, the seconds per band: the slope of a
# least-squares line through (bands, seconds), and the fixed cost at 0 bands.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 BUILD [BANDS...]" >&2; exit 2; }
BIN=$(cd "$1/bin" && pwd)
shift
COUNTS=("${@:-3 30 100 200}")
read -r -a COUNTS <<< "${COUNTS[*]}"
ROUNDS=${ROUNDS:-3} SIZE=${SIZE:-32} PER_BAND_MAX=${PER_BAND_MAX:-100}
SRC=$(cd "$(dirname "$0")/.." && pwd)
H=$SRC/data/scenes/hawkeye
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT

# The pushbroom at SIZE x SIZE (as tests/cli/hawkeye_hyperspectral.bats shrinks it).
f=$(awk -v s="$SIZE" 'BEGIN { print 64 / s }')
awk -v s="$SIZE" -v f="$f" '/^64 64\t/ { sub(/^64 64/, s " " s) }
    /^pixel_pitch_um = / { $3 = $3 * f } /^line_period_s = / { $3 = $3 * f } { print }' \
    "$H/hyperspectral.adv" > "$W/hsi.adv"

# Each count's inputs, made by the scene's own rules (scene node, view range, .sen
# files, materials); the geometry once, shared.
seconds() { /usr/bin/time -f %e -o "$W/time" "$@" > /dev/null 2>> "$W/log" && cat "$W/time"; }
for n in "${COUNTS[@]}"; do
    # Rows 1 + j (T - 1) / (N - 1), j = 0 .. N - 1, rounded, of the T rows.
    awk -v n="$n" -v t="$(grep -vcE '^[[:space:]]*(#|$)' "$H/hyperspectral.bands")" '
        BEGIN { want = n == 1 ? int((t + 1) / 2) : 1 }
        /^[ \t]*(#|$)/ { print; next }
        ++k == want { print; j++; want = int(1 + j * (t - 1) / (n - 1) + 0.5) }' \
        "$H/hyperspectral.bands" > "$W/bands-$n"
    [ "$(grep -vcE '^[[:space:]]*(#|$)' "$W/bands-$n")" = "$n" ] ||
        { echo "$0: $n bands: the table has fewer" >&2; exit 2; }
    o=$W/out/$n
    make -s -C "$H" VIEW=hyperspectral ADV="$W/hsi.adv" OUT="$o" HSI_TABLE="$W/bands-$n" \
        SIGCHAIN_BIN="$BIN" HAWKEYE_SCENE="$BIN/hawkeye_scene" CONTROL7_FLAGS=-q \
        "$o/hawkeye.snd.stamp" "$o/hyperspectral.mat" "$o/sen/band-1.sen" "$o/hawkeye.cdk" \
        >> "$W/log" 2>&1 || { cat "$W/log" >&2; exit 1; }
    for ((k = 1; k <= n && n <= PER_BAND_MAX; k++)); do
        awk -v k="$k" '/^[ \t]*(#|$)/ { print; next } { m++ }
            m == 2 { nb = $1; print 1; next } m >= 3 && m < 3 + nb && m != 2 + k { next }
            { print }' "$o/hawkeye.snd" > "$o/band-$k.snd"
    done
done
ODB=$W/out/scene-4/hawkeye.odb
AZ=$(cat "$W/out/${COUNTS[0]}/hawkeye.azimuth")

# One round over the counts: "bands control7 build_radiance per_band trace setup rad_tables
# render sensorize" per line ("-" where not run).
round() {
    local n o c7 br pb tr line sz
    for n in "${COUNTS[@]}"; do
        o=$W/out/$n
        c7=$(cd "$H" && seconds "$BIN/control7" -q --answers hawkeye.answers -o "$o/c7.cdk")
        br=$(seconds "$BIN/build_radiance" -q --view-azimuth "$AZ" "$o/hawkeye.cdk" \
            "$o/hawkeye.snd" -o "$o/hawkeye-%d.rad")
        pb=-
        if [ "$n" -le "$PER_BAND_MAX" ]; then
            /usr/bin/time -f %e -o "$W/time" sh -c 'o=$1 az=$2 bin=$3 n=$4
                for k in $(seq 1 "$n"); do "$bin/build_radiance" -q --view-azimuth "$az" \
                    "$o/hawkeye.cdk" "$o/band-$k.snd" -o "$o/b-$k.rad" || exit 1; done' \
                sh "$o" "$AZ" "$BIN" "$n" 2>> "$W/log"
            pb=$(cat "$W/time")
            for k in $(seq 1 "$n"); do cmp -s "$o/b-$k.rad" "$o/hawkeye-$k.rad" ||
                { echo "$0: band $k of $n: one run per band wrote other bytes" >&2; exit 1; }; done
        fi
        /usr/bin/time -f %e -o "$W/time" "$BIN/trace" -v "$W/hsi.adv" "$o/hawkeye.snd" "$ODB" \
            "$o/hyperspectral.mat" $(seq -f "$o/hawkeye-%g.rad" 1 "$n") -o "$o/cube.img" ${TRACE_FLAGS:-} \
            2> "$W/trace.log" || { cat "$W/trace.log" >&2; exit 1; }
        tr=$(cat "$W/time")
        line=$(sed -n -E 's/.*set-up ([0-9.]+) s:.*\.rad tables ([0-9.]+) s.*render ([0-9.]+) s.*/\1 \2 \3/p' \
            "$W/trace.log")
        sz=$(seconds "$BIN/sensorize" -q --float "$o/cube.img" \
            $(seq -f "$o/sen/band-%g.sen" 1 "$n") -o "$o/counts.tif")
        echo "$n $c7 $br $pb $tr $line $sz"
    done
}
for ((r = 1; r <= ROUNDS; r++)); do round >> "$W/times"; done

# Medians per count, then the line through them per stage.
median() {  # BANDS COLUMN
    awk -v n="$1" -v c="$2" '$1 == n && $c != "-" { print $c }' "$W/times" | sort -g |
        awk '{ v[NR] = $1 } END { if (NR) print v[int((NR + 1) / 2)]; else print "-" }'
}
names=(bands control7 build_radiance "one per band" trace "  set-up" "  .rad tables" "  render" sensorize)
printf '%-6s' "${names[0]}"
for ((c = 2; c <= 9; c++)); do printf ' %14s' "${names[c - 1]}"; done
echo
for n in "${COUNTS[@]}"; do
    printf '%-6s' "$n"
    for ((c = 2; c <= 9; c++)); do printf ' %14s' "$(median "$n" "$c")"; done
    echo
done | tee "$W/medians"
fit() {  # COLUMN -> "slope intercept" of a least-squares line through the medians
    awk -v c="$1" '$c != "-" { x = $1; y = $c; n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
        END { if (n < 2) { print "- -"; exit } d = n * sxx - sx * sx; s = (n * sxy - sx * sy) / d
              printf "%.4f %.3f\n", s, (sy - s * sx) / n }' "$W/medians"
}
printf '%-6s' "s/band"
for ((c = 2; c <= 9; c++)); do read -r s _ <<< "$(fit "$c")"; printf ' %14s' "$s"; done
echo
printf '%-6s' "fixed"
for ((c = 2; c <= 9; c++)); do read -r _ i <<< "$(fit "$c")"; printf ' %14s' "$i"; done
echo
echo "(wall seconds, medians of $ROUNDS rounds, counts alternating; ${SIZE}x${SIZE} pushbroom," \
    "bands spread over 0.4-2.5 um, 5 samples each; s/band and fixed: least-squares line through the medians;" \
    "\"one per band\" up to $PER_BAND_MAX bands, its tables identical to the one run's)"
if [ -n "${OUT:-}" ]; then
    mkdir -p "$OUT"
    { echo "bands control7_s build_radiance_s build_radiance_per_band_s trace_s trace_setup_s trace_rad_tables_s trace_render_s sensorize_s"
      cat "$W/medians"; } > "$OUT/bands_cost.tsv"
fi
