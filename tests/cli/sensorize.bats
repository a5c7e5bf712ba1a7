#!/usr/bin/env bats
# Tests: sensorize
# Also requires: tests/data/cube/* (hand-made ENVI cubes and .sen files),
# tests/data/bad/sen/not_number.sen, tests/golden/sensorize/*
load test_helper

CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"

# tiny.img: 2 rows x 3 columns, samples at 0.45 0.5 0.55 0.6 um; sample k of pixel p
# (row-major, 0-based) is (0.001, 0.003, 0.002, 0.004)[k] * (p + 1).
# blue.sen: samples 1-2, R = 1, 3, gain 10000, bias 5:
#   L = (0.001 + 3 * 0.003) / 4 * (p + 1) = 0.0025 (p + 1) -> 30 55 80 105 130 155.
# green1.sen: sample 3, gain 10000: 20 40 60 80 100 120.
# red1.sen: sample 4, gain 20000: 80 160 240 320 400 480 -> 255 from pixel 3 on.

@test "--help prints usage to stdout and exits 0" {
    run -0 --separate-stderr sensorize --help
    assert_output --partial "Usage: sensorize"
    assert_equal "${lines[-1]}" "See sensorize(1)."
    assert_equal "$stderr" ""
}

@test "--version prints the version and exits 0" {
    run -0 --separate-stderr sensorize --version
    assert_output --regexp '^sensorize \(sigchain\) [0-9]+\.[0-9]+\.[0-9]+$'
}

@test "unknown option exits 2" {
    run -2 --separate-stderr sensorize --no-such-option
    assert_output ''
    assert_equal "${stderr##*$'\n'}" "Try 'sensorize --help'."
}

