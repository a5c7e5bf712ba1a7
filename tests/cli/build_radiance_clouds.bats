#!/usr/bin/env bats
# Tests: build_radiance (LOWTRAN 7 cloud, rain and cirrus models, CARD 2 ICLD and RAINRT, CARD 2A;
# user-defined aerosol and cloud coefficients, IHAZE 7 and ICLD 11 with CARD 2D)
# Also requires: tests/data/build_radiance/{small.snd,rural23.cdk},
# tests/data/control7/hawkeye.answers, tests/data/white1996/30Sep95800L.rsd,
# tests/data/white1996/flyover.cdk, man/cdk.5.scd (its second EXAMPLE),
# data/atmosphere/lowtran7/cloud_*.txt and aerosol_rural.txt (reference data)
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance"
QUICK=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)

# rural23.cdk with CARD 2 ICLD (columns 21-25) set to $1.
with_icld() { sed "2s/^\(.\{20\}\)    0/\1$(printf '%5d' "$1")/" "$DATA/rural23.cdk"; }

@test "a stratus deck (ICLD 3) darkens the sun's transmittance by exp(-tau_cloud m), m the refracted spherical air mass" {
    with_icld 3 > stratus.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" "$DATA/rural23.cdk" "$DATA/small.snd" -o 'clear-%d.rad'
    run -0 --separate-stderr build_radiance "${QUICK[@]}" stratus.cdk "$DATA/small.snd" -o 'cloud-%d.rad'
    run -0 sigchain-check cloud-1.rad cloud-2.rad
    # tau_cloud(0.55 um) of the stratus, from cloud_rain_profiles.txt by hand: LWC 0, .15,
    # .3, .15, 0 g m-3 at .16, .33, .66, 1, 1.5 km (linear to zero, exponential between
    # positive values), over 5.272e-3 g m-3 per km-1; times the normalised extinction of
    # cloud_models.txt, linear between 0.55 (1) and 0.6943 um (1.0089). Lines 13-14 of
    # band 2 (0.552-0.556 um) are its samples (wavelength, nu, Es, tau1).
    # The air mass m through the cloud, independently of build_radiance's ray tracing: the
    # apparent zenith from Saemundsson's refraction (Sky & Telescope 72, 70, 1986) at the
    # true altitude, carried up to the cloud's centre of extinction (0.68 km above the
    # ground) on a sphere of 6371.23 km (LOWTRAN 7's). Tolerance 1e-4 relative: the
    # formula's standard atmosphere against the deck's (a few % of its 1.35 arcmin: 2e-5
    # of m) and the cloud's vertical extent about its centre (0.16-1.5 km: 5e-5 of m).
    paste -d ' ' <(sed -n '13,14p' clear-2.rad) <(sed -n '13,14p' cloud-2.rad) |
        awk -v sun="$(awk '/^SUN / { print $2 }' cloud-2.rad)" '{
            deg = atan2(0, -1) / 180
            alt = 90 - sun; x = (alt + 10.3 / (alt + 5.11)) * deg
            z = (sun - 1.02 / (sin(x) / cos(x)) / 60) * deg
            ground = 0; earth = 6371.23  # GNDALT 0 (CARD 2)
            s = (earth + ground) * sin(z) / (earth + ground + 0.68); m = 1 / sqrt(1 - s * s)
            lwc = 0.5 * 0.15 * 0.17 + (0.33 + 0.34) * 0.15 / log(2) + 0.5 * 0.15 * 0.5
            tau = lwc / 5.272e-3 * (1 + ($1 - 0.55) / (0.6943 - 0.55) * 0.0089)
            got = log($8 / $4); want = -tau * m
            printf "%s um: ln(ratio) %.9g predicted %.9g (m %.7g, 1/mu0 %.7g)\n", $1, got, want, m, 1 / cos(sun * deg)
            if (!(got - want < 1e-4 * tau * m && want - got < 1e-4 * tau * m)) bad = 1
        } END { exit bad }'
}

@test "every water cloud model (ICLD 1-5) gives valid tables" {
    for m in 1 2 4 5; do
        with_icld "$m" > c$m.cdk
        run -0 --separate-stderr build_radiance "${QUICK[@]}" c$m.cdk "$DATA/small.snd" -o "c$m-%d.rad"
        run -0 sigchain-check "c$m-1.rad" "c$m-2.rad"
    done
}

