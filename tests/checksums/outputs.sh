#!/bin/sh
# Checksums of every output of sigchain's pipelines, for proving that a refactor keeps
# every output byte for byte (docs/ARCHITECTURE.md, "Refactoring").
#
#   tests/checksums/outputs.sh [--full] [--threads N] BUILD OUTDIR
#       runs the chains with BUILD's tools into OUTDIR and prints "SHA256  FILE" for
#       every file made there (FILE relative to OUTDIR), sorted by name. Without
#       --full: the training scene (all stages: control7, find_min_max_view_angle,
#       build_radiance, trace, the shadow history, therm, sensorize with
#       calibration, compare) and the thermal render of its box. With --full also
#       the Olinda, hawkeye (nadir and oblique) and Soho scenes and `make demo`'s
#       outputs (several minutes). --threads N passes --threads N to every tool that
#       takes it (default: all cores); outputs must not depend on it.
#   tests/checksums/outputs.sh --check MANIFEST BUILD OUTDIR
#       runs the small set twice (--threads 1 and --threads 2), fails unless both
#       give the same bytes, then compares them with MANIFEST (a file this script
#       printed). Float outputs are defined byte for byte only for one binary on one
#       instruction set (Embree picks its kernels by CPU; glibc's libm picks FMA
#       variants), so MANIFEST's first line records the machine it was made on and
#       the comparison with it is made only on the same kind of machine; elsewhere
#       the script says so and checks determinism alone.
#
# Before a refactor: outputs.sh --full build /tmp/before > before.sha256; after it:
# outputs.sh --full build /tmp/after > after.sha256; diff before.sha256 after.sha256.
set -eu

src="$(cd "$(dirname "$0")/../.." && pwd)"

# The machine's kind, as far as it decides floating-point bytes: the widest SIMD
# extension Embree and libm can use, and the C library's version.
machine() {
    isa=sse2
    for f in sse4_2 avx avx2 avx512f; do
        if grep -qw "$f" /proc/cpuinfo 2>/dev/null; then isa=$f; fi
    done
    echo "# machine: $(uname -m) $isa glibc $(ldd --version 2>/dev/null | head -n 1 | awk '{print $NF}')"
}

# The scenes' tools run with -q (pipelines/scene.mk's defaults show their warnings).
quiet="CONTROL7_FLAGS=-q CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q"

# run_small BIN OUT THREADS: the training scene's whole chain and the box's thermal render.
run_small() {
    bin="$1" out="$2" threads="$3"
    topt=""
    [ -n "$threads" ] && topt="--threads $threads"
    make -s -C "$src/data/scenes/training" --no-print-directory SIGCHAIN_BIN="$bin" \
        OUT="$out/training" $quiet BUILD_RADIANCE_FLAGS="-q $topt" TRACE_FLAGS="-q $topt" \
        THERM_FLAGS="-q $topt" SHADOW_FLAGS="--points-per-facet 16 $topt" >/dev/null
    # The box on a plane in 8-12.5 um (the demo's thermal chain at 32 x 32 pixels).
    b="$out/box_lwir"
    mkdir -p "$b"
    seed="$src/tests/data/white1996"
    cp "$src/tests/data/therm/box_on_plane.mat" "$seed/fall_grass.ems" "$b/"
    # The answers name the radiosonde 30Sep95800L.rsd, opened from the current directory.
    (cd "$seed" && "$bin/control7" -q --answers "$src/tests/data/control7/hawkeye.answers" \
        -o "$b/hawkeye.cdk")
    "$bin/trace" -q $topt --shadow-history --points-per-facet 4 "$src/data/demo/lwir.snd" \
        "$seed/box_on_plane.gdb" "$b/box_on_plane.mat" -o "$b/box.shd"
    "$bin/therm" -q $topt "$b/box.shd" "$seed/weather_30_Sep_95.wth" "$b/box_on_plane.mat" \
        "$seed/box_on_plane.gdb" "$src/data/demo/lwir.snd" -o "$b/box.tmp"
    "$bin/build_radiance" -q $topt "$b/hawkeye.cdk" "$src/data/demo/lwir.snd" \
        --view-azimuth 0 -o "$b/lwir-%d.rad"
    "$bin/trace" -q $topt "$src/tests/data/trace/box.adv" "$src/data/demo/lwir.snd" \
        "$seed/box_on_plane.gdb" "$b/box_on_plane.mat" "$b/lwir-1.rad" --tmp "$b/box.tmp" \
        -o "$b/box_lwir.img"
    "$bin/sensorize" -q "$b/box_lwir.img" "$src/data/demo/lwir.sen" -o "$b/box_lwir.tif"
}

