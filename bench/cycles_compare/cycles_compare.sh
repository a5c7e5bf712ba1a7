#!/bin/sh
# bench/cycles_compare/cycles_compare.sh BUILD: trace against Blender's Cycles on the
# hawkeye scene, error per second of the Monte Carlo estimate, side by side.
#
# The scene: data/scenes/hawkeye (seed 4: terrain, ~850 instanced structures, ~3000
# instanced trees), its oblique camera (oblique.adv, White (1996), section 4.4; CC_VIEW=nadir
# its nadir one, nadir.adv) cut to
# $CC_SIZE pixels on a side as scripts/chart cuts it (same field of view), its .snd and
# the pipeline's .rad tables (make -C data/scenes/hawkeye: control7, build_radiance).
# bench/cycles_export (cycles_export.cpp) writes the facets as trace assembles them
# (instances flattened, one material per MATERIAL_ID and .ems curve) to OBJ, with the
# camera, the sun and the sky; cycles_render.py renders them with Cycles: Lambertian
# materials of the reflectance at three band-centre spectral samples (R, G, B), a
# point sun of the ground's direct irradiance, a uniform sky of the .rad sky's
# horizontal irradiance, black below the horizon, one bounce, CPU, no denoising.
# trace renders the same files with --sampling montecarlo --bounces 1 --no-adjacency
# --background none (no ground-sky coupling and no background plane, which Cycles'
# set-up lacks); its error is taken on the same three band-centre samples of its cube.
# The row "trace-def" is trace with the set-up flags alone: the sampling a user gets
# without naming a strategy, samples per pixel or hemisphere samples (the .adv's,
# or what trace chooses; its -v line is printed under the table).
#
# Each renderer's N-sample image is measured against ITS OWN converged reference
# (trace at $CC_TRACE_REF_SPP, Cycles at $CC_CYCLES_REF_SPP samples per pixel, other
# seeds), so that the differences between their radiometric models (path radiance and
# transmission, the anisotropic sky, the grass's fall-off, the sky at a bounce) do not
# enter: the error is the Monte Carlo estimate's alone. Samples per pixel are matched:
# N camera rays per pixel each, one diffuse bounce each. trace runs twice per N: with
# --hemisphere-samples 1 (one bounce ray per camera ray, as Cycles' path) and with its
# default 64 (64 bounce rays per camera ray: more work per sample).
#
# Times: "render" excludes the set-up (trace -v's render seconds; Cycles: a second,
# identical render in the same Blender process with persistent data, so without the
# scene sync and BVH build); "total" includes it (the whole trace process; Blender
# from its start to the end of the first render, the OBJ import included). Both on
# $CC_THREADS threads. The renderers run alternately, $CC_RUNS times; medians.
# "eff" is the Monte Carlo efficiency 1 / (relative RMS^2 x render seconds): higher
# is better; it would not depend on N if the error fell as 1/sqrt(N) and the time grew
# as N (it grows with N here: the error falls faster than 1/sqrt(N), as stratified
# samples can, and each render has a fixed cost).
#
# Prints a table and the mean ratio trace/Cycles of the converged surface-leaving
# radiance (trace's (solar + downwelled) / transmission, truth layers), to show the
# two set-ups are comparable, and for information that of the radiance at the sensor.
# Without Blender it prints "skipped: blender not found" and exits 0 (BLENDER=PROGRAM
# names another). Knobs [defaults]: CC_SIZE [128], CC_SPP ["4 16 64"], CC_RUNS [3],
# CC_THREADS [2], CC_VIEW [oblique], CC_DEFAULT [1] (0: no trace-def row),
# CC_DEFAULT_FLAGS [""] (flags added to the trace-def row: a candidate default measured),
# CC_TRACE_REF_SPP [1024], CC_TRACE_REF_HEMI [4] (the reference's
# --hemisphere-samples), CC_CYCLES_REF_SPP [1024], CC_HEMI ["1 64"] (trace's
# --hemisphere-samples rows), CC_WORK [BUILD/cycles_compare] (work files, kept; the
# references are reused by a rerun of the same size and samples: remove them after a
# change to the scene or the renderers). The default run takes about 15 minutes
# (references about 3.5).
set -eu
build="${1:-build}"
blender="${BLENDER:-blender}"
if ! command -v "$blender" >/dev/null 2>&1; then
    echo "skipped: blender not found"
    exit 0
