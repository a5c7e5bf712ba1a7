#!/usr/bin/env bats
# Tests: trace's pushbroom and line scanners (adv(5) SCANNERS, trj(5)), their
# geolocation layers (--igm, --glt; cube(5) GEOLOCATION LAYERS), and their errors
# Also requires: sigchain-check, gdalinfo, gdalwarp, gdal_translate, awk, make,
# olinda_scene, build_radiance, sensorize, compare (the Olinda ETM+ case)
# The scanners fly north over the lawn of tests/data/white1996/box_on_plane.gdb, 30 m
# up, its box lowered to a flat 4 x 4 m target (x and y 8 to 12 m) as in georef.bats.

load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
GDB="$SEED/box_on_plane.gdb"

target_gdb() {
    { sed -n '1,65p' "$GDB" | sed '44,65s/^\([0-9]* [0-9]*\) 3$/\1 0.05/'; echo END; } > target.gdb
}

# A pushbroom of 32 detectors (GSD 30 m x 500 um / 32 mm = 0.46875 m) and 40 lines,
# 4.6875 m/s x 0.1 s apart, from (10, 0.625) north: the lines cover y 0.625 to 19.375.
pushbroom_adv() {
    target_gdb
    cat > push.adv <<'EOF2'
10 10 0	# target point (unused by scanners)
10 0.625 30	# platform position at start_time_s (m)
90 -90 0	# angles (unused by scanners)
32	# focal length (mm)
40 32	# lines, detectors
units = m
pixel_pitch_um = 500
samples_per_pixel = 1
sensor = pushbroom
platform_speed_mps = 4.6875
platform_heading_deg = 0
line_period_s = 0.1
EOF2
}

render() {
    trace "$@" --background none "$DATA/box.snd" target.gdb "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad"
}

@test "scanners: a pushbroom renders, says its geometry, and lies on a map grid" {
    pushbroom_adv
    run -0 --separate-stderr render -v --crs EPSG:32618 push.adv --truth truth.tif -o cube.tif
    [[ "$stderr" == *"sensor: pushbroom scanner, 40 lines of 32 detectors, 0 to 4 s"* ]]
    # Straight level flight: every line is a row of a map grid, so a geotransform.
    [[ "$stderr" == *"georeferencing: a geotransform"* ]]
    run -0 gdalinfo cube.tif
    assert_output --partial "Size is 32, 40"
    # Steps of 0.46875 m along rows and columns (times UTM's scale factor there,
    # 1.0002: within 0.1 %), the grid turned by UTM's meridian convergence (1.8 deg),
    # and the rows running north (a positive northing step).
    run -0 awk '/"geoTransform"/ { on = 1; n = 0; next } on && /\]/ { on = 0 }
        on { gsub(/[ ,]/, ""); g[n++] = $0 }
        END { c = sqrt(g[1] ^ 2 + g[4] ^ 2); r = sqrt(g[2] ^ 2 + g[5] ^ 2); print c, r, g[5]
            exit (c > 0.4683 && c < 0.4693 && r > 0.4683 && r < 0.4693 && g[5] > 0) ? 0 : 1 }' \
        <(gdalinfo -json cube.tif)
    assert_no_temp_files
}

