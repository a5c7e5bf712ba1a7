#!/usr/bin/env bats
# Tests: control7
# Also requires: tests/data/control7/*.answers, tests/data/white1996/30Sep95800L.rsd,
# tests/data/white1996/flyover.cdk, tests/golden/control7/*.cdk
load test_helper

ANSWERS="$SIGCHAIN_SOURCE_DIR/tests/data/control7"

# The answers of White (1996) name 30Sep95800L.rsd, opened from the current directory.
seed_setup() {
    cp "$SEED/30Sep95800L.rsd" .
}

# bad_answer KEY VALUE MESSAGE: the answers of White (1996) with KEY overridden by VALUE
# stop with exit 1, "control7: --answer KEY: MESSAGE" and no deck or temporary file.
bad_answer() {
    local key="$1" value="$2" message="$3"
    seed_setup
    run -1 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -a "$key=$value" -o out.cdk
    assert_output ''
    assert_equal "$stderr" "control7: --answer $key: $message"
    [ ! -e out.cdk ] || fail "out.cdk written after a bad answer"
    assert_no_temp_files .
}

@test "--help prints usage and points to control7(1)" {
    run -0 --separate-stderr control7 --help
    assert_line --index 0 --partial "Usage: control7 "
    assert_equal "${lines[-1]}" "See control7(1)."
    assert_output --partial "--answers"
    assert_equal "$stderr" ""
}

@test "--version prints the project version" {
    run -0 --separate-stderr control7 --version
    assert_output --regexp '^control7 \(sigchain\) [0-9]+\.[0-9]+\.[0-9]+$'
}

@test "an unknown option exits 2" {
    run -2 --separate-stderr control7 --no-such-option
    assert_output ''
    assert_equal "${stderr##*$'\n'}" "Try 'control7 --help'."
}

@test "--list-questions prints every key in order" {
    run -0 --separate-stderr control7 --list-questions
    assert_line --index 0 --partial $'deck\tENTER FILE NAME FOR PRODUCED CARD DECK'
    assert_line --index 1 --partial $'model\tCHOOSE A MODEL NUMBER'
    assert_line --partial $'irpt\tSELECT IRPT'
}

@test "the answers file of White (1996) gives the golden deck" {
    seed_setup
    run -0 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -o hawkeye.cdk
    assert_output ''
    assert_equal "$stderr" ""
    assert_golden hawkeye.cdk "$GOLDEN/control7/hawkeye.cdk"
    assert_no_temp_files .
}

@test "the answers of White (1996) reproduce its fig. 4.31 except VIS and CARD 4" {
    seed_setup
    run -0 control7 --answers "$ANSWERS/hawkeye.answers" -o hawkeye.cdk
    # Lines 2 (CARD 2: VIS 23 answered, 0.000 in the deck of White (1996)) and 26
    # (CARD 4: 0.4-0.7 um answered, 2000-3333.333 cm-1 in that deck) differ; nothing else.
    run diff "$SEED/flyover.cdk" hawkeye.cdk
    assert_failure 1
    run sh -c "diff '$SEED/flyover.cdk' hawkeye.cdk | grep -E '^[0-9]'"
    assert_output $'2c2\n26c26'
    # CARD 2 differs in the VIS columns (31-40) only.
    assert_equal "$(sed -n 2p hawkeye.cdk | cut -c1-30,41-)" "$(sed -n 2p "$SEED/flyover.cdk" | cut -c1-30,41-)"
    assert_equal "$(sed -n 2p hawkeye.cdk | cut -c31-40)" "    23.000"
}

@test "without -o the deck goes to the file the first answer names" {
    seed_setup
    run -0 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers"
    assert_output ''
    assert_golden flyover.cdk "$GOLDEN/control7/hawkeye.cdk"
}

@test "answers from a pipe give the same deck on standard output" {
    seed_setup
    run -0 --separate-stderr sh -c "control7 -o - < '$ANSWERS/hawkeye.answers'"
    printf '%s\n' "$output" > piped.cdk
    assert_golden piped.cdk "$GOLDEN/control7/hawkeye.cdk"
    # The same answers without comments or blank lines.
    run -0 --separate-stderr sh -c "sed -e 's/#.*//' -e '/^ *$/d' '$ANSWERS/hawkeye.answers' | control7 -o bare.cdk"
    assert_golden bare.cdk "$GOLDEN/control7/hawkeye.cdk"
}

@test "--answers - reads standard input" {
    seed_setup
    run -0 sh -c "control7 --answers - -o std.cdk < '$ANSWERS/hawkeye.answers'"
    assert_golden std.cdk "$GOLDEN/control7/hawkeye.cdk"
}

@test "a standard model, cirrus, VSA, navy maritime and repeated runs: golden deck" {
    run -0 --separate-stderr control7 --answers "$ANSWERS/us_standard.answers" -o us.cdk
    assert_golden us.cdk "$GOLDEN/control7/us_standard.cdk"
    run -0 sigchain-check -q us.cdk
}

