# Tests: trace, merge_tiles, sensorize, build_radiance (the write path under faults)
# Also requires: tests/data/trace, tests/data/white1996, tests/data/cube, strace
#
# Faults injected with strace -e inject into the system calls that write and rename
# outputs: every run that meets a full disk (ENOSPC at its N-th write) exits non-zero,
# naming the output, and leaves no output and no temporary; the first N past the
# run's writes gives the clean output byte for byte. A rename that fails (EXDEV) leaves
# the previous outputs exactly as they were. SIGTERM at the moment a temporary is
# created leaves none, and what a SIGKILL leaves is removed by the next run.
# Every case skips without strace (scripts/install-deps installs it).

bats_require_minimum_version 1.5.0
load ../cli/test_helper

TRACE="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"

setup_file() {
    mkdir -p "$BATS_FILE_TMPDIR/bin"
    # small_trace ARGS...: the box scene at one sample per pixel (16 x 16, 6 bands).
    {
        echo '#!/bin/sh'
        echo "exec trace -q --threads 1 --samples-per-pixel 1 '$TRACE/box.adv' '$TRACE/box.snd' \\"
        echo "    '$SEED/box_on_plane.gdb' '$TRACE/box.mat' '$TRACE/band1.rad' '$TRACE/band2.rad' \"\$@\""
    } >"$BATS_FILE_TMPDIR/bin/small_trace"
    # plain_trace ARGS...: the same, not georeferenced (--crs none): the cube alone.
    printf '#!/bin/sh\nexec small_trace --crs none "$@"\n' >"$BATS_FILE_TMPDIR/bin/plain_trace"
    chmod +x "$BATS_FILE_TMPDIR/bin/small_trace" "$BATS_FILE_TMPDIR/bin/plain_trace"
}

setup() {
    command -v strace >/dev/null || skip "no strace (scripts/install-deps installs it)"
    cd "$BATS_TEST_TMPDIR" || return 1
    export PATH="$BATS_FILE_TMPDIR/bin:$PATH"
}

# full_disk_sweep CLEAN OUTPUT... -- CMD...: runs CMD with the N-th write failing with
# ENOSPC, N = 1, 2, ... until a run exits 0; every earlier run must exit 1 with an
# error naming an OUTPUT (the one being written: a georeferenced cube's geolocation
# arrays are part of it) and leave no OUTPUT and no temporary; the run that
# exits 0 must give every OUTPUT as in the folder CLEAN. Prints the number of faults.
full_disk_sweep() {
    local clean="$1" outputs=() n f named
    shift
    while [ "$1" != -- ]; do outputs+=("$1"); shift; done
    shift
    for n in $(seq 1 60); do
        run --separate-stderr strace -f -o /dev/null -e inject=write:error=ENOSPC:when=$n "$@"
        if [ "$status" = 0 ]; then
            for f in "${outputs[@]}"; do
                cmp "$f" "$clean/$f" || fail "write $n failed, exit 0, $f differs from a clean run"
            done
            assert_no_temp_files .
            echo "$((n - 1))"
            return 0
        fi
        [ "$status" = 1 ] || fail "write $n failed: exit $status ($stderr)"
        named=
        for f in "${outputs[@]}"; do [[ "$stderr" == *": $f: "* ]] && named=$f; done
        [ -n "$named" ] || fail "write $n failed: the error names none of ${outputs[*]}: $stderr"
        for f in "${outputs[@]}"; do
            [ ! -e "$f" ] || fail "write $n failed: $f was left behind"
        done
        assert_no_temp_files .
    done
    fail "still failing after 60 faults"
}

@test "trace on a full disk: every failed write is an error, ENVI and GeoTIFF alike" {
    mkdir clean
    (cd clean && small_trace -o c.img && small_trace -o c.tif)
    # Before the read-back, the ENVI cube came out with 1024 zero bytes and exit 0.
    # The box view is oblique: its geolocation arrays go with the cube, its header (13
    # KiB with the ground control points) is read back as GDAL 3.6 writes it silently.
    run -0 full_disk_sweep clean c.img c.hdr c.geoloc.tif -- small_trace -o c.img
    [ "$output" -ge 16 ] || fail "only $output writes were faulted"
    rm c.img c.hdr c.geoloc.tif
    run -0 full_disk_sweep clean c.tif c.geoloc.tif -- small_trace -o c.tif
    [ "$output" -ge 14 ] || fail "only $output writes were faulted"
    # Not georeferenced: the cube alone.
    rm -r clean && mkdir clean
    (cd clean && plain_trace -o c.img)
    rm c.tif c.geoloc.tif
    run -0 full_disk_sweep clean c.img c.hdr -- plain_trace -o c.img
    [ "$output" -ge 8 ] || fail "only $output writes were faulted"
    [ ! -e c.geoloc.tif ]
}

@test "trace's GeoTIFF rows on a full disk: the scratch file they wait in fails as an error" {
    # A GeoTIFF's rows wait in a raw file beside it (pwrite) until its bands are
    # written one after the other; a failed write there ends the run like any other.
    local n
    for n in 1 2 40 100; do
        run -1 --separate-stderr strace -f -o /dev/null -e inject=pwrite64:error=ENOSPC:when=$n \
            small_trace -o c.tif --truth t.tif
        [[ "$stderr" == *": c.tif: write error: No space left on device" ||
            "$stderr" == *": t.tif: write error: No space left on device" ]] ||
            fail "pwrite $n: $stderr"
        [ ! -e c.tif ] && [ ! -e t.tif ] && [ ! -e c.geoloc.tif ] || fail "pwrite $n: output left"
        assert_no_temp_files .
    done
}

