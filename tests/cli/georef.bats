#!/usr/bin/env bats
# Tests: trace and sensorize georeferencing (cube(5), GEOREFERENCING; trace(1) --crs)
# Also requires: build_radiance, gdalinfo, gdalsrsinfo, gdalwarp, gdal_translate, awk
# The Olinda render (a DEM in EPSG:31985, a nadir camera on the Landsat grid) carries
# the CRS and the Landsat grid's geotransform; a tilted view of the box scene placed
# with --crs carries geolocation arrays that gdalwarp -geoloc orthorectifies.

load test_helper

OLINDA="$SIGCHAIN_SOURCE_DIR/data/scenes/olinda"
DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
GDB="$SEED/box_on_plane.gdb"

# The geotransform item K (0-5) of gdalinfo -json FILE, printed with 10 decimals.
gt_item() {
    gdalinfo -json "$1" | awk -v k="$2" '/"geoTransform"/ { on = 1; n = 0; next }
        on && /\]/ { on = 0 } on { gsub(/[ ,]/, ""); if (n++ == k) printf "%.10f\n", $0 }'
}

# Olinda's four bands' .rad tables from the committed card deck (about 10 s).
olinda_rads() {
    [ -f olinda-4.rad ] && return 0
    build_radiance -q --view-azimuth 0 "$OLINDA/olinda.cdk" "$OLINDA/olinda.snd" \
        -o "olinda-%d.rad"
}

# box_lat_lon EAST NORTH: the WGS84 latitude and longitude (deg) of the point EAST and
# NORTH metres from the box scene's origin (43.08333 N, 77.66667 W) on the scene's
# east-north-up frame, by the ellipsoid's radii of curvature there (millimetres over
# tens of metres).
box_lat_lon() {
    awk -v e="$1" -v n="$2" 'BEGIN { a = 6378137; f = 1 / 298.257223563; e2 = f * (2 - f)
        lat0 = 43.08333; lon0 = -77.66667; r = atan2(1, 1) / 45; s = sin(lat0 * r)
        N = a / sqrt(1 - e2 * s * s); M = a * (1 - e2) / (1 - e2 * s * s) ^ 1.5
        printf "%.9f %.9f\n", lat0 + n / M / r, lon0 + e / (N * cos(lat0 * r)) / r }'
}

# target_offset WARP_OPTION TRUTH: orthorectifies the truth cube TRUTH with gdalwarp
# WARP_OPTION... (-geoloc, -tps) into EPSG:4326; its band 4 is the facet each pixel
# centre sees (the target is facet 1 of the .gdb), whose centroid must be the target's
# centre, (10, 10) m east and north of the origin, within one output pixel.
target_offset() {
    local truth="${@: -1}" px
    run -0 gdalwarp -q -overwrite "${@:1:$#-1}" -t_srs EPSG:4326 -r near "$truth" warped.tif
    run -0 gdal_translate -q -of XYZ -b 4 warped.tif facets.xyz
    px=$(gdalinfo warped.tif | sed -n 's/^Pixel Size = (\([^,]*\),\(.*\))$/\1 \2/p')
    run -0 awk -v px="$px" -v want="$(box_lat_lon 10 10)" '
        BEGIN { split(px, p, " "); split(want, w, " "); want_lat = w[1]; want_lon = w[2] }
        $3 == 1 { n++; x += $1; y += $2 }
        END { dx = (x / n - want_lon) / p[1]; dy = (y / n - want_lat) / p[2]
            print n " pixels, offset " dx ", " dy " output pixels"
            exit (n > 4 && dx < 1 && dx > -1 && dy < 1 && dy > -1) ? 0 : 1 }' facets.xyz
    echo "$output"
}

# A flat-response .sen of 3 samples (the box bands').
flat_sen() {
    printf '3\n1000\n0\n1\n1\n1\n' > "$1"
}