@test "options override single answers" {
    seed_setup
    run -0 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -a vis=50 \
        --answer ihaze=1 -a time=19 -o rural.cdk
    assert_equal "$(sed -n 2p rural.cdk)" "    1    2    0    1    0    0    50.000     0.000     0.000     0.000     0.218"
    assert_equal "$(sed -n 25p rural.cdk | cut -c41-50)" "    19.000"
}

@test "an override whose question is not asked gets a warning" {
    seed_setup
    run -0 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -a m1=6 -o out.cdk
    assert_equal "$stderr" "control7: warning: --answer m1: question not asked with these answers"
    run -0 --separate-stderr control7 -q --answers "$ANSWERS/hawkeye.answers" -a m1=6 -o out.cdk
    assert_equal "$stderr" ""
}

@test "an unknown --answer key or one without '=' is bad usage" {
    run -2 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -a no_such=1 -o out.cdk
    [[ "$stderr" == "control7: --answer: unknown question 'no_such'"* ]] || fail "$stderr"
    run -2 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -a vis -o out.cdk
    [[ "$stderr" == "control7: --answer expects KEY=VALUE, found 'vis'"* ]] || fail "$stderr"
    [ ! -e out.cdk ]
}

@test "bad answers: codes out of range" {
    bad_answer model 8 "expected model atmosphere in [0, 7], found '8'"
    bad_answer itype 0 "expected path type in [1, 3], found '0'"
    bad_answer iemsct 4 "expected execution mode in [0, 3], found '4'"
    bad_answer imult 2 "expected multiple scattering mode in [0, 1], found '2'"
    bad_answer ihaze 7 "expected aerosol model IHAZE in [0, 10] except 7 (user defined, not supported), found '7'"
    bad_answer iseasn 3 "expected season in [0, 2], found '3'"
    bad_answer ivulcn 9 "expected volcanic extinction in [0, 8], found '9'"
    bad_answer icld 15 "expected cloud model in [0, 10] or [18, 20] (11, user defined, is not supported), found '15'"
    bad_answer iparm 3 "expected geometry type IPARM in [0, 2], found '3'"
    bad_answer iph 1 "expected phase function type IPH in [0, 2] except 1 (user supplied, not supported), found '1'"
    bad_answer irpt 2 "expected IRPT in [0, 1, 3, 4], found '2'"
    bad_answer irpt 3 "expected IRPT in [0, 1, 4] (LOWTRAN 7 cannot repeat CARD 3 with multiple and solar scattering), found '3'"
}

@test "bad answers: physical values out of range" {
    bad_answer tbound 500 "expected boundary temperature (K, 0 first level) in [0, 400], found '500'"
    bad_answer salb -0.1 "expected surface albedo in [0, 1], found '-0.1'"
    bad_answer vis 0 "expected visibility (km) in (0, 1000], found '0'"
    bad_answer rain_rate 300 "expected rain rate (mm/h) in [0, 200], found '300'"
    bad_answer gndalt 6 "expected ground altitude (km) in [0, 6), found '6'"
    bad_answer h1 0.1 "expected H1, initial altitude (km, ground to 100) in [0.218, 100], found '0.1'"
    bad_answer h2 101 "expected H2, final altitude (km, ground to 100) in [0.218, 100], found '101'"
    bad_answer angle 190 "expected initial zenith angle (deg) in [0, 180], found '190'"
    bad_answer beta 200 "expected earth center angle (deg) in [0, 180], found '200'"
    bad_answer iday 0 "expected day of the year in [1, 366], found '0'"
    bad_answer obs_lat -91 "expected observer latitude (deg north) in [-90, 90], found '-91'"
    bad_answer obs_lon 400 "expected observer longitude (deg west) in [0, 360], found '400'"
    bad_answer time 25 "expected time of day in [0, 24] (decimal hours) or [100, 2400] (HHMM), found '25'"
    bad_answer psipo -5 "expected path azimuth (deg east of north) in [0, 360], found '-5'"
}

@test "bad answers: radiosonde levels, names, spectral range" {
    bad_answer levels 0 "expected number of atmospheric levels in [1, 34], found '0'"
    bad_answer levels 20 "expected number of atmospheric levels in [1, 19] (the levels of the radiosonde file), found 20"
    bad_answer title "$(printf 'x%.0s' {1..73})" "expected the name of the new atmosphere (1 to 72 characters), found 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'"
    bad_answer radiosonde n "expected radiosonde input in [y] (model 0 and 7 layers are read from an .rsd file), found 'n'"
    bad_answer aerosol_by_layer y "expected aerosol control by layer in [n] (CARD 2C3 input is not supported), found 'y'"
    bad_answer units furlongs "expected wavelength units in [microns, nanometers], found 'furlongs'"
    bad_answer wavelengths 0.1-0.7 "expected wavelength (microns) in [0.2, 1000], found '0.1-0.7'"
    bad_answer wavelengths 0.7-0.4 "expected a starting wavelength below the ending wavelength, found '0.7-0.4'"
    bad_answer wavelengths 0.4 "expected starting and ending wavelength (two numbers), found '0.4'"
    bad_answer intervals 400 "expected number of intervals in [1, 396], found '400'"
}

