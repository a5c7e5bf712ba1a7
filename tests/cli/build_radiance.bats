#!/usr/bin/env bats
# Tests: build_radiance
# Also requires: tests/data/build_radiance/{small.snd,rural23.cdk},
# tests/golden/control7/hawkeye.cdk (the Hawkeye deck of White (1996)), tests/data/white1996/hawkeye.snd,
# data/atmosphere/ (reference data)
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance"
HAWKEYE="$GOLDEN/control7/hawkeye.cdk"
# A coarse sky and 8 streams keep each run well under a second; the physics is
# checked by the unit tests (tests/unit/atmos, tests/unit/atmos_table, tests/unit/rt).
QUICK=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)

# The value of line N of a file.
line_of() { sed -n "${2}p" "$1"; }

@test "--help prints usage and points to build_radiance(1)" {
    run -0 --separate-stderr build_radiance --help
    assert_line --index 0 --partial "Usage: build_radiance "
    assert_output --partial "--sky-zenith-step"
    assert_equal "${lines[-1]}" "See build_radiance(1)."
    assert_equal "$stderr" ""
}

@test "--version prints the project version" {
    run -0 --separate-stderr build_radiance --version
    assert_output --regexp '^build_radiance \(sigchain\) [0-9]+\.[0-9]+\.[0-9]+$'
}

@test "an unknown option exits 2" {
    run -2 --separate-stderr build_radiance --no-such-option
    assert_equal "${stderr##*$'\n'}" "Try 'build_radiance --help'."
}

@test "missing -o, a missing input and two standard inputs are usage errors" {
    run -2 --separate-stderr build_radiance "$HAWKEYE" "$DATA/small.snd"
    [[ "$stderr" == *"-o FILE is required"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance "$HAWKEYE" -o 'x-%d.rad'
    [[ "$stderr" == *"expected two inputs"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance - - -o 'x-%d.rad'
    [[ "$stderr" == *"only one input"* ]] || fail "stderr: $stderr"
}

@test "a pattern without %d for two bands, or with another %, is a usage error" {
    run -2 --separate-stderr build_radiance "$HAWKEYE" "$DATA/small.snd" -o out.rad
    [[ "$stderr" == *"has no %d, but the scene node has 2 bands"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance "$HAWKEYE" "$DATA/small.snd" -o 'out-%s.rad'
    [[ "$stderr" == *"'%' must be followed by 'd'"* ]] || fail "stderr: $stderr"
    [ ! -e out.rad ] && [ ! -e out-1.rad ]
}

@test "option values out of range are usage errors" {
    run -2 --separate-stderr build_radiance --streams 5 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"streams must be even, 4 to 64; found 5"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --sky-zenith-step 7 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"sky zenith step must divide 90"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --sky-azimuth-step 7 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"sky azimuth step must divide 360"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --sky-azimuth-step 0 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: --sky-azimuth-step: 0: must be a number > 0 and <= 360"* ]] ||
        fail "stderr: $stderr"
}

@test "the Hawkeye deck gives one valid .rad per band with the scene node's grids" {
    run -0 --separate-stderr build_radiance "${QUICK[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'hawk-%d.rad'
    assert_output ''
    run -0 sigchain-check hawk-1.rad hawk-2.rad
    # Header: sensor altitude, wavenumber range and count, view-angle range and count.
    assert_equal "$(line_of hawk-1.rad 1)" 1
    assert_equal "$(line_of hawk-1.rad 4)" 22000
    assert_equal "$(line_of hawk-1.rad 5)" 22250
    assert_equal "$(line_of hawk-1.rad 7)" 3
    assert_equal "$(line_of hawk-2.rad 7)" 2
    assert_equal "$(line_of hawk-1.rad 8)" -10
    assert_equal "$(line_of hawk-1.rad 12)" 3
    # The sigchain block: units, the sun of 30 Sep 1995 19:00 GMT at Rochester (NREL SPA:
    # zenith 53.18 deg, azimuth 218.35 deg), a 6 x 12 sky.
    run grep -E '^SUN 53\.1[78][0-9]* 218\.3[45][0-9]*$' hawk-1.rad
    assert_success
    run grep -c '^HEMISPHERE 6 12$' hawk-2.rad
    assert_output 1
    assert_no_temp_files .
}

@test "the tables are physical: tau1 and tau2 in (0, 1), Es near 0.2 W cm-2 um-1, L_us > 0" {
    build_radiance "${QUICK[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'h-%d.rad'
    # Sample lines (13..15 of band 1): wavelength wavenumber Es tau1.
    awk 'NR >= 13 && NR <= 15 {
            if (!($3 > 0.15 && $3 < 0.25)) { print "Es " $3; bad = 1 }
            if (!($4 > 0.2 && $4 < 1)) { print "tau1 " $4; bad = 1 } }
         NR >= 17 && NR <= 19 {
            if (!($1 > 0.5 && $1 < 1)) { print "tau2 " $1; bad = 1 }
            if (!($3 > 0)) { print "L_us " $3; bad = 1 } }
         END { exit bad }' h-1.rad
}

@test "reruns and thread counts give identical files" {
    build_radiance "${QUICK[@]}" --threads 1 "$DATA/rural23.cdk" "$DATA/small.snd" -o 'a-%d.rad'
    build_radiance "${QUICK[@]}" --threads 2 "$DATA/rural23.cdk" "$DATA/small.snd" -o 'b-%d.rad'
    cmp a-1.rad b-1.rad
    cmp a-2.rad b-2.rad
}

@test "the deck can come from standard input, and one band can go to standard output" {
    printf '1.0\n1\n18000 18100 100\n0 0 1\n9 30 95\n19\n5\n43.08333 77.66667\n' > one_band.snd
    sigchain-check one_band.snd
    run -0 --separate-stderr build_radiance "${QUICK[@]}" - one_band.snd -o - < "$DATA/rural23.cdk"
    assert_line --index 0 1
    [[ "$output" == *"SIGCHAIN_RAD 1"* ]] || fail "no sigchain block on stdout"
}

@test "--verbose reports the sun, the column and what was skipped" {
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'v-%d.rad'
    [[ "$stderr" == *"build_radiance: sun zenith 53.1"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"ground 0.218 km, sensor 1 km"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"layer emission not solved"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"wrote v-2.rad"* ]] || fail "stderr: $stderr"
}

@test "a deck with bad columns is rejected with the card and columns named" {
    sed '1s/^    6/    x/' "$DATA/rural23.cdk" > bad.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" bad.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: bad.cdk:1: "*"MODEL"* ]] || fail "stderr: $stderr"
    [ ! -e o-1.rad ]
    assert_no_temp_files .
}

@test "an unknown model number and an impossible visibility are rejected" {
    sed '1s/^    6/    9/' "$DATA/rural23.cdk" > model9.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" model9.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: model9.cdk:1: "*"MODEL"* ]] || fail "stderr: $stderr"
    sed '2s/^\(.\{30\}\)    23.000/\1   -23.000/' "$DATA/rural23.cdk" > vis.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" vis.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: vis.cdk:2: "*"VIS"* ]] || fail "stderr: $stderr"
    [ ! -e o-1.rad ]
}

