#!/usr/bin/env bats
# Tests: landsat_sensor
# Also requires: sigchain-check; make with control7 build_radiance find_min_max_view_angle
# trace sensorize (the one-command render of a scene from an MTL file, pipelines/scene.mk).
load test_helper

MARBURG="$SIGCHAIN_SOURCE_DIR/data/scenes/marburg"
ETM="$MARBURG/LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt"
OLI="$MARBURG/LC08_L1TP_195025_20130707_20170503_01_T1_MTL.txt"

@test "landsat_sensor: --help and --version exit 0" {
    run -0 --separate-stderr landsat_sensor --help
    assert_output --partial "See landsat_sensor(1)."
    run -0 --separate-stderr landsat_sensor --version
    assert_output --regexp '^landsat_sensor \(sigchain\) '
}

@test "landsat_sensor: an unknown option, a bad --gain or no -o exits 2" {
    run -2 --separate-stderr landsat_sensor --no-such-option "$ETM" -o out
    run -2 --separate-stderr landsat_sensor --gain 4=M "$ETM" -o out
    [[ "$stderr" == *"--gain: 4=M: expected BAND=H|L"* ]]
    run -2 --separate-stderr landsat_sensor "$ETM"
    run -2 --separate-stderr landsat_sensor --gain 4=H "$OLI" -o out
    [[ "$stderr" == *"has no gain states"* ]]
    [ ! -e out ]
}

@test "landsat_sensor: a malformed MTL exits 1 naming FILE:LINE, and writes nothing" {
    sed 's/SUN_ELEVATION = 53.87765310/SUN_ELEVATION = high/' "$ETM" > bad_MTL.txt
    run -1 --separate-stderr landsat_sensor bad_MTL.txt -o out
    assert_equal "$stderr" "landsat_sensor: bad_MTL.txt:68: expected SUN_ELEVATION (a number), found 'high'"
    head -n 30 "$ETM" > cut_MTL.txt
    run -1 --separate-stderr landsat_sensor cut_MTL.txt -o out
    [[ "$stderr" == "landsat_sensor: cut_MTL.txt:30: unexpected end of file, expected END"* ]]
    [ ! -e out ]
}

@test "landsat_sensor: a band without a response exits 1" {
    run -1 --separate-stderr landsat_sensor --bands 4,6_VCID_1 "$ETM" -o out
    [[ "$stderr" == *"no response column for band 6_VCID_1"* ]]
    [ ! -e out/marburg.snd ]
}

@test "landsat_sensor: golden .snd and .sen of the Marburg ETM+ file (band 4 at low gain)" {
    run -0 --separate-stderr landsat_sensor --samples 8 --bands 3,4 --target 50.8027,8.7715 \
        --name marburg "$ETM" -o out
    assert_equal "$(ls out)" "$(printf 'marburg-b3.sen\nmarburg-b4.sen\nmarburg.snd')"
    for f in marburg.snd marburg-b3.sen marburg-b4.sen; do
        assert_golden "out/$f" "$GOLDEN/landsat_sensor/$f"
        sigchain-check -q "out/$f"
    done
    grep -q '^# gain state L; L = mult x DN + add, mult 0.96929, add -6.06929' out/marburg-b4.sen
}

@test "landsat_sensor: --print-bands lists the default bands; -v prints the table on stderr" {
    run -0 --separate-stderr landsat_sensor --print-bands "$ETM"
    assert_output "1,2,3,4,5,7"
    run -0 --separate-stderr landsat_sensor --print-bands "$OLI"
    assert_output "1,2,3,4,5,6,7"
    # Requested bands are checked as a run would check them: ETM+ has no band 9.
    run -1 --separate-stderr landsat_sensor --print-bands --bands 1,9 "$ETM"
    assert_output ""
    [[ "$stderr" == *"band 9 has no radiance calibration"* ]]
    run -0 --separate-stderr landsat_sensor -v --gain 4=H --bands 4 "$ETM" -o out
    assert_output ""
    [[ "$stderr" == *"4 H 0.639763779527559 -5.739763779527559 "*"table (high gain, --gain)"* ]]
    [[ "$stderr" == *"NREL SPA elevation 53.909 azimuth 144.090"* ]]
}

@test "landsat_sensor: the training scene renders as the Marburg ETM+ scene with one make" {
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" scene
    rm -rf scene/out
    cp "$ETM" scene/
    # The deck's sun must be the .snd's: the training answers at Marburg's place and time
    # (30 July 2001 is day 211; 10.081 h GMT; longitude in degrees west).
    sed -e 's/^273 .*/211/' -e 's/^43.083 .*/50.8027/' -e 's/^77.667 .*/351.2285/' \
        -e 's/^1400.0 .*/10.081/' "$SIGCHAIN_SOURCE_DIR/data/scenes/training/hawkeye.answers" \
        > scene/hawkeye.answers
    run -0 make --no-print-directory -C scene counts \
        MTL=LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt LANDSAT_BANDS=1,2,3 \
        LANDSAT_SENSOR_FLAGS='-q --samples 4 --target 50.8027,8.7715' WTH= CARDS_GDB=
    [[ "$output" == *"bin/landsat_sensor -q --samples 4 --target 50.8027,8.7715 --bands 1,2,3 --name training"* ]]
    [ -f scene/out/training.tif ]
    [ -f scene/out/landsat/training-b3.sen ]
    sigchain-check -q scene/out/landsat/training.snd scene/out/training.snd
    [[ "$output" == *"out/landsat/training-b1.sen out/landsat/training-b2.sen out/landsat/training-b3.sen -o out/training.tif"* ]]
    # A rerun does nothing; make -n runs nothing either.
    run -0 make --no-print-directory -C scene counts \
        MTL=LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt LANDSAT_BANDS=1,2,3 \
        LANDSAT_SENSOR_FLAGS='-q --samples 4 --target 50.8027,8.7715' WTH= CARDS_GDB=
    [[ "$output" != *"landsat_sensor"* && "$output" != *"build_radiance"* ]]
    # Other sensor options rerun landsat_sensor and what follows.
    run -0 make --no-print-directory -n -C scene counts \
        MTL=LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt LANDSAT_BANDS=1,2,3 \
        LANDSAT_SENSOR_FLAGS='-q --samples 5 --target 50.8027,8.7715' WTH= CARDS_GDB=
    [[ "$output" == *"landsat_sensor -q --samples 5"* ]]
}
