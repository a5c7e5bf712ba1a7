#!/usr/bin/env bats
# Tests: landsat_scene (classes(5), materials(5)) on the real Pennsylvania data
# Also requires: compare, gdalinfo (gdal-bin)
# The preparation steps of a real-image validation on data/scenes/pennsylvania's
# images: cloud and shadow mask, land cover, terrain on the pixel corners, control
# points, materials from the ECOSTRESS spectra, and the scores of an image against
# itself and against a shifted copy.

load test_helper

PA="$SIGCHAIN_SOURCE_DIR/data/scenes/pennsylvania"

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    [ -x "$SIGCHAIN_BIN/landsat_scene" ] || skip "landsat_scene not built in $SIGCHAIN_BIN"
}

# The first ``` block after "# EXAMPLE" of man page $1.
example_of() {
    awk '/^# EXAMPLE/{e=1; next} e && /^```/{ if (inb) exit; inb=1; next } inb{print}' "$1"
}

@test "landsat_scene: --help, --version, usage errors" {
    run -0 --separate-stderr landsat_scene --help
    assert_line --index 0 "Usage: landsat_scene [OPTIONS] COMMAND ARGS..."
    assert_line "See landsat_scene(1)."
    run -0 --separate-stderr landsat_scene --version
    assert_output --regexp "^landsat_scene \(sigchain\) [0-9]+[.][0-9]+[.][0-9]+$"
    run -2 --separate-stderr landsat_scene frobnicate
    [ "$stderr" = "landsat_scene: unknown command 'frobnicate'
Try 'landsat_scene --help'." ]
    run -2 --separate-stderr landsat_scene
    run -2 --separate-stderr landsat_scene --frobnicate terrain a b c
    run -2 --separate-stderr landsat_scene fit a.cpt b.tif
    [[ "$stderr" == "landsat_scene: fit takes 4 arguments, found 2"* ]]
    run -2 --separate-stderr landsat_scene mask m.tif "$PA/etm_20020720.tif"
    [[ "$stderr" == "landsat_scene: mask needs --sun ELEVATION,AZIMUTH"* ]]
    run -2 --separate-stderr landsat_scene mask --sun 0,120 m.tif "$PA/etm_20020720.tif"
    run -2 --separate-stderr landsat_scene --buffer 101 mask --sun 30,120 m.tif x.tif
    run -2 --separate-stderr landsat_scene points r.classes c.tif - many 1 5 p
    [[ "$stderr" == "landsat_scene: PER_CLASS must be an integer"* ]]
    [ ! -e m.tif ]
}

@test "landsat_scene: the EXAMPLEs of classes(5) and materials(5) are valid files" {
    example_of "$SIGCHAIN_SOURCE_DIR/man/classes.5.scd" > example.classes
    run -0 --separate-stderr landsat_scene classify example.classes - classes.tif \
        "$PA/etm_20020720.tif"
    [[ "$stderr" == *"1 forest 0."* ]]
    example_of "$SIGCHAIN_SOURCE_DIR/man/materials.5.scd" > materials.txt
    cp "$SIGCHAIN_SOURCE_DIR/data/spectra/ecostress_deciduous.txt" .
    printf '0.5\n1\n19000 22000 500\n-1 1 1\n7 20 2002\n15.5\n5\n40.5 76.2\n' > one.snd
    run -0 landsat_scene ems materials.txt one.snd - .
    run -0 grep -c '^CURVE_BEGIN$' forest.ems
    run -0 sigchain-check -q forest.ems
}

@test "landsat_scene: malformed rules, materials and spectra name their file and line" {
    printf '1 forest nd(4,3) >= 0.4\n2 field b9 <\n' > bad.classes
    run -1 --separate-stderr landsat_scene classify bad.classes - c.tif "$PA/etm_20020720.tif"
    [[ "$stderr" == "landsat_scene: bad.classes:2: expected terms of three fields"* ]]
    printf '1 forest b9 > 3\n' > nine.classes
    run -1 --separate-stderr landsat_scene classify nine.classes - c.tif "$PA/etm_20020720.tif"
    [[ "$stderr" == "landsat_scene: nine.classes: a rule reads band 9, the images have 6"* ]]
    [ ! -e c.tif ]
    printf '0.4 0.1\n0.3 0.2\n' > bad_spectrum.txt
    printf 'x 0.5 bad_spectrum.txt\n' > m.txt
    printf '0.5\n1\n19000 22000 500\n-1 1 1\n7 20 2002\n15.5\n5\n40.5 76.2\n' > one.snd
    run -1 --separate-stderr landsat_scene ems m.txt one.snd - .
    [[ "$stderr" == "landsat_scene: bad_spectrum.txt:2: expected a wavelength above"* ]]
    printf 'x 0.7 bad_spectrum.txt 0.7 bad_spectrum.txt\n' > m2.txt
    run -1 --separate-stderr landsat_scene ems m2.txt one.snd - .
    [ ! -e x.ems ]
}

@test "landsat_scene: July's clouds and shadows, land cover, terrain and points" {
    run -0 --separate-stderr landsat_scene mask --sun 61.4,125.8 \
        --cloud 'b1 > 110 b7 < 130' --dark 'b4 < 75' mask.tif \
        "$PA/etm_20020720.tif" "$PA/etm_20020720_thermal.tif"
    # The data's README counts 3.6 % of pixels with b1 > 110 and b61 < 130 (before the
    # 2-pixel buffer, which about doubles a small cumulus's area).
    cloud=$(awk '$2 == "cloud" { print $3 }' <<< "$stderr")
    shadow=$(awk '$2 == "shadow" { print $3 }' <<< "$stderr")
    awk -v c="$cloud" -v s="$shadow" 'BEGIN { exit !(c > 0.036 && c < 0.10 && s > 0.02 && s < 0.15) }'
    run -0 --separate-stderr landsat_scene classify "$PA/july.classes" mask.tif classes.tif \
        "$PA/etm_20020720.tif"
    [[ "$stderr" == *"1 forest 0."* ]]
    run -0 --separate-stderr landsat_scene terrain "$PA/dem.tif" classes.tif .
    [[ "$stderr" == *"centre latitude 40.523475 longitude -76.244962"* ]]
    run -0 gdalinfo terrain.tif
    assert_line --partial "Size is 301, 301"
    # The corners' grid starts half a pixel up and left of the image's.
    assert_line --partial "Origin = (390030.000000000000000,4491120.000000000000000)"
    run -0 gdalinfo landuse.tif
    assert_line --partial "Size is 301, 301"
    run -0 --separate-stderr landsat_scene points "$PA/july.classes" classes.tif mask.tif \
        10 7 5 p
    [[ "$stderr" == *"forest 10 points"* ]]
    run -0 grep -c 'held-out half' p_held.cpt
    [ "$output" -eq 15 ]
}

@test "landsat_scene: an image scores ROC 1 and RMS 0 against itself, less against another date" {
    printf '1 all\n' > all.classes
    run -0 landsat_scene classify all.classes - classes.tif "$PA/etm_20020720.tif"
    run -0 landsat_scene score --bands 2 all.classes "$PA/etm_20020720.tif" \
        "$PA/etm_20020720.tif" classes.tif
    assert_line "image 1 90000 1.0000 0.000 0.000 $(awk '$1 == "image" && $2 == 1 { print $7 }' <<< "$output") $(awk '$1 == "image" && $2 == 1 { print $8 }' <<< "$output")"
    run -0 landsat_scene score --bands 1 all.classes "$PA/etm_20021125.tif" \
        "$PA/etm_20020720.tif" classes.tif
    roc=$(awk '$1 == "image" { print $4 }' <<< "$output")
    awk -v r="$roc" 'BEGIN { exit !(r < 0.9) }'
    run -0 landsat_scene difference "$PA/etm_20021125.tif" "$PA/etm_20020720.tif" 4 30 d.png
    run -0 landsat_scene side-by-side "$PA/etm_20021125.tif" "$PA/etm_20020720.tif" 3,2,1 s.png
    run -0 gdalinfo s.png
    assert_line --partial "Size is 608, 300"
}

@test "landsat_scene: stats per class and the cross-tabulation of two class maps" {
    printf '1 dark b4 < 60\n2 bright\n' > two.classes
    run -0 landsat_scene classify two.classes - a.tif "$PA/etm_20021125.tif"
    run -0 landsat_scene classify two.classes - b.tif "$PA/etm_20020720.tif"
    run -0 landsat_scene stats two.classes "$PA/etm_20021125.tif" a.tif
    assert_line --index 0 "# class band n mean std p01 median p99"
    # By construction every "dark" pixel of November has b4 < 60 and every "bright" one
    # b4 >= 60: the 99th percentile of one and the 1st of the other say so.
    run -0 awk '$1 == "dark" && $2 == 4 && $8 < 60 { a = 1 } $1 == "bright" && $2 == 4 && $6 >= 60 { b = 1 }
        $1 == "all" && $2 == 4 && $3 == 90000 { c = 1 } END { exit !(a && b && c) }' <<< "$output"
    run -0 landsat_scene crosstab two.classes a.tif two.classes b.tif
    # The four pairs' counts add up to every pixel, and each class's fractions to 1.
    run -0 awk '!/^#/ { n += $3; f[$1] += $4 } END { exit !(n == 90000 &&
        f["dark"] > 0.9999 && f["dark"] < 1.0001 && f["bright"] > 0.9999 && f["bright"] < 1.0001) }' \
        <<< "$output"
}
