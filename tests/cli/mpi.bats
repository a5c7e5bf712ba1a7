# Tests: trace therm build_radiance
# Also requires: mpirun (Open MPI), a build with SIGCHAIN_MPI
#
# trace under mpirun (trace(1), MPI): rank 0 hands out row tiles to the other ranks and
# writes the one cube, bit-identical to a one-process render for any rank and thread
# count; a worker that dies makes the run fail, with no output and no hang. Skipped
# when the build has no MPI. The box scene of trace.bats (16 x 16 pixels, 6 bands).

bats_require_minimum_version 1.5.0
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"

inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "$SEED/box_on_plane.gdb" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad"
}

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    # A build with MPI has the module sigchain_mpi (lib/core/mpi_module.hpp).
    local modules=("$SIGCHAIN_BIN"/../lib*/sigchain/sigchain_mpi.so)
    : "${SIGCHAIN_MPI:=$([ -e "${modules[0]}" ] && echo ON || echo OFF)}"
    [ "$SIGCHAIN_MPI" = ON ] || skip "the build has no MPI (SIGCHAIN_MPI is off)"
    : "${SIGCHAIN_MPIEXEC:=mpirun}"
    # CI runs as root, which Open MPI refuses unless told.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # No network probing on a single machine; quiet about missing fabrics.
    export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
}

# The last run exited 0; else the test fails with its status and standard error (where
# mpirun and the ranks say why; assert_success shows standard output only).
assert_ran() {
    [ "$status" -eq 0 ] || fail "status $status: $stderr"
}

# mpi_trace NP ARGS...: trace under mpirun with NP ranks, at most 60 s.
mpi_trace() {
    local np="$1"
    shift
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np "$np" \
        "$SIGCHAIN_BIN/trace" "$@"
}

@test "mpirun -np 2 and -np 3: the cube is byte for byte the one-process render" {
    run -0 --separate-stderr trace -q --threads 2 $(inputs) --truth truth.img -o one.img
    mkdir np2 np3
    mpi_trace 2 -q --threads 1 $(inputs) --truth np2/truth.img -o np2/one.img
    assert_ran
    assert_equal "$stderr" ''
    mpi_trace 3 -q --threads 2 $(inputs) --truth np3/truth.img -o np3/one.img
    assert_ran
    for d in np2 np3; do
        run -0 cmp "$d/one.img" one.img
        run -0 cmp "$d/truth.img" truth.img
        # The header too: the recorded command holds base names only, the geolocation
        # arrays (the oblique box view's) their file name.
        run -0 cmp "$d/one.hdr" one.hdr
        run -0 cmp "$d/one.geoloc.tif" one.geoloc.tif
    done
    assert_no_temp_files np2
}

@test "mpirun -np 3 -v: 2 workers share 8 tiles (4 per worker); uneven tiles of 16 rows" {
    mkdir np3
    mpi_trace 3 -v --threads 1 $(inputs) -o np3/one.img
    assert_ran
    [[ "$stderr" == *"trace: MPI: 2 worker(s), 8 tiles of about 2 rows"* ]] || fail "$stderr"
    run -0 --separate-stderr trace -q $(inputs) -o one.img
    run -0 cmp np3/one.img one.img
}

@test "mpirun with --tile: the part is farmed and records its rows" {
    mkdir mpi
    mpi_trace 2 -q $(inputs) --tile 2/3 -o mpi/part2.img
    assert_ran
    run -0 --separate-stderr trace -q $(inputs) --tile 2/3 -o part2.img
    run -0 cmp mpi/part2.img part2.img
    run -0 cmp mpi/part2.hdr part2.hdr
    run -0 cmp mpi/part2.geoloc.tif part2.geoloc.tif
    run -0 grep -x 'sigchain rows = 5:10 of 16' mpi/part2.hdr
}

@test "a worker killed after its first tile fails the run: no output, no hang" {
    local start=$SECONDS
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 2 \
        -x SIGCHAIN_TEST_KILL_WORKER_AFTER_TILES=1 "$SIGCHAIN_BIN/trace" -q $(inputs) -o out.img
    [ "$status" -ne 0 ] || fail "status 0"
    [ "$status" -ne 124 ] || fail "mpirun hung (timeout)"
    [ ! -e out.img ] && [ ! -e out.hdr ] || fail "an output was written"
    assert_no_temp_files .
    [ $((SECONDS - start)) -lt 60 ]
}