@test "bad answers: not a number, not y or n" {
    bad_answer model seven "expected model atmosphere (a number), found 'seven'"
    bad_answer model 2.5 "expected model atmosphere in [0, 7], found '2.5'"
    bad_answer ivsa maybe "expected army vertical structure algorithm in [y, n], found 'maybe'"
}

@test "a bad answer in a file names the file and line" {
    seed_setup
    sed 's/^5   /7   /' "$ANSWERS/hawkeye.answers" > bad.answers
    run -1 --separate-stderr control7 --answers bad.answers -o out.cdk
    assert_equal "$stderr" "control7: bad.answers:20: expected aerosol model IHAZE in [0, 10] except 7 (user defined, not supported), found '7'"
    [ ! -e out.cdk ]
}

@test "a bad answer from a pipe names <stdin>" {
    seed_setup
    run -1 --separate-stderr sh -c "sed 's/^5   /7   /' '$ANSWERS/hawkeye.answers' | control7 -o out.cdk"
    assert_equal "$stderr" "control7: <stdin>:20: expected aerosol model IHAZE in [0, 10] except 7 (user defined, not supported), found '7'"
}

@test "a missing radiosonde file is an error naming it" {
    run -1 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -o out.cdk
    [[ "$stderr" == "control7: $ANSWERS/hawkeye.answers:32: radiosonde: "*"30Sep95800L.rsd"* ]] || fail "$stderr"
    [ ! -e out.cdk ]
    assert_no_temp_files .
}

@test "a malformed radiosonde file is an error naming its line" {
    printf '0.2\t998\t23.8\t7.8\n0.6\t999\t14.7\t6.4\n' > 30Sep95800L.rsd
    run -1 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -o out.cdk
    [[ "$stderr" == "control7: $ANSWERS/hawkeye.answers:32: radiosonde: 30Sep95800L.rsd:2: "* ]] || fail "$stderr"
}

@test "dew points missing above the last valid one are extrapolated" {
    # White (1996), table 4.3: -999 from 250 mb up; the 300 mb depression (3.1 C) is kept.
    sed -e 's/-50.7$/-999/' -e 's/-59.9$/-999/' -e 's/-65.5$/-999/' -e 's/-71.5$/-999/' \
        "$SEED/30Sep95800L.rsd" > 30Sep95800L.rsd
    run -0 control7 --answers "$ANSWERS/hawkeye.answers" -o out.cdk
    run sh -c "sed -n '19,22p' out.cdk | cut -c31-40"
    assert_output $'-0.508E+02\n-0.600E+02\n-0.656E+02\n-0.716E+02'
}

@test "too few or too many answers" {
    seed_setup
    head -n 20 "$ANSWERS/hawkeye.answers" > short.answers
    run -1 --separate-stderr control7 --answers short.answers -o out.cdk
    [[ "$stderr" == "control7: short.answers"*"unexpected end of the answers, expected the answer to 'iseasn'" ]] || fail "$stderr"
    { cat "$ANSWERS/hawkeye.answers"; echo 1; } > long.answers
    run -1 --separate-stderr control7 --answers long.answers -o out.cdk
    assert_equal "$stderr" "control7: long.answers:51: unexpected answer after IRPT 0, found '1'"
    [ ! -e out.cdk ]
}

@test "output is atomic: an error leaves an existing deck untouched" {
    seed_setup
    echo "old deck" > out.cdk
    run -1 control7 --answers "$ANSWERS/hawkeye.answers" -a model=9 -o out.cdk
    assert_equal "$(cat out.cdk)" "old deck"
    run -1 --separate-stderr control7 --answers "$ANSWERS/hawkeye.answers" -o no/such/dir/out.cdk
    [ ! -e no ]
    assert_no_temp_files .
}

@test "a missing answers file is an I/O error" {
    run -1 --separate-stderr control7 --answers no_such.answers -o out.cdk
    [[ "$stderr" == "control7: "*"no_such.answers"* ]] || fail "$stderr"
}

@test "on a terminal the questions are asked and a bad answer is asked again" {
    command -v script > /dev/null || skip "script(1) (util-linux) is needed for a terminal"
    seed_setup
    # The answers of White (1996) typed on a pseudo-terminal, with a bad model number first.
    { printf 'flyover.cdk\n12\n'; sed -e 's/#.*//' -e '/^ *$/d' "$ANSWERS/hawkeye.answers" | tail -n +2; } > typed
    run -0 sh -c "script -qec 'control7 -o tty.cdk' /dev/null < typed"
    assert_output --partial "ENTER FILE NAME FOR PRODUCED CARD DECK:"
    assert_output --partial "7 NEW MODEL ATMOSPHERE (RADIOSONDE DATA)"
    assert_output --partial "control7: expected model atmosphere in [0, 7], found '12'; please answer again"
    assert_output --partial "ENTERING DATA FOR LAYER 19: ALTITUDE 16.493"
    assert_golden tty.cdk "$GOLDEN/control7/hawkeye.cdk"
}