# The checkerboard of light lawn and dark target, seen by a jittering pushbroom
# (roll 1 deg at 0.4 Hz, pitch 0.5 deg at 0.3 Hz), which no geotransform holds:
# geolocation arrays, which gdalwarp -geoloc follows so that the target's corners land
# on (8, 8) and (12, 12) m within an output pixel; the GLT's cells inside the target
# name pixels that see it.
@test "scanners: gdalwarp -geoloc puts a jittering pushbroom's target corners in place" {
    pushbroom_adv
    printf 'jitter_amplitude_deg = 1 0.5 0\njitter_frequency_hz = 0.4 0.3 0\n' >> push.adv
    run -0 --separate-stderr render -v --crs EPSG:32618 push.adv --truth truth.tif \
        --igm igm.tif --glt glt.tif -o cube.tif
    [[ "$stderr" == *"georeferencing: geolocation arrays"* ]]
    [[ "$stderr" == *"IGM: 8 layers to igm.tif; GLT: "* ]]
    run -0 gdalwarp -q -overwrite -geoloc -t_srs EPSG:4326 -r near truth.tif warped.tif
    run -0 gdal_translate -q -of XYZ -b 4 warped.tif facets.xyz
    px=$(gdalinfo warped.tif | sed -n 's/^Pixel Size = (\([^,]*\),\(.*\))$/\1 \2/p')
    run -0 awk -v px="$px" '
        BEGIN { split(px, p, " "); a = 6378137; f = 1 / 298.257223563; e2 = f * (2 - f)
            lat0 = 43.08333; lon0 = -77.66667; r = atan2(1, 1) / 45; s = sin(lat0 * r)
            N = a / sqrt(1 - e2 * s * s); M = a * (1 - e2) / (1 - e2 * s * s) ^ 1.5
            kx = r * N * cos(lat0 * r); ky = r * M
            dx = p[1] * kx; dy = -p[2] * ky; x0 = 1e9; x1 = -1e9; y0 = 1e9; y1 = -1e9 }
        $3 == 1 { x = ($1 - lon0) * kx; y = ($2 - lat0) * ky; n++
            if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y }
        END { # pixel centres lie half a pixel inside the edges
            ex0 = x0 - dx / 2 - 8; ex1 = x1 + dx / 2 - 12; ey0 = y0 - dy / 2 - 8; ey1 = y1 + dy / 2 - 12
            printf "%d pixels of %.3f x %.3f m; corner errors %.3f %.3f %.3f %.3f m\n", n, dx, dy, ex0, ex1, ey0, ey1
            bad = (ex0 > dx || -ex0 > dx || ex1 > dx || -ex1 > dx || ey0 > dy || -ey0 > dy || ey1 > dy || -ey1 > dy)
            exit (n > 40 && !bad) ? 0 : 1 }' facets.xyz
    echo "# $output" >&3
    # The IGM: easting, northing, height, longitude, latitude, scene x y z; the GLT:
    # two int32 bands on a north-up grid in the map CRS.
    run -0 gdalinfo igm.tif
    assert_output --partial "Description = easting"
    assert_output --partial "Description = scene z"
    run -0 gdalinfo glt.tif
    assert_output --partial "Type=Int32"
    assert_output --partial "UTM zone 18N"
    # GLT cells whose centre lies in the target's middle (IGM scene x, y 9 to 11 m of
    # their source pixel) name a pixel whose truth facet is the target's (1).
    gdal_translate -q -of XYZ -b 1 glt.tif gc.xyz
    gdal_translate -q -of XYZ -b 2 glt.tif gr.xyz
    gdal_translate -q -of XYZ -b 6 igm.tif sx.xyz
    gdal_translate -q -of XYZ -b 7 igm.tif sy.xyz
    gdal_translate -q -of XYZ -b 4 truth.tif tf.xyz
    run -0 awk '
        FILENAME == "sx.xyz" { X[FNR] = $3; next } FILENAME == "sy.xyz" { Y[FNR] = $3; next }
        FILENAME == "tf.xyz" { F[FNR] = $3; next } FILENAME == "gc.xyz" { C[FNR] = $3; next }
        { if (C[FNR] == 0) next; i = ($3 - 1) * 32 + C[FNR]
          if (X[i] > 9 && X[i] < 11 && Y[i] > 9 && Y[i] < 11) { n++; if (F[i] != 1) bad++ } }
        END { print n " target cells, " bad + 0 " wrong"; exit (n > 10 && bad == 0) ? 0 : 1 }' \
        sx.xyz sy.xyz tf.xyz gc.xyz gr.xyz
    echo "# $output" >&3
    assert_no_temp_files
}

# A random-walk attitude jitter is reproducible: the same jitter_seed gives the same
# pixels at 1 and 2 threads (the files differ only in their provenance, which names
# --threads), another seed another image.
@test "scanners: a seeded random-walk jitter gives the same image for the same seed" {
    pushbroom_adv
    printf 'jitter_walk_deg = 0.5 0.5 0.2\njitter_seed = 3\n' >> push.adv
    run -0 render -q --threads 1 push.adv -o one.tif
    run -0 render -q --threads 2 push.adv -o two.tif
    run -0 compare --pixelwise --fail-max 0 one.tif two.tif
    sed -i 's/^jitter_seed = 3/jitter_seed = 4/' push.adv
    run -0 render -q --threads 1 push.adv -o other.tif
    run -1 compare --pixelwise --fail-max 0 one.tif other.tif
}

@test "scanners: a bidirectional line scanner renders from a trajectory file" {
    target_gdb
    printf '# sigchain-trj 1.1\n0 10 0.5 30 0 0 0\n10 10 40.5 30 0 0 0\n# sigchain-end 2\n' \
        > flight.trj
    run -0 sigchain-check flight.trj
    assert_output "flight.trj: ok: 2 records, 0 to 10 s"
    printf '# sigchain-trj 1\nposition = geodetic\n0 -8 -34.9 705000 0 0 191.6\n1 -8.06 -34.91 705000 0 0 191.6\n' \
        > orbit.trj
    run -0 sigchain-check orbit.trj
    assert_output "orbit.trj: ok: 2 records, 0 to 1 s, geodetic"
    cat > line.adv <<'EOF2'
10 10 0
10 0 30
90 -90 0
32
24 40	# 6 scans of 4 detectors, 40 samples
units = m
pixel_pitch_um = 500
sensor = line
trajectory = flight.trj
scan_half_angle_deg = 15
scan_period_s = 0.5
detectors_per_scan = 4
scan_direction = bidirectional
EOF2
    run -0 --separate-stderr render -v line.adv -o cube.img
    [[ "$stderr" == *"sensor: line scanner, 6 scans of 4 detector(s) (24 lines) of 40 samples, bidirectional, 0 to 3 s"* ]]
    run -0 grep -x "sensor type = sigchain line scanner" cube.hdr
    run -0 gdalinfo cube.img
    assert_output --partial "Size is 40, 24"
    # sigchain-check rewrites the .adv with its scanner keys unchanged.
    run -0 sigchain-check --rewrite -o again.adv line.adv
    run -0 diff <(grep -v '^#' line.adv | sed 's/[[:space:]]*#.*//') again.adv
}

