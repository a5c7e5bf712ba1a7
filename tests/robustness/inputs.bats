#!/usr/bin/env bats
# Tests: every text input of every tool against bad inputs: a directory, /dev/zero,
# an empty file, a NUL byte, a 100-MB line (sigchain(7), Text files), and NaN or
# 1e300 numbers where a reader must refuse them. Each run must exit 1 with
# "TOOL: FILE:LINE: ..." or "TOOL: FILE: ..." on stderr, leave no output and no
# temporary file, and finish within 10 s under a 2 GiB address-space limit.
# Also requires: tests/data/{white1996,trace,therm,cube}, data/scenes/training, data/brdf

load ../cli/test_helper
bats_require_minimum_version 1.5.0

T="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
TH="$SIGCHAIN_SOURCE_DIR/tests/data/therm"
CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"
TRAIN="$SIGCHAIN_SOURCE_DIR/data/scenes/training"
GDB="$SEED/box_on_plane.gdb"
ODB="$SEED/neighbourhood.odb"

setup_file() {
    # The 100-MB line (no newline), made once for the whole file.
    head -c 100000000 /dev/zero | tr '\0' a > "$BATS_FILE_TMPDIR/long"
}

# The command lines that read a file of format $1, with @ where that file goes.
readers() {
    local rad="$T/band1.rad $T/band2.rad"
    case "$1" in
        adv) echo "trace @ $T/box.snd $GDB $T/box.mat $rad -o out.img"
             echo "find_min_max_view_angle @ $GDB" ;;
        snd) echo "trace $T/box.adv @ $GDB $T/box.mat $rad -o out.img"
             echo "therm $SEED/box_on_plane.shd $SEED/weather_30_Sep_95.wth $TH/box_on_plane.mat $GDB @ -o out.tmp"
             echo "build_radiance $SEED/flyover.cdk @ -o out-%d.rad" ;;
        gdb | odb)
             echo "trace $T/box.adv $T/box.snd @ $T/box.mat $rad -o out.img"
             echo "trace --shadow-history $T/box.snd @ $T/box.mat -o out.shd"
             echo "find_min_max_view_angle $T/box.adv @"
             echo "therm $SEED/box_on_plane.shd $SEED/weather_30_Sep_95.wth $TH/box_on_plane.mat @ $SEED/hawkeye.snd -o out.tmp" ;;
        mat) echo "trace $T/box.adv $T/box.snd $GDB @ $rad -o out.img"
             echo "therm $SEED/box_on_plane.shd $SEED/weather_30_Sep_95.wth @ $GDB $SEED/hawkeye.snd -o out.tmp" ;;
        ems) echo "trace $T/box.adv $T/box.snd $GDB ems.mat $rad -o out.img" ;;
        ext) echo "trace $T/box.adv $T/box.snd $GDB ext.mat $rad -o out.img" ;;
        rad) echo "trace $T/box.adv $T/box.snd $GDB $T/box.mat @ $T/band2.rad -o out.img" ;;
        tmp) echo "trace $T/box.adv $T/box.snd $GDB $T/box.mat $rad --tmp @ -o out.img" ;;
        shd) echo "therm @ $SEED/weather_30_Sep_95.wth $TH/box_on_plane.mat $GDB $SEED/hawkeye.snd -o out.tmp" ;;
        wth) echo "therm $SEED/box_on_plane.shd @ $TH/box_on_plane.mat $GDB $SEED/hawkeye.snd -o out.tmp" ;;
        cdk) echo "build_radiance @ $SEED/hawkeye.snd -o out-%d.rad" ;;
        sen) echo "sensorize $CUBE/tiny.img @ $CUBE/green1.sen $CUBE/red1.sen -o out.ppm" ;;
        cpt) echo "compare $TRAIN/reference.tif $TRAIN/reference.tif @" ;;
    esac
    echo "sigchain-check @"
}

# A .mat whose first emissivity (or extinction) file is $2, for the formats a .mat names.
material_naming() {
    cp "$T/wood.ems" "$T/grass.ems" "$T/glass.ext" .
    case "$1" in
        ems) sed "s|= grass.ems|= $2|" "$T/box.mat" > ems.mat ;;
        ext) sed "s|= glass.ext|= $2|" "$T/transmissive.mat" > ext.mat ;;
    esac
}

