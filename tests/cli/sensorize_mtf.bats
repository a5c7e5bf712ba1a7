#!/usr/bin/env bats
# Tests: sensorize's MTF chain (--mtf-* options)
# Also requires: tests/data/cube/tiny.img, tiny.hdr, blue.sen, red.sen
load test_helper

CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"

@test "--help lists the MTF options" {
    run -0 --separate-stderr sensorize --help
    for o in --mtf-fnumber --mtf-pitch --mtf-fill --mtf-defocus --mtf-smear --mtf-electronics; do
        assert_output --partial -- "$o"
    done
}

@test "-v prints each term's MTF at Nyquist per band" {
    run -0 --separate-stderr sensorize -v --mtf-fnumber 4 --mtf-pitch 5 --mtf-fill 1 \
        --mtf-smear 1 --mtf-electronics 5000,1e-4 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    # cutoff 5 / (λ · 4) c/px; detector sinc(0.5) = 0.637; motion sinc(0.5) = 0.637;
    # electronics: Nyquist is 5000 Hz at 1e-4 s/pixel, the cutoff: 1/√2 = 0.707.
    [[ "$stderr" =~ "band 1 ("[0-9.]+" um): MTF at Nyquist: optics "[0-9.]+", detector 0.637, motion 0.637, electronics 0.707, system "[0-9.]+ ]] ||
        fail "stderr: $stderr"
    [ -s out.pgm ]
}

@test "the MTF blurs, is deterministic, and without --mtf-* nothing changes" {
    run -0 sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" -o plain.pgm
    run -0 sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" -o plain2.pgm
    cmp plain.pgm plain2.pgm
    run -0 sensorize --mtf-defocus 1 "$CUBE/tiny.img" "$CUBE/blue.sen" -o mtf1.pgm
    run -0 sensorize --mtf-defocus 1 "$CUBE/tiny.img" "$CUBE/blue.sen" -o mtf2.pgm
    cmp mtf1.pgm mtf2.pgm
    ! cmp -s plain.pgm mtf1.pgm || fail "the MTF changed nothing"
    # 30 55 80 / 105 130 155 blurred: the range shrinks, the extremes move inward.
    run -0 tail -n 2 mtf1.pgm
    read -r a _ _ <<<"${lines[0]}"
    read -r _ _ f <<<"${lines[1]}"
    (( a > 30 && f < 155 )) || fail "not blurred: $output"
}

@test "bad MTF values exit 2 naming the option" {
    run -2 --separate-stderr sensorize --mtf-fnumber -2 --mtf-pitch 5 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    assert_equal "${stderr%%$'\n'*}" "sensorize: --mtf-fnumber must be a positive number"
    run -2 --separate-stderr sensorize --mtf-fnumber nan --mtf-pitch 5 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    assert_equal "${stderr%%$'\n'*}" "sensorize: --mtf-fnumber must be a positive number"
    run -2 --separate-stderr sensorize --mtf-fnumber 4 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"give --mtf-fnumber and --mtf-pitch together"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --mtf-fill 0 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"--mtf-fill must be greater than 0 and at most 1"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --mtf-smear 1,2,3 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"--mtf-smear: expected PX or PX,DEGREES, found '1,2,3'"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --mtf-electronics 100 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"--mtf-electronics: expected HZ,SECONDS"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --mtf-electronics 100,-1 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"the dwell time must be positive"* ]] || fail "stderr: $stderr"
    assert_equal "${stderr##*$'\n'}" "Try 'sensorize --help'."
    [ ! -e out.pgm ]
}

@test "the optics term on a cube without wavelengths exits 1 and writes nothing" {
    cp "$CUBE/tiny.img" nowave.img
    grep -v -i '^wavelength' "$CUBE/tiny.hdr" > nowave.hdr
    run -1 --separate-stderr sensorize -q --mtf-fnumber 4 --mtf-pitch 5 \
        nowave.img "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"nowave.img: no wavelength list: the diffraction MTF"* ]] || fail "stderr: $stderr"
    [ ! -e out.pgm ]
}
