#!/bin/sh
# bench/landsat_sampling.sh: how many spectral samples a Landsat band needs in
# landsat_sensor(1) (its default --samples). For each reflective band of the Marburg ETM+
# and OLI files it computes the at-sensor band radiance of a gray ground (reflectance 0.3,
# nadir, no sky term) from build_radiance tables on a fine grid (--increment 5, LOWTRAN 7's
# 5 cm-1 step) and on coarse grids of N samples, each weighted by the .sen responses
# landsat_sensor writes exactly as sensorize(1) weights them (midpoint widths in um), and
# prints the relative error of each N against the fine grid, per band.
#
#   bench/landsat_sampling.sh [BIN_DIR] [SAMPLES...]    (default build/bin; 4 6 8 12 16 24)
#
# The atmosphere is data/scenes/olinda/olinda.cdk (maritime aerosol, 23 km visibility) with
# the mid-latitude summer profile (MODEL 2) and its sun put at the Marburg subset's centre and
# each file's date and time (build_radiance checks the deck's sun against the .snd's), solved
# cheaply (8 streams, one sky cell, one upwelled azimuth): the error measured is the spectral
# sampling's, which those options do not change much.
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$src/build/bin}
[ $# -gt 0 ] && shift
samples=${*:-4 6 8 12 16 24}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=$work/deck.cdk
lat=50.8027 lon=8.7715  # the Marburg subset's centre
cheap="-q --streams 8 --sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 --upwelled-azimuth-step 360"

# band_radiance RAD SEN COS_SUN: sum(R w L) / sum(R w), L = 0.3/pi Es cos tau1 tau2 + Lus + Lue,
# w the midpoint widths of the .rad's wavelengths (sensor_response::sample_widths_um).
band_radiance() {
    awk -v cs="$3" '
    FNR == 1 { f++ ; n = 0 }
    /^[ \t]*(#|$)/ { next }
    f == 1 { n++; if (n == 7) N = $1; else if (n > 12 && n <= 12 + N) { k = n - 12; wl[k] = $1; es[k] = $3; t1[k] = $4 }
             else if (n > 13 + N && n <= 13 + 2 * N) { k = n - 13 - N; t2[k] = $1; lue[k] = $2; lus[k] = $3 } }
    f == 2 { n++; if (n > 3) r[n - 3] = $1 }
    END {
        for (k = 1; k <= N; k++) {
            if (N == 1) w = 1; else if (k == 1) w = wl[2] - wl[1]; else if (k == N) w = wl[N] - wl[N - 1];
            else w = (wl[k + 1] - wl[k - 1]) / 2
            if (w < 0) w = -w
            L = 0.3 / 3.141592653589793 * es[k] * cs * t1[k] * t2[k] + lus[k] + lue[k]
            s += r[k] * w * L; sw += r[k] * w
        }
        printf "%.10g\n", s / sw
    }' "$1" "$2"
}

for mtl in "$src"/data/scenes/marburg/LE07*_MTL.txt "$src"/data/scenes/marburg/LC08*_MTL.txt; do
    sc=$(awk -F' = ' '/SUN_ELEVATION/ { print sin($2 * 3.141592653589793 / 180); exit }' "$mtl")
    date=$(awk -F' = ' '/DATE_ACQUIRED/ { print $2; exit }' "$mtl")
    hours=$(awk -F' = ' '/SCENE_CENTER_TIME/ { gsub(/"|Z/, "", $2); split($2, t, ":");
        printf "%.3f", t[1] + t[2] / 60 + t[3] / 3600; exit }' "$mtl")
    # CARD 1 MODEL 2; CARD 3A1 IPARM 1 and IDAY; CARD 3A2 latitude, longitude (west) and TIME.
    awk -v doy="$(date -u -d "$date" +%j)" -v h="$hours" -v lat="$lat" -v lon="$lon" '
        NR == 1 { $0 = "    2" substr($0, 6) }
        NR == 4 { $0 = sprintf("    1    2%5d    0", doy + 0) }
        NR == 5 { $0 = sprintf("%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f",
                               lat, 360 - lon, 0, 0, h, 0, 0, 0) }
        { print }' "$src/data/scenes/olinda/olinda.cdk" > "$work/deck.cdk"
    bands=$("$bin/landsat_sensor" --print-bands "$mtl")
    for grid in fine $samples; do
        opt="--samples $grid"; [ "$grid" = fine ] && opt="--increment 5"
        "$bin/landsat_sensor" -q $opt --target $lat,$lon --view-angles 0,0,1 --name g "$mtl" -o "$work/$grid"
        "$bin/build_radiance" $cheap "$deck" "$work/$grid/g.snd" -o "$work/$grid/g-%d.rad"
    done
    echo "$(basename "$mtl"): relative error of the band radiance against 5 cm-1 (%), by samples"
    printf '%-5s %8s' band fine_n; for n in $samples; do printf ' %8s' "$n"; done; echo
    k=0
    for b in $(echo "$bands" | tr , ' '); do
        k=$((k + 1))
        ref=$(band_radiance "$work/fine/g-$k.rad" "$work/fine/g-b$b.sen" "$sc")
        printf '%-5s %8s' "$b" "$(awk '!/^[ \t]*#/ { print; exit }' "$work/fine/g-b$b.sen")"
        for n in $samples; do
            v=$(band_radiance "$work/$n/g-$k.rad" "$work/$n/g-b$b.sen" "$sc")
            printf ' %8.3f' "$(awk -v a="$v" -v r="$ref" 'BEGIN { print 100 * (a / r - 1) }')"
        done
        echo
    done
done
