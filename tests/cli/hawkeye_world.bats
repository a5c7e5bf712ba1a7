#!/usr/bin/env bats
# Tests: trace (the world beyond the scene) on data/scenes/hawkeye/horizon.adv and
# oblique.adv
# Also requires: hawkeye_scene, control7, find_min_max_view_angle, build_radiance,
# compare, and data/scenes/hawkeye/Makefile (pipelines/scene.mk)
# The hawkeye scene's low oblique view, whose top rows look above the horizon: every
# pixel sees something (a facet, the sky, or the background plane between the scene's
# far edge and the horizon), so none is zero or NaN, and the truth layers say which.

load test_helper

HAWKEYE="$SIGCHAIN_SOURCE_DIR/data/scenes/hawkeye"
SIZE=32  # rows and columns of the reduced view

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    command -v hawkeye_scene > /dev/null || skip "hawkeye_scene not built in $SIGCHAIN_BIN"
}

# The float32 values of an ENVI cube, one per line, band by band, row by row.
values() { od -An -v -tf4 -w4 "$1"; }

# The index (from 0) of the layer named $2 in ENVI header $1's band names.
layer() {
    tr -d '\n' < "$1" | sed -n 's/.*band names *= *{\([^}]*\)}.*/\1/p' | tr ',' '\n' |
        awk -v name="$2" '{ gsub(/^ +| +$/, "") } $0 == name { print NR - 1; found = 1; exit }
            END { if (!found) exit 1 }'
}

# count_bad CUBE: the number of values and how many are zero or NaN.
count_bad() {
    values "$1" | awk '$1 == 0 || $1 ~ /nan/ { bad++ } END { print NR, bad + 0 }'
}

# check_truth TRUTH.img: per pixel, hit + sky_fraction + background_fraction = 1 (a
# primary sample that misses the scene goes up to the sky or down to the background
# plane, which lies below the whole scene); the whole top row sees the sky, the bottom
# row the scene, the lower half no sky; some pixels see the background plane. Prints
# what fails (status 1), then the counts of sky and background pixels.
check_truth() {
    local hit sky bg
    hit=$(layer "${1%.img}.hdr" hit) && sky=$(layer "${1%.img}.hdr" sky_fraction) &&
        bg=$(layer "${1%.img}.hdr" background_fraction) || return 1
    values "$1" | awk -v n="$SIZE" -v hit="$hit" -v sky="$sky" -v bg="$bg" '
        function fail(what) { if (++bad <= 10) print what }
        { layer = int((NR - 1) / (n * n)); i = (NR - 1) % (n * n) }
        layer == hit { h[i] = $1 } layer == sky { s[i] = $1 } layer == bg { b[i] = $1 }
        END {
            for (i = 0; i < n * n; i++) {
                d = h[i] + s[i] + b[i] - 1
                if (d > 1e-6 || d < -1e-6) fail("pixel " i ": fractions sum to " d + 1)
                if (i < n && s[i] <= 0) fail("top row pixel " i ": sky_fraction " s[i])
                if (i >= n * (n - 1) && h[i] != 1) fail("bottom row pixel " i ": hit " h[i])
                if (i >= n * n / 2 && s[i] != 0) fail("lower half pixel " i ": sky " s[i])
                sky_px += s[i] > 0; bg_px += b[i] > 0
            }
            if (bg_px == 0) fail("no pixel sees the background plane")
            print "sky pixels " sky_px ", background pixels " bg_px
            exit bad > 0
        }'
}

# render VIEW: the hawkeye view VIEW.adv at SIZE x SIZE pixels, each 512 / SIZE times
# larger (same field of view, as scripts/chart shrinks a camera), traced with its truth
# layers into out/VIEW/hawkeye.img and VIEW_truth.img; then checks that no value of
# the cube is zero or NaN.
render() {
    local view="$1" pitch cube="out/$1/hawkeye.img" bands
    pitch=$(awk -v s="$SIZE" 'BEGIN { print 21.5 * 512 / s }')
    sed "s/^512 512\t/$SIZE $SIZE\t/; s/^pixel_pitch_um = 21.5/pixel_pitch_um = $pitch/" \
        "$HAWKEYE/$view.adv" > "$view.adv"
    grep -q "^$SIZE $SIZE" "$view.adv" && grep -q "^pixel_pitch_um = $pitch\$" "$view.adv"
    run -0 make -C "$HAWKEYE" -j2 VIEW="$view" ADV="$BATS_TEST_TMPDIR/$view.adv" \
        OUT="$BATS_TEST_TMPDIR/out/$view" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
        HAWKEYE_SCENE="$(command -v hawkeye_scene)" \
        TRACE_FLAGS="-q --truth $BATS_TEST_TMPDIR/${view}_truth.img" cube
    [ -s "$cube" ] && [ -s "${view}_truth.img" ] && [ -s "${view}_truth.hdr" ]
    # No NaN (compare rejects a cube holding one, exit 2) and no zero.
    run -0 --separate-stderr compare --pixelwise "$cube" "$cube"
    bands=$(sed -n 's/^bands *= *//p' "out/$view/hawkeye.hdr")
    run -0 count_bad "$cube"
    assert_output "$((SIZE * SIZE * bands)) 0"
}

@test "hawkeye oblique view: no zero or NaN pixel" {
    render oblique
}

@test "hawkeye horizon view: sky in the top row, no zero or NaN pixel, consistent truth" {
    render horizon
    run -0 check_truth horizon_truth.img
    assert_line --regexp '^sky pixels [0-9]+, background pixels [1-9][0-9]*$'
}
