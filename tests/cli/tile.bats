# Tests: trace merge_tiles
# Also requires: (nothing else)
#
# trace --tile K/N renders the K-th of N equal parts of the rows and records its
# provenance (cube(5), Parts); merge_tiles checks the parts belong to one render and
# joins them bit for bit. The box scene of trace.bats: 16 x 16 pixels, 6 bands.

bats_require_minimum_version 1.5.0
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
GDB="$SEED/box_on_plane.gdb"

inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "$GDB" "${1:-$DATA/box.mat}" \
        "$DATA/band1.rad" "$DATA/band2.rad"
}

# Once for every test: the box render whole (one.img) and in three tiles (16 rows:
# 0:5, 5:10, 10:16), in $BATS_FILE_TMPDIR.
setup_file() {
    local k
    cd "$BATS_FILE_TMPDIR" || return 1
    trace -q $(inputs) -o one.img
    for k in 1 2 3; do
        trace -q $(inputs) --tile $k/3 -o "part$k.img"
    done
}

# The shared renders into the test's folder.
tiles() {
    cp "$BATS_FILE_TMPDIR"/one.* "$BATS_FILE_TMPDIR"/part?.* .
}

# merge_bad PREFIX ARGS...: exit 1, stderr "merge_tiles: PREFIX...", no whole.img.
merge_bad() {
    local prefix="$1"
    shift
    run -1 --separate-stderr merge_tiles "$@"
    assert_output ''
    [[ "$stderr" == "merge_tiles: $prefix"* ]] || fail "stderr: $stderr (wanted '$prefix...')"
    [ ! -e whole.img ] && [ ! -e whole.hdr ] || fail "a whole cube was written"
    assert_no_temp_files .
}

@test "merge_tiles --help and --version; a missing -o is a usage error" {
    run -0 --separate-stderr merge_tiles --help
    assert_line --index 0 --partial "Usage: merge_tiles "
    assert_equal "${lines[-1]}" "See merge_tiles(1)."
    run -0 --separate-stderr merge_tiles --version
    assert_output --partial "merge_tiles (sigchain) "
    run -2 --separate-stderr merge_tiles a.img
    run -2 --separate-stderr merge_tiles --bogus a.img -o b.img
}

@test "trace --tile 1/3, 2/3, 3/3 merged equal the one render byte for byte" {
    tiles
    # Rows floor((K-1) 16 / 3) to floor(K 16 / 3): 0:5, 5:10, 10:16.
    run -0 grep -x 'lines   = 5' part1.hdr
    run -0 grep -x 'lines   = 6' part3.hdr
    run -0 grep -x 'sigchain rows = 5:10 of 16' part2.hdr
    run -0 grep -x 'sigchain tile = 2/3' part2.hdr
    run -0 grep -E '^sigchain inputs = [0-9a-f]{64}$' part2.hdr
    # The tiles in any order; the whole cube records the untiled command (-o last), so
    # merged under the same name it is the same file, header included.
    # Their geolocation arrays (the box view is oblique) are found beside them.
    mkdir merged
    run -0 --separate-stderr merge_tiles part3.img part1.img part2.img -o merged/one.img
    assert_equal "$stderr" ''
    run -0 cmp merged/one.img one.img
    run -0 cmp merged/one.hdr one.hdr
    run -0 cmp merged/one.geoloc.tif one.geoloc.tif
    assert_no_temp_files merged
    # GeoTIFF parts too.
    run -0 --separate-stderr trace -q $(inputs) -o one.tif
    for k in 1 2; do
        run -0 --separate-stderr trace -q $(inputs) --tile $k/2 -o "p$k.tif"
    done
    run -0 --separate-stderr merge_tiles p2.tif p1.tif -o merged/one.tif
    run -0 cmp merged/one.tif one.tif
}

@test "merge_tiles joins truth cubes (their names are not options of the part)" {
    run -0 --separate-stderr trace -q $(inputs) --truth truth.img -o one.img
    for k in 1 2; do
        run -0 --separate-stderr trace -q $(inputs) --tile $k/2 --truth "t$k.img" -o "p$k.img"
    done
    run -0 --separate-stderr merge_tiles -v t1.img t2.img -o merged.img
    assert_equal "$stderr" "merge_tiles: merging 2 part(s) into 16 rows, 16 columns, 27 band(s)"
    run -0 cmp merged.img truth.img
    run -0 --separate-stderr merge_tiles p1.img p2.img -o whole.img
    run -0 cmp whole.img one.img
}

@test "trace --tile: bad values are usage errors" {
    for t in 0/3 4/3 3 a/b 1/0 -1/2; do
        run -2 --separate-stderr trace $(inputs) --tile "$t" -o out.img
        [[ "$stderr" == "trace: --tile: expected K/N"* ]] || fail "$t: $stderr"
    done
    run -2 --separate-stderr trace $(inputs) --tile 1/2 --rows 0:4 -o out.img
    assert_equal "$stderr" "trace: --rows and --tile cannot be given together
Try 'trace --help'."
    # More tiles than rows: tile 1 of 17 of 16 rows holds none.
    run -2 --separate-stderr trace $(inputs) --tile 1/17 -o out.img
    [[ "$stderr" == *"fewer than the tiles"* ]] || fail "$stderr"
    [ ! -e out.img ]
}

@test "merge_tiles refuses a part from another input or other options" {
    tiles
    # The same .mat beside an .ems that differs in a comment only: the files the .mat
    # names are inputs too.
    mkdir other
    cp "$DATA/box.mat" "$DATA/grass.ems" "$DATA/wood.ems" other/
    printf '# changed\n' >> other/wood.ems
    run -0 --separate-stderr trace -q $(inputs other/box.mat) --tile 2/3 -o other/part2.img
    merge_bad "other/part2.img: made from other inputs than part1.img" \
        part1.img other/part2.img part3.img -o whole.img
    run -0 --separate-stderr trace -q $(inputs) --seed 7 --tile 2/3 -o seed7.img
    merge_bad "seed7.img: made with other options than part1.img" \
        part1.img seed7.img part3.img -o whole.img
    # A render in one piece is not a part.
    merge_bad "one.img: not a part of a render" one.img part1.img -o whole.img
}

@test "merge_tiles refuses a missing or an overlapping part" {
    tiles
    merge_bad "part3.img: rows 5:10 are missing" part1.img part3.img -o whole.img
    merge_bad "part2.img: rows 10:16 are missing" part1.img part2.img -o whole.img
    run -0 --separate-stderr trace -q $(inputs) --rows 4:10 -o rows.img
    merge_bad "rows.img: rows 4:10 of 16 overlap rows 0:5 of 16 of part1.img" \
        part1.img rows.img part3.img -o whole.img
    # --rows parts that tile the image merge like --tile parts.
    run -0 --separate-stderr trace -q $(inputs) --rows 0:4 -o rows0.img
    run -0 --separate-stderr merge_tiles rows0.img rows.img part3.img -o whole.img
    run -0 cmp whole.img one.img
    # The output may not be a part.
    run -2 --separate-stderr merge_tiles part1.img part2.img part3.img -o part2.img
}
