#!/usr/bin/env bats
# Tests: build_radiance with the deck's own options (man build_radiance(1), DECK FIELDS):
# each honoured field changes the .rad as it must, each refused one names its card and
# columns, and control7 warns when it writes a deck build_radiance refuses.
# Also requires: tests/data/build_radiance/{small.snd,rural23.cdk},
# tests/data/control7/hawkeye.answers, tests/data/white1996/30Sep95800L.rsd, data/atmosphere/ (reference data)
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance"
# A coarse sky and 8 streams keep each run well under a second.
QUICK=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)

radiance() { build_radiance "${QUICK[@]}" "$1" "$DATA/small.snd" -o "$2-%d.rad"; }

# The lines of a .rad before its SIGCHAIN_RAD block (the view table) and the block.
view_table() { sed '/SIGCHAIN_RAD/,$d' "$1"; }
sky_block() { sed -n '/SIGCHAIN_RAD/,/UPWELLED/p' "$1"; }

@test "IMULT 0 (single scattering) gives less path radiance than IMULT 1, same transmission" {
    radiance "$DATA/rural23.cdk" multiple
    sed '1s/^\(.\{15\}\)    1/\1    0/' "$DATA/rural23.cdk" > single.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" single.cdk "$DATA/small.snd" -o 'single-%d.rad'
    [[ "$stderr" == *"IMULT 0: solar scattering of first order only"* ]] || fail "stderr: $stderr"
    run ! cmp -s multiple-1.rad single-1.rad
    sigchain-check single-1.rad single-2.rad
}

@test "SALB brightens the sky, leaves the view table (a black ground's) and drops COUPLING" {
    radiance "$DATA/rural23.cdk" black
    sed '1s/   0.00$/   0.50/' "$DATA/rural23.cdk" > salb.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" salb.cdk "$DATA/small.snd" -o 'salb-%d.rad'
    [[ "$stderr" == *"SALB 0.5: the sky includes the ground's reflection"* ]] || fail "stderr: $stderr"
    assert_equal "$(view_table salb-1.rad)" "$(view_table black-1.rad)"
    run ! cmp -s <(sky_block salb-1.rad) <(sky_block black-1.rad)
    # The sky holds the ground: no COUPLING terms for trace to add it a second time.
    grep -q '^COUPLING' black-1.rad
    run ! grep -q '^COUPLING' salb-1.rad
    sigchain-check salb-1.rad
}

@test "IPH 0 with the deck's G changes the aerosol's scattering" {
    radiance "$DATA/rural23.cdk" mie
    sed -e '4s/^    1    2/    1    0/' -e '5s/     0.000$/     0.300/' "$DATA/rural23.cdk" > hg.cdk
    radiance hg.cdk hg
    run ! cmp -s mie-1.rad hg-1.rad
}

# The sky cell nearest the sun: its distance (deg) and its first sample's radiance.
near_sun_cell() {
    awk 'function sep(z1, a1, z2, a2,   c) {
             c = cos(z1 * d) * cos(z2 * d) + sin(z1 * d) * sin(z2 * d) * cos((a1 - a2) * d)
             return atan2(sqrt(1 - c * c), c) / d }
         BEGIN { d = atan2(0, -1) / 180; best = 1e9 }
         $1 == "SUN" { sz = $2; sa = $3 }
         $1 == "HEMISPHERE" { sky = 1; next }
         $1 == "UPWELLED" { sky = 0 }
         sky && k == 1 { if (s < best) { best = s; l = $1 } k = 2; next }
         sky && k == 2 { k = 0; next }
         sky && NF == 3 { s = sep($1, $2, sz, sa); k = 1 }
         END { print best, l }' "$1"
}

@test "IPH 2 (Mie) brightens the sky next to the sun against IPH 0 (Henyey-Greenstein)" {
    # The default sky grid (5 x 10 deg cells): its cell nearest the sun is within the
    # Mie functions' forward peak (a few degrees wide); QUICK's 15 x 30 deg cells are not.
    run -0 --separate-stderr build_radiance -v --streams 8 "$DATA/rural23.cdk" "$DATA/small.snd" -o 'mie-%d.rad'
    [[ "$stderr" == *"IPH 2: aerosol scattering by LOWTRAN 7's Mie phase functions"* ]] ||
        fail "stderr: $stderr"
    # G 0.70: about the rural model's tabulated asymmetry in the visible.
    sed -e '4s/^    1    2/    1    0/' -e '5s/     0.000$/     0.700/' "$DATA/rural23.cdk" > hg.cdk
    build_radiance --streams 8 hg.cdk "$DATA/small.snd" -o 'hg-%d.rad'
    read -r dist mie < <(near_sun_cell mie-1.rad)
    read -r _ hg < <(near_sun_cell hg-1.rad)
    # The forward peak: 1.8 times Henyey-Greenstein's radiance 2.8 deg from the sun.
    awk -v d="$dist" -v m="$mie" -v h="$hg" 'BEGIN { exit !(d < 5 && m > 1.3 * h) }' ||
        fail "cell $dist deg from the sun: Mie $mie, Henyey-Greenstein $hg"
    sigchain-check mie-1.rad mie-2.rad
}

