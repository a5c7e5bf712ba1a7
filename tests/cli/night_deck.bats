#!/usr/bin/env bats
# Tests: build_radiance with a deck's execution mode IEMSCT (man build_radiance(1), The
# deck's mode): a night LWIR deck of IEMSCT 1 (thermal radiance only, no CARD 3A1 or
# 3A2) gives the thermal tables of the same deck with IEMSCT 2 and the sun below the
# horizon, and no sun; IEMSCT 0 and 3 are refused naming the card.
# Also requires: sigchain-check, data/atmosphere/ (reference data)
bats_require_minimum_version 1.5.0
load test_helper

# A coarse sky and 8 streams keep each run within seconds.
QUICK=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)

# deck IEMSCT FILE: the tropical model (MODEL 1), rural aerosols at 23 km (IHAZE 1),
# multiple scattering, 800-1250 cm-1; with IEMSCT 2 the sun of the night scene node
# (IPARM 1: 8 S 34.85 W, day 75, 3 h GMT) and IPH 2, LOWTRAN 7's Mie functions.
deck() {
    {
        printf '%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%8.3f%7.2f\n' \
            1 2 "$1" 1 0 0 0 0 0 0 0 0 1 0 0
        printf '%5d%5d%5d%5d%5d%5d%10.3f%10.3f%10.3f%10.3f%10.3f\n' 1 0 0 0 0 0 23 0 0 0 0
        printf '%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%5d\n' 3 0 180 0 0 0 0
        if [ "$1" = 2 ]; then
            printf '%5d%5d%5d%5d\n' 1 2 75 0
            printf '%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f\n' -8 34.85 0 0 3 0 0 0
        fi
        printf '%10.3f%10.3f%10.3f\n' 800 1250 50
        printf '%5d\n' 0
    } > "$2"
}

# night.snd: 3 km over Olinda (8 S 34.85 W) at local midnight of 15 March 2020 (the
# sun 77 deg below the horizon), one band of 800-1250 cm-1 (8-12.5 um), three views.
night_snd() {
    printf '%s\n' 3.0 1 '800 1250 50' '-30 30 30' '3 15 2020' 3.0 3 '8.0S 34.85W' > night.snd
}

# The .rad without Es (the third field of its sample lines, lines 13 to 12 + N).
without_es() {
    awk 'NR == 7 { n = $1 } NR > 12 && NR <= 12 + n { $3 = "-" } { print }' "$1"
}

@test "a night IEMSCT 1 deck gives the thermal tables of IEMSCT 2 with the sun down, and no sun" {
    night_snd
    deck 1 thermal.cdk
    deck 2 solar.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" thermal.cdk night.snd -o t.rad
    [[ "$stderr" == *"IEMSCT 1: thermal radiance only: no sun"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"IEMSCT 1: aerosol scattering by LOWTRAN 7's Mie phase functions"* ]] ||
        fail "stderr: $stderr"
    [[ "$stderr" != *warning* ]] || fail "stderr: $stderr"
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" solar.cdk night.snd -o s.rad
    [[ "$stderr" == *"the sun is below the horizon"* ]] || fail "stderr: $stderr"
    sigchain-check t.rad s.rad
    # Every table but Es byte for byte: tau2, L_ue, L_de, the upwelled grid, the
    # COUPLING terms, tau1 and the solar terms (0 with the sun down) and the SUN line.
    diff <(without_es t.rad) <(without_es s.rad)
    # IEMSCT 1 records the sun's absence: Es 0 (IEMSCT 2 keeps the exoatmospheric
    # irradiance of a sun below the horizon); tau1 0 in both.
    awk 'NR > 12 && NR <= 22 { if ($3 != 0 || $4 != 0) exit 1 }' t.rad ||
        fail "Es or tau1 not 0: $(sed -n 13,22p t.rad)"
    awk 'NR > 12 && NR <= 22 { if (!($3 > 0) || $4 != 0) exit 1 }' s.rad ||
        fail "IEMSCT 2: $(sed -n 13,22p s.rad)"
    # The thermal terms are there: the nadir view's L_ue > 0 and L_us 0 in every sample.
    awk '$1 == 0 && NF == 2 { v = 1; next } v && NF == 3 { n++; if (!($2 > 0) || $3 != 0) exit 1 }
         NF != 3 { v = 0 } END { exit n != 10 }' t.rad || fail "nadir view: $(cat t.rad)"
}

@test "IEMSCT 1 under a sun above the horizon warns that the tables hold no sunlight" {
    night_snd
    sed -i 's/^3.0$/15.0/' night.snd  # 15 h GMT: noon at Olinda
    deck 1 thermal.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" thermal.cdk night.snd -o t.rad
    [[ "$stderr" == "build_radiance: warning: thermal.cdk: CARD 1 IEMSCT (columns 11-15) is 1 (thermal radiance only) but the scene node's sun is up (zenith "*" deg): the tables hold no sunlight" ]] ||
        fail "stderr: $stderr"
    awk 'NR > 12 && NR <= 22 { if ($3 != 0 || $4 != 0) exit 1 }' t.rad
}

@test "IEMSCT 0 and 3 are refused naming CARD 1 IEMSCT, for the solver and --write-decks" {
    night_snd
    deck 1 thermal.cdk
    sed '1s/^\(.\{10\}\)    1/\1    0/' thermal.cdk > transmittance.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" transmittance.cdk night.snd -o o.rad
    assert_equal "$stderr" "build_radiance: transmittance.cdk: CARD 1 IEMSCT (columns 11-15) is 0: a transmittance run computes no radiance, and rad(5) tables hold path and sky radiances (use 1 for thermal radiance only, 2 with the sun)"
    # IEMSCT 3: the alternate CARD 3 (H1, H2, ANGLE, IDAY, RO, ISOURC, ANGLEM).
    card3=$(printf '%10.3f%10.3f%10.3f%5d%5s%10.3f%5d%10.3f' 0 0 0 75 '' 0 0 0)
    sed -e '1s/^\(.\{10\}\)    1/\1    3/' -e "3s/.*/$card3/" thermal.cdk > irradiance.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" irradiance.cdk night.snd -o o.rad
    [[ "$stderr" == "build_radiance: irradiance.cdk: CARD 1 IEMSCT (columns 11-15) is 3: a solar irradiance run computes only the sun's transmitted irradiance"* ]] ||
        fail "stderr: $stderr"
    run -1 --separate-stderr build_radiance --write-decks runs transmittance.cdk night.snd
    [[ "$stderr" == *"CARD 1 IEMSCT (columns 11-15) is 0"* ]] || fail "stderr: $stderr"
    [ ! -e o.rad ]
    [ ! -e runs/runs.t7m ]
}

@test "--write-decks writes IEMSCT 1 runs for an IEMSCT 1 deck, without CARD 3A1" {
    night_snd
    deck 1 thermal.cdk
    run -0 build_radiance --write-decks runs --sky-zenith-step 45 --sky-azimuth-step 90 \
        thermal.cdk night.snd
    [ ! -e runs/sun.tp5 ]  # the sun is below the horizon
    for d in runs/view-001.tp5 runs/sky-0001.tp5; do
        [ "$(cut -c11-15 "$d" | head -n 1)" = "    1" ] || fail "$d: $(head -n 1 "$d")"
        [ "$(wc -l < "$d")" -eq 5 ] || fail "$d: $(cat "$d")"  # CARD 1, 2, 3, 4, 5
    done
}
