#!/usr/bin/env bats
# Tests: make install (CMakeLists.txt), sigchain-config, the scene Makefiles' SCENE_MK
# Also requires: pipelines/scene.mk, data/scenes/training, lib/core/data_dir.cpp
#
# The build is installed once into a scratch prefix (setup_file); a copy of the
# training scene outside the repository then runs with only that prefix's bin on
# PATH, as after `make install PREFIX=...`.

bats_require_minimum_version 1.5.0
load test_helper

setup_file() {
    : "${SIGCHAIN_SOURCE_DIR:=$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
    : "${SIGCHAIN_BIN:=$SIGCHAIN_SOURCE_DIR/build/bin}"
    cmake --install "$SIGCHAIN_BIN/.." --prefix "$BATS_FILE_TMPDIR/prefix" \
        > "$BATS_FILE_TMPDIR/install.log" 2>&1 || echo "install failed: $?" >> "$BATS_FILE_TMPDIR/install.log"
}

# outside ARGS...: run ARGS with the installed bin first on PATH and none of the
# variables that point the scene Makefiles at the repository or its build.
outside() {
    run env -u SIGCHAIN_SOURCE_DIR -u SIGCHAIN_BIN -u SCENE_MK \
        PATH="$BATS_FILE_TMPDIR/prefix/bin:/usr/bin:/bin" "$@"
}

@test "install: tools, sigchain-config, man pages, scene.mk and the data tables" {
    run -1 grep -q 'install failed' "$BATS_FILE_TMPDIR/install.log"
    local p="$BATS_FILE_TMPDIR/prefix" f
    for f in bin/control7 bin/build_radiance bin/find_min_max_view_angle bin/trace bin/therm \
        bin/sensorize bin/compare bin/sigchain-check bin/sigchain-config; do
        [ -x "$p/$f" ] || fail "$f is not installed"
    done
    for f in share/man/man1/trace.1 share/man/man5/snd.5 share/man/man7/sigchain.7 \
        share/sigchain/pipelines/scene.mk lib/sigchain/sigchain_oiio.so \
        share/sigchain/data/atmosphere/solar_lowtran7_extraterrestrial.txt \
        share/sigchain/data/atmosphere/lowtran7/aerosol_rural.txt; do
        [ -f "$p/$f" ] || fail "$f is not installed"
    done
    # A build with MPI loads Open MPI through its module under a launcher.
    if [ "${SIGCHAIN_MPI:-OFF}" = ON ]; then
        [ -f "$p/lib/sigchain/sigchain_mpi.so" ] || fail "sigchain_mpi.so is not installed"
    fi
}

@test "install: sigchain-config prints the installed folders and the version" {
    local p="$BATS_FILE_TMPDIR/prefix"
    outside sigchain-config --prefix --pipelines --datadir --version
    assert_success
    assert_output "$p
$p/share/sigchain/pipelines
$p/share/sigchain/data
$(sed -n 's/^project(sigchain VERSION \([0-9.]*\).*/\1/p' "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt")"
    outside sigchain-config --bogus
    [ "$status" -eq 2 ]
    assert_line "sigchain-config: unknown option '--bogus'"
    outside sigchain-config
    [ "$status" -eq 2 ]
}

@test "install: a scene folder copied anywhere runs with the installed tools" {
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" .
    rm -rf training/out
    outside make --no-print-directory -C training CONTROL7_FLAGS=-q BUILD_RADIANCE_FLAGS=-q \
        TRACE_FLAGS=-q THERM_FLAGS=-q CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q PREVIEW_FLAGS=-q
    assert_success
    # Every stage ran the installed program.
    assert_output --partial "$BATS_FILE_TMPDIR/prefix/bin/trace -q"
    refute_output --partial "$SIGCHAIN_BIN"
    local f
    for f in hawkeye.cdk training-1.rad training.shd training.tmp training.img \
        calibrated/green.sen training.tif training.png training.report; do
        [ -s "training/out/$f" ] || fail "out/$f was not made"
    done
    grep -q '(9 control points' training/out/training.report
    # A second make with the same options does nothing.
    outside make -q -C training CONTROL7_FLAGS=-q BUILD_RADIANCE_FLAGS=-q \
        TRACE_FLAGS=-q THERM_FLAGS=-q CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q PREVIEW_FLAGS=-q
    assert_success
}

@test "install: without sigchain-config on PATH a copied scene says where scene.mk is looked for" {
    cp -R "$SIGCHAIN_SOURCE_DIR/data/scenes/training" .
    run -2 env -u SIGCHAIN_SOURCE_DIR -u SIGCHAIN_BIN PATH=/usr/bin:/bin make -C training
    assert_output --partial 'no scene.mk: put an installed'
    # SCENE_MK names it directly.
    run -0 env -u SIGCHAIN_SOURCE_DIR PATH=/usr/bin:/bin make -C training help \
        SCENE_MK="$SIGCHAIN_SOURCE_DIR/pipelines/scene.mk"
    assert_output --partial 'SIGCHAIN_BIN'
}

@test "install: an installed tool reads the data installed beside it" {
    # A prefix whose data folder lacks the tables: build_radiance names the folder it
    # chose, not the build's data/.
    mkdir -p p/bin p/share/sigchain/data
    cp "$BATS_FILE_TMPDIR/prefix/bin/build_radiance" p/bin/
    local snd="$SIGCHAIN_SOURCE_DIR/data/scenes/training/training.snd"
    run -1 --separate-stderr env -u SIGCHAIN_DATA p/bin/build_radiance -q "$SEED/flyover.cdk" \
        "$snd" -o 'x-%d.rad'
    assert_output ''
    [[ "$stderr" == *"in $PWD/p/share/sigchain/data/atmosphere" ]] || fail "stderr: $stderr"
    # Without that folder (a program outside an installed tree) the build's data/ serve.
    rmdir p/share/sigchain/data
    run -0 env -u SIGCHAIN_DATA p/bin/build_radiance -q "$SEED/flyover.cdk" "$snd" -o 'x-%d.rad'
    [ -s x-3.rad ]
}
