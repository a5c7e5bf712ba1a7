# Tests: compare
# Also requires: lib/image (reads binary PNM through GDAL, ENVI for NaN pixels),
# tests/golden/compare/
#
# Images are made at test time with printf: binary PGM (P5, one band) and PPM (P6,
# three bands) hold exact 8-bit counts; an ENVI float32 file holds a NaN.

bats_require_minimum_version 1.5.0
load test_helper

# syn.pgm / ref.pgm: 2 rows x 4 columns; row 0 holds the five-point hand case of the
# unit tests (syn 10 20 30 40 | 50, ref 12 25 28 45 | 41 at row 1 column 0).
make_gray() {
    printf 'P5\n4 2\n255\n\012\024\036\050\062\001\002\003' >syn.pgm
    printf 'P5\n4 2\n255\n\014\031\034\055\051\001\002\003' >ref.pgm
    cat >pts.cpt <<'CPT'
# sigchain-cpt 1
# name syn_row syn_col ref_row ref_col radius description
a 0 0 0 0 0 darkest
b 0 1 0 1 0
c 0 2 0 2 0 roof
d 0 3 0 3 0
e 1 0 1 0 0 brightest
CPT
}

# rgb.ppm: 1 row x 5 columns, R 1..5, G 10..50, B 100 200 150 80 50; bgr.ppm the same
# with R and B swapped.
make_rgb() {
    printf 'P6\n5 1\n255\n\001\012\144\002\024\310\003\036\226\004\050\120\005\062\062' >rgb.ppm
    printf 'P6\n5 1\n255\n\144\012\001\310\024\002\226\036\003\120\050\004\062\062\005' >bgr.ppm
    printf '# sigchain-cpt 1\n' >row.cpt
    for i in 0 1 2 3 4; do printf 'p%s 0 %s 0 %s 0\n' "$i" "$i" "$i" >>row.cpt; done
}

@test "compare --help prints usage and points to compare(1)" {
    run -0 --separate-stderr compare --help
    assert_line --index 0 --partial "Usage: compare "
    assert_equal "${lines[-1]}" "See compare(1)."
}

@test "compare --version prints the tool name" {
    run -0 --separate-stderr compare --version
    assert_output --partial "compare (sigchain) "
}

@test "compare rejects an unknown option with exit 2" {
    run -2 --separate-stderr compare --no-such-option
    assert_output ''
    assert_equal "${stderr_lines[-1]}" "Try 'compare --help'."
}

@test "compare with a missing control-point file argument is bad usage (exit 2)" {
    make_gray
    run -2 --separate-stderr compare syn.pgm ref.pgm
    assert_output ''
}

@test "compare writes the golden text report (values, ranks, ROC, RMS, statistics, histograms)" {
    make_gray
    run -0 --separate-stderr compare --bins 4 syn.pgm ref.pgm pts.cpt
    assert_equal "$stderr" ""
    printf '%s\n' "$output" >report.txt
    assert_golden report.txt "$GOLDEN/compare/gray_report.txt"
}

@test "compare reads the control points from stdin" {
    make_gray
    run -0 --separate-stderr compare --bins 4 syn.pgm ref.pgm - <pts.cpt
    assert_line "ROC   0.9 (spearman)"
    assert_line "points     <stdin> (5 control points; rank 1 = lowest value)"
}

@test "compare --bands maps bands and adds the combined band; JSON golden" {
    make_rgb
    run -0 --separate-stderr compare --json --bins 2 --bands 3,2,1 rgb.ppm bgr.ppm row.cpt
    printf '%s\n' "$output" >report.json
    assert_golden report.json "$GOLDEN/compare/rgb_bands.json"
    run -0 python3 -c 'import json,sys; d=json.load(open("report.json")); print(d["bands"][3]["name"], d["bands"][3]["rms"], d["bands"][0]["roc"])'
    assert_output "combined 0 1"
}