fi
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
bin="$(cd "$build/bin" && pwd)"
export_bin="$(cd "$build/bench" && pwd)/cycles_export"
size="${CC_SIZE:-128}"
spps="${CC_SPP:-4 16 64}"
runs="${CC_RUNS:-3}"
threads="${CC_THREADS:-2}"
trace_ref_spp="${CC_TRACE_REF_SPP:-1024}"
cycles_ref_spp="${CC_CYCLES_REF_SPP:-1024}"
trace_ref_hemi="${CC_TRACE_REF_HEMI:-4}"
hemis="${CC_HEMI:-1 64}"
view="${CC_VIEW:-oblique}"
default_row="${CC_DEFAULT:-1}"
work="${CC_WORK:-$build/cycles_compare}/$view"
mkdir -p "$work/export"
work="$(cd "$work" && pwd)"
H="$top/data/scenes/hawkeye"
stats() { python3 "$here/cycles_stats.py" "$@"; }
now() { date +%s.%N; }

# The camera with its longer side cut to $size pixels and the pixel pitch
# scaled by the same factor (scripts/chart's shrink).
awk -v size="$size" '
    !/^[ \t]*(#|$)/ && !/=/ { if (++k == 5) { r = $1; c = $2; m = (r > c ? r : c)
        f = (m > size ? m / size : 1); print int(r / f + 0.5), int(c / f + 0.5); next } }
    /^[ \t]*pixel_pitch_um[ \t]*=/ { split($0, a, "="); print "pixel_pitch_um = " (a[2] + 0) * f; next }
    { print }' "$H/$view.adv" > "$work/view.adv"
out="$work/out"
rads="$out/hawkeye-1.rad $out/hawkeye-2.rad $out/hawkeye-3.rad"
# shellcheck disable=SC2086
make -s -C "$H" VIEW="$view" ADV="$work/view.adv" OUT="$out" SIGCHAIN_BIN="$bin" \
    $rads "$out/hawkeye.snd" >&2
odb="$work/scene-4/hawkeye.odb"
# shellcheck disable=SC2086
"$export_bin" "$work/view.adv" "$odb" "$H/hawkeye.mat" $rads "$work/export" >&2
bands=$(awk '$1 == "cube_bands" { print $2 "," $3 "," $4 }' "$work/export/scene.txt")

# run_trace SPP HEMI SEED OUT [EXTRA...] -> "render_seconds total_seconds"
run_trace() {
    spp=$1 hemi=$2 seed=$3 img=$4
    shift 4
    run_trace_with "$seed" "$img" --sampling montecarlo --samples-per-pixel "$spp" \
        --hemisphere-samples "$hemi" "$@"
}

# run_trace_with SEED OUT [FLAGS...]: trace with the set-up flags and FLAGS (the
# sampling trace chooses when FLAGS name none) -> "render_seconds total_seconds"
run_trace_with() {
    seed=$1 img=$2
    shift 2
    t0=$(now)
    # shellcheck disable=SC2086
    (cd "$H" && "$bin/trace" -v --bounces 1 --no-adjacency --background none \
        --seed "$seed" --threads "$threads" "$@" "$work/view.adv" "$out/hawkeye.snd" \
        "$odb" hawkeye.mat $rads -o "$img") 2> "$work/trace.log" ||
        { cat "$work/trace.log" >&2; exit 1; }
    t1=$(now)
    r=$(sed -n 's/.*; render \([0-9.]*\) s.*/\1/p' "$work/trace.log" | tail -n 1)
    [ -n "$r" ] || { echo "$0: no render time in trace -v's output" >&2; exit 1; }
    echo "$r $(echo "$t1 - $t0" | bc)"
}

# run_cycles SPP SEED OUT.raw [once] -> "render_seconds total_seconds" (once: no
# second render, no render seconds)
run_cycles() {
    t0=$(now)
    "$blender" -b -noaudio --python-exit-code 1 --python "$here/cycles_render.py" -- \
        "$work/export" "$1" "$2" "$threads" "$3" ${4:+"$4"} > "$work/cycles.log" 2>&1 ||
        { cat "$work/cycles.log" >&2; exit 1; }
    t1=$(sed -n 's/^cycles: first render ended at //p' "$work/cycles.log")
    r=$(sed -n 's/^cycles: second render \([0-9.]*\) s/\1/p' "$work/cycles.log")
    echo "$r $(echo "$t1 - $t0" | bc)"
}