# expect_refused FORMAT FILE PATTERN: every reader of FORMAT refuses FILE with exit 1
# (2 for compare, which follows cmp(1)), "TOOL: FILE[:LINE]: " then PATTERN on
# stderr, nothing written and nothing half-written.
expect_refused() {
    local format="$1" file="$2" pattern="$3" line tool want lines
    material_naming "$format" "$file"
    mapfile -t lines < <(readers "$format")
    for line in "${lines[@]}"; do
        tool="${line%% *}"
        want=1
        [ "$tool" = compare ] && want=2
        # shellcheck disable=SC2086
        run --separate-stderr bash -c "ulimit -v 2097152; exec timeout 10 ${line//@/$file}"
        if [ "$status" -ne "$want" ]; then
            echo "$line: exit $status, wanted $want; stderr: $stderr"
            return 1
        fi
        local where
        case "$format" in ems | ext) where=".*$file" ;; *) where="$file" ;; esac
        if ! [[ "$stderr" =~ ^$tool:\ ([^\ ]*: )?$where(:[0-9]+)?:\ .*$pattern ]]; then
            echo "$line: stderr: $stderr"
            echo "wanted: $tool: $file[:LINE]: ...$pattern"
            return 1
        fi
        run find . -maxdepth 1 -name 'out*'
        assert_output ''
        assert_no_temp_files .
    done
}

FORMATS="adv snd gdb odb mat ems ext rad tmp shd wth cdk sen cpt rsd brdf"

@test "a directory is named as a directory by every reader" {
    for f in $FORMATS; do
        mkdir "dir.$f"
        expect_refused "$f" "$PWD/dir.$f" "is a directory"
    done
}

@test "/dev/zero is binary data at line 1 for every reader, at once" {
    for f in $FORMATS; do
        ln -s /dev/zero "zero.$f"
        expect_refused "$f" "$PWD/zero.$f" "binary data \(NUL byte\)"
    done
}

@test "an empty file is refused by every reader" {
    for f in $FORMATS; do
        : > "empty.$f"
        expect_refused "$f" "$PWD/empty.$f" ""
    done
}

@test "a NUL byte is binary data at its line for every reader" {
    for f in $FORMATS; do
        printf 'first line\nsecond\0line\n' > "nul.$f"
        expect_refused "$f" "$PWD/nul.$f" "binary data \(NUL byte\)"
    done
}

@test "a 100-MB line is refused at line 1 by every reader, without reading it whole" {
    for f in $FORMATS; do
        ln -s "$BATS_FILE_TMPDIR/long" "long.$f"
        expect_refused "$f" "$PWD/long.$f" "line longer than 1048576 bytes"
    done
}

# --- NaN and 1e300 --------------------------------------------------------------------
@test "NaN in an .adv is refused with its line" {
    { echo "# a comment first"; grep -v '^#' "$T/box.adv" | sed '1s/^[^ \t]*/nan/'; } > nan.adv
    expect_refused adv "$PWD/nan.adv" "expected target point x \(a finite number\), found 'nan'"
}

@test "1e300 in a .gdb vertex is refused by the reader with the documented range" {
    awk '/^FACE$/ {f=1} f && /^[34]$/ && !done {print; getline; print "1e300 0 0"; done=1; next} {print}' \
        "$GDB" > far.gdb
    expect_refused gdb "$PWD/far.gdb" "expected vertex coordinates within \+-1e\+08, found 1e\+300"
}

@test "an .odb scale of 1e300 is refused at its line" {
    cp "$SEED"/*.gdb .
    sed 's/^\( *\)0,0,0, 1,1,1, 0,0,0/\10,0,0, 1e300,1,1, 0,0,0/' "$ODB" > big.odb
    grep -q 1e300 big.odb
    expect_refused odb "$PWD/big.odb" "expected scale factors sx,sy,sz of magnitude"
}

@test "MATERIAL_ID = 1000000000000 is refused by the .mat reader" {
    sed '0,/MATERIAL_ID *=.*/s//MATERIAL_ID = 1000000000000/' "$T/box.mat" > huge.mat
    cp "$T/wood.ems" "$T/grass.ems" .
    expect_refused mat "$PWD/huge.mat" "expected MATERIAL_ID from 0 to 16777216"
}

@test "NaN in a .tmp temperature is refused with its line" {
    printf '# sigchain-tmp 1\n1-1-1 nan\n' > nan.tmp
    expect_refused tmp "$PWD/nan.tmp" "expected temperature \(K\) \(a finite number\), found 'nan'"
}

# --- Named pipes and standard input -----------------------------------------------------
@test "a pipe on standard input is read to its end like a file" {
    run -0 --separate-stderr sigchain-check -f adv - < <(cat "$T/box.adv")
    assert_output --partial "-: ok:"
}