@test "compare without --bands on swapped bands finds the tie-free anticorrelation" {
    make_rgb
    run -0 --separate-stderr compare rgb.ppm bgr.ppm row.cpt
    # R 1..5 against B 100 200 150 80 50 (ranks 3 5 4 2 1): sum d^2 = 4+9+1+4+16 = 34,
    # rho = 1 - 6*34/120 = -0.7.
    assert_line "ROC   -0.7 (spearman)"
}

@test "compare exits 0 within the thresholds and 1 outside them" {
    make_gray
    run -0 --separate-stderr compare --fail-rms 6 --fail-roc 0.9 syn.pgm ref.pgm pts.cpt
    run -1 --separate-stderr compare --fail-rms 5 syn.pgm ref.pgm pts.cpt
    assert_equal "$stderr" "compare: band 1: RMS 5.272570530585627 above --fail-rms 5"
    assert_line "RMS   5.27257"
    run -1 --separate-stderr compare --fail-roc 0.95 syn.pgm ref.pgm pts.cpt
    assert_equal "$stderr" "compare: band 1: ROC 0.9 below --fail-roc 0.95"
}

@test "compare: a control point outside an image is trouble (exit 2) naming FILE:LINE" {
    make_gray
    printf '# sigchain-cpt 1\na 0 0 0 0 0\nb 0 9 0 1 0\n' >out.cpt
    run -2 --separate-stderr compare -o report.txt syn.pgm ref.pgm out.cpt
    assert_equal "$stderr" "compare: out.cpt:3: control point 'b' of syn.pgm at row 0, column 9 lies outside the image (2 rows, 4 columns)"
    [ ! -e report.txt ]
    assert_no_temp_files
}

@test "compare: fewer than 2 control points is trouble (exit 2)" {
    make_gray
    printf '# sigchain-cpt 1\na 0 0 0 0 0\n' >one.cpt
    run -2 --separate-stderr compare syn.pgm ref.pgm one.cpt
    assert_output ''
    assert_equal "$stderr" "compare: one.cpt: only 1 control point: the rank-order correlation needs at least 2"
}

@test "compare: a malformed control-point file is trouble (exit 2) naming FILE:LINE" {
    make_gray
    printf '# sigchain-cpt 1\na 0 0 0 0 0\nb 0 x 0 1 0\n' >bad.cpt
    run -2 --separate-stderr compare syn.pgm ref.pgm bad.cpt
    assert_output ''
    assert_equal "$stderr" "compare: bad.cpt:3: expected synthetic column (pixels) (a number), found 'x'"
}

@test "compare: an unreadable image is trouble (exit 2)" {
    make_gray
    run -2 --separate-stderr compare missing.png ref.pgm pts.cpt
    assert_output ''
    assert_output --partial ''
    [[ "$stderr" == "compare: missing.png: "* ]]
}

@test "compare: NaN pixels are trouble (exit 2)" {
    printf 'ENVI\nsamples = 2\nlines = 1\nbands = 1\nheader offset = 0\nfile type = ENVI Standard\ndata type = 4\ninterleave = bsq\nbyte order = 0\n' >nan.hdr
    # float32 little-endian: 1.0, then a quiet NaN.
    printf '\000\000\200\077\000\000\300\177' >nan.img
    run -2 --separate-stderr compare --pixelwise nan.img nan.img
    assert_output ''
    assert_equal "$stderr" "compare: nan.img: NaN pixel at band 1, row 0, column 1"
}

@test "compare --pixelwise reports RMS, bias, maximum and relative error" {
    make_gray
    run -0 --separate-stderr compare --pixelwise syn.pgm ref.pgm
    # d = -2 -5 2 -5 | 9 0 0 0: sum d^2 = 139, RMS = sqrt(139/8) = 4.16833; bias -1/8.
    assert_line --regexp '^1 +1 +1 +4\.16833 +-0\.125 +9 +0\.0960898$'
}

@test "compare --pixelwise: a size mismatch is trouble (exit 2)" {
    make_gray
    make_rgb
    run -2 --separate-stderr compare --pixelwise syn.pgm rgb.ppm
    assert_output ''
    assert_equal "$stderr" "compare: rgb.ppm: size mismatch: 1 rows, 5 columns, but syn.pgm has 2 rows, 4 columns"
}