# rural23.cdk with CARD 2 RAINRT (columns 61-70) set to $1 (F10.3).
with_rainrt() { sed "2s/^\(.\{60\}\)     0.000/\1$(printf '%10.3f' "$1")/" "$DATA/rural23.cdk"; }
# rural23.cdk with ICLD $1 and CARD 2A "CTHIK CALT CEXT ISEED" = $2 $3 $4 0 after CARD 2.
with_cirrus() {
    with_icld "$1" | sed "2a\\$(printf '%10.3f%10.3f%10.3f%10d' "$2" "$3" "$4" 0)"
}

@test "RAINRT 5 mm/h lowers tau1 and tau2 by the Marshall-Palmer extinction times the path" {
    with_rainrt 5 > rain.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" "$DATA/rural23.cdk" "$DATA/small.snd" -o 'clear-%d.rad'
    run -0 --separate-stderr build_radiance "${QUICK[@]}" rain.cdk "$DATA/small.snd" -o 'rain-%d.rad'
    run -0 sigchain-check rain-1.rad rain-2.rad
    # beta = pi N0 / Lambda^3 = 0.3647 R^0.63 km-1 (Marshall & Palmer 1948, Q_ext = 2), any
    # wavelength. tau1: the rain (0-6 km, tapering to 0 at 7 km: a column of 6.5 km) along
    # the sun's air mass m at the rain's centre of extinction (3.256 km), m as in the
    # stratus test above with the refraction left above that height (Saemundsson's at the
    # ground times the air density there over the ground's, 0.724 in the US standard
    # atmosphere). tau2: the sensor (1 km) looks down through constant rain, so its ratio
    # is exp(-beta x range), the range printed in each view-angle line. Tolerances: tau1
    # 1e-4 relative of beta H m (the deck's refraction and density against the standard
    # ones, a few % of 0.4 arcmin: 1e-5 of m; the air mass's spread over the 7 km of rain
    # about its centre, second order: 1e-5); tau2 1e-5 relative (the Earth's curvature
    # along the slanted kilometre, tan^2(10 deg) h / 2R = 2.4e-6; the gas path's
    # re-layering, 1e-8).
    for b in 1 2; do
        paste -d ' ' <(sed -n '13,14p' clear-$b.rad) <(sed -n '13,14p' rain-$b.rad) |
            awk -v sun="$(awk '/^SUN / { print $2 }' rain-$b.rad)" '{
                deg = atan2(0, -1) / 180
                beta = atan2(0, -1) * 8000 / (4.1 * 5 ^ -0.21) ^ 3 * 1e-3
                alt = 90 - sun; x = (alt + 10.3 / (alt + 5.11)) * deg
                z = (sun - 0.724 * 1.02 / (sin(x) / cos(x)) / 60) * deg
                earth = 6371.23; s = earth * sin(z) / (earth + 3.256); m = 1 / sqrt(1 - s * s)
                got = log($8 / $4); want = -beta * 6.5 * m
                printf "%s um: ln tau1 ratio %.9g predicted %.9g\n", $1, got, want
                if (!(got < 0 && got - want < 1e-4 * -want && want - got < 1e-4 * -want)) bad = 1
            } END { exit bad }'
    done
    # Band 2's view-angle blocks (lines 15-23: "angle range", then two "tau2 L_ue L_us").
    paste -d ' ' <(sed -n '15,23p' clear-2.rad) <(sed -n '15,23p' rain-2.rad) |
        awk 'NF == 4 { range = $2; next } {
                 beta = atan2(0, -1) * 8000 / (4.1 * 5 ^ -0.21) ^ 3 * 1e-3
                 got = log($4 / $1); want = -beta * range; n++
                 printf "range %s km: ln tau2 ratio %.9g predicted %.9g\n", range, got, want
                 if (!(got - want < 1e-5 * -want && want - got < 1e-5 * -want)) bad = 1
             } END { exit bad || n != 6 }'
}

@test "every rain model (ICLD 6-10) gives valid tables, ICLD 9 darker than its cumulus alone" {
    for m in 6 7 8 9 10; do
        with_icld "$m" > r$m.cdk
        run -0 --separate-stderr build_radiance "${QUICK[@]}" r$m.cdk "$DATA/small.snd" -o "r$m-%d.rad"
        run -0 sigchain-check "r$m-1.rad" "r$m-2.rad"
    done
    with_icld 1 > c1.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" c1.cdk "$DATA/small.snd" -o 'c1-%d.rad'
    # tau1 (4th field) of band 2's samples: the 25 mm/h rain under the cumulus darkens.
    paste -d ' ' <(sed -n '13,14p' c1-2.rad) <(sed -n '13,14p' r9-2.rad) |
        awk '{ printf "%s um: cumulus %s, with rain %s\n", $1, $4, $8; if (!($8 < $4)) bad = 1 }
             END { exit bad }'
}

