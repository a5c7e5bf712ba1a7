#!/usr/bin/env bats
# Tests: data/scenes/hawkeye's imaging spectrometer (`make hyperspectral`:
# hyperspectral.mk, hyperspectral.bands, hyperspectral.adv)
# Also requires: hawkeye_scene, control7, find_min_max_view_angle, build_radiance, trace,
# sensorize, gdalinfo, and pipelines/scene.mk
# The example's pushbroom rendered tiny (4 x 4 pixels, coarse sky tables), so that the
# test checks its 211 bands, not its radiometry: the radiance cube's ENVI header lists
# every band's samples with their wavelengths, band after band in the table's order,
# and the band-radiance product carries each band's centre and FWHM.

load test_helper

HAWKEYE="$SIGCHAIN_SOURCE_DIR/data/scenes/hawkeye"
SIZE=4  # lines and detectors of the reduced pushbroom

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    command -v hawkeye_scene > /dev/null || skip "hawkeye_scene not built in $SIGCHAIN_BIN"
}

# The band table's centres (nm), one per line.
centres() { awk '!/^[ \t]*(#|$)/ { print $1 }' "$HAWKEYE/hyperspectral.bands"; }

# An ENVI header item's list ({a, b, ...}), one value per line.
header_list() {
    tr -d '\n' < "$1" | sed -n "s/.*$2 *= *{\([^}]*\)}.*/\1/p" | tr ',' '\n' |
        sed 's/^ *//; s/ *$//'
}

@test "make hyperspectral: 211 bands in order, their wavelengths in the cube's ENVI header" {
    # hyperspectral.adv at SIZE x SIZE: the same swath and flight, pixels 64 / SIZE
    # times larger, one line every 64 / SIZE line periods.
    local f=$((64 / SIZE))
    awk -v s="$SIZE" -v f="$f" '/^64 64\t/ { sub(/^64 64/, s " " s) }
        /^pixel_pitch_um = / { $3 = $3 * f } /^line_period_s = / { $3 = $3 * f } { print }' \
        "$HAWKEYE/hyperspectral.adv" > hyperspectral.adv
    grep -q "^$SIZE $SIZE" hyperspectral.adv && grep -q '^pixel_pitch_um = 2752$' hyperspectral.adv
    run -0 make -C "$HAWKEYE" -j2 hyperspectral ADV="$BATS_TEST_TMPDIR/hyperspectral.adv" \
        OUT="$BATS_TEST_TMPDIR/out/hyperspectral" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
        HAWKEYE_SCENE="$(command -v hawkeye_scene)" CONTROL7_FLAGS=-q TRACE_FLAGS=-q \
        BUILD_RADIANCE_FLAGS="-q --streams 4 --sky-zenith-step 30 --sky-azimuth-step 90 --sky-subsamples 1 --upwelled-azimuth-step 360"
    local out=out/hyperspectral
    # One build_radiance run wrote the 211 tables.
    assert_equal "$(grep -c 'bin/build_radiance ' <<< "$output")" 1
    [ -s "$out/hawkeye-211.rad" ] && [ ! -e "$out/hawkeye-212.rad" ]
    # The radiance cube: 5 spectral samples per band, named after their band, each
    # band's samples rising from centre - 10 nm to centre + 10 nm, the middle one within
    # 0.3 nm of the centre (it is (c^2 - w^2) / c), bands in the table's order.
    grep -q '^bands *= 1055$' "$out/hawkeye.hdr"
    grep -q '^wavelength units = Micrometers$' "$out/hawkeye.hdr"
    header_list "$out/hawkeye.hdr" wavelength > wavelengths.txt
    header_list "$out/hawkeye.hdr" 'band names' | awk '{ print $1 }' > names.txt
    centres > centres.txt
    assert_equal "$(grep -c . wavelengths.txt)" 1055
    run -0 awk 'FNR == 1 { file++ } file == 1 { c[FNR] = $1; next } file == 2 { name[FNR] = $1; next }
        { b = int((FNR - 1) / 5) + 1; i = (FNR - 1) % 5; nm = $1 * 1000
          if (name[FNR] != "hawkeye-" b) { print "sample " FNR ": named " name[FNR] ", not band " b; bad++ }
          if (i > 0 && nm <= last) { print "band " b ": sample " i + 1 " at " nm " nm, not above " last; bad++ }
          if (i == 0 && (nm < c[b] - 10.001 || nm > c[b] - 9.999)) { print "band " b " starts at " nm " nm"; bad++ }
          if (i == 2 && (nm < c[b] - 0.3 || nm > c[b] + 0.001)) { print "band " b ": middle " nm " nm, centre " c[b]; bad++ }
          if (i == 2 && b > 1 && nm <= mid) { print "band " b " not after band " b - 1; bad++ }
          if (i == 2) mid = nm; last = nm }
        END { print "bands " b; exit bad > 0 }' centres.txt names.txt wavelengths.txt
    assert_output 'bands 211'
    # The product: one float band per table row, its centre within 0.1 nm of the
    # table's and its FWHM within 0.2 nm of 10 nm, in the table's order.
    run -0 gdalinfo "$out/hawkeye.tif"
    awk '/^Band [0-9]+ / { b = $2 } /^ +wavelength=/ { sub(/.*=/, ""); w[b] = $0 }
        /^ +fwhm=/ { sub(/.*=/, ""); f[b] = $0 }
        END { for (i = 1; i <= b; i++) print i, w[i] * 1000, f[i] * 1000 }' <<< "$output" > product.txt
    run -0 awk 'FNR == NR { c[FNR] = $1; next }
        { if ($2 < c[$1] - 0.1 || $2 > c[$1] + 0.1 || $3 < 9.8 || $3 > 10.2) { print; bad++ } }
        END { print FNR " bands"; exit bad > 0 }' centres.txt product.txt
    assert_output '211 bands'
    [ -s "$out/hawkeye.png" ]
}