@test "compare --pixelwise --error-map writes synthetic - reference as a float image" {
    make_gray
    run -0 --separate-stderr compare --pixelwise --error-map err.tif syn.pgm ref.pgm
    [ -s err.tif ]
    assert_no_temp_files
    # The error map read back: it compares with itself at RMS 0, and its largest value
    # is the difference 9 (50 - 41) of row 1, column 0.
    run -0 --separate-stderr compare --pixelwise --fail-rms 0 err.tif err.tif
    run -0 --separate-stderr compare --pixelwise --json err.tif err.tif
    assert_output --partial '"max_abs": 0,'
    run -1 --separate-stderr compare --pixelwise --fail-rms 0 err.tif syn.pgm
    run -0 --separate-stderr compare --bins 2 err.tif err.tif pts.cpt
    assert_line --regexp '^e +9 +5 +9 +5$'
    assert_line "ROC   1 (tie-corrected)"  # -5 appears twice
}

@test "compare --pixelwise with --fail-rms exits 1 when the RMS exceeds it" {
    make_gray
    run -1 --separate-stderr compare --pixelwise --fail-rms 4 syn.pgm ref.pgm
    assert_equal "$stderr" "compare: band 1: RMS 4.168333000133266 above --fail-rms 4"
}

@test "compare --pixelwise --fail-max bounds the largest difference" {
    make_gray
    run -0 --separate-stderr compare --pixelwise --fail-max 9 syn.pgm ref.pgm
    run -1 --separate-stderr compare --pixelwise --fail-max 8.5 syn.pgm ref.pgm
    assert_equal "$stderr" "compare: band 1: largest difference 9 above --fail-max 8.5"
    run -2 --separate-stderr compare --fail-max 1 syn.pgm ref.pgm pts.cpt
}

@test "compare --plot writes one PNG histogram per band and combined" {
    make_rgb
    run -0 --separate-stderr compare --plot plots --bands 3,2,1 rgb.ppm bgr.ppm row.cpt
    for name in band1 band2 band3 combined; do
        [ -s "plots/histogram_$name.png" ] || fail "no plots/histogram_$name.png"
        run -0 od -An -c -N4 "plots/histogram_$name.png"
        assert_output --partial 'P   N   G'
    done
    assert_no_temp_files plots
}

@test "compare --plot draws with gnuplot: labelled axes, a legend, a script to redraw" {
    make_rgb
    run -0 --separate-stderr compare --plot plots --bands 3,2,1 rgb.ppm bgr.ppm row.cpt
    run -0 grep -c -e "set xlabel 'pixel value'" -e "set ylabel 'pixels per bin'" \
        -e "title 'reference'" -e "title 'synthetic'" plots/histogram_band1.gp
    assert_output 4
    run -0 grep -F "set title 'band 1: rgb.ppm band 1 against bgr.ppm band 3 (whole images)'" plots/histogram_band1.gp
    # The kept script redraws the same picture.
    gnuplot plots/histogram_band1.gp > again.png
    cmp again.png plots/histogram_band1.png
}

@test "compare --plot without gnuplot on PATH exits 2 (trouble) naming it and writes no PNG" {
    make_rgb
    mkdir bin
    ln -s "$(command -v compare)" bin/compare
    run -2 --separate-stderr /usr/bin/env PATH="$PWD/bin" compare --plot plots rgb.ppm bgr.ppm row.cpt
    assert_equal "$stderr" "compare: gnuplot: cannot run: No such file or directory (compare --plot draws with gnuplot: install gnuplot-nox)"
    [ ! -e plots/histogram_band1.png ]
}

@test "compare -o writes the report atomically" {
    make_gray
    run -0 --separate-stderr compare -o report.txt syn.pgm ref.pgm pts.cpt
    assert_output ''
    run -0 grep -c '^ROC ' report.txt
    assert_output 1
    assert_no_temp_files
}