@test "georef: the Olinda render and its counts carry EPSG:31985 and the Landsat grid" {
    olinda_rads
    cp "$OLINDA/olinda.mat" "$OLINDA"/*.ems .
    # The CRS the Olinda Makefile gives (the Landsat image's; the DEM's is the same
    # projection on an unnamed datum, below).
    run -0 --separate-stderr trace -v --crs EPSG:31985 --no-adjacency --rows 0:4 "$OLINDA/olinda.adv" \
        "$OLINDA/olinda.snd" "$OLINDA/olinda.odb" olinda.mat olinda-1.rad olinda-2.rad \
        olinda-3.rad olinda-4.rad -o cube.tif
    [[ "$stderr" == *"georeferencing: a geotransform"* ]]
    run -0 gdalinfo cube.tif
    assert_output --partial 'ID["EPSG",31985]'
    run -0 gdalsrsinfo -o epsg cube.tif
    assert_output --partial "EPSG:31985"
    # The render's grid against the Landsat image's: offsets in pixels of 28.5 m.
    for k in 0 1 2 3 4 5; do
        want=$(gt_item "$OLINDA/L7_ETMs.tif" $k)
        got=$(gt_item cube.tif $k)
        echo "geotransform[$k]: render $got, Landsat $want"
        run -0 awk -v a="$got" -v b="$want" -v k=$k 'BEGIN {
            d = (k == 0 || k == 3) ? (a - b) / 28.5 : (a - b) * 352 / 28.5
            print "offset " d " pixel"; exit (d < 0.1 && d > -0.1) ? 0 : 1 }'
    done
    # sensorize carries the CRS and geotransform into the counts.
    printf '9\n1000\n0\n1\n1\n1\n1\n1\n1\n1\n1\n1\n' > flat9.sen
    run -0 sensorize -q cube.tif flat9.sen flat9.sen flat9.sen flat9.sen -o counts.tif
    run -0 gdalsrsinfo -o epsg counts.tif
    assert_output --partial "EPSG:31985"
    [ "$(gt_item counts.tif 0)" = "$(gt_item cube.tif 0)" ]
    [ "$(gt_item counts.tif 3)" = "$(gt_item cube.tif 3)" ]
    # The ENVI header holds the same as map info and a coordinate system string.
    run -0 trace -q --crs EPSG:31985 --no-adjacency --rows 0:2 "$OLINDA/olinda.adv" \
        "$OLINDA/olinda.snd" "$OLINDA/olinda.odb" olinda.mat olinda-1.rad olinda-2.rad \
        olinda-3.rad olinda-4.rad -o cube.img
    # (within a metre of the Landsat corner; pixels of 28.5 m times UTM's scale factor)
    run -0 grep -E '^map info = \{UTM, 1, 1, 28877[56]\.[0-9]*, 912076[01]\.[0-9]*, 28\.50[0-9]*, 28\.50[0-9]*, 25, South' cube.hdr
    run -0 grep -c '^coordinate system string = ' cube.hdr
    run -0 grep -c '^sensor type = sigchain frame camera$' cube.hdr
    # gdalwarp onto the Landsat grid (nearest neighbour) gives back the render itself.
    run -0 gdalwarp -q -overwrite -r near -te 288776.25 9120646.75 298722.75 9120760.75 \
        -tr 28.5 28.5 cube.tif warped.tif
    run -0 compare --pixelwise --fail-max 0 warped.tif cube.tif
    # Without --crs: the DEM's own CRS, and the same grid.
    run -0 trace -q --no-adjacency --rows 0:2 "$OLINDA/olinda.adv" "$OLINDA/olinda.snd" \
        "$OLINDA/olinda.odb" olinda.mat olinda-1.rad olinda-2.rad olinda-3.rad olinda-4.rad \
        -o dem.tif
    run -0 gdalinfo dem.tif
    assert_output --partial 'UTM Zone 25, Southern Hemisphere'
    run -0 awk -v a="$(gt_item dem.tif 0)" -v b="$(gt_item cube.tif 0)" \
        'BEGIN { exit (a - b < 0.285 && b - a < 0.285) ? 0 : 1 }'  # within 0.01 pixel
    # --crs none: no georeferencing at all.
    run -0 trace -q --crs none --no-adjacency --rows 0:2 "$OLINDA/olinda.adv" \
        "$OLINDA/olinda.snd" "$OLINDA/olinda.odb" olinda.mat olinda-1.rad olinda-2.rad \
        olinda-3.rad olinda-4.rad -o plain.tif
    run -0 gdalinfo plain.tif
    refute_output --partial "EPSG"
    assert_no_temp_files
}

# The lawn of tests/data/white1996/box_on_plane.gdb with the box's top lowered to a flat
# target 5 cm above it (x and y 8 to 12 m, facet 1): no wall hides ground behind it, so
# the orthorectified target has its true shape. Placed at box.snd's site with --crs
# EPSG:32618 (UTM 18N), seen from the south at 56 deg elevation.
target_gdb() {
    { sed -n '1,65p' "$GDB" | sed '44,65s/^\([0-9]* [0-9]*\) 3$/\1 0.05/'; echo END; } > target.gdb
}
tilted_adv() {
    target_gdb
    cat > tilt.adv <<'EOF'
10 10 0	# target point (m)
10 -10 30	# camera point (m)
56.31 -90 0	# elevation, azimuth, twist (deg)
32	# focal length (mm)
32 32	# rows, columns
units = m
pixel_pitch_um = 500
samples_per_pixel = 1
EOF
}

@test "georef: a tilted view writes geolocation arrays that gdalwarp -geoloc follows" {
    tilted_adv
    run -0 --separate-stderr trace -v --crs EPSG:32618 --background none tilt.adv \
        "$DATA/box.snd" target.gdb "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" \
        --truth truth.tif -o cube.tif
    [[ "$stderr" == *"georeferencing: geolocation arrays"* ]]
    [ -f cube.geoloc.tif ]
    run -0 gdalinfo cube.tif
    assert_output --partial "X_DATASET=cube.geoloc.tif"
    assert_output --partial "GEOREFERENCING_CONVENTION=PIXEL_CENTER"
    run -0 gdalinfo truth.tif
    assert_output --partial "Y_DATASET=cube.geoloc.tif"
    # The top rows look past the 20 m lawn: with --background none they see no ground.
    run -0 gdalinfo -stats cube.geoloc.tif
    assert_output --partial "NoData Value=-999999"
    run -0 gdal_translate -q -of XYZ -b 1 -srcwin 0 0 32 1 cube.geoloc.tif row0.xyz
    run -0 awk '$3 == -999999 { n++ } END { print n + 0; exit n > 0 ? 0 : 1 }' row0.xyz
    # Orthorectify the truth layers; band 4 is the facet each pixel centre sees (the
    # target is facet 1 of the .gdb). Its centroid must be the target's centre, (10, 10)
    # m east and north of the origin, within one output pixel.
    target_offset -geoloc truth.tif
    # sensorize copies the arrays beside its counts, which name the copy.
    flat_sen b.sen
    run -0 sensorize -q cube.tif b.sen b.sen -o counts.tif
    run -0 gdalinfo counts.tif
    assert_output --partial "X_DATASET=counts.geoloc.tif"
    run -0 cmp <(gdal_translate -q -of XYZ -b 2 cube.geoloc.tif /vsistdout/) \
        <(gdal_translate -q -of XYZ -b 2 counts.geoloc.tif /vsistdout/)
    run -0 gdalwarp -q -overwrite -geoloc -t_srs EPSG:4326 counts.tif counts_warped.tif
    assert_no_temp_files
}

@test "georef: moved away, a cube lands by its ground control points or SRC_GEOLOC_ARRAY" {
    tilted_adv
    mkdir a
    run -0 trace -q --crs EPSG:32618 --background none tilt.adv "$DATA/box.snd" target.gdb \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" --truth a/truth.tif -o a/cube.img
    # Named by their file name: they lie beside the cube (GDAL 3.6 opens the name from
    # the working directory, so -geoloc is run in the cube's folder).
    run -0 grep -Fx "sigchain geolocation = cube.geoloc.tif" a/cube.hdr
    run -0 gdalinfo a/truth.tif
    assert_output --partial "X_DATASET=cube.geoloc.tif"
    # 17 x 17 lattice points less those that see no ground (the top rows see the sky),
    # in the GeoTIFF with their CRS and in the ENVI header as its "geo points".
    n=$(gdalinfo a/truth.tif | grep -c '^GCP\[')
    (( n > 100 && n < 289 )) || fail "$n GCPs"
    run -0 gdalinfo a/truth.tif
    assert_output --partial "GCP Projection"
    [ "$(gdalinfo a/cube.img | grep -c '^GCP\[')" -eq "$n" ]
    (cd a && target_offset -geoloc truth.tif)
    # Moved, and used from elsewhere: the GCPs alone place it (a thin-plate spline).
    mv a b && mkdir c && cd c
    target_offset -tps ../b/truth.tif
    run -0 gdalwarp -q -overwrite -tps -t_srs EPSG:4326 ../b/cube.img cube_tps.tif
    # The arrays themselves, named to gdalwarp; sensorize finds them beside the cube.
    target_offset -geoloc -to SRC_GEOLOC_ARRAY=../b/cube.geoloc.tif ../b/truth.tif
    flat_sen b.sen
    run -0 sensorize -q ../b/cube.img b.sen b.sen -o counts.tif
    run -0 cmp <(gdal_translate -q -of XYZ -b 1 ../b/cube.geoloc.tif /vsistdout/) \
        <(gdal_translate -q -of XYZ -b 1 counts.geoloc.tif /vsistdout/)
    [ "$(gdalinfo counts.tif | grep -c '^GCP\[')" -eq "$(gdalinfo ../b/cube.img | grep -c '^GCP\[')" ]
}

@test "georef: a scene named by its .snd alone is placed in its UTM zone; --crs none is not" {
    tilted_adv
    run -0 --separate-stderr trace -v tilt.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o utm.tif
    [[ "$stderr" == *"map CRS EPSG:32618, the UTM zone of the .snd's latitude 43.0833"* ]]
    [ -f utm.geoloc.tif ]
    run -0 gdalinfo utm.tif
    assert_output --partial "X_DATASET=utm.geoloc.tif"
    # A nadir view lies on the UTM grid: a CRS and geotransform, WGS 84 / UTM zone 18N.
    sed -e 's/^56.31 -90 0/90 0 0/' -e 's/^10 -10 30/10 10 30/' tilt.adv > nadir.adv
    run -0 --separate-stderr trace -v nadir.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o nadir.tif
    [[ "$stderr" == *"georeferencing: a geotransform"* ]]
    [ ! -f nadir.geoloc.tif ]
    run -0 gdalsrsinfo -o epsg nadir.tif
    assert_output --partial "EPSG:32618"
    run -0 trace -q --crs none nadir.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o none.tif
    run -0 gdalinfo none.tif
    refute_output --partial "Coordinate System is:"
    refute_output --partial "Origin ="
}

@test "georef: --crs errors are usage errors; --crs none places nothing" {
    tilted_adv
    run -2 --separate-stderr trace --crs EPSG:99999999 tilt.adv "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o cube.tif
    [[ "$stderr" == "trace: --crs EPSG:99999999: unknown CRS"* ]]
    run -2 --separate-stderr trace --crs nowhere.wkt tilt.adv "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o cube.tif
    [[ "$stderr" == "trace: --crs nowhere.wkt: expected EPSG:N or a WKT file"* ]]
    echo 'not a crs' > bad.wkt
    run -1 --separate-stderr trace --crs bad.wkt tilt.adv "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o cube.tif
    [[ "$stderr" == "trace: bad.wkt:1: not a coordinate reference system"* ]]
    run -2 --separate-stderr trace --shadow-history --crs EPSG:32618 "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" -o x.shd
    # A WKT file works as EPSG:N does; without --crs the .gdb scene is not geo-placed.
    gdalsrsinfo -o wkt EPSG:32618 > utm18.wkt
    run -0 trace -q --crs utm18.wkt tilt.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o cube.tif
    [ -f cube.geoloc.tif ]
    # An ENVI cube names its arrays in its header; sensorize follows it.
    run -0 trace -q --crs EPSG:32618 tilt.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o envi.img
    run -0 grep -Fx "sigchain geolocation = envi.geoloc.tif" envi.hdr
    flat_sen b.sen
    run -0 sensorize -q envi.img b.sen b.sen -o envi_counts.tif
    run -0 gdalinfo envi_counts.tif
    assert_output --partial "X_DATASET=envi_counts.geoloc.tif"
    run -0 trace -q --crs none tilt.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o plain.tif
    [ ! -f plain.geoloc.tif ]
    run -0 gdalinfo plain.tif
    refute_output --partial "GEOLOCATION"
    refute_output --partial "GCP"
    run -0 trace --help
    assert_output --partial "--crs EPSG:N|FILE|none"
}

@test "georef: --like RASTER renders on the raster's grid, the box top where the map has it" {
    # A 0.5 m grid in UTM 18N about the box scene's origin (43.08333 N, 77.66667 W).
    local e0 n0
    read -r e0 n0 < <(echo "-77.66667 43.08333" |
        gdaltransform -s_srs EPSG:4326 -t_srs EPSG:32618 -output_xy)
    run -0 gdal_create -q -of GTiff -outsize 48 48 -a_srs EPSG:32618 \
        -a_ullr "$(awk -v e="$e0" 'BEGIN { printf "%.6f", e - 2 }')" \
        "$(awk -v n="$n0" 'BEGIN { printf "%.6f", n + 22 }')" \
        "$(awk -v e="$e0" 'BEGIN { printf "%.6f", e + 22 }')" \
        "$(awk -v n="$n0" 'BEGIN { printf "%.6f", n - 2 }')" -bands 1 grid.tif
    # A camera 1 km above the box (a nadir view, its relief displacement 0.6 cm).
    printf '10 10 0\n10 10 1000\n90 -90 0\n32\n16 16\nunits = m\npixel_pitch_um = 500\nsamples_per_pixel = 1\n' > high.adv
    run -0 --separate-stderr trace -v --like grid.tif high.adv "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" --truth truth.tif -o like.tif
    [[ "$stderr" == *"sensor: frame camera position on a map grid of 48 x 48 cells (--like)"* ]]
    # Its grid is the raster's, exactly: size, origin, cell size and CRS.
    for f in like.tif truth.tif; do
        [ "$(gdalinfo "$f" | grep -E '^(Size is|Origin =|Pixel Size =)')" = \
            "$(gdalinfo grid.tif | grep -E '^(Size is|Origin =|Pixel Size =)')" ]
        [ "$(gdalsrsinfo -o epsg "$f")" = "$(gdalsrsinfo -o epsg grid.tif)" ]
    done
    [ ! -e like.geoloc.tif ]
    # The box top (wood, 4 x 4 m, centred 10 m east and north of the origin in the
    # scene's east-north-up frame) on the map: UTM's grid turns by the meridian
    # convergence (1.8 deg here), so its centre is where gdaltransform puts the
    # point's longitude and latitude. Cells are taken whole by their centre's ray, so
    # the turned square's edges are quantised by up to half a cell: about 64 cells,
    # their centroid within half a cell (0.25 m) of the centre on each axis.
    local lat lon want
    read -r lat lon < <(box_lat_lon 10 10)
    want=$(echo "$lon $lat" | gdaltransform -s_srs EPSG:4326 -t_srs EPSG:32618 -output_xy)
    run -0 awk -v want="$want" 'BEGIN { split(want, w, " ") }
        $3 == 37 { n++; x += $1; y += $2 }
        END { dx = x / n - w[1]; dy = y / n - w[2]
            printf "%d cells, centroid %.3f, %.3f m off\n", n, dx, dy
            exit !(n >= 56 && n <= 72 && dx * dx < 0.0625 && dy * dy < 0.0625) }' \
        <(gdal_translate -q -of XYZ -b 2 truth.tif /vsistdout/)
    echo "$output"
    run -2 --separate-stderr trace --like grid.tif --crs EPSG:32618 high.adv "$DATA/box.snd" \
        "$GDB" "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o x.tif
    [[ "$stderr" == *"--like takes the raster's CRS: not with --crs"* ]]
    run -1 --separate-stderr trace --like high.adv high.adv "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o x.tif
    [ ! -e x.tif ]
}