@test "the NOAA cirrus and a horizontal-path model are refused with the card named" {
    sed '2s/^\(.\{20\}\)    0/\1   20/' "$DATA/rural23.cdk" | sed '2a\     0.000     0.000     0.000         0' > noaa.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" noaa.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"CARD 2 ICLD (columns 21-25) is 20: the NOAA cirrus"* ]] ||
        fail "stderr: $stderr"
    sed '1s/^    6/    0/' "$DATA/rural23.cdk" > model0.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" model0.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: model0.cdk:1: CARD 1 ITYPE"*"MODEL 0"* ]] || fail "stderr: $stderr"
    [ ! -e o-1.rad ]
    assert_no_temp_files .
}

@test "a sensor below the ground is bad data naming the scene node" {
    sed 's/^1\.0\t# sensor altitude (km)/0.1/' "$DATA/small.snd" > low.snd
    run -1 --separate-stderr build_radiance "${QUICK[@]}" "$HAWKEYE" low.snd -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: low.snd: the sensor altitude (0.1 km) must lie above the ground"* ]] ||
        fail "stderr: $stderr"
    assert_no_temp_files .
}

@test "a missing data directory is an error naming it" {
    run -1 --separate-stderr build_radiance --data-dir /nonexistent "${QUICK[@]}" "$HAWKEYE" \
        "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"/nonexistent: data directory (--data-dir) does not exist"* ]] ||
        fail "stderr: $stderr"
    SIGCHAIN_DATA=/nowhere run -1 --separate-stderr build_radiance "${QUICK[@]}" "$HAWKEYE" \
        "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"/nowhere: data directory (SIGCHAIN_DATA) does not exist"* ]] ||
        fail "stderr: $stderr"
}

