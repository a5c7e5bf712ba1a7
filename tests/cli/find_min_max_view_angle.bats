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

# A line scanner rolled 5 deg on a trajectory file in a folder of its own, named
# relative to the .adv as trace finds it (adv(5) trajectory), 30 m over the lawn of
# box_on_plane.gdb, sweeping +-20 deg.
scanner_adv() {
    mkdir -p flight
    printf '# sigchain-trj 1\n0 10 0.5 30 5 0 0\n10 10 40.5 30 5 0 0\n' > flight/roll.trj
    cat > line.adv <<'EOF2'
10 10 0
10 0 30
90 -90 0
32
24 40	# 6 scans of 4 detectors, 40 samples
units = m
pixel_pitch_um = 500
sensor = line
trajectory = flight/roll.trj
scan_half_angle_deg = 20
scan_period_s = 0.5
detectors_per_scan = 4
EOF2
}

# band1.rad and band2.rad of tests/data/trace with their view-angle grid made LO to HI
# by INC (the nadir block's terms at every angle): OUT1 and OUT2.
narrow_rads() {
    local lo="$1" hi="$2" inc="$3"
    for b in 1 2; do
        awk -v lo="$lo" -v hi="$hi" -v inc="$inc" '
            FNR == NR { if (blk && n < 4) nadir[n++] = $0
                if (!blk && $1 == "0" && NF == 2) { blk = 1; nadir[0] = $2; n = 1 } next }
            /^# view angle \(deg\), range/ { print; skip = 1; m = int((hi - lo) / inc + 0.5)
                for (k = 0; k <= m; ++k) { print lo + k * inc, nadir[0]
                    for (i = 1; i < 4; ++i) print nadir[i] } next }
            skip && /^SIGCHAIN_RAD/ { skip = 0 }
            skip { next }
            /# min view angle/ { print lo "\t# min view angle (deg)"; next }
            /# max view angle/ { print hi "\t# max view angle (deg)"; next }
            /# view angle increment/ { print inc "\t# view angle increment (deg)"; next }
            /# view angles$/ { print int((hi - lo) / inc + 0.5) + 1 "\t# view angles"; next }
            { print }' "$SIGCHAIN_SOURCE_DIR/tests/data/trace/band$b.rad" \
            "$SIGCHAIN_SOURCE_DIR/tests/data/trace/band$b.rad" > "narrow$b.rad"
    done
}

# trace of line.adv over box_on_plane.gdb with the narrowed tables.
render() {
    trace "$@" --background none line.adv "$SIGCHAIN_SOURCE_DIR/tests/data/trace/box.snd" \
        "$SEED/box_on_plane.gdb" "$SIGCHAIN_SOURCE_DIR/tests/data/trace/box.mat" narrow1.rad narrow2.rad
}

@test "a line scanner's range: its scan angles shifted by its roll, tables trace accepts" {
    scanner_adv
    run -0 --separate-stderr find_min_max_view_angle line.adv "$SEED/box_on_plane.gdb"
    # Positive toward the body's right, east for a platform flying north; the 5 deg
    # roll (right wing down) turns the sweep of +-20 deg to -25 .. 15 deg across
    # track, and the outer detectors' edges look alpha = 2 x 500 um / 32 mm rad along
    # track: acos(cos(alpha) cos(25 deg)) and acos(cos(alpha) cos(15 deg)) off nadir
    # (to the report's 4 decimals).
    assert_line --index 0 --partial "positive toward azimuth 90.000 deg"
    run -0 awk '$1 == "unclipped-image" || $1 == "field-of-view" {
            r = atan2(0, -1) / 180; ca = cos(2 * 0.5 / 32)
            c = ca * cos(25 * r); lo = -atan2(sqrt(1 - c * c), c) / r
            c = ca * cos(15 * r); hi = atan2(sqrt(1 - c * c), c) / r
            print $1, $2, $3, lo, hi
            if ((($2 - lo) ^ 2) ^ 0.5 > 6e-5 || (($3 - hi) ^ 2) ^ 0.5 > 6e-5) bad = 1; n++ }
        END { exit (n == 2 && !bad) ? 0 : 1 }' <<< "$output"
    run -0 --separate-stderr find_min_max_view_angle --snd line.adv "$SEED/box_on_plane.gdb"
    read -r lo hi inc _ <<< "$output"
    narrow_rads "$lo" "$hi" "$inc"
    run -0 sigchain-check narrow1.rad narrow2.rad
    run -0 --separate-stderr render -v -o cube.img
    [[ "$stderr" == *"sensor: line scanner"* ]]
    [[ "$stderr" != *"path terms are clamped"* ]]
    # The control: tables a degree short of the range raise trace's warning.
    narrow_rads "$(awk -v v="$lo" 'BEGIN { print v + 1 }')" "$hi" "$inc"
    run -0 --separate-stderr render -o cube2.img
    [[ "$stderr" == *"path terms are clamped at the ends"* ]]
}

@test "a geodetic trajectory needs --origin; with it the scanner is placed about that point" {
    scanner_adv
    printf '# sigchain-trj 1\nposition = geodetic\n0 43.08333 -77.66667 30 5 0 0\n10 43.0837 -77.66667 30 5 0 0\n' \
        > flight/geo.trj
    sed -i 's#^trajectory = .*#trajectory = flight/geo.trj#' line.adv
    run -1 --separate-stderr find_min_max_view_angle line.adv "$SEED/box_on_plane.gdb"
    [[ "$stderr" == "find_min_max_view_angle: flight/geo.trj:3: a geodetic trajectory needs the scene's geodetic origin"* ]]
    # Over the origin, flying north at 30 m with the same roll: the same range as the
    # scene-frame trajectory's.
    run -0 --separate-stderr find_min_max_view_angle --origin 43.08333,-77.66667 line.adv \
        "$SEED/box_on_plane.gdb"
    assert_line --index 0 --partial "positive toward azimuth 90.000 deg"
    assert_line --index 4 --regexp '^unclipped-image +-25\.0599 +15\.1040 '
}