@test "an endless pipe of NUL bytes on standard input is refused at once" {
    run -1 --separate-stderr bash -c "ulimit -v 2097152; timeout 10 sigchain-check -f gdb - < /dev/zero"
    assert_equal "$stderr" "sigchain-check: <stdin>:1: binary data (NUL byte); expected a text file"
}

# --- Line numbers of errors found after reading ------------------------------------------
@test "the .adv azimuth error names the file line of the angles, comments included" {
    printf '# comment\n# another\n0 10 0\n0 0 0\n\n0 0 0  # angles\n40\n8 8\n' > along.adv
    run -1 --separate-stderr trace along.adv "$T/box.snd" "$GDB" "$T/box.mat" \
        "$T/band1.rad" "$T/band2.rad" -o out.img
    [[ "$stderr" == "trace: along.adv:6: camera azimuth "*"points along the line of sight"* ]] ||
        { echo "stderr: $stderr"; return 1; }
    run -1 --separate-stderr find_min_max_view_angle along.adv "$GDB"
    [[ "$stderr" == "find_min_max_view_angle: along.adv:6: camera azimuth "* ]] ||
        { echo "stderr: $stderr"; return 1; }
}

@test "a .gdb with a facet id used twice is refused by every reader, naming both lines" {
    # The second FACE takes the first FACE's id.
    first=$(awk '/^FACE$/ {getline; getline; print; exit}' "$GDB")
    second_line=$(awk '/^FACE$/ {c++; if (c == 2) {print NR + 2; exit}}' "$GDB")
    first_line=$(awk '/^FACE$/ {print NR + 2; exit}' "$GDB")
    awk -v l="$second_line" -v id="$first" 'NR == l {print id; next} {print}' "$GDB" > twice.gdb
    expect_refused gdb "$PWD/twice.gdb" "facet id $first already used at line $first_line"
}

@test "coincident .odb instances are warned about with their lines" {
    cp "$SEED/box_on_plane.gdb" .
    printf 'OBJECT {\n    GDB_FILENAME = box_on_plane.gdb\n    UNITS = m\n    INSTANCES {\n        0,0,0, 1,1,1, 0,0,0\n        0,0,0, 1,1,1, 0,0,0\n    }\n}\n' > twice.odb
    run -0 --separate-stderr trace "$T/box.adv" "$T/box.snd" twice.odb "$T/box.mat" \
        "$T/band1.rad" "$T/band2.rad" -o out.img
    [[ "$stderr" == *"twice.odb:5: 1 more instance(s) of the same object with the same placement (line 6)"* ]] ||
        { echo "stderr: $stderr"; return 1; }
}

# The side files GDAL reads with a raster (geo::check_sidecars): /dev/zero as a DEM's
# .prj or a cube's ENVI .hdr had cost 12-22 s and 2 GB; a directory or an oversized
# side file is refused at once, naming it.
@test "a raster's side files: /dev/zero, a directory or a huge file is refused, naming it" {
    # An ESRI ASCII grid DEM and its .prj.
    printf 'ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 30\n1 2 3\n4 5 6\n7 8 9\n' > dem.asc
    printf '1 all\n' > all.classes
    ln -s /dev/zero dem.prj
    run -1 --separate-stderr timeout 10 landsat_scene classify all.classes - c.tif dem.asc
    [[ "$stderr" == "landsat_scene: dem.prj: not a regular file (a side file GDAL would read with dem.asc)" ]]
    [ ! -e c.tif ]
    rm dem.prj && mkdir dem.prj
    run -1 --separate-stderr timeout 10 landsat_scene classify all.classes - c.tif dem.asc
    [[ "$stderr" == "landsat_scene: dem.prj: not a regular file"* ]]
    rmdir dem.prj && truncate -s 17M dem.prj
    run -1 --separate-stderr timeout 10 landsat_scene classify all.classes - c.tif dem.asc
    [[ "$stderr" == "landsat_scene: dem.prj: 17825792 bytes: larger than a side file of dem.asc may be (16 MiB)" ]]
    # An ENVI cube whose header is /dev/zero.
    cp "$CUBE/tiny.img" .
    ln -s /dev/zero tiny.hdr
    # (compare follows cmp and diff: trouble is exit 2.)
    run -2 --separate-stderr timeout 10 compare --pixelwise tiny.img tiny.img
    [[ "$stderr" == "compare: tiny.hdr: not a regular file"* ]]
    run -1 --separate-stderr timeout 10 sensorize tiny.img "$CUBE/blue.sen" -o t.tif
    [[ "$stderr" == "sensorize: tiny.hdr: not a regular file"* ]]
    [ ! -e t.tif ]
    assert_no_temp_files .
}
