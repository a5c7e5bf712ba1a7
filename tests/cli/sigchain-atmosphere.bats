#!/usr/bin/env bats
# Tests: sigchain-atmosphere (pipelines/sigchain-atmosphere.in)
# Also requires: build_radiance, sigchain-check, trace, tests/data/tape7/fake_lowtran7 (a
# stand-in for LOWTRAN 7: fake_lowtran7.awk's TAPE7 of a deck, or a failure on a bad
# deck), tests/golden/control7/hawkeye.cdk, tests/data/build_radiance/small.snd,
# data/scenes/training (the stage swap)
#
# Each run's .rad is compared with the one the hand-made loop gives (build_radiance
# --write-decks, fake_lowtran7.awk on each deck, build_radiance --from-tape7), whose
# values tests/cli/build_radiance_tape7.bats checks number by number.
bats_require_minimum_version 1.5.0
load test_helper

HAWKEYE="$GOLDEN/control7/hawkeye.cdk"
SMALL="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance/small.snd"
FAKE="$SIGCHAIN_SOURCE_DIR/tests/data/tape7/fake_lowtran7"
SKY=(--sky-zenith-step 45 --sky-azimuth-step 90)

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    # Temporary work folders go here, so that a test sees what is left behind.
    mkdir -p tmp
    export TMPDIR="$BATS_TEST_TMPDIR/tmp"
}

# expected: the .rad of the hand-made loop, into want-1.rad and want-2.rad.
expected() {
    build_radiance -q --write-decks want "${SKY[@]}" "$HAWKEYE" "$SMALL"
    local deck
    for deck in want/*.tp5; do
        awk -v T=0.8 -v ES=5e-6 -v LP=1e-7 -v LS=2e-7 -f "$FAKE.awk" "$deck" > "${deck%.tp5}.tp7"
    done
    build_radiance -q --from-tape7 want "$HAWKEYE" "$SMALL" -o 'want-%d.rad'
}

@test "sigchain-atmosphere --help and --version" {
    run -0 --separate-stderr sigchain-atmosphere --help
    assert_line --index 0 --partial "Usage: sigchain-atmosphere --program CMD"
    assert_line "See sigchain-atmosphere(1)."
    assert_equal "$stderr" ''
    run -0 sigchain-atmosphere --version
    assert_output "sigchain-atmosphere (sigchain) $(sed -n 's/^project(sigchain VERSION \([0-9.]*\).*/\1/p' \
        "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt")"
}

@test "sigchain-atmosphere: LOWTRAN 7's way (TAPE5 in, TAPE7 out) gives the hand-made loop's tables" {
    expected
    run -0 --separate-stderr sigchain-atmosphere --program "$FAKE" -q "${SKY[@]}" "$HAWKEYE" \
        "$SMALL" -o 'got-%d.rad'
    assert_output ''
    assert_equal "$stderr" ''
    cmp got-1.rad want-1.rad && cmp got-2.rad want-2.rad
    run -0 sigchain-check got-1.rad
    # The temporary work folder is gone.
    [ -z "$(ls -A tmp)" ] || fail "left behind: $(ls tmp)"
}

@test "sigchain-atmosphere: the deck on stdin or as an argument, the TAPE7 on stdout or in a folder, -j 2" {
    expected
    run -0 sigchain-atmosphere --program "$FAKE --stdin --stdout" --deck-as stdin --tape7 - \
        -j 2 -q "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'a-%d.rad'
    cmp a-1.rad want-1.rad && cmp a-2.rad want-2.rad
    run -0 sigchain-atmosphere --program "$FAKE --tape7 out/T7" --deck-as argument \
        --tape7 out/T7 --work=runs --jobs=2 -q "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'b-%d.rad'
    cmp b-1.rad want-1.rad && cmp b-2.rad want-2.rad
    # --work keeps the decks, the list and the TAPE7s (12 runs), and no run folder.
    [ "$(ls runs/*.tp5 | wc -l)" -eq 12 ] && [ "$(ls runs/*.tp7 | wc -l)" -eq 12 ]
    cmp runs/view-002.tp7 want/view-002.tp7
    run -0 sigchain-check runs/runs.t7m
    [ -z "$(ls -d runs/*.run 2> /dev/null)" ] || fail "run folders left: $(ls -d runs/*.run)"
    # A program given by a relative path runs in its own folder all the same.
    cp "$FAKE" "$FAKE.awk" .
    run -0 sigchain-atmosphere --program ./fake_lowtran7 -q "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'c-%d.rad'
    cmp c-1.rad want-1.rad
}