@test "the scene node of White (1996) runs: three bands, 156 view angles, sky of 648 cells" {
    run -0 --separate-stderr build_radiance "$HAWKEYE" "$SEED/hawkeye.snd" -o 'seed-%d.rad'
    run -0 sigchain-check seed-1.rad seed-2.rad seed-3.rad
    assert_equal "$(line_of seed-1.rad 7)" 41
    assert_equal "$(line_of seed-1.rad 12)" 156
    run grep -c '^HEMISPHERE 18 36$' seed-3.rad
    assert_output 1
}

@test "the grid, solver and emission options have their documented effect" {
    # --upwelled-azimuth-step 90: rings at |view angle| 0 and 10, four azimuths.
    run -0 build_radiance "${QUICK[@]}" --upwelled-azimuth-step 90 "$HAWKEYE" "$DATA/small.snd" -o 'u-%d.rad'
    run -0 grep -c '^UPWELLED 2 4$' u-1.rad
    # --sky-subsamples 2 averages directions inside a cell: a different sky, same grid.
    build_radiance --streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 2 \
        "$HAWKEYE" "$DATA/small.snd" -o 's-%d.rad'
    build_radiance "${QUICK[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'q-%d.rad'
    run -0 grep -c '^HEMISPHERE 6 12$' s-1.rad
    ! cmp -s s-1.rad q-1.rad
    # --merge-tau 0 keeps every level: tau1 and L_us within 1e-3 of the merged solver.
    build_radiance "${QUICK[@]}" --merge-tau 0 "$HAWKEYE" "$DATA/small.snd" -o 'm-%d.rad'
    paste -d ' ' <(sed -n '13,27p' m-1.rad) <(sed -n '13,27p' q-1.rad) | awk '
        NF == 8 { if (($4 / $8 - 1)^2 > 1e-6) bad = 1 }
        NF == 6 { if ($3 > 0 && ($3 / $6 - 1)^2 > 1e-6) bad = 1 }
        END { exit bad }'
    # --thermal-from 0.4: layer emission is solved in the visible too (tiny, not zero).
    build_radiance "${QUICK[@]}" --thermal-from 0.4 "$HAWKEYE" "$DATA/small.snd" -o 't-%d.rad'
    awk 'NR == 17 { exit !($2 > 0) }' t-1.rad
    awk 'NR == 17 { exit !($2 == 0) }' q-1.rad
    # --top 50: a lower top of the atmosphere changes the sun's path, not the format.
    build_radiance "${QUICK[@]}" --top 50 "$HAWKEYE" "$DATA/small.snd" -o 'p-%d.rad'
    run -0 sigchain-check p-1.rad
}

@test "out-of-range grid and solver options are usage errors" {
    run -2 --separate-stderr build_radiance --upwelled-azimuth-step 7 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"upwelled azimuth step must divide 360"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --merge-tau 2 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--merge-tau: 2: must be a number from 0 to 1"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --top 0 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--top: 0: must be a number > 0 and <= 1000"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --sky-subsamples 9 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--sky-subsamples: 9: must be an integer from 1 to 8"* ]] || fail "stderr: $stderr"
}

@test "the tables carry the coupling terms (SIGCHAIN_RAD 1.2), physically bounded" {
    run -0 build_radiance "${QUICK[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'k-%d.rad'
    run -0 grep -c '^SIGCHAIN_RAD 1.2$' k-1.rad
    run -0 grep -c '^COUPLING$' k-1.rad
    # One DIFFUSE_UP line per view angle (line 12 of the header).
    assert_equal "$(grep -c '^DIFFUSE_UP ' k-1.rad)" "$(line_of k-1.rad 12)"
    # S and t_d in (0, 1): the atmosphere scatters and does not reflect everything.
    awk '/^(SPHERICAL_ALBEDO|DIFFUSE_DOWN)/ { for (i = 2; i <= NF; ++i) if (!($i > 0 && $i < 1)) exit 1 }
         /^DIFFUSE_UP/ { for (i = 3; i <= NF; ++i) if (!($i > 0 && $i < 1)) exit 1 }' k-1.rad
}

