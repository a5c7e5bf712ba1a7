# The box scene of tests/data/trace and the trace runs that the trace*.bats files share
# (loaded after test_helper).
DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
GDB="$SEED/box_on_plane.gdb"

# inputs [SCENE [MAT]]: the box scene's trace arguments (a .gdb and .mat may replace its own).
inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "${1:-$GDB}" "${2:-$DATA/box.mat}" \
        "$DATA/band1.rad" "$DATA/band2.rad"
}

# trace_ok ARGS...: exit 0, nothing on stdout or stderr, no temporary files left.
trace_ok() {
    run -0 --separate-stderr trace "$@"
    assert_output ''
    assert_equal "$stderr" ''
    assert_no_temp_files .
}

# trace_bad STATUS PREFIX ARGS...: exit STATUS, stderr starting "trace: PREFIX", no
# output (cube or shadow history) and no temporary files.
trace_bad() {
    local status="$1" prefix="$2"
    shift 2
    run "-$status" --separate-stderr trace "$@"
    assert_output ''
    [[ "$stderr" == "trace: $prefix"* ]] || fail "stderr: $stderr (wanted 'trace: $prefix...')"
    [ ! -e out.img ] && [ ! -e out.hdr ] || fail "an output cube was written"
    [ ! -e out.shd ] || fail "out.shd was written"
    assert_no_temp_files .
}
