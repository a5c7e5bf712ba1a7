#!/usr/bin/env bats
# Tests: sensorize's MTF chain (--mtf-* options)
# Also requires: tests/data/cube/tiny.img, tiny.hdr, blue.sen, green1.sen, red1.sen
load test_helper

CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"
# tiny.img's 4 samples are taken by blue (2), green1 and red1 (see sensorize.bats);
# blue's counts are 30 55 80 / 105 130 155, mean 92.5.
SENS=("$CUBE/blue.sen" "$CUBE/green1.sen" "$CUBE/red1.sen")

@test "--help lists the MTF options" {
    run -0 --separate-stderr sensorize --help
    for o in --mtf-fnumber --mtf-pitch --mtf-fill --mtf-defocus --mtf-smear --mtf-electronics; do
        assert_output --partial -- "$o"
    done
}

@test "-v prints each term's MTF at Nyquist per band" {
    run -0 --separate-stderr sensorize -v --mtf-fnumber 4 --mtf-pitch 5 --mtf-fill 1 \
        --mtf-smear 1 --mtf-electronics 5000,1e-4 "$CUBE/tiny.img" "${SENS[@]}" -o out.ppm
    # Blue's centre 0.4875 um: cutoff 5 / (0.4875 · 4) = 2.564 c/px, x = 0.5 / 2.564 =
    # 0.195, (2/π)(acos x − x√(1−x²)) = 0.753; detector and motion sinc(0.5) = 2/π =
    # 0.637; electronics: Nyquist is 5000 Hz at 1e-4 s/pixel, the cutoff: 1/√2 = 0.707;
    # product 0.216.
    [[ "$stderr" == *"sensorize: band 1 (0.487 um): MTF at Nyquist: optics 0.753, detector 0.637, motion 0.637, electronics 0.707, system 0.216"* ]] ||
        fail "stderr: $stderr"
    [[ "$stderr" == *"sensorize: band 3 (0.6 um): MTF at Nyquist: optics 0.697, "* ]] ||
        fail "stderr: $stderr"
    [ -s out.ppm ]
}

@test "the MTF blurs, is deterministic, and without --mtf-* nothing changes" {
    run -0 sensorize -q "$CUBE/tiny.img" "${SENS[@]}" -o plain.ppm
    run -0 sensorize -q "$CUBE/tiny.img" "${SENS[@]}" -o plain2.ppm
    cmp plain.ppm plain2.ppm
    run -0 sensorize -q --mtf-defocus 1 "$CUBE/tiny.img" "${SENS[@]}" -o mtf1.ppm
    run -0 sensorize -q --mtf-defocus 1 "$CUBE/tiny.img" "${SENS[@]}" -o mtf2.ppm
    cmp mtf1.ppm mtf2.ppm
    ! cmp -s plain.ppm mtf1.ppm || fail "the MTF changed nothing"
    # Blue (the first of each pixel's 3 values after the 3 header lines): the extremes
    # move inward, and the mean (MTF(0) = 1) stays 92.5 within the rounding to counts.
    run -0 awk 'NR > 3 && (NR - 4) % 3 == 0 { v[n++] = $1; s += $1 }
                END { print v[0], v[5], s / n }' mtf1.ppm
    read -r first last mean <<<"$output"
    (( first > 30 && last < 155 )) || fail "not blurred: $output"
    awk -v m="$mean" 'BEGIN { exit !(m > 92 && m < 93) }' || fail "mean moved: $output"
}

@test "bad MTF values exit 2 naming the option" {
    run -2 --separate-stderr sensorize --mtf-fnumber -2 --mtf-pitch 5 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    assert_equal "${stderr%%$'\n'*}" "sensorize: --mtf-fnumber: -2: must be a number > 0 and <= 1000"
    run -2 --separate-stderr sensorize --mtf-fnumber nan --mtf-pitch 5 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    assert_equal "${stderr%%$'\n'*}" "sensorize: --mtf-fnumber: nan: must be a number > 0 and <= 1000"
    run -2 --separate-stderr sensorize --mtf-fnumber 4 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"give --mtf-fnumber and --mtf-pitch together"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --mtf-fill 0 "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.pgm
    [[ "$stderr" == *"--mtf-fill: 0: must be a number > 0 and <= 1"* ]] || fail "stderr: $stderr"
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
        nowave.img "${SENS[@]}" -o out.ppm
    [[ "$stderr" == *"nowave.img: no wavelength list: the diffraction MTF"* ]] || fail "stderr: $stderr"
    [ ! -e out.ppm ]
}