@test "--streams auto chooses per band, -v says which and the estimated error" {
    local one=(--sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 --upwelled-azimuth-step 360)
    run -0 --separate-stderr build_radiance -v --streams auto "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'a-%d.rad'
    [[ "$stderr" =~ "band 1: "[0-9]+" streams (auto: estimated error "[0-9.e-]+" % against "[0-9]+" streams at "[12]" samples)" ]] ||
        fail "stderr: $stderr"
    [[ "$stderr" == *"band 2: "* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"thin layers merged up to optical depth 0.01 (--streams auto at 1 %: 0.01 x sqrt(REL / 1 %))"* ]] ||
        fail "stderr: $stderr"
    sigchain-check a-1.rad a-2.rad
    # A looser tolerance merges thicker layers (their error grows as the depth squared).
    run -0 --separate-stderr build_radiance -v --streams auto --stream-tolerance 0.05 "${one[@]}" \
        "$HAWKEYE" "$DATA/small.snd" -o 'd-%d.rad'
    [[ "$stderr" == *"thin layers merged up to optical depth 0.0224 (--streams auto at 5 %"* ]] ||
        fail "stderr: $stderr"
    run -0 --separate-stderr build_radiance -v --streams auto --stream-tolerance 0.05 --merge-tau 0.01 \
        "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'e-%d.rad'
    [[ "$stderr" == *"thin layers merged up to optical depth 0.01 (--merge-tau)"* ]] || fail "stderr: $stderr"
    # Without auto, -v names the fixed streams.
    run -0 --separate-stderr build_radiance -v --streams 8 "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'b-%d.rad'
    [[ "$stderr" == *"band 1: 8 streams"$'\n'* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"thin layers merged up to optical depth 0.01"$'\n'* ]] || fail "stderr: $stderr"
    # Threads do not change the choice or the tables.
    build_radiance --streams auto --threads 2 "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'c-%d.rad'
    cmp a-1.rad c-1.rad
    cmp a-2.rad c-2.rad
}

@test "-v names the gas tables the .snd's wavenumbers do not need, which are not read" {
    local one=(--sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 --upwelled-azimuth-step 360)
    run -0 --separate-stderr build_radiance -v --streams 4 "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'g-%d.rad'
    [[ "$stderr" == *"gas tables not read (no sample within 100 cm-1 of them): "*"band_model_CO2.txt, "*"o3_hartley_huggins.txt"* ]] ||
        fail "stderr: $stderr"
    [[ "$stderr" != *"h2o_continuum.txt"* ]] || fail "stderr: $stderr"  # it reaches 20000 cm-1
    sigchain-check g-1.rad g-2.rad
}

@test "--streams takes auto or an even count, --stream-tolerance (0, 1]" {
    run -2 --separate-stderr build_radiance --streams automatic "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--streams: automatic: must be auto or an integer from 4 to 64"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --streams 7 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"streams must be even"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --streams auto --stream-tolerance 0 "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--stream-tolerance: 0: must be a number > 0 and <= 1"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr build_radiance --stream-tolerance nan "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"--stream-tolerance: nan: must be"* ]] || fail "stderr: $stderr"
    [ ! -e o-1.rad ]
}

@test "--streams auto warns when no streams up to 32 meet the tolerance" {
    printf '1.0\n1\n18000 18100 100\n0 0 1\n9 30 95\n19\n5\n43.08333 77.66667\n' > two_samples.snd
    run -0 --separate-stderr build_radiance --streams auto --stream-tolerance 1e-9 \
        --sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 --upwelled-azimuth-step 360 \
        "$HAWKEYE" two_samples.snd -o w.rad
    [[ "$stderr" == *"build_radiance: warning: band 1: no streams up to 32 meet --stream-tolerance (estimated error "*" %): 32 used"* ]] ||
        fail "stderr: $stderr"
    sigchain-check w.rad
}

@test "-v says when only azimuthal means are solved (nadir views, whole-ring sky cells)" {
    local one=(--sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 2 --upwelled-azimuth-step 360)
    printf '1.0\n1\n18000 18100 100\n0 0 1\n9 30 95\n19\n5\n43.08333 77.66667\n' > nadir.snd
    run -0 --separate-stderr build_radiance -v --streams 8 "${one[@]}" "$HAWKEYE" nadir.snd -o n.rad
    [[ "$stderr" == *"only means over azimuth tabulated (nadir views, whole-ring sky cells)"* ]] ||
        fail "stderr: $stderr"
    sigchain-check n.rad
    # A view off nadir needs every Fourier mode; so do sky cells narrower than a ring.
    run -0 --separate-stderr build_radiance -v --streams 8 "${one[@]}" "$HAWKEYE" "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" != *"only means over azimuth"* ]] || fail "stderr: $stderr"
    run -0 --separate-stderr build_radiance -v --streams 8 --sky-zenith-step 90 --sky-azimuth-step 180 \
        "$HAWKEYE" nadir.snd -o h.rad
    [[ "$stderr" != *"only means over azimuth"* ]] || fail "stderr: $stderr"
}