@test "bad --bits and a missing -o exit 2" {
    run -2 --separate-stderr sensorize --bits 10 "$CUBE/tiny.img" "$CUBE/red.sen" -o out.png
    [[ "$stderr" == *"--bits must be 8, 12 or 16"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize "$CUBE/tiny.img" "$CUBE/red.sen"
    [[ "$stderr" == *"give -o FILE"* ]] || fail "stderr: $stderr"
    [ ! -e out.png ]
}

@test "three bands: golden counts, saturation reported per band" {
    run -0 --separate-stderr sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/green1.sen" \
        "$CUBE/red1.sen" -o out.ppm
    assert_output ''
    assert_equal "$stderr" \
        "sensorize: warning: band 3 ($CUBE/red1.sen): 3 of 6 pixels clipped (0 low, 3 high)"
    assert_golden out.ppm "$GOLDEN/sensorize/tiny_8bit.ppm"
    assert_no_temp_files .
}

@test "-v reports every band; a band that fits is not a warning" {
    run -0 --separate-stderr sensorize -v "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o out.png
    assert_equal "${stderr_lines[0]}" \
        "sensorize: band 1 ($CUBE/blue.sen): 0 of 6 pixels clipped (0 low, 0 high)"
    [[ "$stderr" == *"warning: band 2 ($CUBE/red.sen): 2 of 6 pixels clipped (0 low, 2 high)"* ]] ||
        fail "stderr: $stderr"
    [ -s out.png ]
}

@test "a .sen read from standard input" {
    run -0 --separate-stderr sensorize "$CUBE/tiny.img" - "$CUBE/green1.sen" "$CUBE/red1.sen" \
        -o out.ppm < "$CUBE/blue.sen"
    assert_golden out.ppm "$GOLDEN/sensorize/tiny_8bit.ppm"
}

@test ".sen sample counts that do not fit the cube: exit 1 naming both files, no output" {
    run -1 --separate-stderr sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.png
    assert_equal "$stderr" \
        "sensorize: $CUBE/tiny.img: 4 bands, but the .sen files ($CUBE/blue.sen) have 2 response samples in all"
    run -1 --separate-stderr sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" \
        "$CUBE/red1.sen" -o out.png
    assert_equal "$stderr" \
        "sensorize: $CUBE/red1.sen:1: 1 response samples, but $CUBE/tiny.img has 0 bands left for this band (4 in all)"
    [ ! -e out.png ]
    assert_no_temp_files .
}

@test "a malformed .sen exits 1 naming FILE:LINE" {
    run -1 --separate-stderr sensorize "$CUBE/tiny.img" "$BAD/sen/not_number.sen" "$CUBE/red.sen" -o out.png
    assert_equal "$stderr" "sensorize: $BAD/sen/not_number.sen:3: expected bias (a number), found 'zero'"
    [ ! -e out.png ]
}

@test "a missing cube exits 1" {
    run -1 --separate-stderr sensorize absent.img "$CUBE/red.sen" -o out.png
    [[ "$stderr" == "sensorize: absent.img: cannot open"* ]] || fail "stderr: $stderr"
}

@test "four one-sample bands go into one PNG" {
    printf '1\n1000\n0\n1\n' > one.sen
    run -0 --separate-stderr sensorize "$CUBE/tiny.img" one.sen one.sen one.sen one.sen -o out.png
    [ -s out.png ]
    assert_no_temp_files .
}

@test "noise is reproducible with a seed and --float writes a TIFF" {
    run -0 --separate-stderr sensorize --shot-noise 2 --read-noise 1 --seed 4 --psf-sigma 0.7 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/green1.sen" "$CUBE/red1.sen" -o a.ppm
    run -0 --separate-stderr sensorize --shot-noise 2 --read-noise 1 --seed 4 --psf-sigma 0.7 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/green1.sen" "$CUBE/red1.sen" -o b.ppm
    cmp a.ppm b.ppm
    run -0 --separate-stderr sensorize --float "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o f.tif
    [ -s f.tif ]
    run -2 --separate-stderr sensorize --float "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o f.png
}

@test "--noise-seed is a deprecated alias of --seed; the default seed is 0" {
    local noisy=(--shot-noise 2 --read-noise 1 "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/green1.sen"
        "$CUBE/red1.sen")
    run -0 --separate-stderr sensorize "${noisy[@]}" --seed 4 -o new.ppm
    run -0 --separate-stderr sensorize "${noisy[@]}" --noise-seed 4 -o old.ppm
    assert_equal "${stderr_lines[0]}" "sensorize: warning: --noise-seed is deprecated: use --seed"
    cmp new.ppm old.ppm
    run -0 --separate-stderr sensorize "${noisy[@]}" -o default.ppm
    run -0 --separate-stderr sensorize "${noisy[@]}" --seed 0 -o zero.ppm
    cmp default.ppm zero.ppm
    ! cmp -s default.ppm new.ppm || fail "seeds 0 and 4 gave the same noise"
    run -2 --separate-stderr sensorize "${noisy[@]}" --seed 4 --noise-seed 4 -o both.ppm
    [[ "$stderr" == *"give --seed or --noise-seed, not both"* ]] || fail "stderr: $stderr"
    [ ! -e both.ppm ]
}

@test "--psf reads a kernel file; a bad one exits 1 naming FILE:LINE" {
    printf '# box\n1 3\n1 1 1\n' > box.psf
    run -0 --separate-stderr sensorize --psf box.psf "$CUBE/tiny.img" "$CUBE/blue.sen" \
        "$CUBE/green1.sen" "$CUBE/red1.sen" -o out.ppm
    # green row 0 is 20 40 60: blurred with clamped edges (20+20+40)/3, 40, (40+60+60)/3
    run -0 sed -n 4,12p out.ppm
    assert_equal "$(sed -n '5p;8p;11p' out.ppm | tr '\n' ' ')" "27 40 53 "
    printf '2 2\n1 1\n1 1\n' > even.psf
    run -1 --separate-stderr sensorize --psf even.psf "$CUBE/tiny.img" "$CUBE/blue.sen" \
        "$CUBE/green1.sen" "$CUBE/red1.sen" -o out2.ppm
    assert_equal "$stderr" "sensorize: even.psf:1: kernel sizes must be odd, 1 to 99, found 2"
    [ ! -e out2.ppm ]
}

@test "--calibrate solves gain and bias from two gray cards and writes .sen files" {
    mkdir cal
    run -0 --separate-stderr sensorize --calibrate --card1 0,0,1,1 --card2 0,2,1,3 \
        --target1 20,30 --target2 220,230 "$CUBE/cards.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o cal
    # Cards at 2^-8 and 2^-7 W cm-2 sr-1 um-1: gain = 200 / 2^-8 = 51200,
    # bias = 20 - 51200 * 2^-8 = -180 (blue) and 30 - 200 = -170 (red).
    assert_line --index 1 "$CUBE/blue.sen 0.00390625 0.0078125 20 220 51200 -180"
    assert_line --index 2 "$CUBE/red.sen 0.00390625 0.0078125 30 230 51200 -170"
    assert_equal "$(cat cal/blue.sen | tr '\n' ' ')" "2 51200 -180 1 3 "
    assert_equal "$(cat cal/red.sen | tr '\n' ' ')" "2 51200 -170 1 1 "
    assert_no_temp_files .
}

@test "--calibrate with swapped targets or a box outside the image fails and writes nothing" {
    mkdir cal
    run -1 --separate-stderr sensorize --calibrate --card1 0,0,1,1 --card2 0,2,1,3 \
        --target1 220 --target2 20 "$CUBE/cards.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o cal
    [[ "$stderr" == *"blue.sen: the solved gain -51200 is not positive"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --calibrate --card1 0,0,1,1 --card2 0,2,2,3 \
        --target1 20 --target2 220 "$CUBE/cards.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o cal
    [[ "$stderr" == *"--card2: the box reaches outside the 2x4 image"* ]] || fail "stderr: $stderr"
    run -0 ls cal
    assert_output ''
}

@test "-q hides the saturation warning; 12- and 16-bit TIFF and PNG outputs" {
    run -0 --separate-stderr sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/green1.sen" \
        "$CUBE/red1.sen" -o out.ppm
    assert_equal "$stderr" ""
    for out in c12.tif c12.png c16.tif c16.png; do
        run -0 --separate-stderr sensorize --bits "${out:1:2}" "$CUBE/tiny.hdr" "$CUBE/blue.sen" \
            "$CUBE/red.sen" -o "$out"
        assert_equal "$stderr" ""  # 12 and 16 bits hold every count of this cube
        [ -s "$out" ]
    done
    run -2 --separate-stderr sensorize --bits 16 "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o c.jpg
    [[ "$stderr" == *"must be a .tif, .png, .pgm or .ppm file"* ]] || fail "stderr: $stderr"
    assert_no_temp_files .
}

@test "a TIFF written twice is byte-identical (no wall-clock time stamp)" {
    # Two folders: the recorded command holds base names only (cube(5), Provenance).
    mkdir first second
    sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o first/out.tif
    sleep 1.1
    (cd second && sensorize "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o out.tif -q)
    cmp first/out.tif second/out.tif
}

# GeoTIFF outputs through GDAL (cube(5), Counts and band-radiance images): gdalinfo is
# from gdal-bin (scripts/install-deps).
@test "a 4-band counts TIFF holds 4 gray bands, no alpha, with names and wavelengths" {
    printf '1\n1000\n0\n1\n' > b1.sen
    cp b1.sen b2.sen; cp b1.sen b3.sen; cp b1.sen b4.sen
    run -0 --separate-stderr sensorize -q "$CUBE/tiny.img" b1.sen b2.sen b3.sen b4.sen -o four.tif
    run -0 gdalinfo four.tif
    assert_output --partial "Band 4 Block="
    refute_output --partial "Band 5 "
    # PHOTOMETRIC=MINISBLACK: band 1 gray, the others plain data; never RGB or alpha.
    assert_output --partial "Band 1 Block=3x2 Type=Byte, ColorInterp=Gray"
    refute_output --regexp "ColorInterp=(Alpha|Red|Green|Blue)"
    for b in 1 2 3 4; do assert_output --partial "Description = b$b"; done
    for w in 0.45 0.5 0.55 0.6; do assert_output --partial "wavelength=$w"; done
    assert_output --partial "wavelength_units=Micrometers"
    assert_output --partial "UNITS=DC"
}

@test "counts carry their gain and bias back to band radiance (GDAL scale and offset)" {
    # c = 2000 L + 5: L = c / 2000 - 5 / 2000, in the cube's radiance unit.
    printf '4\n2000\n5\n1\n1\n1\n1\n' > g.sen
    run -0 --separate-stderr sensorize -q --bits 16 "$CUBE/tiny.img" g.sen -o c.tif
    run -0 gdalinfo c.tif
    assert_output --partial "Offset: -0.0025,   Scale:0.0005"
    assert_output --partial "Unit Type: W cm-2 sr-1 um-1"
    # gdal_translate -unscale gives the band radiance within half a count (0.00025).
    run -0 --separate-stderr sensorize -q --float "$CUBE/tiny.img" g.sen -o l.tif
    run -0 gdal_translate -q -unscale -ot Float64 -of XYZ c.tif unscaled.xyz
    run -0 gdal_translate -q -ot Float64 -of XYZ l.tif float.xyz
    run -0 awk 'NR == FNR { l[FNR] = $3; next }
        { d = $3 - l[FNR]; if (d < 0) d = -d; if (d > m) m = d; n++ }
        END { print n " pixels, largest difference " m; exit !(n == 6 && m <= 0.00025 + 1e-12) }' \
        float.xyz unscaled.xyz
    echo "$output"
}

@test "a counts TIFF records FWHM, centre wavelength and its provenance (gdalinfo)" {
    # blue.sen: R = 1, 3 at 0.45, 0.5 um: centre (0.45 + 3 * 0.5) / 4 = 0.4875 um; half
    # maximum 1.5 crossed at 0.4625 um and still exceeded at the end sample, whose bin ends
    # at 0.525 um: FWHM 0.0625 um.
    mkdir sub
    run -0 --separate-stderr sensorize -q "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" \
        -o sub/two.tif
    run -0 gdalinfo sub/two.tif
    assert_output --partial "Description = blue"
    assert_output --partial "wavelength=0.4875"
    assert_output --partial "fwhm=0.0625"
    assert_output --regexp "SIGCHAIN_VERSION=[0-9]+\.[0-9]+\.[0-9]+"
    # Paths cut to base names, -q left out: the same text from any folder.
    assert_output --partial "SIGCHAIN_COMMAND=sensorize tiny.img blue.sen red.sen -o two.tif"
}

@test "--co passes GDAL creation options; bad ones and non-TIFF outputs exit 2" {
    run -0 --separate-stderr sensorize --co COMPRESS=DEFLATE --co PREDICTOR=2 --bits 16 \
        "$CUBE/tiny.img" "$CUBE/blue.sen" "$CUBE/red.sen" -o z.tif
    run -0 gdalinfo z.tif
    assert_output --partial "COMPRESSION=DEFLATE"
    assert_output --partial "Type=UInt16"
    run -2 --separate-stderr sensorize --co COMPRESS "$CUBE/tiny.img" "$CUBE/blue.sen" -o y.tif
    [[ "$stderr" == *"--co COMPRESS: expected KEY=VALUE"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --co COMPRESS=NOPE "$CUBE/tiny.img" "$CUBE/blue.sen" -o y.tif
    [[ "$stderr" == *"invalid creation option"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr sensorize --co COMPRESS=DEFLATE "$CUBE/tiny.img" "$CUBE/blue.sen" -o y.png
    [[ "$stderr" == *"--co applies to GeoTIFF (.tif) outputs only"* ]] || fail "stderr: $stderr"
    [ ! -e y.tif ] && [ ! -e y.png ]
    assert_no_temp_files .
}

@test "--help names what each option takes" {
    run -0 --separate-stderr sensorize --help
    refute_output --regexp " arg( |$)"
    assert_output --partial "--co KEY=VALUE"
    assert_output --partial "--psf FILE"
}

@test "--preview writes a true-colour PNG; without 3 visible bands it exits 1, writing nothing" {
    printf '1\n1000\n0\n1\n' > b1.sen
    cp b1.sen b2.sen; cp b1.sen b3.sen; cp b1.sen b4.sen
    # Bands at 0.45, 0.5, 0.55, 0.6 um: red 0.6 (b4), green 0.55 (b3), blue 0.45 (b1).
    run -0 --separate-stderr sensorize -q "$CUBE/tiny.img" b1.sen b2.sen b3.sen b4.sen \
        -o four.tif --preview p.png
    run -0 gdalinfo p.png
    assert_output --partial "Band 3 Block="
    refute_output --partial "Band 4 "
    run -0 gdalinfo -stats p.png
    assert_output --partial "STATISTICS_MAXIMUM=255"
    assert_output --partial "STATISTICS_MINIMUM=0"
    rm -f p.png.aux.xml
    # Fewer than 3 visible bands (a thermal or near-infrared sensor): the shortest band
    # in grey, stretched as above.
    run -0 --separate-stderr sensorize -q "$CUBE/tiny.img" "$CUBE/red.sen" "$CUBE/blue.sen" \
        -o two.tif --preview q.png
    run -0 gdalinfo -stats q.png
    assert_output --partial "Band 1 Block="
    refute_output --partial "Band 2 "
    assert_output --partial "ColorInterp=Gray"
    assert_output --partial "STATISTICS_MAXIMUM=255"
    rm -f q.png.aux.xml
    run -2 --separate-stderr sensorize "$CUBE/tiny.img" b1.sen b2.sen b3.sen b4.sen -o f.tif \
        --preview p.tif
    assert_no_temp_files .
}

# OpenImageIO is loaded only for an image read or written through it (the module
# sigchain_oiio, lib/image/oiio_module.hpp); its errors keep their messages and exit 1.
@test "a corrupt PNG or TIFF cube exits 1 naming it; no tool links OpenImageIO itself" {
    printf '\211PNG\r\n\032\nnot a png at all' >bad.png
    printf 'II*\000garbage garbage garbage' >bad.tif
    run -1 --separate-stderr sensorize bad.png "$CUBE/red.sen" -o out.png
    [[ "$stderr" == *"sensorize: bad.png: not a readable image: PNG read error: "* ]] ||
        fail "stderr: $stderr"
    run -1 --separate-stderr sensorize bad.tif "$CUBE/red.sen" -o out.png
    assert_equal "$stderr" \
        "sensorize: bad.tif: not a readable image: Could not open file: Failed to read directory at offset 1651663207"
    [ ! -e out.png ]
    run -0 readelf -d "$SIGCHAIN_BIN/sensorize" "$SIGCHAIN_BIN/trace" "$SIGCHAIN_BIN/compare"
    refute_output --partial OpenImageIO
}

@test "an unloadable OpenImageIO module is an error naming it only when an image needs it" {
    local rel
    rel=$(cd "$SIGCHAIN_BIN/.." && find lib* -name 'sigchain_oiio.so' -path '*/sigchain/*' | head -1)
    [ -n "$rel" ] || fail "no sigchain_oiio.so under $SIGCHAIN_BIN/../lib*"
    mkdir -p copy/bin "copy/$(dirname "$rel")"
    cp "$SIGCHAIN_BIN/sensorize" copy/bin/
    echo 'not a shared object' >"copy/$rel"
    local sens=("$CUBE/blue.sen" "$CUBE/green1.sen" "$CUBE/red1.sen") m="$PWD/copy/$rel"
    run -0 --separate-stderr copy/bin/sensorize -q "$CUBE/tiny.img" "${sens[@]}" -o out.tif
    run -1 --separate-stderr copy/bin/sensorize -q "$CUBE/tiny.img" "${sens[@]}" -o out.png
    # dlerror() follows: "PATH: file too short" here.
    [[ "$stderr" == "sensorize: out.png: cannot load the OpenImageIO module $m: $m: "?* ]] ||
        fail "stderr: $stderr"
    [ ! -e out.png ]
    assert_no_temp_files .
}

@test "--preview of a small object on a uniform background: the object white, not a black image" {
    # A 100 x 100 cube of 0.01 W cm-2 sr-1 um-1 with a 2 x 2 pixel object (0.04 % of
    # the image, below the 2nd-98th percentile stretch) of 0.05, 0.04, 0.03 at 0.45,
    # 0.55, 0.65 um: a blue object.
    gdal_create -q -of ENVI -ot Float32 -outsize 100 100 -bands 3 -burn 0.01 \
        -a_ullr 0 100 100 0 obj.img
    printf '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[50,50],[52,50],[52,52],[50,52],[50,50]]]}}]}' > sq.geojson
    gdal_rasterize -q -b 1 -b 2 -b 3 -burn 0.05 -burn 0.04 -burn 0.03 sq.geojson obj.img 2>/dev/null
    printf 'wavelength units = Micrometers\nwavelength = {0.45, 0.55, 0.65}\n' >> obj.hdr
    printf '1\n5000\n0\n1\n' > one.sen
    # levels PNG BAND: "COUNT VALUE" pairs of a band's pixel values, on one line.
    levels() { gdal_translate -q -of XYZ -b "$2" "$1" /vsistdout/ | awk '{ print $3 }' |
        sort -n | uniq -c | awk '{ printf "%s%s %s", (NR > 1 ? ", " : ""), $1, $2 }'; }
    run -0 sensorize -q obj.img one.sen one.sen one.sen -o c.tif --preview p.png
    for b in 1 2 3; do assert_equal "$(levels p.png $b)" "9996 0, 4 255"; done
    # One stretch for the three: the object keeps its colour (blue > green > red).
    run -0 sensorize -q obj.img one.sen one.sen one.sen -o c.tif --preview q.png \
        --preview-stretch common
    local r g b
    r=$(levels q.png 1 | sed 's/.*, 4 //') g=$(levels q.png 2 | sed 's/.*, 4 //')
    b=$(levels q.png 3 | sed 's/.*, 4 //')
    [ "$b" -gt "$g" ] && [ "$g" -gt "$r" ] || fail "object R $r, G $g, B $b"
}