@test "cirrus (ICLD 18, 19) is accepted and CARD 2A's CTHIK, CALT and CEXT are honoured" {
    with_cirrus 18 0 0 0 > defaults.cdk
    with_cirrus 18 1 10 0.14 > explicit.cdk  # CIRR18's defaults, MODEL 6: 1 km, 10 km, 0.14
    with_cirrus 18 1 10 0.42 > thick.cdk
    with_cirrus 19 0 0 0 > subvisual.cdk
    for d in defaults explicit thick subvisual; do
        run -0 --separate-stderr build_radiance "${QUICK[@]}" $d.cdk "$DATA/small.snd" -o "$d-%d.rad"
        run -0 sigchain-check "$d-1.rad" "$d-2.rad"
    done
    run -0 --separate-stderr build_radiance "${QUICK[@]}" "$DATA/rural23.cdk" "$DATA/small.snd" -o 'clear-%d.rad'
    # The defaults spelled out give the same tables, byte for byte.
    cmp defaults-1.rad explicit-1.rad
    cmp defaults-2.rad explicit-2.rad
    # Three times CEXT (same levels): three times ln(tau1 / clear tau1), to 1e-6 relative
    # (rounding of the printed transmissions, 9 digits).
    paste -d ' ' <(sed -n '13,14p' clear-2.rad) <(sed -n '13,14p' explicit-2.rad) <(sed -n '13,14p' thick-2.rad) |
        awk '{ one = log($8 / $4); three = log($12 / $4)
               printf "%s um: %.9g x 3 = %.9g\n", $1, one, three
               if (!(one < 0 && (three - 3 * one) ^ 2 < (1e-6 * three) ^ 2)) bad = 1 }
             END { exit bad }'
    # Thinner sub-visual cirrus (0.2 km x 0.028 km-1) dims less than the standard one.
    paste -d ' ' <(sed -n '13,14p' defaults-2.rad) <(sed -n '13,14p' subvisual-2.rad) |
        awk '{ if (!($8 > $4)) bad = 1 } END { exit bad }'
    # CTHIK, CALT, CEXT 0 mean the defaults; the NOAA cirrus (20) stays refused.
    with_cirrus 20 0 0 0 > noaa.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" noaa.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"CARD 2 ICLD (columns 21-25) is 20"* ]] || fail "stderr: $stderr"
    [ ! -e o-1.rad ]
    assert_no_temp_files .
}

@test "control7 writes a cloud deck (ICLD 3) without a warning and build_radiance takes it" {
    cp "$SEED/30Sep95800L.rsd" .
    run -0 --separate-stderr control7 --answers "$SIGCHAIN_SOURCE_DIR/tests/data/control7/hawkeye.answers" \
        -a icld=3 -o stratus.cdk
    assert_equal "$stderr" ""
    assert_equal "$(sed -n '2p' stratus.cdk | cut -c21-25)" "    3"
    run -0 --separate-stderr build_radiance "${QUICK[@]}" stratus.cdk "$DATA/small.snd" -o 'o-%d.rad'
    run -0 sigchain-check o-1.rad o-2.rad
    # control7 still warns about cirrus (ICLD 18): the unit test
    # Control7Job.WarnsAboutAnOverrideWhoseQuestionIsNotAsked.
}

# CARD 2D "$1" (IREG(1..4)), then for every region with IREG 1 a CARD 2D1 and the 16
# lines of CARD 2D2 written by printf (F6.2,2F7.5,F6.4) from columns $2 (ext), $3 (abs)
# and $4 (g) of the LOWTRAN 7 table $5 (data/atmosphere/lowtran7).
card2d() {
    printf '%s\n' "$1"
    for r in $1; do
        [ "$r" = 1 ] || continue
        printf ' 0.000E+00USER\n'
        awk -v e="$2" -v a="$3" -v g="$4" '!/^#/ && NF {
            printf "%6.2f%7.5f%7.5f%6.4f", $1, $e, $a, $g
            if (++n % 3 == 0 || n == 47) printf "\n"
        }' "$SIGCHAIN_SOURCE_DIR/data/atmosphere/lowtran7/$5"
    done
}

