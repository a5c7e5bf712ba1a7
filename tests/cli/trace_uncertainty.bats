#!/usr/bin/env bats
# Tests: trace
# Also requires: sensorize sigchain-check gdalinfo
#
# trace --uncertainty FILE (trace(1) UNCERTAINTY, unc(5)) on the box scene of trace.bats
# (tests/data/trace, training.unc), and sensorize --uncertainty-cube carrying its layers
# into counts (sensorize(1) UNCERTAINTY).

bats_require_minimum_version 1.5.0
load test_helper
load trace_helper

@test "trace --uncertainty adds uncertainty_BAND to the truth, the cube unchanged" {
    trace_ok $(inputs) --samples-per-pixel 1 -o out.img --truth truth.img \
        --standard-error --uncertainty "$DATA/training.unc"
    run -0 tr -d '\n' < truth.hdr
    [[ "$output" == *"standard_error_band2,uncertainty_band1,uncertainty_band2}"* ]] ||
        fail "truth band names: $output"
    trace_ok $(inputs) --samples-per-pixel 1 -o plain.img
    run -0 cmp out.img plain.img
}

@test "trace --uncertainty gives the same truth with 1 and 2 threads" {
    trace_ok $(inputs) --threads 1 -o one.img --truth one_truth.img --uncertainty "$DATA/training.unc"
    trace_ok $(inputs) --threads 2 -o two.img --truth two_truth.img --uncertainty "$DATA/training.unc"
    run -0 cmp one_truth.img two_truth.img
}

@test "trace --uncertainty needs --truth (exit 2)" {
    trace_bad 2 "--uncertainty: its layers are in the truth cube: give --truth FILE" \
        $(inputs) -o out.img --uncertainty "$DATA/training.unc"
}

@test "trace --uncertainty: a material not in the .mat names the .unc line (exit 1)" {
    trace_bad 1 "$DATA/unknown_material.unc:2: material 'asphalt' is not in the material file" \
        $(inputs) -o out.img --truth t.img --uncertainty "$DATA/unknown_material.unc"
}

@test "trace --uncertainty: a malformed .unc names its line (exit 1)" {
    trace_bad 1 "$BAD/unc/negative.unc:3: expected sigma at or above 0, found '-0.1'" \
        $(inputs) -o out.img --truth t.img --uncertainty "$BAD/unc/negative.unc"
}

@test "trace --uncertainty: a missing .unc (exit 1)" {
    trace_bad 1 "" $(inputs) -o out.img --truth t.img --uncertainty missing.unc
}

@test "sensorize --uncertainty-cube writes one counts uncertainty band per .sen" {
    trace_ok $(inputs) --samples-per-pixel 1 -o cube.img --truth truth.img \
        --uncertainty "$DATA/training.unc"
    printf '3\n10000\n5\n1\n1\n1\n' > b1.sen
    printf '3\n10000\n5\n1\n1\n1\n' > b2.sen
    run -0 --separate-stderr sensorize cube.img b1.sen b2.sen -o dc.tif \
        --uncertainty-cube truth.img --uncertainty-output u.tif --read-noise 1
    run -0 gdalinfo -stats u.tif
    [[ "$output" == *"Band 2 Block"* ]] || fail "gdalinfo: $output"
    [[ "$output" != *"Band 3 Block"* ]] || fail "gdalinfo: $output"
    # Read noise 1 count alone would give 1: the inputs' uncertainty adds to it.
    [[ "$output" =~ STATISTICS_MINIMUM=([0-9.]+) ]] || fail "gdalinfo: $output"
    awk -v m="${BASH_REMATCH[1]}" 'BEGIN { exit !(m >= 1) }' || fail "minimum ${BASH_REMATCH[1]} < 1"
    [[ "$output" =~ STATISTICS_MAXIMUM=([0-9.]+) ]] || fail "gdalinfo: $output"
    awk -v m="${BASH_REMATCH[1]}" 'BEGIN { exit !(m > 1.5) }' || fail "maximum ${BASH_REMATCH[1]} <= 1.5"
}

@test "sensorize --uncertainty-cube without --uncertainty-output is a usage error (exit 2)" {
    trace_ok $(inputs) --samples-per-pixel 1 -o cube.img --truth truth.img
    printf '3\n10000\n5\n1\n1\n1\n' > b1.sen
    run -2 --separate-stderr sensorize cube.img b1.sen b1.sen -o dc.tif --uncertainty-cube truth.img
    [[ "$stderr" == "sensorize: --uncertainty-cube and --uncertainty-output go together"* ]] ||
        fail "stderr: $stderr"
}

@test "sensorize --uncertainty-cube: a truth cube without uncertainty layers (exit 1)" {
    trace_ok $(inputs) --samples-per-pixel 1 -o cube.img --truth truth.img
    printf '3\n10000\n5\n1\n1\n1\n' > b1.sen
    run -1 --separate-stderr sensorize cube.img b1.sen b1.sen -o dc.tif --uncertainty-cube truth.img \
        --uncertainty-output u.tif
    [[ "$stderr" == "sensorize: truth.img"*"0 uncertainty_BAND layer(s) (trace --uncertainty), but 2 sensor band(s)"* ]] ||
        fail "stderr: $stderr"
    [ ! -e u.tif ] && [ ! -e dc.tif ]
}

@test "sensorize --uncertainty is a deprecated name of --uncertainty-cube" {
    trace_ok $(inputs) --samples-per-pixel 1 -o cube.img --truth truth.img \
        --uncertainty "$DATA/training.unc"
    printf '3\n10000\n5\n1\n1\n1\n' > b1.sen
    run -0 --separate-stderr sensorize cube.img b1.sen b1.sen -o new.tif \
        --uncertainty-cube truth.img --uncertainty-output new_u.tif
    run -0 --separate-stderr sensorize cube.img b1.sen b1.sen -o old.tif \
        --uncertainty truth.img --uncertainty-output old_u.tif
    assert_equal "${stderr_lines[0]}" "sensorize: warning: --uncertainty is deprecated: use --uncertainty-cube"
    # The same values (the files differ in the command line they record).
    run -0 diff <(gdalinfo -stats new_u.tif | grep STATISTICS_) \
        <(gdalinfo -stats old_u.tif | grep STATISTICS_)
    run -2 --separate-stderr sensorize cube.img b1.sen b1.sen -o both.tif \
        --uncertainty-cube truth.img --uncertainty truth.img --uncertainty-output both_u.tif
    [[ "$stderr" == "sensorize: give --uncertainty-cube or --uncertainty, not both"* ]] ||
        fail "stderr: $stderr"
}