@test "an input error under mpirun exits 1 with the message, no output, no hang" {
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 2 \
        "$SIGCHAIN_BIN/trace" -q "$DATA/box.adv" "$DATA/box.snd" "$SEED/box_on_plane.gdb" \
        "$DATA/missing_wood.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o out.img
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "status $status"
    [[ "$stderr" == *"trace: "*"material 37 is not in the material file"* ]] || fail "$stderr"
    [ ! -e out.img ]
    # Rank 0 alone says it, once (3 ranks each printed it, interleaved: "thermtherm:").
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 3 \
        "$SIGCHAIN_BIN/therm" -q "$SEED/box_on_plane.shd" "$SEED/weather_30_Sep_95.wth" \
        "$DATA/missing_wood.mat" "$SEED/box_on_plane.gdb" "$SEED/hawkeye.snd" -o out.tmp
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "status $status"
    [ "$(printf '%s\n' "$stderr" | grep -c '^therm: ')" = 1 ] || fail "$stderr"
    [ ! -e out.tmp ]
    # An error of one worker alone (a file its node lacks: rank 1 is given a bad .mat
    # here) is still reported, by that rank, after its short wait.
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 2 sh -c '
        mat=$1; [ "$OMPI_COMM_WORLD_RANK" = 1 ] && mat=$2
        exec "$3/therm" -q "$4/box_on_plane.shd" "$4/weather_30_Sep_95.wth" "$mat" \
            "$4/box_on_plane.gdb" "$4/hawkeye.snd" -o out.tmp' sh \
        "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$DATA/missing_wood.mat" \
        "$SIGCHAIN_BIN" "$SEED"
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "status $status"
    [[ "$stderr" == *"therm: rank 1: "*"material 37 is not in "*"missing_wood.mat"* ]] ||
        fail "$stderr"
    [ ! -e out.tmp ]
}

@test "therm under mpirun -np 3: the .tmp is byte for byte the one-process .tmp" {
    local in=("$SEED/box_on_plane.shd" "$SEED/weather_30_Sep_95.wth"
        "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/box_on_plane.gdb"
        "$SEED/hawkeye.snd")
    run -0 --separate-stderr therm -q "${in[@]}" -o one.tmp
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 3 \
        "$SIGCHAIN_BIN/therm" -q --threads 1 "${in[@]}" -o np3.tmp
    assert_ran
    assert_equal "$stderr" ''
    run -0 cmp np3.tmp one.tmp
    # Standard input is read by rank 0 alone: refused.
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 2 \
        "$SIGCHAIN_BIN/therm" -q - "${in[@]:1}" -o in.tmp < "${in[0]}"
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "status $status"
    [[ "$stderr" == *"therm: standard input cannot be read under mpirun"* ]] || fail "$stderr"
    [ ! -e in.tmp ]
}

@test "trace --shadow-history under mpirun -np 3: the .shd is byte for byte the one-process .shd" {
    # box_on_plane.mat of the therm tests beside the .ems it names.
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
    local in=("$SEED/hawkeye.snd" "$SEED/box_on_plane.gdb" box_on_plane.mat)
    run -0 --separate-stderr trace --shadow-history -q --points-per-facet 4 "${in[@]}" -o one.shd
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 3 \
        "$SIGCHAIN_BIN/trace" --shadow-history -q --threads 1 --points-per-facet 4 "${in[@]}" \
        -o np3.shd
    assert_ran
    run -0 cmp np3.shd one.shd
}

@test "build_radiance under mpirun -np 3: the .rad tables are byte for byte one process's" {
    local quick=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)
    local in=("$GOLDEN/control7/hawkeye.cdk" "$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance/small.snd")
    run -0 --separate-stderr build_radiance -q "${quick[@]}" "${in[@]}" -o 'one-%d.rad'
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 3 \
        "$SIGCHAIN_BIN/build_radiance" -q --threads 1 "${quick[@]}" "${in[@]}" -o 'np3-%d.rad'
    assert_ran
    run -0 cmp np3-1.rad one-1.rad
    run -0 cmp np3-2.rad one-2.rad
}

# Open MPI is loaded only when a launcher started the process: every MPI call is in the
# module sigchain_mpi (lib/core/mpi_module.hpp), opened when the farm's Session starts.
@test "no tool links MPI; an unloadable MPI module fails only a run under mpirun, naming it" {
    run -0 readelf -d "$SIGCHAIN_BIN/trace" "$SIGCHAIN_BIN/therm" "$SIGCHAIN_BIN/build_radiance"
    refute_output --partial libmpi
    local modules=("$SIGCHAIN_BIN"/../lib*/sigchain/sigchain_mpi.so)
    local rel=${modules[0]#"$SIGCHAIN_BIN/../"}
    mkdir -p copy/bin "copy/$(dirname "$rel")"
    cp "$SIGCHAIN_BIN/trace" copy/bin/
    echo 'not a shared object' >"copy/$rel"
    local m="$PWD/copy/$rel"
    run -0 --separate-stderr copy/bin/trace -q $(inputs) -o one.img
    run --separate-stderr timeout 60 "$SIGCHAIN_MPIEXEC" --oversubscribe -np 2 \
        copy/bin/trace -q $(inputs) -o np2.img
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "status $status"
    # dlerror() follows: "PATH: file too short" here.
    [[ "$stderr" == *"trace: MPI: cannot load the MPI module $m: $m: "?* ]] ||
        fail "stderr: $stderr"
    [ ! -e np2.img ] && [ ! -e np2.hdr ]
    assert_no_temp_files .
}