@test "ICLD 11 with the cumulus's coefficients in CARD 2D (IREG(2) 1) gives ICLD 1's tables" {
    with_icld 1 > c1.cdk
    { with_icld 11 | sed -n 1,2p; card2d "    0    1    0    0" 2 3 4 cloud_models.txt
      sed -n '3,$p' "$DATA/rural23.cdk"; } > c11.cdk
    run -0 sigchain-check c11.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" c1.cdk "$DATA/small.snd" -o 'c1-%d.rad'
    run -0 --separate-stderr build_radiance "${QUICK[@]}" c11.cdk "$DATA/small.snd" -o 'c11-%d.rad'
    run -0 sigchain-check c11-1.rad c11-2.rad
    # The same liquid water (LAYCLD's MC=1), CULWC and coefficients: the same numbers.
    for b in 1 2; do
        diff <(grep -v 'c1\.cdk' "c1-$b.rad") <(grep -v 'c11\.cdk' "c11-$b.rad")
    done
}

@test "IHAZE 7 (the deck of cdk(5)'s second EXAMPLE) is accepted and makes tables; a truncated CARD 2D2 exits 1 with file:line" {
    awk '/^# EXAMPLE/{e=1} e && /^```/{n++; next} e && n == 3' \
        "$SIGCHAIN_SOURCE_DIR/man/cdk.5.scd" > user.cdk
    run -0 sigchain-check user.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" user.cdk "$DATA/small.snd" -o 'u-%d.rad'
    run -0 sigchain-check u-1.rad u-2.rad
    # CARD 2D2 cut after its 15th line: CARD 3 is read as its 16th and fails at VX(46).
    sed '20d' user.cdk > cut.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" cut.cdk "$DATA/small.snd" -o 'x-%d.rad'
    [[ "$stderr" == "build_radiance: cut.cdk:20: CARD 2D2 (region 1, line 16 of 16) VX(46) (columns 1-6): "* ]] ||
        fail "stderr: $stderr"
    [ ! -e x-1.rad ]
}

@test "CARD 2D IREG(3) with a cloud is refused with card and columns" {
    { with_icld 3 | sed -n 1,2p | sed "2s/^    1/    7/"; card2d "    1    0    1    0" 2 6 10 aerosol_rural.txt
      sed -n '3,$p' "$DATA/rural23.cdk"; } > ireg3.cdk
    run -0 sigchain-check ireg3.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" ireg3.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"CARD 2D IREG(3) (columns 11-15) is 1 with ICLD 3: with a cloud LOWTRAN 7 makes the cloud aerosol region 2"* ]] ||
        fail "stderr: $stderr"
}

# rural23.cdk's cards as MODEL 7 with IHAZE $1, IPH 0 (Henyey-Greenstein with G) and the
# 19 layers of White (1996)'s profile (tests/data/white1996/flyover.cdk) made dry: H2O
# given as relative humidity (JCHAR H) 0 %.
dry_deck() {
    sed -n 1p "$DATA/rural23.cdk" | sed 's/^    6/    7/; s/^\(.\{55\}\)    0/\1    1/'
    sed -n 2p "$DATA/rural23.cdk" | sed "s/^    1/$(printf '%5d' "$1")/"
    local white="$SIGCHAIN_SOURCE_DIR/tests/data/white1996/flyover.cdk"
    sed -n 3p "$white"
    sed -n 4,22p "$white" | awk '{ printf "%s 0.000E+00%sABH\n", substr($0, 1, 30), substr($0, 41, 20) }'
}

@test "IHAZE 7 with the rural model's RH 0 % coefficients (CARD 2D2) makes IHAZE 1's tables over a dry profile, byte for byte" {
    { dry_deck 1; sed -n '3,$p' "$DATA/rural23.cdk"; } | sed 's/^    1    2  273    0$/    1    0  273    0/' > dry1.cdk
    { dry_deck 7; card2d "    1    0    0    0" 2 6 10 aerosol_rural.txt; sed -n '3,$p' "$DATA/rural23.cdk"; } |
        sed 's/^    1    2  273    0$/    1    0  273    0/' > dry7.cdk
    grep -q '^    1    0  273    0$' dry7.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" dry1.cdk "$DATA/small.snd" -o 'd1-%d.rad'
    run -0 --separate-stderr build_radiance "${QUICK[@]}" dry7.cdk "$DATA/small.snd" -o 'd7-%d.rad'
    # The same 0.55-um profiles (VIS 23), the same coefficients (IHAZE 1's ln-ln
    # interpolation in RH lands on its 0 % column), the same interpolation in wavelength.
    cmp d1-1.rad d7-1.rad
    cmp d1-2.rad d7-2.rad
}
