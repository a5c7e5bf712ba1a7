# Tests: the README's counts of tests (scripts/test_counts)
# Also requires: the unit test binaries of the build, bats
#
# The README's paragraph on what `make test` runs is written by `make counts`; this
# case fails when a test was added or removed since, so the figure never goes stale.

bats_require_minimum_version 1.5.0
load test_helper

@test "the README's counts of GoogleTest and Bats cases are the tree's (make counts)" {
    run --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/test_counts" "$SIGCHAIN_BIN/.." --check
    [ "$status" = 0 ] || fail "$stderr"
}