echo "== references: trace $trace_ref_spp spp x $trace_ref_hemi hemisphere rays, Cycles $cycles_ref_spp spp ==" >&2
# Kept in $work under names that hold their settings, and reused by a rerun.
tref="$work/trace_ref_${size}_${trace_ref_spp}x$trace_ref_hemi"
cref="$work/cycles_ref_${size}_$cycles_ref_spp"
if [ ! -s "$tref.img" ] || [ ! -s "$tref.truth.img" ]; then
    run_trace "$trace_ref_spp" "$trace_ref_hemi" 20261124 "$tref.img" --truth "$tref.truth.img" >&2
fi
[ -s "$cref.raw" ] || run_cycles "$cycles_ref_spp" 7 "$cref.raw" once >&2

: > "$work/times.txt"
i=0
while [ "$i" -lt "$runs" ]; do
    i=$((i + 1))
    for n in $spps; do
        for h in $hemis; do
            echo "== run $i: trace $n spp x $h ==" >&2
            echo "trace-h$h $n $(run_trace "$n" "$h" 1 "$work/trace_${n}_$h.img")" >> "$work/times.txt"
        done
        echo "== run $i: cycles $n spp ==" >&2
        echo "cycles $n $(run_cycles "$n" 0 "$work/cycles_$n.raw")" >> "$work/times.txt"
    done
    if [ "$default_row" = 1 ]; then
        echo "== run $i: trace with its default sampling ==" >&2
        # shellcheck disable=SC2086
        echo "trace-def 0 $(run_trace_with 1 "$work/trace_default.img" ${CC_DEFAULT_FLAGS:-})" \
            >> "$work/times.txt"
        grep -m 1 'per pixel' "$work/trace.log" > "$work/default_sampling.txt" || :
    fi
done

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
printf '%-10s %5s %10s %10s %10s %9s %10s\n' renderer spp render_s total_s rms_uW rel_rms eff_1/s
for n in $spps; do
    for who in $(for h in $hemis; do printf 'trace-h%s ' "$h"; done) cycles; do
        case $who in
            cycles) e=$(stats error "$work/cycles_$n.raw" "$cref.raw" -) ;;
            *) e=$(stats error "$work/trace_${n}_${who#trace-h}.img" "$tref.img" "$bands") ;;
        esac
        r=$(awk -v w="$who" -v n="$n" '$1 == w && $2 == n { print $3 }' "$work/times.txt" | median)
        t=$(awk -v w="$who" -v n="$n" '$1 == w && $2 == n { print $4 }' "$work/times.txt" | median)
        echo "$who $n $r $t $e" | awk '{ printf "%-10s %5d %10.3f %10.3f %10.4g %8.3f%% %10.4g\n",
            $1, $2, $3, $4, $5, 100 * $6, 1 / ($6 * $6 * $3) }'
    done
done
if [ "$default_row" = 1 ]; then
    e=$(stats error "$work/trace_default.img" "$tref.img" "$bands")
    r=$(awk '$1 == "trace-def" { print $3 }' "$work/times.txt" | median)
    t=$(awk '$1 == "trace-def" { print $4 }' "$work/times.txt" | median)
    echo "trace-def - $r $t $e" | awk '{ printf "%-10s %5s %10.3f %10.3f %10.4g %8.3f%% %10.4g\n",
        $1, $2, $3, $4, $5, 100 * $6, 1 / ($6 * $6 * $3) }'
    # Its efficiency against Cycles' at each N (the same measure, 1 / (rel_rms^2 s)).
    for n in $spps; do
        ec=$(stats error "$work/cycles_$n.raw" "$cref.raw" - | awk '{ print $2 }')
        rc=$(awk -v n="$n" '$1 == "cycles" && $2 == n { print $3 }' "$work/times.txt" | median)
        echo "$(echo "$e" | awk '{ print $2 }') $r $ec $rc $n" | awk '{ printf "trace-def / cycles %d spp: %.2fx the error per second\n",
            $5, ($3 * $3 * $4) / ($1 * $1 * $2) }'
    done
    echo "trace-def's sampling: $(cat "$work/default_sampling.txt" 2>/dev/null)"
fi
ratio=$(stats ratio "$tref.truth.img" "$cref.raw" hawkeye-1,hawkeye-2,hawkeye-3)
echo "converged mean surface-leaving radiance, trace / Cycles (bands 1, 2, 3, all): $ratio"
echo "converged mean radiance at the sensor (trace's path terms included): $(stats sensor "$tref.img" "$bands" "$cref.raw")"
echo "($runs runs each, alternating; medians; ${size}-pixel $view hawkeye view; $threads threads;"
echo " errors against each renderer's own reference: trace $trace_ref_spp spp x $trace_ref_hemi, Cycles $cycles_ref_spp spp)"
