# Tests: trace
# Also requires: sigchain-check compare
#
# Separate specular reflectance (mat(5) SPECULAR REFLECTANCE): the SPECULAR_CURVE key and
# the cone's .ems depth column, on the box scene of trace.bats (tests/data/trace).

bats_require_minimum_version 1.5.0
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
GDB="$SEED/box_on_plane.gdb"

# trace on the box scene with material file MAT into OUT.
render() {
    trace "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$1" "$DATA/band1.rad" "$DATA/band2.rad" -o "$2"
}

# The mean difference of two cubes (compare's "all" bias).
bias_of() {
    run -0 compare --pixelwise "$1" "$2"
    awk '$1 == "all" { print $5 }' <<<"$output"
}

@test "sigchain-check accepts SPECULAR_CURVE and --rewrite keeps it" {
    run -0 --separate-stderr sigchain-check "$DATA/specular.mat"
    assert_output "$DATA/specular.mat: ok: 2 materials"
    run -0 --separate-stderr sigchain-check --rewrite -o out.mat "$DATA/specular.mat"
    run -0 grep -x 'SPECULAR_CURVE = 1' out.mat
    run -0 sigchain-check -q out.mat
}

@test "sigchain-check refuses SPECULAR_CURVE with the lambertian model" {
    check_bad mat specular_lambertian.mat 14 \
        "unexpected tag SPECULAR_CURVE: REFLECTANCE_MODEL = lambertian has no specular part"
}

@test "trace renders a SPECULAR_CURVE material, brighter where the specular curve is" {
    run -0 --separate-stderr render "$DATA/specular.mat" curve.img
    assert_equal "$stderr" ''
    # The same entries without the tag: the specular part reflects curve 0 (0.1-0.4)
    # instead of curve 1 (0.8), so the grass is darker.
    cp "$DATA/grass2.ems" "$DATA/wood.ems" .
    grep -v '^SPECULAR_CURVE' "$DATA/specular.mat" > plain.mat
    run -0 --separate-stderr render plain.mat plain.img
    bias="$(bias_of curve.img plain.img)"
    awk -v b="$bias" 'BEGIN { exit !(b > 0.0001) }' || fail "bias $bias"
    assert_no_temp_files .
}

@test "trace refuses a SPECULAR_CURVE its .ems does not have, naming the .mat line" {
    run -1 --separate-stderr render "$DATA/specular_bad_curve.mat" out.img
    assert_output ''
    assert_equal "$stderr" "trace: $DATA/specular_bad_curve.mat:16: material 'grass' (1): expected SPECULAR_CURVE a curve of grass2.ems (0 to 1), found 2"
    [ ! -e out.img ]
    assert_no_temp_files .
}

@test "trace renders White's cone with the depth column; -999 depths leave SPECULARITY's lobe" {
    run -0 --separate-stderr render "$DATA/cone_depth.mat" depth.img
    assert_equal "$stderr" ''
    # The same table with the depth column unused: SPECULARITY 0 then leaves no lobe,
    # so the render is the Lambertian grass of box.mat, byte for byte.
    cp "$DATA/wood.ems" .
    sed 's/^[0-9.]* \([0-9.]*\) -999 -999$/-999 \1 -999 -999/' "$DATA/cone_depth.ems" > cone_depth.ems
    run -0 grep -c '^-999 [0-9.]* -999 -999$' cone_depth.ems
    assert_output 7
    cp "$DATA/cone_depth.mat" .
    run -0 --separate-stderr render cone_depth.mat unused.img
    run -0 --separate-stderr render "$DATA/box.mat" box.img
    run -0 cmp unused.img box.img
    bias="$(bias_of depth.img box.img)"
    awk -v b="$bias" 'BEGIN { exit !(b > 0) }' || fail "bias $bias"
}

@test "trace refuses SPECULAR_CURVE with a cone depth column, and a mixed depth column" {
    cp "$DATA/cone_depth.ems" "$DATA/wood.ems" .
    sed 's/^CONE_HALF_ANGLE_DEG = 10$/&\nSPECULAR_CURVE = 0/' "$DATA/cone_depth.mat" > both.mat
    run -1 --separate-stderr render both.mat out.img
    [[ "$stderr" == "trace: both.mat:18: material 'grass' (1): SPECULAR_CURVE and the lobe depths of cone_depth.ems both set the specular reflectance"* ]] ||
        fail "stderr: $stderr"
    sed '96s/^0.5 /-999 /' "$DATA/cone_depth.ems" > cone_depth.ems
    cp "$DATA/cone_depth.mat" .
    run -1 --separate-stderr render cone_depth.mat out.img
    [[ "$stderr" == *"cone_depth.ems:96: expected lobe depth in [0, 1] like the row at 0 deg"* ]] ||
        fail "stderr: $stderr"
    [ ! -e out.img ]
}
