# Tests: trace
# Also requires: compare
#
# trace --standard-error and --convergence MIN,MAX,THRESHOLD (trace(1) SAMPLING ERROR)
# on the box scene of trace.bats (tests/data/trace).

bats_require_minimum_version 1.5.0
load test_helper
load trace_helper

@test "trace --standard-error adds samples and standard_error_BAND to the truth, the cube unchanged" {
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 8 -o out.img --truth truth.img \
        --standard-error
    run -0 tr -d '\n' < truth.hdr
    [[ "$output" == *"material_3_fraction,samples,standard_error_band1,standard_error_band2}"* ]] ||
        fail "truth band names: $output"
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 8 -o plain.img --truth plain_truth.img
    run -0 cmp out.img plain.img
}

@test "trace --standard-error needs --truth" {
    trace_bad 2 "--standard-error: its layers are in the truth cube: give --truth FILE" \
        $(inputs) -o out.img --standard-error
}

@test "trace --convergence gives the same cube and truth with 1 and 2 threads" {
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 8 --convergence 4,32,0.02 \
        --threads 1 -o one.img --truth one_truth.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 8 --convergence 4,32,0.02 \
        --threads 2 -o two.img --truth two_truth.img
    run -0 cmp one.img two.img
    run -0 cmp one_truth.img two_truth.img
}

@test "trace refuses bad --convergence values with exit 2" {
    trace_bad 2 "--convergence: 4,32: expected MIN,MAX,THRESHOLD" $(inputs) -o out.img --convergence 4,32
    trace_bad 2 "--convergence: 4,32,0.1,2: expected MIN,MAX,THRESHOLD" $(inputs) -o out.img \
        --convergence 4,32,0.1,2
    trace_bad 2 "--convergence: 1: must be an integer from 2 to" $(inputs) -o out.img --convergence 1,32,0.1
    trace_bad 2 "--convergence: x: must be an integer" $(inputs) -o out.img --convergence x,32,0.1
    trace_bad 2 "--convergence: 0: must be a number > 0" $(inputs) -o out.img --convergence 4,32,0
    trace_bad 2 "--convergence: nan: must be" $(inputs) -o out.img --convergence 4,32,nan
    trace_bad 2 "--convergence: expected 2 <= MIN <= MAX" $(inputs) -o out.img --convergence 32,4,0.1
    trace_bad 2 "--convergence: not with --samples-per-pixel" $(inputs) -o out.img \
        --convergence 4,32,0.1 --samples-per-pixel 8
    trace_bad 2 "--convergence does not apply to --shadow-history" --shadow-history \
        --convergence 4,32,0.1 "$DATA/box.snd" "$GDB" "$DATA/box.mat" -o out.shd
}

@test "trace -v --convergence reports the samples the pixels took" {
    run -0 --separate-stderr trace -v $(inputs) --sampling montecarlo --hemisphere-samples 8 \
        --convergence 4,32,0.02 -o out.img
    [[ "$stderr" == *"--convergence 4 to 32 sample(s) per pixel"* ]] || fail "stderr: $stderr"
    [[ "$stderr" =~ trace:\ [0-9.]+\ primary\ sample\(s\)\ per\ pixel\ on\ average,\ at\ most\ (4|8|12|16|20|24|28|32)$'\n' ]] ||
        fail "stderr: $stderr"
}

@test "trace --convergence-error absolute|rms|scene: a threshold every pixel meets stops at MIN, and needs --convergence" {
    for e in absolute rms scene; do
        run -0 --separate-stderr trace -v $(inputs) --sampling montecarlo --hemisphere-samples 8 \
            --convergence 4,32,1 --convergence-error $e -o $e.img
        [[ "$stderr" == *"trace: 4.00 primary sample(s) per pixel on average, at most 4"* ]] ||
            fail "$e: stderr: $stderr"
    done
    trace_bad 2 "--convergence-error: unknown error 'both' (relative, absolute, rms or scene)" $(inputs) -o out.img \
        --convergence 4,32,0.1 --convergence-error both
    trace_bad 2 "--convergence-error: only with --convergence" $(inputs) -o out.img \
        --convergence-error absolute
}