@test "sigchain-atmosphere: a run that fails or leaves no TAPE7 exits 1 naming its deck" {
    # The deck on stdin while the program reads TAPE5: it fails, and says so.
    run -1 --separate-stderr sigchain-atmosphere --program "$FAKE" --deck-as stdin \
        "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'x-%d.rad'
    assert_output ''
    [[ "${stderr_lines[0]}" =~ ^sigchain-atmosphere:\ $TMPDIR/sigchain-atmosphere\.[A-Za-z0-9]+/sun\.tp5:\ fake_lowtran7\ exited\ with\ status\ 1:\ fake_lowtran7:\ TAPE5:\ cannot\ read\ the\ deck$ ]] ||
        fail "stderr: $stderr"
    assert_equal "${stderr_lines[1]}" "sigchain-atmosphere: the decks were in a temporary folder, now removed: --work DIR keeps them"
    [ ! -e x-1.rad ] && [ -z "$(ls -A tmp)" ]
    # A deck that is not one (the program gets an empty file as its deck).
    printf '#!/bin/sh\n: > TAPE5\nexec %s\n' "$FAKE" > empty_deck
    chmod +x empty_deck
    run -1 --separate-stderr sigchain-atmosphere --program "$PWD/empty_deck" --work runs -q \
        "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'x-%d.rad'
    assert_equal "$stderr" "sigchain-atmosphere: runs/sun.tp5: empty_deck exited with status 1: fake_lowtran7: TAPE5: not a LOWTRAN 7 deck (CARD 1: MODEL, IEMSCT)"
    # The failed run's folder is kept with --work; no later run was started.
    [ -f runs/sun.run/log ] && [ ! -e runs/view-001.run ] && [ ! -e x-1.rad ]
    # A program that exits 0 but leaves no TAPE7, or prints none.
    run -1 --separate-stderr sigchain-atmosphere --program "$FAKE --no-tape7" --work runs -q \
        "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'x-%d.rad'
    assert_equal "$stderr" "sigchain-atmosphere: runs/sun.tp5: fake_lowtran7 left no TAPE7 (no TAPE7 in its directory)"
    run -1 --separate-stderr sigchain-atmosphere --program "$FAKE --no-tape7" --tape7 - \
        --work runs -q "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'x-%d.rad'
    assert_equal "$stderr" "sigchain-atmosphere: runs/sun.tp5: fake_lowtran7 wrote no TAPE7 on its standard output"
    [ ! -e x-1.rad ]
}

@test "sigchain-atmosphere: a bad TAPE7 exits 1 with build_radiance's FILE:LINE" {
    run -1 --separate-stderr sigchain-atmosphere --program "$FAKE --transmittance 1.8" \
        --work runs -q "${SKY[@]}" "$HAWKEYE" "$SMALL" -o 'x-%d.rad'
    assert_equal "$stderr" "build_radiance: runs/sun.tp7:12: expected a transmittance in [0, 1], found 1.8"
    [ ! -e x-1.rad ] && assert_no_temp_files .
    # A bad deck input is build_radiance's too, before any run.
    run -1 --separate-stderr sigchain-atmosphere --program "$FAKE" "$BAD/cdk/dv_zero.cdk" \
        "$SMALL" -o 'x-%d.rad'
    [[ "$stderr" == "build_radiance: $BAD/cdk/dv_zero.cdk:"* ]] || fail "stderr: $stderr"
}