@test "scanners: a trajectory that does not cover the image is an error at its last record" {
    target_gdb
    printf '# sigchain-trj 1\n0 10 0.5 30 0 0 0\n1 10 4.5 30 0 0 0\n' > short.trj
    pushbroom_adv
    sed -i 's/^platform_speed_mps.*/trajectory = short.trj/; /^platform_heading_deg/d' push.adv
    run -1 --separate-stderr render push.adv -o cube.tif
    assert_output ''
    [[ "$stderr" == "trace: short.trj:3: the trajectory ends at 1 s but the pushbroom image spans 0 to 4 s"* ]]
    [ ! -e cube.tif ]
    assert_no_temp_files
}

@test "scanners: non-monotonic trajectory times are an error naming the line" {
    pushbroom_adv
    printf '# sigchain-trj 1\n0 10 0 30 0 0 0\n2 10 5 30 0 0 0\n1 10 9 30 0 0 0\n' > back.trj
    sed -i 's/^platform_speed_mps.*/trajectory = back.trj/; /^platform_heading_deg/d' push.adv
    run -1 --separate-stderr render push.adv -o cube.tif
    [[ "$stderr" == "trace: back.trj:4: expected a time after 2 s (line 3): times must increase, found 1"* ]]
    run -1 --separate-stderr sigchain-check back.trj
    [[ "$stderr" == *"back.trj:4: expected a time after 2 s"* ]]
}

@test "scanners: an unknown sensor kind or a missing scanner key is an error naming the line" {
    pushbroom_adv
    sed 's/^sensor = pushbroom/sensor = whiskbroom/' push.adv > bad.adv
    run -1 --separate-stderr render bad.adv -o cube.tif
    assert_equal "$stderr" "trace: bad.adv:9: expected sensor frame, line or pushbroom, found 'whiskbroom'"
    sed '/^line_period_s/d' push.adv > noperiod.adv
    run -1 --separate-stderr render noperiod.adv -o cube.tif
    assert_equal "$stderr" \
        "trace: noperiod.adv:9: expected a line_period_s key for a pushbroom sensor (adv(5), SCANNERS)"
    sed 's/^sensor = pushbroom/sensor = frame/' push.adv > frame.adv
    run -1 --separate-stderr render frame.adv -o cube.tif
    assert_equal "$stderr" \
        "trace: frame.adv:10: expected no platform_speed_mps for a frame sensor (adv(5), SCANNERS)"
}

@test "scanners: --igm and --glt must be GeoTIFFs" {
    pushbroom_adv
    run -2 --separate-stderr render push.adv --igm igm.img -o cube.tif
    [[ "$stderr" == "trace: --igm: expected a GeoTIFF FILE.tif, found 'igm.img'"* ]]
    run -2 --separate-stderr render push.adv --glt cube.tif -o cube.tif
    [[ "$stderr" == "trace: --glt: cube.tif would overwrite another output"* ]]
    [ ! -e cube.tif ]
}

# data/scenes/olinda `make etm`: Olinda as ETM+ scanned it (olinda_etm.adv: 16 detectors,
# bidirectional, scan-line corrector, 30 m from 705 km at 6.8 km/s), with the frame
# chain's fitted materials, resampled onto the reference grid. Held-out floors as
# olinda.bats's (ROC 0.75 per band, RMS 25 DN); today's values, beside the frame
# camera's, are the generated table of data/scenes/olinda/README.md ("As ETM+ scanned
# it"; the lowest ROC, band 4's, is about 0.8).
@test "scanners: Olinda as ETM+ scanned it stays within the held-out floors" {
    [ -x "$SIGCHAIN_BIN/olinda_scene" ] || skip "olinda_scene not built in $SIGCHAIN_BIN"
    cp -r "$SIGCHAIN_SOURCE_DIR/data/scenes/olinda" scene
    rm -rf scene/out
    run -0 make -C scene -j2 etm SIGCHAIN_SOURCE_DIR="$SIGCHAIN_SOURCE_DIR" \
        SIGCHAIN_BIN="$SIGCHAIN_BIN"
    run -0 gdalinfo scene/out/etm/cube.tif
    assert_output --partial "Size is 400, 400"
    run -0 compare --fail-roc 0.75 --fail-rms 25 --bands 1,2,3,4 scene/out/etm/olinda.tif \
        scene/L7_ETMs.tif scene/olinda_held.cpt
    assert_output --partial "(352 rows, 349 columns)"
}
