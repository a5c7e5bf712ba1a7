#!/usr/bin/env bats
# Tests: scripts/accuracy (docs/accuracy.md) and scripts/chapter5 (docs/chapter5.md):
# the committed pages are what the scripts write today
# Also requires: unit_rt, unit_atmos, unit_atmos_table, unit_thermal, unit_trace, unit_radiometry,
# build_radiance, scripts/atmosphere-table, tests/cli/build_radiance_clouds.bats, python3
# Every figure of these pages comes from a run of the tests that check it; a figure
# typed by hand, or left from an older run, goes stale. Each test regenerates a page
# into the test's folder and compares it with the committed one (about 6 s and 4 s on
# 2 cores).

load test_helper

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    command -v python3 > /dev/null || skip "no python3"
}

# unit tests of BUILD that the page needs, else skip.
needs() {
    local t
    for t in "$@"; do
        [ -x "$SIGCHAIN_BIN/../tests/$t" ] || skip "$t not built in $SIGCHAIN_BIN/../tests"
    done
}

# same_figures COMMITTED FRESH: the two pages alike but for their numbers, and every
# number of FRESH within a relative 1e-6 of the committed one. The tests behind the
# figures are deterministic (fixed inputs; the Monte Carlo ones draw counter-based
# random numbers from fixed seeds, the same for any thread count), so a rerun of the
# same code prints the same digits. The pages print 2 to 6 significant digits, so any
# change of a printed digit is at least 1e-5 relative: 1e-6 fails on every change a
# reader could see and on none below the printed precision.
same_figures() {
    python3 - "$1" "$2" << 'PY'
import re
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
committed, fresh = (open(p, encoding="utf-8").read().split("\n") for p in sys.argv[1:3])
bad = 0
if len(committed) != len(fresh):
    print(f"{len(committed)} lines committed, {len(fresh)} today")
    sys.exit(1)
for n, (a, b) in enumerate(zip(committed, fresh), 1):
    if NUMBER.sub("#", a) != NUMBER.sub("#", b):
        print(f"line {n} differs in its words:\n  committed: {a}\n  today:     {b}")
        bad += 1
        continue
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if abs(float(x) - float(y)) > 1e-6 * max(abs(float(x)), abs(float(y))):
            print(f"line {n}: committed {x}, today {y}")
            bad += 1
sys.exit(1 if bad else 0)
PY
}

@test "accuracy: docs/accuracy.md holds today's figures (every test passed, each figure to 1e-6)" {
    needs unit_rt unit_atmos unit_atmos_table unit_thermal unit_trace
    [ -x "$SIGCHAIN_BIN/build_radiance" ] || skip "build_radiance not built"
    run -0 --separate-stderr python3 "$SIGCHAIN_SOURCE_DIR/scripts/accuracy" "$SIGCHAIN_BIN/.." fresh.md
    run -0 same_figures "$SIGCHAIN_SOURCE_DIR/docs/accuracy.md" fresh.md
    # A verdict is a word, so a failure shows as a changed line above; none committed.
    run -1 grep -c 'FAIL' "$SIGCHAIN_SOURCE_DIR/docs/accuracy.md"
}

@test "chapter5: docs/chapter5.md holds today's figures (each to 1e-6)" {
    needs unit_trace unit_radiometry
    run -0 --separate-stderr python3 "$SIGCHAIN_SOURCE_DIR/scripts/chapter5" "$SIGCHAIN_BIN/.." fresh.md
    run -0 same_figures "$SIGCHAIN_SOURCE_DIR/docs/chapter5.md" fresh.md
}
