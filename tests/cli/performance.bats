#!/usr/bin/env bats
# Tests: scripts/performance --from (the page of make performance from benchmark outputs)
# Also requires: bench/performance.md.in, tests/data/performance (the raw outputs of one
# run of the benchmarks: Google Benchmark JSON, bench_trace's and bench_build_radiance's
# printed lines, bench/trace_setup.sh's and scripts/mie-aureole's, machine.txt)
#
# No benchmark is run: the page is written from the canned outputs, so that every
# placeholder of the template is checked to have a figure behind it.
bats_require_minimum_version 1.5.0
load test_helper

PERF="$SIGCHAIN_SOURCE_DIR/scripts/performance"
CANNED="$SIGCHAIN_SOURCE_DIR/tests/data/performance"

@test "performance: every placeholder of the template is filled from the outputs" {
    run -0 --separate-stderr "$PERF" --from "$CANNED" page.md
    assert_equal "$stderr" "performance: wrote page.md"
    run -1 grep -n '@@' page.md
    # Figures from each kind of output.
    grep -q 'on a machine with 2 cores (AMD EPYC;' page.md
    grep -q 'about 1.16 million facets per second' page.md
    grep -q '490 ms serially,$' page.md
    grep -q 'takes 1.6 ms of CPU with 8$' page.md
    grep -q 'render runs at \*\*0.75\*\* of it' page.md
    grep -q '(0.76 per CPU second; target 0.9: not met)' page.md
    grep -q '\*\*1.008 s\*\* on one thread (best of 3; target under 2 s: met)' page.md
    grep -q '8 (0.76 %), 8 (0.86 %), 6 (1.00 %)' page.md
    grep -q 'sun +9.5 % / +10.1 % / +18.7 %' page.md
    grep -q 'start (wall minus set-up and render) is 0.13 s' page.md
    # No LOWTRAN 7 output: the page says how to get one.
    grep -q '^Not measured in this run: LOWTRAN 7 is not part of sigchain' page.md
}

@test "performance: bench/lowtran_side_by_side.sh's output goes in when there is one" {
    cp -R "$CANNED" run
    printf 'one line of sight, Hawkeye deck, 3 alternating runs\nratio to LOWTRAN 7: 1.50\n' > run/lowtran.txt
    run -0 "$PERF" --from run page.md
    run -0 grep -A3 '^Measured by `bench/lowtran_side_by_side.sh` in this run' page.md
    # (lines holds no blank line)
    assert_line --index 1 '```'
    assert_line --index 2 'one line of sight, Hawkeye deck, 3 alternating runs'
    run -1 grep -q '^Not measured in this run' page.md
}

@test "performance: a figure missing from the outputs, or a placeholder without one, exits 1" {
    cp -R "$CANNED" run
    sed -i '/^ratio render \/ bare golf-ball  /d' run/bench_trace.txt
    echo old > page.md
    run -1 --separate-stderr "$PERF" --from run page.md
    assert_equal "$stderr" "performance: run: no figure trace_ratio in the outputs
performance: run: no figure trace_ratio_cpu in the outputs"
    [ "$(cat page.md)" = old ]
    rm run/bench_rt.json
    run -1 --separate-stderr "$PERF" --from run page.md
    assert_equal "$stderr" "performance: run/bench_rt.json: no such output"
    printf 'a @@cores@@ b @@no_such_figure@@\n' > t.md.in
    run -1 --separate-stderr env PERF_TEMPLATE=t.md.in "$PERF" --from "$CANNED" page.md
    assert_equal "$stderr" "performance: t.md.in:1: no value for @@no_such_figure@@"
    [ "$(cat page.md)" = old ]
}

@test "performance: make performance builds the benchmarks it runs, then the page (dry run)" {
    run -0 make -n --no-print-directory -C "$SIGCHAIN_SOURCE_DIR" performance BUILD=b JOBS=2
    assert_line "cmake --build b -j 2 --target tools bench_parsers bench_view_angle bench_sensor_compare bench_rt bench_mtf bench_trace bench_build_radiance"
    assert_line "scripts/performance b"
}
