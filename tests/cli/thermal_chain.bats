#!/usr/bin/env bats
# Tests: trace therm build_radiance (the thermal chain, end to end)
# Also requires: tests/data/white1996/{box_on_plane.gdb,weather_30_Sep_95.wth,fall_grass.ems},
# tests/data/therm/box_on_plane.mat, tests/golden/control7/hawkeye.cdk,
# data/demo/{box256.adv,lwir.snd}
#
# trace --shadow-history -> therm -> build_radiance (8-12.5 um) -> trace --tmp: the
# training scene (a wooden box on grass) rendered in a thermal band with the
# temperatures therm computed.
load test_helper

DEMO="$SIGCHAIN_SOURCE_DIR/data/demo"

# The chain up to the temperatures and the tables, in the test's directory.
chain() {
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
    trace --shadow-history --points-per-facet 4 "$DEMO/lwir.snd" "$SEED/box_on_plane.gdb" \
        box_on_plane.mat -o box.shd
    therm box.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat "$SEED/box_on_plane.gdb" \
        "$DEMO/lwir.snd" -o box.tmp
    build_radiance --streams 8 --sky-zenith-step 10 --sky-azimuth-step 20 --view-azimuth 0 \
        "$GOLDEN/control7/hawkeye.cdk" "$DEMO/lwir.snd" -o 'lwir-%d.rad'
}

render() {  # render TMP OUT: a 64 x 64 view, one sample per pixel
    sed -e 's/^256 256.*/64 64\t# rows, columns/' -e 's/^pixel_pitch_um = .*/pixel_pitch_um = 250/' \
        -e 's/^samples_per_pixel = .*/samples_per_pixel = 1/' "$DEMO/box256.adv" > box64.adv
    trace -q box64.adv "$DEMO/lwir.snd" "$SEED/box_on_plane.gdb" box_on_plane.mat lwir-1.rad \
        --tmp "$1" -o "$2"
}

@test "every stage of the thermal chain writes a valid file" {
    chain
    run -0 sigchain-check box.shd box.tmp lwir-1.rad
    # therm's temperatures at 14:00 local: the sunlit south wall (2-1-2) warmer than the
    # north wall (2-1-4) in the shade.
    south=$(awk '$1 == "2-1-2" { print $2 }' box.tmp)
    north=$(awk '$1 == "2-1-4" { print $2 }' box.tmp)
    awk -v s="$south" -v n="$north" 'BEGIN { exit !(s > n + 5) }' || fail "south $south, north $north"
    # The tables of a thermal band carry emitted path and sky radiance.
    awk 'NR == 17 { exit !($2 > 0) }' lwir-1.rad || fail "no L_ue in $(sed -n 17p lwir-1.rad)"
}

@test "trace renders the thermal band with the temperatures, and warns without them" {
    chain
    render box.tmp cube.img
    run -0 --separate-stderr trace box64.adv "$DEMO/lwir.snd" "$SEED/box_on_plane.gdb" \
        box_on_plane.mat lwir-1.rad -o cold.img
    [[ "$stderr" == *"warning: "*"no facet temperatures (--tmp)"* ]] || fail "stderr: $stderr"
}

# 10 K warmer facets raise the 10 um radiance by epsilon x (B(T + 10) - B(T)) on every
# pixel (plus a little of it reflected). The grass emissivity of White (1996) (0.93)
# is the nadir value; by Kirchhoff with its fall-off (trace(1): 1 - (1 - eps) F Fbar,
# F 0.87 to 0.69 at this camera's 20-48 deg) the directional emissivity is 0.95-0.98,
# and the pixels beyond the plate's far edge see the background plane, as warm as the
# scene's mean with emissivity 0.93. So the factor lies within 0.9-1.02 of the Planck
# difference at 303 K (Planck's law with CODATA constants here, independent of the
# code; 1.02 leaves room for the warmer neighbours' reflected emission).
@test "warmer facets brighten the thermal band by emissivity x the Planck difference" {
    chain
    render box.tmp cube.img
    awk '/^[0-9]/ { $2 = $2 + 10 } { print }' box.tmp > hot.tmp
    render hot.tmp hot.img
    run -0 compare --pixelwise hot.img cube.img
    # Band 6 is 10 um (1000 cm-1). The bias is a mean over every pixel.
    bias=$(awk '$1 == 6 { print $5 }' <<< "$output")
    awk -v b="$bias" 'BEGIN {
        c1 = 1.191042972e4; c2 = 14387.7688; l = 10
        B1 = c1 / l^5 / (exp(c2 / (l * 303)) - 1); B2 = c1 / l^5 / (exp(c2 / (l * 313)) - 1)
        d = B2 - B1
        if (!(b > 0.9 * d && b < 1.02 * d)) { print "bias " b " vs dB " d; exit 1 } }'
}
