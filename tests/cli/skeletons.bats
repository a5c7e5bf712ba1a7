# Tests: therm
# Also requires: CMakeLists.txt (the version in its project() line)
#
# The shared behaviour of the skeleton tools until their issues land (3, 4, 5, 6):
# --help and --version work, an unknown option is bad usage, and real work says
# "not implemented yet", exits 1 and writes nothing. When a tool's issue lands, its
# own TOOL.bats takes over and the tool leaves the "real work" tests here.

bats_require_minimum_version 1.5.0
load test_helper

# The version CMake stamps into every tool, read from the project() line.
project_version() {
    sed -n 's/^project(sigchain VERSION \([0-9][0-9.]*\).*/\1/p' \
        "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt"
}

# --help: exit 0, usage on stdout, nothing on stderr, last line "See TOOL(1).".
check_help() {
    local tool="$1"
    run -0 --separate-stderr "$tool" --help
    assert_line --index 0 --partial "Usage: $tool "
    assert_equal "${lines[-1]}" "See $tool(1)."
    assert_equal "$stderr" ""
}

# --version: exit 0, exactly "TOOL (sigchain) X.Y.Z" on stdout.
check_version() {
    local tool="$1" version
    version="$(project_version)"
    [ -n "$version" ] || fail "no version in the project() line of CMakeLists.txt"
    run -0 --separate-stderr "$tool" --version
    assert_output "$tool (sigchain) $version"
    assert_equal "$stderr" ""
}

# An unknown option: exit 2, nothing on stdout, "Try 'TOOL --help'." on stderr.
check_unknown_option() {
    local tool="$1"
    run -2 --separate-stderr "$tool" --no-such-option
    assert_output ""
    [[ "$stderr" == "$tool: "*"no-such-option"* ]] || fail "stderr: $stderr"
    assert_equal "${stderr##*$'\n'}" "Try '$tool --help'."
}

# Real work: exit 1 with "not implemented yet", no output file, no temporary file.
check_not_implemented() {
    local tool="$1"
    printf '1 2 3\n' > input.txt
    run -1 --separate-stderr "$tool" input.txt -o out
    assert_output ""
    [[ "$stderr" == "$tool: not implemented yet"* ]] || fail "stderr: $stderr"
    [ ! -e out ] || fail "$tool wrote 'out' although it is not implemented"
    assert_no_temp_files .
}

@test "therm --help prints usage and points to therm(1)" { check_help therm; }
@test "therm --version prints the project version" { check_version therm; }
@test "therm rejects an unknown option with exit 2" { check_unknown_option therm; }
@test "therm says not implemented yet and writes nothing" { check_not_implemented therm; }

@test "every skeleton tool has its section-1 man page" {
    local tool
    for tool in therm; do
        [ -f "$SIGCHAIN_SOURCE_DIR/man/$tool.1.scd" ] || fail "no man/$tool.1.scd"
    done
}
