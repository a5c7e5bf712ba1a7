#!/usr/bin/env bats
# Tests: build_radiance (--write-decks, --from-tape7: LOWTRAN 7 / MODTRAN as the solver)
# Also requires: sigchain-check trace, tests/data/tape7/fake_lowtran7.awk,
# tests/golden/control7/hawkeye.cdk, tests/data/build_radiance/small.snd,
# data/scenes/training (the stage swap)
#
# The TAPE7s are made by fake_lowtran7.awk in LOWTRAN 7's layout with constant values
# (transmittance 0.8, solar irradiance 5e-6 W cm-2 (cm-1)-1, path radiance 1e-7 and sky
# radiance 2e-7 W cm-2 sr-1 (cm-1)-1), so every number of the .rad is known.
bats_require_minimum_version 1.5.0
load test_helper

HAWKEYE="$GOLDEN/control7/hawkeye.cdk"
SMALL="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance/small.snd"
FAKE="$SIGCHAIN_SOURCE_DIR/tests/data/tape7/fake_lowtran7.awk"
SKY=(--sky-zenith-step 45 --sky-azimuth-step 90)

# fake_runs DIR: a TAPE7 beside every deck of DIR.
fake_runs() {
    local deck
    for deck in "$1"/*.tp5; do
        awk -v T=0.8 -v ES=5e-6 -v LP=1e-7 -v LS=2e-7 -f "$FAKE" "$deck" > "${deck%.tp5}.tp7"
    done
}

# near A B: |A - B| <= 1e-6 |B|. The .rad's values are the mean over each sample's
# interval of a piecewise linear interpolation (20 cm-1 rows) of c nu^2 / 1e4; the
# interpolation adds h^2/6 = 67 cm-2 to nu^2 ~ 5e8: 1.4e-7 relative.
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * (b < 0 ? -b : b)) }' || fail "$1 is not $2 within 1e-6"; }

@test "--help lists --write-decks and --from-tape7" {
    run -0 --separate-stderr build_radiance --help
    assert_output --partial "--write-decks DIR"
    assert_output --partial "--from-tape7 LIST"
}

@test "--write-decks writes one LOWTRAN 7 deck per path and the run list" {
    run -0 --separate-stderr build_radiance -q --write-decks runs "${SKY[@]}" "$HAWKEYE" "$SMALL"
    assert_output ''
    # The sun, 3 view angles, 2 x 4 sky cells.
    [ "$(ls runs/*.tp5 | wc -l)" -eq 12 ]
    run -0 sigchain-check runs/runs.t7m
    assert_output "runs/runs.t7m: ok: 3 view runs, 8 sky runs, a sun run"
    run -0 sigchain-check -f cdk runs/view-001.tp5
    assert_output --partial "IEMSCT 2, 17920-22320 cm-1 step 20"
    # View -10 deg: from the sensor (1 km) down to the ground (0.218 km) at zenith 170.
    [ "$(sed -n 23p runs/view-001.tp5)" = "     1.000     0.218   170.000     0.000     0.000     0.000    0" ]
    run -0 sigchain-check -f cdk runs/sun.tp5
    assert_output --partial "IEMSCT 3"
    assert_no_temp_files runs
}

@test "--from-tape7 assembles the .rad from the TAPE7s: the analytic values" {
    build_radiance -q --write-decks runs "${SKY[@]}" "$HAWKEYE" "$SMALL"
    fake_runs runs
    run -0 --separate-stderr build_radiance -q --from-tape7 runs "$HAWKEYE" "$SMALL" -o 'b-%d.rad'
    assert_output ''
    run -0 sigchain-check b-1.rad b-2.rad
    # Band 1, sample 1: 22250 cm-1, interval 125 cm-1; <nu^2> = nu^2 + 125^2/12.
    local nu2=$(awk 'BEGIN { printf "%.10g", 22250^2 + 125^2/12 }')
    read -r wl nu es tau1 <<< "$(sed -n 13p b-1.rad)"
    [ "$nu" = 22250 ] && near "$wl" 0.449438202247191
    near "$es" "$(awk -v n="$nu2" 'BEGIN { printf "%.10g", 5e-6 * n / 1e4 }')"
    [ "$tau1" = 0.8 ]
    # View -10 deg: range 0.782 / cos 10 deg; tau2 0.8, no emission, L_us = 1e-7 <nu^2>/1e4.
    read -r angle range <<< "$(sed -n 16p b-1.rad)"
    [ "$angle" = -10 ] && near "$range" "$(awk 'BEGIN { printf "%.10g", 0.782 / cos(10 * atan2(0, -1) / 180) }')"
    read -r tau2 lue lus <<< "$(sed -n 17p b-1.rad)"
    [ "$tau2" = 0.8 ] && [ "$lue" = 0 ]
    near "$lus" "$(awk -v n="$nu2" 'BEGIN { printf "%.10g", 1e-7 * n / 1e4 }')"
    # The sky: version 1 block, 2 x 4 cells; the first at zenith 22.5, azimuth 45, solid
    # angle (1 - cos 45 deg) pi/2, its L_ds = 2e-7 <nu^2>/1e4.
    run -0 grep -n -A3 '^HEMISPHERE' b-1.rad
    assert_line --index 0 --partial "HEMISPHERE 2 4"
    read -r z a omega <<< "${lines[1]#*-}"
    [ "$z" = 22.5 ] && [ "$a" = 45 ]
    near "$omega" "$(awk 'BEGIN { pi = atan2(0, -1); printf "%.10g", (1 - cos(pi / 4)) * pi / 2 }')"
    read -r lds _ <<< "${lines[2]#*-}"
    near "$lds" "$(awk -v n="$nu2" 'BEGIN { printf "%.10g", 2e-7 * n / 1e4 }')"
    grep -q '^SIGCHAIN_RAD 1$' b-1.rad
    ! grep -q '^COUPLING' b-1.rad
}

@test "--from-tape7: a bad row, a run of another path or a missing TAPE7 exit 1 naming FILE:LINE" {
    build_radiance -q --write-decks runs "${SKY[@]}" "$HAWKEYE" "$SMALL"
    fake_runs runs
    cp -a runs bad
    sed -i '14s/0.8000/1.8000/' bad/view-002.tp7
    run -1 --separate-stderr build_radiance -q --from-tape7 bad "$HAWKEYE" "$SMALL" -o 'b-%d.rad'
    assert_equal "$stderr" "build_radiance: bad/view-002.tp7:14: expected a transmittance in [0, 1], found 1.8"
    [ ! -e b-1.rad ] && assert_no_temp_files .
    cp runs/view-002.tp7 bad/view-002.tp7
    cp runs/view-002.tp7 bad/view-001.tp7   # nadir's TAPE7 given for -10 deg
    run -1 --separate-stderr build_radiance -q --from-tape7 bad/runs.t7m "$HAWKEYE" "$SMALL" -o 'b-%d.rad'
    [[ "$stderr" == "build_radiance: bad/view-001.tp7:6: expected the path of VIEW -10 (H1 1 km, H2 0.218 km, ANGLE 170 deg), found"* ]] || fail "$stderr"
    rm bad/sky-0003.tp7
    cp runs/view-001.tp7 bad/
    run -1 --separate-stderr build_radiance -q --from-tape7 bad "$HAWKEYE" "$SMALL" -o 'b-%d.rad'
    [[ "$stderr" == "build_radiance: "*"bad/sky-0003.tp7"* ]] || fail "$stderr"
    run -2 --separate-stderr build_radiance --from-tape7 runs --write-decks x "$HAWKEYE" "$SMALL"
    [[ "$stderr" == *"cannot be given together"* ]] || fail "$stderr"
}

@test "--from-tape7 swaps in for the BUILD_RADIANCE stage: the training scene renders" {
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" training
    rm -rf training/out
    make -s -C training view out/hawkeye.cdk
    build_radiance -q --write-decks runs --sky-zenith-step 30 --sky-azimuth-step 90 \
        --view-azimuth "$(cat training/out/training.azimuth)" training/out/hawkeye.cdk \
        training/out/training.snd
    fake_runs runs
    run -0 make -s -C training cube WTH= BUILD_RADIANCE_FLAGS="-q --from-tape7 $PWD/runs"
    run -0 sigchain-check training/out/training-1.rad training/out/training-3.rad
    [ -s training/out/training.img ]
    run -0 grep -c '^SIGCHAIN_RAD 1$' training/out/training-2.rad
}
