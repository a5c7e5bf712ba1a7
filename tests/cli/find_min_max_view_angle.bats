#!/usr/bin/env bats
# Tests: find_min_max_view_angle
# Also requires: tests/data/geom/*.adv, tests/data/geom/*.gdb, tests/data/white1996/box_on_plane.gdb,
#   tests/data/scene/{flat.odb,flat.asc,flat.prj,quad_tri.odb,quad_tri.obj,quad_tri.map}
load test_helper

GEOM="$SIGCHAIN_SOURCE_DIR/tests/data/geom"
SCENE="$SIGCHAIN_SOURCE_DIR/tests/data/scene"

@test "--help prints usage to stdout and exits 0" {
    run -0 --separate-stderr find_min_max_view_angle --help
    assert_output --partial "Usage: find_min_max_view_angle"
    assert_output --partial "See find_min_max_view_angle(1)."
}

@test "--version prints the version and exits 0" {
    run -0 --separate-stderr find_min_max_view_angle --version
    assert_output --regexp '^find_min_max_view_angle \(sigchain\) [0-9]+\.[0-9]+\.[0-9]+$'
}

@test "unknown option exits 2" {
    run -2 --separate-stderr find_min_max_view_angle --no-such-option
    [[ "$stderr" == *"Try 'find_min_max_view_angle --help'."* ]]
    assert_output ''
}

@test "wrong number of files exits 2" {
    run -2 --separate-stderr find_min_max_view_angle "$GEOM/nadir.adv"
    [[ "$stderr" == *"expected two files"* ]]
}

@test "unknown method exits 2" {
    run -2 --separate-stderr find_min_max_view_angle -m sideways --snd "$GEOM/nadir.adv" "$GEOM/plane_100m.gdb"
    [[ "$stderr" == *"unknown method 'sideways'"* ]]
}

@test "nadir view: golden report" {
    run -0 --separate-stderr find_min_max_view_angle -o report.txt "$GEOM/nadir.adv" "$GEOM/plane_100m.gdb"
    assert_golden report.txt "$GOLDEN/find_min_max_view_angle/nadir.txt"
    assert_no_temp_files .
}

@test "oblique view: the field of view reaches the world beyond the scene, golden report" {
    run -0 --separate-stderr find_min_max_view_angle "$GEOM/oblique.adv" "$GEOM/plane_100m.gdb"
    # Hand-computed: bounding box 45.0358..47.7557 deg (atan(hypot(1000,50)/1000),
    # atan(hypot(1100,50)/1000)). The image spans more than the plane and every ray is
    # below the horizon: the rays past the plane's edges see the background plane
    # through their own angles, so the field of view is the unclipped image's range.
    assert_output --regexp 'scene-bounding-box +45\.0358 +47\.7557'
    assert_output --regexp 'field-of-view +43\.8463 +49\.0240'
    assert_output --regexp 'unclipped-image +43\.8463 +49\.0240'
    echo "$output" > report.txt
    assert_golden report.txt "$GOLDEN/find_min_max_view_angle/oblique.txt"
}

@test "--snd prints a line ready for a .snd file, rounded outward" {
    run -0 --separate-stderr find_min_max_view_angle --snd "$GEOM/oblique.adv" "$GEOM/plane_100m.gdb"
    assert_output --regexp '^43\.5 49\.5 0\.5	# min, max and increment of the view angle \(deg, field-of-view\)$'
    run -0 --separate-stderr find_min_max_view_angle --snd -m scene-bounding-box "$GEOM/oblique.adv" "$GEOM/plane_100m.gdb"
    assert_output --partial "scene-bounding-box"
}

@test "a tower raises the bounding box maximum" {
    run -0 --separate-stderr find_min_max_view_angle "$GEOM/oblique.adv" "$GEOM/tower.gdb"
    # atan(hypot(1100, 50) / 950) = 49.2142 deg
    assert_output --regexp 'scene-bounding-box +45\.0358 +49\.2142'
}

@test "no ray hits the scene: exit 1, nothing written" {
    run -1 --separate-stderr find_min_max_view_angle -o out.txt "$GEOM/sky.adv" "$GEOM/plane_100m.gdb"
    [[ "$stderr" == *"no ray of the field of view hits the scene"* ]]
    [ ! -e out.txt ]
    assert_no_temp_files .
}

