#!/usr/bin/env bats
# Tests: trace (its library, through unit_trace) and build_radiance through make
#
# trace --uncertainty's first-order layer against a Monte Carlo over the inputs (2000
# draws of tests/data/trace/training.unc's sigmas) on the pipeline's training scene
# (data/scenes/training) rendered as trace renders it by default: one bounce, the
# background world and the ground-sky coupling. The scene's .rad files are built in a
# scratch copy by its Makefile; the comparison is unit_trace's
# Uncertainty.FirstOrderAgainstMonteCarloOnThePipelinesTrainingScene (tolerance 5 %,
# over 3 standard errors of a 2000-draw standard deviation), which skips without them.
load test_helper

@test "trace --uncertainty agrees with a Monte Carlo over the inputs on the training scene" {
    cp -r "$SIGCHAIN_SOURCE_DIR/data/scenes/training" training
    rm -rf training/out
    run make -s -C training SIGCHAIN_BIN="$SIGCHAIN_BIN" out/training-1.rad out/training-2.rad \
        out/training-3.rad
    [ "$status" -eq 0 ] || fail "make: $output"
    SIGCHAIN_TRAINING_DIR="$PWD/training" run "$SIGCHAIN_BIN/../tests/unit_trace" \
        --gtest_filter='Uncertainty.FirstOrderAgainstMonteCarloOnThePipelinesTrainingScene'
    [ "$status" -eq 0 ] || fail "unit_trace: $output"
    [[ "$output" == *"[  PASSED  ] 1 test."* ]] || fail "not run: $output"
    [[ "$output" != *"SKIPPED"* ]] || fail "skipped: $output"
}
