#!/bin/sh
# run_chain.sh OUTDIR: the Olinda chain (README.md), from the committed scene files to
# the held-out comparison. Tools from $SIGCHAIN_BIN (default: the build's bin/, which
# also holds olinda_scene). Writes into OUTDIR only. Steps:
#   1. build_radiance: the four ETM+ band tables from olinda.cdk and olinda.snd;
#   2. trace + sensorize (16-bit counts, unclipped) twice: the class reflectances of
#      reflectance.txt ("base") and zero reflectance ("dark", path radiance only);
#   3. olinda_scene fit: each class's scale per band on olinda_fit.cpt (least squares);
#   4. the fitted .ems, trace + sensorize (8-bit ETM+ DN): OUTDIR/olinda.tif;
#   5. compare with L7_ETMs.tif bands 1-4 at the held-out points (olinda_held.cpt):
#      OUTDIR/held.txt and held.json (and fit.txt on the fit half).
set -eu
out=$1
here=$(cd "$(dirname "$0")" && pwd)
bin=${SIGCHAIN_BIN:-$here/../../../build/bin}
threads=${OLINDA_THREADS:-0}
mkdir -p "$out/base" "$out/dark" "$out/fitted"
cd "$out"
"$bin/build_radiance" -q --view-azimuth 0.26 "$here/olinda.cdk" "$here/olinda.snd" -o band-%d.rad
rads="band-1.rad band-2.rad band-3.rad band-4.rad"
sens="$here/etm1.sen $here/etm2.sen $here/etm3.sen $here/etm4.sen"
render() {  # render MATDIR COUNTS_BITS OUTPUT.tif
    cp "$here/olinda.mat" "$1/olinda.mat"
    # shellcheck disable=SC2086
    "$bin/trace" -q --threads "$threads" "$here/olinda.adv" "$here/olinda.snd" \
        "$here/olinda.odb" "$1/olinda.mat" $rads -o "$1/cube.img"
    # shellcheck disable=SC2086
    "$bin/sensorize" -q -b "$2" "$1/cube.img" $sens -o "$3"
}
"$bin/olinda_scene" ems "$here/reflectance.txt" - base
"$bin/olinda_scene" ems "$here/black.txt" - dark
render base 16 base16.tif
render dark 16 dark16.tif
"$bin/olinda_scene" fit "$here/olinda_fit.cpt" dark16.tif base16.tif "$here/L7_ETMs.tif" > scales.txt
"$bin/olinda_scene" ems "$here/reflectance.txt" scales.txt fitted
render fitted 8 olinda.tif
"$bin/compare" --bands 1,2,3,4 olinda.tif "$here/L7_ETMs.tif" "$here/olinda_held.cpt" > held.txt
"$bin/compare" --json --bands 1,2,3,4 olinda.tif "$here/L7_ETMs.tif" "$here/olinda_held.cpt" > held.json
"$bin/compare" --bands 1,2,3,4 olinda.tif "$here/L7_ETMs.tif" "$here/olinda_fit.cpt" > fit.txt
