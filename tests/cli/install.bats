#!/usr/bin/env bats
# Tests: make install (Makefile, CMakeLists.txt), sigchain-config, the scene Makefiles' SCENE_MK
# Also requires: pipelines/scene.mk, data/scenes/training, lib/core/data_dir.cpp
#
# The build is installed once into a scratch prefix (setup_file); a copy of the
# training scene outside the repository then runs with only that prefix's bin on
# PATH, as after `make install PREFIX=...`. `make install` itself is checked by a dry run
# (it must build the tools and pages only and run no package manager).

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
        bin/sensorize bin/compare bin/sigchain-check bin/sigchain-config bin/sigchain-atmosphere; do
        [ -x "$p/$f" ] || fail "$f is not installed"
    done
    for f in share/man/man1/trace.1 share/man/man1/sigchain-atmosphere.1 share/man/man5/snd.5 \
        share/man/man7/sigchain.7 \
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
        TRACE_FLAGS=-q THERM_FLAGS=-q CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q
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
        TRACE_FLAGS=-q THERM_FLAGS=-q CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q
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

@test "install: sigchain-atmosphere runs the build_radiance installed beside it" {
    # Only the installed bin on PATH: the stand-in LOWTRAN 7's TAPE7s become the tables.
    outside "$BATS_FILE_TMPDIR/prefix/bin/sigchain-atmosphere" -q \
        --program "$SIGCHAIN_SOURCE_DIR/tests/data/tape7/fake_lowtran7" \
        --sky-zenith-step 45 --sky-azimuth-step 90 "$SIGCHAIN_SOURCE_DIR/tests/golden/control7/hawkeye.cdk" \
        "$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance/small.snd" -o 'x-%d.rad'
    assert_success
    grep -q '^SIGCHAIN_RAD 1$' x-2.rad
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

@test "make install: builds only the tools and their pages and runs no package manager (dry run)" {
    local build
    build=$(cd "$SIGCHAIN_BIN/.." && pwd)
    run -0 --separate-stderr make -n --no-print-directory -C "$SIGCHAIN_SOURCE_DIR" install \
        BUILD="$build" PREFIX="$BATS_TEST_TMPDIR/p" JOBS=2
    refute_output --regexp 'install-deps|apt-get|apt |dpkg|sudo'
    # Every command is the build of the target `tools` or the installation.
    local line
    for line in "${lines[@]}"; do
        case "$line" in
            "cmake --build $build -j 2 --target tools" | "cmake --install $build --prefix $BATS_TEST_TMPDIR/p") ;;
            *) fail "make install would run: $line" ;;
        esac
    done
    assert_line "cmake --build $build -j 2 --target tools"
    assert_line "cmake --install $build --prefix $BATS_TEST_TMPDIR/p"
}

@test "make install: the target tools builds no test and no benchmark" {
    # What `tools` depends on, transitively, from the Makefile generator's target graph.
    local graph="$SIGCHAIN_BIN/../CMakeFiles/Makefile2"
    [ -f "$graph" ] || skip "not a Makefile build"
    run -0 awk '/^[^ \t#][^:]*\.dir\/all: [^ ]*\.dir\/all$/ { sub(/:$/, "", $1); dep[$1] = dep[$1] " " $2 }
        END { q[1] = "CMakeFiles/tools.dir/all"; n = 1; seen[q[1]] = 1
            for (i = 1; i <= n; i++) { k = split(dep[q[i]], d, " ")
                for (j = 1; j <= k; j++) if (!(d[j] in seen)) { seen[d[j]] = 1; q[++n] = d[j] } }
            for (i = 1; i <= n; i++) print q[i] }' "$graph"
    assert_line "CMakeFiles/trace.dir/all"
    assert_line "CMakeFiles/man.dir/all"
    refute_output --regexp '(^|/)(tests|bench)/|unit_|bench_|fuzz|cycles_export'
}

@test "make install: the installed tree holds no test or benchmark program" {
    local p="$BATS_FILE_TMPDIR/prefix" f name
    # Every program in bin is a tool with its section-1 page; every other binary is a
    # module in lib/sigchain.
    for f in "$p"/bin/*; do
        name=${f##*/}
        [ -f "$p/share/man/man1/$name.1" ] || fail "bin/$name has no man page: not a tool"
    done
    while IFS= read -r f; do
        case "$f" in
            "$p"/bin/* | "$p"/lib/sigchain/*.so) ;;
            *) fail "an executable outside bin and lib/sigchain: ${f#"$p"/}" ;;
        esac
    done < <(find "$p" -type f -perm -u+x)
    [ -z "$(find "$p" \( -name 'unit_*' -o -name 'bench_*' -o -name 'fuzz_*' \
        -o -name cycles_export -o -name '*.bats' -o -name '*_test' \) -print)" ] ||
        fail "test or benchmark files installed"
}