# run_full BUILD OUT THREADS: the small set, the four scenes and make demo's outputs.
run_full() {
    build="$1" out="$2" threads="$3"
    bin="$build/bin"
    run_small "$bin" "$out" "$threads"
    topt=""
    [ -n "$threads" ] && topt="--threads $threads"
    flags="BUILD_RADIANCE_FLAGS=-q $topt"
    for scene in olinda soho; do
        make -s -C "$src/data/scenes/$scene" --no-print-directory -j2 SIGCHAIN_BIN="$bin" \
            OUT="$out/$scene" $quiet "$flags" TRACE_FLAGS="-q $topt" >/dev/null
    done
    for view in nadir oblique; do
        make -s -C "$src/data/scenes/hawkeye" --no-print-directory -j2 SIGCHAIN_BIN="$bin" \
            VIEW=$view OUT="$out/hawkeye/$view" $quiet "$flags" TRACE_FLAGS="-q $topt" >/dev/null
    done
    # make demo writes into BUILD/demo (made afresh here); copy what it made.
    rm -rf "$build/demo"
    (cd "$src" && scripts/demo "$build" >/dev/null)
    (cd "$build" && tar cf - demo) | (cd "$out" && tar xf -)
}

# sums OUT: "SHA256  FILE" for every file under OUT, sorted. Some outputs name the
# files they were made from (compare's reports, the Olinda fit's .ems comments), whose
# paths contain OUT (or BUILD, for make demo's): in a file that holds either, they are
# replaced by "OUT" and "BUILD" before hashing, so that runs into different folders
# compare equal.
sums() {
    (cd "$1" && find . -type f ! -name '*.stamp' -print | sed 's|^\./||' | LC_ALL=C sort |
        while IFS= read -r f; do
            if grep -qF -e "$1" -e "$build" "$f"; then
                sum=$(sed -e "s|$1|OUT|g" -e "s|$build|BUILD|g" "$f" | sha256sum | cut -d' ' -f1)
            else
                sum=$(sha256sum < "$f" | cut -d' ' -f1)
            fi
            printf '%s  %s\n' "$sum" "$f"
        done)
}

full=0 threads="" check=""
while [ $# -gt 0 ]; do
    case "$1" in
        --full) full=1; shift ;;
        --threads) threads="$2"; shift 2 ;;
        --check) check="$2"; shift 2 ;;
        -*) echo "outputs.sh: unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
[ $# -eq 2 ] || { echo "usage: outputs.sh [--full] [--threads N] [--check MANIFEST] BUILD OUTDIR" >&2; exit 2; }
build="$(cd "$1" && pwd)" out="$2"
# Make skips what is up to date: a folder holding an earlier run would hide changes.
if [ -d "$out" ] && [ -n "$(ls -A "$out")" ]; then
    echo "outputs.sh: $out is not empty: give an empty or new folder" >&2
    exit 2
fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"

if [ -z "$check" ]; then
    if [ "$full" = 1 ]; then run_full "$build" "$out" "$threads"; else run_small "$build/bin" "$out" "$threads"; fi
    machine
    sums "$out"
    exit 0
fi

# (The run functions set globals of their own, out among them: fix the folders first.)
root="$out"
run_small "$build/bin" "$root/t1" 1
run_small "$build/bin" "$root/t2" 2
out="$root"
sums "$out/t1" > "$out/t1.sha256"
sums "$out/t2" > "$out/t2.sha256"
if ! diff -u "$out/t1.sha256" "$out/t2.sha256"; then
    echo "outputs.sh: outputs differ between --threads 1 and --threads 2" >&2
    exit 1
fi
echo "outputs.sh: $(wc -l < "$out/t1.sha256") outputs identical with 1 and 2 threads"
if [ "$(head -n 1 "$check")" != "$(machine)" ]; then
    echo "outputs.sh: $check was recorded on '$(head -n 1 "$check" | sed 's/^# machine: //')';" \
        "this is '$(machine | sed 's/^# machine: //')': bytes compared for determinism only"
    exit 0
fi
if ! tail -n +2 "$check" | diff -u - "$out/t1.sha256"; then
    echo "outputs.sh: outputs differ from $check (- recorded, + now)" >&2
    exit 1
fi
echo "outputs.sh: every output matches $check"
