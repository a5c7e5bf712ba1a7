# Tests: trace
# Also requires: compare
#
# trace --sky-lookup on the box scene of trace.bats (trace_helper.bash): exact by default,
# the same bytes when named; a table is said by -v, renders the same bytes on 1 and 2
# threads and stays near the exact cube, while camera rays that see the sky keep the
# interpolation; bad values are usage errors.

bats_require_minimum_version 1.5.0
load test_helper
load trace_helper

@test "trace --sky-lookup: exact by default and when named, -v says which" {
    run -0 --separate-stderr trace -v $(inputs) -o default.img
    [[ "$stderr" == *"sky lookup: exact (four-neighbour interpolation"* ]] || fail "$stderr"
    trace_ok --sky-lookup exact $(inputs) -o exact.img
    cmp default.img exact.img
}

@test "trace --sky-lookup table[:N]: 64 by default, said by -v, same bytes on any threads, near exact" {
    # The open sky sampled: with it integrated (the default) the rays that reach the sky
    # from a camera ray's hit read none (trace(1), The open sky integrated).
    trace_ok --open-sky sampled $(inputs) -o exact.img
    run -0 --separate-stderr trace -v --open-sky sampled --sky-lookup table --threads 1 $(inputs) -o t1.img
    [[ "$stderr" == *"sky lookup: table 64 x 64 for rays from facets (the interpolation"* ]] ||
        fail "$stderr"
    trace_ok --open-sky sampled --sky-lookup table:64 --threads 2 $(inputs) -o t2.img
    cmp t1.img t2.img
    run -0 --separate-stderr trace -v --open-sky sampled --sky-lookup table:128 $(inputs) -o t128.img
    [[ "$stderr" == *"sky lookup: table 128 x 128"* ]] || fail "$stderr"
    # The box's sky has 2 x 4 cells; a 64 x 64 table reads it within 3/64 rad of each
    # direction, a few per cent of a cell's change: 0.016 % of the radiance on average
    # when this test was written; 0.2 % allows for the platform, not for a wrong cell.
    run -0 --separate-stderr compare --json --pixelwise t1.img exact.img
    local rel
    rel=$(sed -n 's/.*"name": "all".*"mean_relative": \([^,]*\),.*/\1/p' <<< "$output")
    [ -n "$rel" ] || fail "no mean_relative in: $output"
    awk -v r="$rel" 'BEGIN { exit !(r > 0 && r < 0.002) }' || fail "mean relative error $rel"
}

@test "trace --sky-lookup table: camera rays that see the sky keep the interpolation" {
    # The box camera lowered to 2 m and turned to the horizon: its top row sees only sky.
    sed -e 's/^10 10 0\t/10 10 2\t/' -e 's/^10 -10 30\t/10 -40 2\t/' \
        -e 's/^56.31 -90 0\t/0 -90 0\t/' "$DATA/box.adv" > horizon.adv
    local args=(horizon.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" "$DATA/band1.rad"
        "$DATA/band2.rad")
    run -0 --separate-stderr trace -v --open-sky sampled "${args[@]}" -o exact.img
    [[ "$stderr" =~ trace:\ [1-9][0-9]*\ primary\ sample\(s\)\ saw\ the\ sky ]] || fail "$stderr"
    trace_ok --open-sky sampled --sky-lookup table:4 "${args[@]}" -o table.img
    local bands b
    bands=$(sed -n 's/^bands *= *//p' exact.hdr)
    for ((b = 0; b < bands; b++)); do
        # Row 0 of band b (16 float32 pixels; ENVI, band sequential): the same bytes.
        cmp <(dd if=exact.img bs=64 skip=$((b * 16)) count=1 status=none) \
            <(dd if=table.img bs=64 skip=$((b * 16)) count=1 status=none) ||
            fail "band $b: the sky row differs"
    done
    # ... while the hemisphere rays of the rows below read the coarse table.
    ! cmp -s exact.img table.img || fail "a 4 x 4 table changed nothing"
}

@test "trace --sky-lookup: a bad value is a usage error" {
    for bad in table:1 table:513 table: table:x table:64x bilinear ''; do
        trace_bad 2 "--sky-lookup: expected exact, table or table:N (N cells a side, 2 to 512), not '$bad'" \
            $(inputs) -o out.img --sky-lookup "$bad"
    done
    run -2 --separate-stderr trace --shadow-history --sky-lookup table "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" -o out.shd
    [[ "$stderr" == *"--sky-lookup does not apply to --shadow-history"* ]] || fail "$stderr"
}
