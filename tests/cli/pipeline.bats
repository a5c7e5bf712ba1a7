#!/usr/bin/env bats
# Tests: pipelines/scene.mk on the training scene (data/scenes/training)
# Tools run through make: control7 build_radiance find_min_max_view_angle trace therm
# sensorize compare; sigchain-check validates the text outputs.
#
# The scene is built once into a scratch copy (setup_file); each test copies that
# built tree with its time stamps (cp -a), changes an input and runs make again,
# then reads from make's echoed commands which stages ran.
load test_helper

# stretch_error PNG CHANNEL TIF BAND: the largest difference (DN) between a preview's
# channel and the TIF band stretched as sensorize(1) --preview says: linearly from its
# 2nd percentile (nearest rank) to its 98th, to 0-255, rounded and clipped.
stretch_error() {
    local lo hi n
    gdal_translate -q -of XYZ -b "$4" "$3" /vsistdout/ | awk '{ print $3 }' > band.txt
    n=$(wc -l < band.txt)
    lo=$(sort -g band.txt | awk -v k="$(awk -v n="$n" 'BEGIN { print int(0.02 * (n - 1) + 0.5) }')" 'NR == k + 1')
    hi=$(sort -g band.txt | awk -v k="$(awk -v n="$n" 'BEGIN { print int(0.98 * (n - 1) + 0.5) }')" 'NR == k + 1')
    paste <(gdal_translate -q -of XYZ -b "$2" "$1" /vsistdout/ | awk '{ print $3 }') band.txt |
        awk -v lo="$lo" -v hi="$hi" '{ v = ($2 - lo) / (hi - lo) * 255; v = v < 0 ? 0 : v > 255 ? 255 : v
            d = $1 - int(v + 0.5); if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }'
    rm band.txt
}

# band_mean IMAGE BAND: the mean of a band's pixels.
band_mean() {
    gdal_translate -q -of XYZ -b "$2" "$1" /vsistdout/ | awk '{ s += $3; n++ } END { print s / n }'
}

SCENE_SRC="$SIGCHAIN_SOURCE_DIR/data/scenes/training"

setup_file() {
    : "${SIGCHAIN_SOURCE_DIR:=$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
    : "${SIGCHAIN_BIN:=$SIGCHAIN_SOURCE_DIR/build/bin}"
    export SIGCHAIN_SOURCE_DIR SIGCHAIN_BIN
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" "$BATS_FILE_TMPDIR/built"
    rm -rf "$BATS_FILE_TMPDIR/built/out"
    make -s -C "$BATS_FILE_TMPDIR/built" > "$BATS_FILE_TMPDIR/first.log" 2>&1 \
        || echo "make failed: $?" >> "$BATS_FILE_TMPDIR/first.log"
}

# A fresh copy of the built scene in the test's directory, as ./training.
copy_built() {
    cp -a "$BATS_FILE_TMPDIR/built" training
}

# mk ARGS...: make in ./training, with make's command echo in $output.
mk() {
    run make --no-print-directory -C training "$@"
}

# ran STAGE: how many commands of STAGE make ran (from the echoed recipes).
ran() {
    local pattern
    case "$1" in
        control7) pattern='bin/control7 ' ;;
        build_radiance) pattern='bin/build_radiance ' ;;
        find_view) pattern='bin/find_min_max_view_angle ' ;;
        render) pattern='bin/trace -q' ;;
        shadow) pattern='bin/trace --shadow-history' ;;
        therm) pattern='bin/therm ' ;;
        calibrate) pattern='bin/sensorize --calibrate' ;;
        sensorize) pattern='bin/sensorize -q' ;;
        compare) pattern='bin/compare ' ;;
    esac
    grep -c -e "$pattern" <<< "$output" || true
}

# stages: the stages that ran, as "stage=count" words, for readable failures.
stages() {
    local s out=""
    for s in control7 build_radiance find_view render shadow therm calibrate sensorize compare; do
        out+="$s=$(ran "$s") "
    done
    echo "${out% }"
}