@test "malformed .adv exits 1 naming FILE:LINE" {
    printf '50 50 0\n50 50 1000\n90 -90 0\nfifty\n10 10\n' > bad.adv
    run -1 --separate-stderr find_min_max_view_angle bad.adv "$GEOM/plane_100m.gdb"
    [[ "$stderr" == "find_min_max_view_angle: bad.adv:4: "* ]]
}

@test "malformed .gdb exits 1 naming FILE:LINE" {
    printf 'OBJECT\nthing\n1-0-0\nPART\n' > bad.gdb
    run -1 --separate-stderr find_min_max_view_angle "$GEOM/nadir.adv" bad.gdb
    [[ "$stderr" == "find_min_max_view_angle: bad.gdb:"* ]]
}

@test "missing file exits 1 naming it" {
    run -1 --separate-stderr find_min_max_view_angle "$GEOM/nadir.adv" no-such.gdb
    [[ "$stderr" == *"no-such.gdb: cannot open"* ]]
}

@test "the .adv can come from standard input" {
    run -0 --separate-stderr sh -c "find_min_max_view_angle --snd - '$GEOM/plane_100m.gdb' < '$GEOM/oblique.adv'"
    assert_output --regexp '^43\.5 49\.5 0\.5'
}

@test "--grid sets the interior rays; the border alone fixes a nadir view's range" {
    run -0 --separate-stderr find_min_max_view_angle --grid 2 "$GEOM/nadir.adv" "$GEOM/plane_100m.gdb"
    # 4 corners + 4 x 100 border pixels + 2 x 2 interior rays all hit the square.
    assert_output --regexp 'field-of-view +-0\.7292 +0\.7292 +0\.10 +408'
    run -2 --separate-stderr find_min_max_view_angle --grid 0 "$GEOM/nadir.adv" "$GEOM/plane_100m.gdb"
    [[ "$stderr" == *"--grid: 0: must be an integer from 1 to 100000"* ]]
}

@test "an .odb with an OBJ object is read (its material map too)" {
    run -0 --separate-stderr find_min_max_view_angle --snd -m scene-bounding-box "$GEOM/nadir.adv" "$SCENE/quad_tri.odb"
    # The two copies span x 0..6, y 0..12 at z = 0, south-west of the camera at
    # (50, 50, 1000) (reference azimuth north, so negative): the box corners give
    # -atan(hypot(50, 50) / 1000) = -4.05 to -atan(hypot(44, 38) / 1000) = -3.33 deg,
    # rounded outward to the 0.05 increment.
    assert_output --regexp '^-4\.05 -3\.30 0\.05'
}

@test "a DEM object needs --origin; with it the terrain is placed about that point" {
    run -1 --separate-stderr find_min_max_view_angle "$GEOM/nadir.adv" "$SCENE/flat.odb"
    [[ "$stderr" == *"flat.odb:3: a DEM object needs the scene's geodetic origin"* ]]
    # The flat DEM covers about 0..105 m east and 0..111 m north of 43 N 77.6 W: the
    # nadir image (+-12.7 m about (50, 50)) sees terrain in every ray.
    run -0 --separate-stderr find_min_max_view_angle --origin 43,-77.6 "$GEOM/nadir.adv" "$SCENE/flat.odb"
    assert_output --regexp 'field-of-view +-0\.7292 +0\.7292 +0\.10 +10404'
    run -0 --separate-stderr find_min_max_view_angle --origin 43,-77.6,0 "$GEOM/nadir.adv" "$SCENE/flat.odb"
    run -2 --separate-stderr find_min_max_view_angle --origin 43 "$GEOM/nadir.adv" "$SCENE/flat.odb"
    [[ "$stderr" == *"--origin expects LAT,LON or LAT,LON,HEIGHT"* ]]
    run -2 --separate-stderr find_min_max_view_angle --origin 95,0 "$GEOM/nadir.adv" "$SCENE/flat.odb"
    [[ "$stderr" == *"latitude within -90..90 deg"* ]]
}