@test "sigchain-atmosphere: bad usage exits 2" {
    local args=("$HAWKEYE" "$SMALL" -o 'x-%d.rad')
    run -2 --separate-stderr sigchain-atmosphere "${args[@]}"
    assert_equal "$stderr" "sigchain-atmosphere: --program CMD is required
Try 'sigchain-atmosphere --help'."
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" "$HAWKEYE" "$SMALL"
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: -o PATTERN is required"
    run -2 --separate-stderr sigchain-atmosphere --program no-such-lowtran "${args[@]}"
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: --program: no-such-lowtran: not found on PATH"
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" --deck-as pipe "${args[@]}"
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: --deck-as: pipe: must be file:NAME, stdin or argument"
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" -j 0 "${args[@]}"
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: --jobs: 0: must be an integer from 1 to 256"
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" "$HAWKEYE" - -o 'x-%d.rad'
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: '-': an input must be a file (build_radiance reads it twice)"
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" --from-tape7 runs "${args[@]}"
    assert_equal "${stderr_lines[0]}" "sigchain-atmosphere: --from-tape7: not an option here (sigchain-atmosphere writes the decks and reads the TAPE7s itself)"
    # An option neither knows: build_radiance's usage error.
    run -2 --separate-stderr sigchain-atmosphere --program "$FAKE" --bogus "${args[@]}"
    [[ "$stderr" == "build_radiance: "*"bogus"* ]] || fail "stderr: $stderr"
    [ ! -e x-1.rad ] && [ -z "$(ls -A tmp)" ]
}

@test "sigchain-atmosphere: SIGTERM ends the runs and removes the temporary folder" {
    # A slow program that waits for a child of its own, recording both process ids.
    printf '#!/bin/sh\nsleep 30 &\necho $! $$ >> %s/pids\nwait\n' "$BATS_TEST_TMPDIR" > slow
    chmod +x slow
    sigchain-atmosphere --program "$PWD/slow" -j 2 -q "${SKY[@]}" "$HAWKEYE" "$SMALL" \
        -o 'x-%d.rad' 3>&- &
    local pid=$! i
    for i in $(seq 100); do [ "$(wc -l < pids 2> /dev/null)" = 2 ] && break; sleep 0.1; done
    [ "$(wc -l < pids)" = 2 ] || fail "the runs did not start"
    kill -TERM "$pid"
    local rc=0
    wait "$pid" || rc=$?
    [ "$rc" -eq 143 ] || fail "exit status $rc"
    sleep 0.2
    # Gone, or a zombie waiting for init to reap it.
    for i in $(cat pids); do
        [[ "$(ps -o stat= -p "$i")" == @(|Z*) ]] || fail "process $i of a run is still going"
    done
    [ -z "$(ls -A tmp)" ] && [ ! -e x-1.rad ]
}

@test "sigchain-atmosphere as the BUILD_RADIANCE stage: the training scene renders" {
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" training
    rm -rf training/out
    run -0 make -s -C training cube WTH= SIGCHAIN_SOURCE_DIR="$SIGCHAIN_SOURCE_DIR" \
        SIGCHAIN_BIN="$SIGCHAIN_BIN" BUILD_RADIANCE_FLAGS="-q --sky-zenith-step 30 --sky-azimuth-step 90" \
        BUILD_RADIANCE="\$(SIGCHAIN_BIN)/sigchain-atmosphere --program '$FAKE' -j 2"
    run -0 sigchain-check training/out/training-1.rad training/out/training-3.rad
    [ -s training/out/training.img ]
    run -0 grep -c '^SIGCHAIN_RAD 1$' training/out/training-2.rad
    grep -q "sigchain-atmosphere --program '$FAKE' -j 2" training/out/build_radiance.cmd.stamp
}