@test "pipeline: make builds the training scene; every output is valid" {
    cat "$BATS_FILE_TMPDIR/first.log"
    run -1 grep -q 'make failed' "$BATS_FILE_TMPDIR/first.log"
    copy_built
    cd training/out
    # Text outputs: sigchain-check accepts each (it knows their formats).
    run -0 sigchain-check hawkeye.cdk training.snd \
        training-1.rad training-2.rad training-3.rad training.shd training.tmp \
        calibrated/blue.sen calibrated/green.sen calibrated/red.sen
    # Images: compare reads each one (an image against itself differs by 0).
    local image
    for image in training.img cards.img training.tif training.png; do
        run -0 compare --pixelwise --fail-max 0 "$image" "$image"
    done
    # The preview is true colour whatever the .sen order (blue, green, red here): its
    # red channel is the red band's counts stretched, its blue the blue band's.
    local channel band
    for channel in 1 2 3; do
        band=$((4 - channel))
        run -0 stretch_error training.png "$channel" training.tif "$band"
        [ "$output" -le 1 ] || fail "preview channel $channel is not counts band $band: $output DN off"
    done
    # With one stretch for the three bands (of band radiance) the colour is the
    # materials': the training scene's grass is the ECOSTRESS library's green grass
    # (grass.ems: reflectance 0.04 at 0.45 um, 0.11 at 0.55 um, 0.05 at 0.65 um), so
    # green is brightest, as in the band radiance: the preview shows green grass.
    run -0 sensorize -q training.img calibrated/blue.sen calibrated/green.sen \
        calibrated/red.sen -o c.tif --preview common.png --preview-stretch common
    local r g b
    r=$(band_mean common.png 1) g=$(band_mean common.png 2) b=$(band_mean common.png 3)
    awk -v r="$r" -v g="$g" -v b="$b" 'BEGIN { exit !(g > r && g > b) }' ||
        fail "common stretch: mean R $r, G $g, B $b"
    rm c.tif common.png
    run -2 sensorize -q training.img calibrated/red.sen -o c.tif --preview-stretch common
    # The cube: 32 x 32 pixels, 3 bands of 5 spectral samples.
    grep -q '^samples = 32' training.hdr
    grep -q '^lines *= 32' training.hdr
    grep -q '^bands *= 15' training.hdr
    # The report compares the counts with the reference at all 9 control points.
    grep -q '(9 control points' training.report
    assert_no_temp_files .
}

@test "pipeline: the view-angle line of out/training.snd is find_min_max_view_angle's" {
    copy_built
    # The training and card views share their camera, so the union of the two ranges
    # is the --snd line of either (field-of-view method, rounded outward).
    want=$(find_min_max_view_angle --snd training/training.adv training/training.gdb |
        awk '{ printf "%g %g %g", $1, $2, $3 }')
    run -0 sed -n '/find_min_max_view_angle$/p' training/out/training.snd
    [[ "$output" == "$want"$'\t'* ]] || { echo "line: $output; wanted: $want"; return 1; }
    # The camera looks north, so build_radiance's positive view angles do too.
    run -0 cat training/out/training.azimuth
    assert_output '0.000'
}

@test "pipeline: a second make runs nothing" {
    copy_built
    mk
    assert_success
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=0 render=0 shadow=0 therm=0 calibrate=0 sensorize=0 compare=0" ] \
        || { echo "$output"; stages; return 1; }
    run -0 make -q -C training
}

@test "pipeline: changing TRACE_FLAGS reruns trace and what follows, not build_radiance" {
    copy_built
    mk TRACE_FLAGS="-q --threads 1"
    assert_success
    # The scene and the cards are traced again, then calibration, counts with preview and
    # report; the tables, the view range and the thermal chain stay.
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=0 render=2 shadow=0 therm=0 calibrate=1 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
    run -0 cat training/out/trace.cmd.stamp
    assert_output --partial 'bin/trace -q --threads 1 --tmp out/training.tmp'
    # The same flags again: nothing to do; the old flags: trace again.
    mk TRACE_FLAGS="-q --threads 1"
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=0 render=0 shadow=0 therm=0 calibrate=0 sensorize=0 compare=0" ] \
        || { echo "$output"; stages; return 1; }
    run -0 make -q -C training TRACE_FLAGS="-q --threads 1"
    mk
    [ "$(ran render)" = 2 ] || { echo "$output"; stages; return 1; }
}