@test "TBOUND, ISOURC and a second atmosphere are refused with card and columns" {
    sed '1s/^\(.\{65\}\)   0.000/\1 290.000/' "$DATA/rural23.cdk" > tbound.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" tbound.cdk "$DATA/small.snd" -o 'o-%d.rad'
    assert_equal "$stderr" "build_radiance: tbound.cdk: CARD 1 TBOUND (columns 66-73) is 290 K: the ground's temperature and emission come from the scene, rad(5) tables hold none (use 0)"
    sed '4s/^\(.\{15\}\)    0/\1    1/' "$DATA/rural23.cdk" > moon.cdk
    sed -i '4s/^    1/    0/' moon.cdk  # ISOURC 1 needs IPARM 0
    run -1 --separate-stderr build_radiance "${QUICK[@]}" moon.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"CARD 3A1 ISOURC (columns 16-20) is 1"* ]] || fail "stderr: $stderr"
    { sed '$s/^    0$/    1/' "$DATA/rural23.cdk"; sed '2s/    23.000/    10.000/' "$DATA/rural23.cdk"; } > two.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" two.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == *"CARD 5 IRPT (columns 1-5) is 1 and run 2 changes the atmosphere"* ]] ||
        fail "stderr: $stderr"
    [ ! -e o-1.rad ]
    assert_no_temp_files .
}

@test "IPARM 2 with the scene node's sun is accepted and gives the same tables as IPARM 1" {
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" "$DATA/rural23.cdk" "$DATA/small.snd" -o 'p1-%d.rad'
    [[ "$stderr" == *"sun from the scene node; the deck's (IPARM 1) agrees within"* ]] ||
        fail "stderr: $stderr"
    zen=$(sed -n 's/.*sun zenith \([0-9.]*\) deg, azimuth \([0-9.]*\) deg.*/\1/p' <<< "$stderr")
    azi=$(sed -n 's/.*sun zenith \([0-9.]*\) deg, azimuth \([0-9.]*\) deg.*/\2/p' <<< "$stderr")
    # PARM1: the sun's azimuth from the line of sight (PSIPO 90), PARM2: its zenith.
    card=$(awk -v z="$zen" -v a="$azi" 'BEGIN { r = 90 - a; if (r < -180) r += 360;
        printf "%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f", r, z, 0, 0, 0, 90, 0, 0 }')
    sed -e '4s/^    1/    2/' -e "5s/.*/$card/" "$DATA/rural23.cdk" > p2.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" p2.cdk "$DATA/small.snd" -o 'p2-%d.rad'
    [[ "$stderr" == *"the deck's (IPARM 2) agrees within"* ]] || fail "stderr: $stderr"
    cmp p1-1.rad p2-1.rad
    cmp p1-2.rad p2-2.rad
}

@test "a deck's sun that disagrees with the scene node's is an error naming the fields" {
    sed '5s/^\(.\{40\}\)    19.000/\1    10.000/' "$DATA/rural23.cdk" > ten.cdk
    run -1 --separate-stderr build_radiance "${QUICK[@]}" ten.cdk "$DATA/small.snd" -o 'o-%d.rad'
    [[ "$stderr" == "build_radiance: ten.cdk: CARD 3A1 IDAY (columns 11-15) and CARD 3A2 PARM1-PARM2 (columns 1-20) and TIME (columns 41-50, Greenwich) put the sun at zenith "* ]] ||
        fail "stderr: $stderr"
    [ ! -e o-1.rad ]
    # TIME as the scene's local time (White (1996)'s 14.000 for 19 h GMT): a warning.
    sed '5s/^\(.\{40\}\)    19.000/\1    14.000/' "$DATA/rural23.cdk" > local.cdk
    run -0 --separate-stderr build_radiance "${QUICK[@]}" local.cdk "$DATA/small.snd" -o 'o-%d.rad'
    assert_equal "$stderr" "build_radiance: warning: local.cdk: CARD 3A2 TIME (columns 41-50) 14 h is the scene's local time, not Greenwich time (19 h): the scene node's sun is used"
}

@test "control7 warns when it writes a deck build_radiance refuses" {
    answers="$SIGCHAIN_SOURCE_DIR/tests/data/control7"
    cp "$SEED/30Sep95800L.rsd" .
    run -0 --separate-stderr control7 --answers "$answers/hawkeye.answers" -a tbound=290 -o t.cdk
    assert_equal "$stderr" "control7: warning: build_radiance will refuse this deck: CARD 1 TBOUND (columns 66-73) is 290 K: the ground's temperature and emission come from the scene, rad(5) tables hold none (use 0)"
    [ -s t.cdk ]
    run -0 --separate-stderr control7 --answers "$answers/hawkeye.answers" -o ok.cdk
    assert_equal "$stderr" ""
}

@test "the Navy maritime model (IHAZE 3) runs, its visibility set by the wind" {
    # IHAZE 3, VIS 0: the visibility follows from the modes; WSS 15 m/s raises the sea salt.
    sed -e '2s/^    1/    3/' -e '2s/    23.000/     0.000/' "$DATA/rural23.cdk" > navy.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" navy.cdk "$DATA/small.snd" -o 'n-%d.rad'
    calm=$(sed -n 's/.*visibility \([0-9.]*\) km.*/\1/p' <<< "$stderr")
    sed '2s/^\(.\{40\}\)     0.000/\1    15.000/' navy.cdk > windy.cdk
    run -0 --separate-stderr build_radiance -v "${QUICK[@]}" windy.cdk "$DATA/small.snd" -o 'w-%d.rad'
    windy=$(sed -n 's/.*visibility \([0-9.]*\) km.*/\1/p' <<< "$stderr")
    awk -v c="$calm" -v w="$windy" 'BEGIN { exit !(w < c && w > 0) }' || fail "calm $calm windy $windy"
    sigchain-check n-1.rad w-1.rad
    run ! cmp -s n-1.rad w-1.rad
}