@test "merge_tiles on a full disk, and parts whose size disagrees with their header" {
    local k
    for k in 1 2 3; do small_trace --tile $k/3 -o part$k.img; done
    mkdir clean
    merge_tiles part1.img part2.img part3.img -o clean/w.img
    run -0 full_disk_sweep clean w.img w.hdr w.geoloc.tif -- \
        merge_tiles part1.img part2.img part3.img -o w.img
    [ "$output" -ge 16 ]
    # A part cut short (a copy interrupted) merged before with zeros in its place.
    cp part2.img whole2.img
    truncate -s 1024 part2.img
    run -1 --separate-stderr merge_tiles part1.img part2.img part3.img -o m.img
    assert_equal "$stderr" "merge_tiles: part2.img: the file holds 1024 bytes, but its header describes 1920 (5 rows x 16 columns x 6 bands x 4 bytes): truncated"
    [ ! -e m.img ] && [ ! -e m.hdr ]
    # More data than the header describes (a header of another cube) is refused too.
    cp whole2.img part2.img
    printf 'x' >>part2.img
    run -1 --separate-stderr merge_tiles part1.img part2.img part3.img -o m.img
    assert_equal "$stderr" "merge_tiles: part2.img: the file holds 1921 bytes, but its header describes 1920 (5 rows x 16 columns x 6 bands x 4 bytes): more data than the header describes"
    # Every reader of cubes makes the same check (sensorize here).
    run -1 --separate-stderr sensorize part2.img "$CUBE/red.sen" -o s.png
    assert_output ''
    [[ "$stderr" == "sensorize: part2.img: the file holds 1921 bytes"* ]]
}

@test "sensorize on a full disk: no PNG with exit 0 (OpenImageIO's writer is read back)" {
    mkdir clean
    sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o clean/s.png
    run -0 full_disk_sweep clean s.png -- \
        sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o s.png
    [ "$output" -ge 1 ]
}

@test "a rename that fails (EXDEV) leaves the previous ENVI cube exactly as it was" {
    # Not georeferenced (--crs none): the renames of the ENVI pair alone.
    mkdir old
    (cd old && plain_trace -o c.img)
    local n
    # Moving the old header aside, the old data, renaming the new data, the new header.
    for n in 1 2 3 4; do
        cp old/c.img old/c.hdr .
        run -1 --separate-stderr strace -f -o /dev/null -e inject=rename:error=EXDEV:when=$n \
            plain_trace --seed 7 -o c.img
        [[ "$stderr" == *"Invalid cross-device link" ]] || fail "rename $n: $stderr"
        cmp c.img old/c.img && cmp c.hdr old/c.hdr || fail "rename $n failed: the old cube changed"
        assert_no_temp_files .
    done
    # Every rename from the first new one on fails: the old files cannot come back
    # either, and the error says where each is.
    cp old/c.img old/c.hdr .
    run -1 --separate-stderr strace -f -o /dev/null -e inject=rename:error=EXDEV:when=3+ \
        plain_trace --seed 7 -o c.img
    assert_regex "$stderr" "the previous c.img is kept as (c.img.tmp.[A-Za-z0-9]{6}); the previous c.hdr is kept as (c.hdr.tmp.[A-Za-z0-9]{6})$"
    local kept_img kept_hdr
    kept_img=$(echo "$stderr" | sed -n 's/.*c.img is kept as \(c.img.tmp.[A-Za-z0-9]*\);.*/\1/p')
    kept_hdr=$(echo "$stderr" | sed -n 's/.*c.hdr is kept as \(c.hdr.tmp.[A-Za-z0-9]*\)$/\1/p')
    cmp "$kept_img" old/c.img && cmp "$kept_hdr" old/c.hdr
    # The next run takes them for a killed run's litter and removes them.
    run -0 plain_trace --seed 7 -o c.img
    assert_no_temp_files .
}

@test "SIGTERM as a temporary is created leaves no temporary" {
    local call
    # mkdir: GDAL's private folder (ENVI, GeoTIFF); openat: every file, mkostemp's too.
    for call in mkdir openat; do
        run strace -f -o /dev/null -e inject=$call:signal=TERM:when=1+ small_trace -o c.img
        assert_equal "$status" 143
        assert_no_temp_files .
        [ ! -e c.img ]
        run strace -f -o /dev/null -e inject=$call:signal=TERM:when=1+ \
            sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o s.png
        assert_equal "$status" 143
        assert_no_temp_files .
    done
}

@test "what a SIGKILL leaves is removed by the next run writing the same output" {
    plain_trace -o c.img
    run env SIGCHAIN_TEST_KILL_AT_RENAME=3 plain_trace --seed 3 -o c.img
    assert_equal "$status" 137
    # The new data's folder and the two old files moved aside.
    [ "$(find . -name '*.tmp.*' | wc -l)" = 3 ]
    # A symbolic link and other names are left alone.
    ln -s c.img c.img.tmp.AAAAAA
    touch c.img.tmp.toolong1 d.img.tmp.BBBBBB
    run -0 plain_trace --seed 4 -o c.img
    run find . -name '*.tmp.*'
    assert_equal "$(echo "$output" | sort | tr '\n' ' ')" "./c.img.tmp.AAAAAA ./c.img.tmp.toolong1 ./d.img.tmp.BBBBBB "
}