@test "pipeline: another BUILD_RADIANCE reruns build_radiance and the stages after it" {
    copy_built
    mk BUILD_RADIANCE="$SIGCHAIN_BIN/build_radiance --threads 1"
    assert_success
    [ "$(stages)" = "control7=0 build_radiance=1 find_view=0 render=2 shadow=0 therm=0 calibrate=1 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
    # Same tables, so the same counts.
    run -0 compare --pixelwise --fail-max 0 training/out/training.tif "$BATS_FILE_TMPDIR/built/out/training.tif"
}

@test "pipeline: one build_radiance run writes every band's table, as one run per band does" {
    copy_built
    # The default for sigchain's build_radiance: one run, every band (-o PATTERN).
    rm training/out/training-*.rad
    mk rad
    assert_success
    [ "$(ran build_radiance)" = 1 ] || { echo "$output"; stages; return 1; }
    assert_output --partial 'out/training.snd -o out/training-%d.rad'
    [ ! -e training/out/band-1.snd ]
    # One run per band (a one-band scene node each) gives the same bytes.
    mk BUILD_RADIANCE_RUNS=band OUT=per_band rad
    assert_success
    [ "$(ran build_radiance)" = 3 ] || { echo "$output"; stages; return 1; }
    assert_output --partial 'per_band/band-2.snd -o per_band/training-2.rad'
    local k
    for k in 1 2 3; do
        cmp training/out/training-$k.rad training/per_band/training-$k.rad
    done
    mk BUILD_RADIANCE_RUNS=each rad
    assert_failure
    assert_output --partial 'BUILD_RADIANCE_RUNS=each: expected all or band'
}

@test "pipeline: touching a .sen reruns only sensorize and compare" {
    copy_built
    touch training/green.sen
    mk
    assert_success
    # calibrate (cards -> .sen), counts and preview, then the report.
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=0 render=0 shadow=0 therm=0 calibrate=1 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
}

@test "pipeline: touching the .adv reruns the view range, trace and later, not build_radiance" {
    copy_built
    snd_before=$(stat -c %Y.%y training/out/training.snd)
    touch training/training.adv
    mk
    assert_success
    # The range is recomputed (2 runs: the --snd line and the report) but is the same,
    # so out/training.snd keeps its time and the tables are not recomputed; the cards'
    # view (cards.adv) is untouched, so only the training cube is rendered again.
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=2 render=1 shadow=0 therm=0 calibrate=0 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
    assert_equal "$(stat -c %Y.%y training/out/training.snd)" "$snd_before"
}

@test "pipeline: a camera move that changes the view range reruns build_radiance" {
    copy_built
    # Camera 10 m further south: every view angle grows.
    sed -i 's/^10 -10 30\t/10 -20 30\t/' training/training.adv
    mk
    assert_success
    [ "$(stages)" = "control7=0 build_radiance=1 find_view=2 render=2 shadow=0 therm=0 calibrate=1 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
    # The new line is the union of the moved view's range and the cards' range: its
    # maximum is the moved view's.
    run -1 diff "$BATS_FILE_TMPDIR/built/out/training.snd" training/out/training.snd
    run -0 find_min_max_view_angle --snd training/training.adv training/training.gdb
    new=$(awk '{ printf "%g", $2 }' <<< "$output")
    run -0 grep "^[-0-9.]* $new [0-9.]*"$'\t'"# view angles" training/out/training.snd
}

@test "pipeline: touching the deck answers reruns control7, build_radiance and later" {
    copy_built
    touch training/hawkeye.answers
    mk
    assert_success
    # Not the view range, nor the thermal chain (which reads no .rad).
    [ "$(stages)" = "control7=1 build_radiance=1 find_view=0 render=2 shadow=0 therm=0 calibrate=1 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
}

@test "pipeline: touching the weather reruns therm, trace and later" {
    copy_built
    touch training/weather_30_Sep_95.wth
    mk
    assert_success
    [ "$(stages)" = "control7=0 build_radiance=0 find_view=0 render=1 shadow=0 therm=1 calibrate=0 sensorize=1 compare=1" ] \
        || { echo "$output"; stages; return 1; }
}

@test "pipeline: BUILD_RADIANCE swapped for a stub that copies valid tables works" {
    copy_built
    mkdir tables
    cp training/out/training-*.rad tables/
    rm -rf training/out
    # The stage's interface: BUILD_RADIANCE [FLAGS] --view-azimuth DEG CDK SND -o FILE.
    cat > stub.sh <<EOF
#!/bin/sh
while [ \$# -gt 0 ]; do case "\$1" in -o) out="\$2"; shift ;; esac; shift; done
echo "stub \$out" >> "$PWD/stub.log"
cp "$PWD/tables/\$(basename "\$out")" "\$out"
EOF
    chmod +x stub.sh
    mk BUILD_RADIANCE="$PWD/stub.sh"
    assert_success
    run -0 cat stub.log
    assert_line 'stub out/training-1.rad'
    assert_line 'stub out/training-3.rad'
    assert_equal "${#lines[@]}" 3
    # The same tables give the same image as the real stage.
    run -0 compare --pixelwise --fail-max 0 training/out/training.tif "$BATS_FILE_TMPDIR/built/out/training.tif"
}

@test "pipeline: a failing stage leaves no target behind (.DELETE_ON_ERROR)" {
    copy_built
    touch training/hawkeye.answers
    # A build_radiance that writes a partial table, then fails.
    cat > fail.sh <<'EOF'
#!/bin/sh
while [ $# -gt 0 ]; do case "$1" in -o) out="$2"; shift ;; esac; shift; done
echo partial > "$out"
exit 1
EOF
    chmod +x fail.sh
    mk BUILD_RADIANCE="$PWD/fail.sh" rad
    assert_failure
    assert_output --partial "Deleting file 'out/training-1.rad'"
    [ ! -e training/out/training-1.rad ]
    # The real stage then rebuilds what was deleted, and nothing is half-written.
    mk rad
    assert_success
    run -0 sigchain-check training/out/training-1.rad training/out/training-2.rad \
        training/out/training-3.rad
}

@test "pipeline: TILES=3 renders row tiles in parallel and merges them bit for bit" {
    copy_built
    mk -j2 TILES=3 OUT=tiled cube
    assert_success
    # Three trace --rows runs (rows 0:10, 10:21, 21:32 of 32), no other render.
    [ "$(grep -c -e '--rows' <<< "$output")" = 3 ] || { echo "$output"; return 1; }
    assert_output --partial '--rows $((0 * 32 / 3)):$(((0 + 1) * 32 / 3))'
    run -0 cmp training/tiled/training.img training/out/training.img
    run -0 cmp training/tiled/training.hdr training/out/training.hdr
    run -0 cmp training/tiled/training.geoloc.tif training/out/training.geoloc.tif
}

@test "pipeline: the calibrated sensor gives the cards their target counts" {
    copy_built
    cd training/out
    # Counts of the calibration scene with the calibrated .sen files, as plain PPM.
    run -0 sensorize -q cards.img calibrated/blue.sen calibrated/green.sen \
        calibrated/red.sen -o cards.ppm
    # Mean count of each band over each card's box (CARD1 14,7,17,10 and CARD2
    # 14,21,17,24 in the scene's Makefile). Each pixel's count is its calibrated value
    # rounded, so the box means are within 0.5 of the targets 60 and 180.
    run -0 awk '
        { sub(/#.*/, ""); for (i = 1; i <= NF; i++) v[n++] = $i }
        END {
            w = v[1]; k = 4
            for (b = 0; b < 3; b++) {
                s1 = s2 = 0
                for (r = 14; r <= 17; r++) for (c = 7; c <= 10; c++) s1 += v[k + 3 * (r * w + c) + b]
                for (r = 14; r <= 17; r++) for (c = 21; c <= 24; c++) s2 += v[k + 3 * (r * w + c) + b]
                printf "%d %.3f %.3f\n", b + 1, s1 / 16, s2 / 16
            }
        }' cards.ppm
    local band m1 m2
    while read -r band m1 m2; do
        awk -v a="$m1" -v b="$m2" 'BEGIN { exit !(a >= 59.5 && a <= 60.5 && b >= 179.5 && b <= 180.5) }' \
            || { echo "band $band: card means $m1 $m2, wanted 60 and 180 within 0.5"; return 1; }
    done <<< "$output"
}

@test "pipeline: a scene without cards, weather or reference runs the plain chain" {
    cp -R "$SCENE_SRC" training
    rm -rf training/out
    mk CARDS_GDB= WTH= REFERENCE=
    assert_success
    # One view range, no thermal chain, no calibration, no report; the counts use
    # the scene's own .sen files.
    [ "$(stages)" = "control7=1 build_radiance=1 find_view=2 render=1 shadow=0 therm=0 calibrate=0 sensorize=1 compare=0" ] \
        || { echo "$output"; stages; return 1; }
    assert_output --partial 'training.img blue.sen green.sen red.sen -o out/training.tif'
    [ ! -e training/out/training.tmp ] && [ ! -e training/out/cards.img ]
}

@test "pipeline: make help lists the stage and scene variables" {
    copy_built
    mk help
    assert_success
    local v
    for v in SIGCHAIN_BIN CONTROL7 BUILD_RADIANCE FIND_VIEW TRACE SHADOW THERM SENSORIZE \
        COMPARE TRACE_FLAGS SCENE_GDB SCENE_MAT ADV SND ANSWERS WTH SENS BANDS=3 TILES=1; do
        assert_output --partial "$v"
    done
}
