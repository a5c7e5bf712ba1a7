# Tests: trace find_min_max_view_angle therm
# Also requires: sigchain-check, gdal_translate; the spider of Debian's assimp-testmodels
#   (/usr/share/assimp/models/STL/Spider_ascii.stl) when installed, else that case skips
#
# Meshes (through Assimp) and DEM rasters given directly as the scene argument, against
# the same files placed by an .odb (odb(5) SCENE ARGUMENT, MESH_FILENAME, DEM_FILENAME):
# trace's box.adv camera (tests/data/trace) over a 20 m plate of two triangles (grass
# and wood of box.mat) or a 6 x 6-cell DEM written here about box.snd's point. Then the
# scene options every scene reader shares: a mesh's degenerate facets (skipped with one
# line, --strict-mesh), --up-axis, and find_min_max_view_angle's geometry-only scenes.

bats_require_minimum_version 1.5.0
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
MESHES="$SIGCHAIN_SOURCE_DIR/tests/data/meshes"

# trace's inputs with SCENE in its place: ADV SND SCENE MAT RAD...
inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "$1" "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad"
}

# plate.obj (a grass and a wood triangle, 20 m square at z = 0), plate.map, plate.stl.
write_plate() {
    printf 'o plate\nv 0 0 0\nv 20 0 0\nv 20 20 0\nv 0 20 0\nusemtl grass\nf 1 2 3\n' > plate.obj
    printf 'usemtl wood\nf 1 3 4\n' >> plate.obj
    printf 'grass 1\nwood 37\n' > plate.map
    printf 'solid plate\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 20 0 0\n' > plate.stl
    printf 'vertex 20 20 0\nendloop\nendfacet\nendsolid plate\n' >> plate.stl
}

# t.asc (+ t.prj, WGS84): 6 x 6 cells of 0.0001 deg from box.snd's point, gently sloping.
write_dem() {
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/scene/flat.prj" t.prj
    {
        printf 'ncols 6\nnrows 6\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize 0.0001\n'
        for r in 0 1 2 3 4 5; do
            for c in 0 1 2 3 4 5; do printf '%s ' "$((r * 2 + c)).5"; done
            printf '\n'
        done
    } > t.asc
}

@test "trace renders a mesh given as the scene as it renders the same mesh in an .odb" {
    write_plate
    printf 'OBJECT {\n    MESH_FILENAME = plate.obj\n    MATERIAL_MAP = plate.map\n    UNITS = m\n}\n' \
        > plate.odb
    run -0 --separate-stderr trace $(inputs plate.obj) --material-map plate.map -o lone.img
    assert_equal "$stderr" ''
    run -0 --separate-stderr trace $(inputs plate.odb) -o odb.img
    run -0 cmp lone.img odb.img
    # Both triangles are seen: the picture is not one value (grass and wood differ).
    run -0 --separate-stderr trace $(inputs plate.obj) --material-id 1 -o grass.img
    run -1 cmp -s lone.img grass.img
    assert_no_temp_files .
}

@test "trace renders an STL with one --material-id as an .odb MESH_FILENAME with MATERIAL_ID" {
    write_plate
    printf 'OBJECT {\n    MESH_FILENAME = plate.stl\n    MATERIAL_ID = 37\n    UNITS = m\n}\n' \
        > stl.odb
    run -0 --separate-stderr trace $(inputs plate.stl) --material-id 37 -o lone.img
    run -0 --separate-stderr trace $(inputs stl.odb) -o odb.img
    run -0 cmp lone.img odb.img
    # Without the id the STL's faces have no material: exit 1 naming the file.
    run -1 --separate-stderr trace $(inputs plate.stl) --material-map plate.map -o x.img
    [[ "$stderr" == "trace: $PWD/plate.stl: mesh 'plate' (1-1-0), facet '' (1-1-1): the face has no material name"* ||
        "$stderr" == "trace: plate.stl: mesh 'plate' (1-1-0), facet '' (1-1-1): the face has no material name"* ]] ||
        fail "stderr: $stderr"
    [ ! -e x.img ] || fail "an output cube was written"
}

@test "trace renders a DEM given as the scene as it renders the same DEM in an .odb" {
    write_dem
    printf 'OBJECT {\n    DEM_FILENAME = t.asc\n    MATERIAL_ID = 1\n    UNITS = m\n}\n' > dem.odb
    run -0 --separate-stderr trace $(inputs t.asc) --material-id 1 -o lone.img
    assert_equal "$stderr" ''
    run -0 --separate-stderr trace $(inputs dem.odb) -o odb.img
    run -0 cmp lone.img odb.img
    # Placed on the map alike: the DEM given as the scene lends its CRS (it gave none):
    # this oblique view gets the same geolocation arrays as the .odb route.
    run -0 cmp lone.geoloc.tif odb.geoloc.tif
    run -0 grep -qx 'sigchain geolocation = lone.geoloc.tif' lone.hdr
    # Land use by options: one class mapped to grass, the same picture.
    sed 's/[0-9][0-9]*\.5 /3 /g' t.asc > lu.asc
    cp t.prj lu.prj
    printf '3 1\n' > lu.map
    run -0 --separate-stderr trace $(inputs t.asc) --landuse lu.asc --landuse-map lu.map -o lu.img
    run -0 cmp lone.img lu.img
}

@test "a mesh or DEM scene without its materials is a usage error" {
    write_plate
    write_dem
    run -2 --separate-stderr trace $(inputs plate.obj) -o x.img
    [[ "$stderr" == "trace: plate.obj: a mesh given as the scene needs --material-map FILE or --material-id N"* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs t.asc) --landuse t.asc -o x.img
    [[ "$stderr" == "trace: --landuse and --landuse-map go together"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs plate.map) --material-id 1 -o x.img
    [[ "$stderr" == "trace: plate.map: the scene must be a .gdb or .odb file, a mesh"* ]] ||
        fail "stderr: $stderr"
    [ ! -e x.img ] || fail "an output cube was written"
}

@test "a scene option the scene does not use is refused, not ignored" {
    write_plate
    write_dem
    run -2 --separate-stderr trace $(inputs "$SEED/box_on_plane.gdb") --material-id 1 -o x.img
    [[ "$stderr" == "trace: --material-id does not apply to $SEED/box_on_plane.gdb, a .gdb or .odb scene (it names its materials itself)"* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs "$SEED/box_on_plane.gdb") --material-map plate.map -o x.img
    [[ "$stderr" == "trace: --material-map does not apply to "* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs plate.obj) --material-id 1 --landuse t.asc \
        --landuse-map plate.map -o x.img
    [[ "$stderr" == "trace: --landuse does not apply to plate.obj, a mesh scene"* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs t.asc) --material-id 1 --material-map plate.map -o x.img
    [[ "$stderr" == "trace: --material-map does not apply to t.asc, a DEM scene"* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr find_min_max_view_angle "$DATA/box.adv" "$SEED/box_on_plane.gdb" \
        --material-id 1
    [ ! -e x.img ] || fail "an output cube was written"
}

@test "a material missing from the map and an unreadable mesh are bad data" {
    write_plate
    printf 'grass 1\n' > grass.map
    run -1 --separate-stderr trace $(inputs plate.obj) --material-map grass.map -o x.img
    assert_equal "$stderr" "trace: plate.obj:9: material 'wood' is not in the material map grass.map"
    echo junk > bad.ply
    run -1 --separate-stderr trace $(inputs bad.ply) --material-id 1 -o x.img
    assert_equal "$stderr" "trace: bad.ply:1: not a PLY file (no 'ply' line)"
    run -1 --separate-stderr trace $(inputs missing.glb) --material-id 1 -o x.img
    assert_equal "$stderr" "trace: missing.glb: cannot open the mesh file"
    [ ! -e x.img ] || fail "an output cube was written"
    assert_no_temp_files .
}

@test "find_min_max_view_angle takes a glTF mesh and a DEM as the scene" {
    write_dem
    # The unit square at z = 0 (stored +Y up, turned to +Z up) seen from (10, -10, 30).
    run -0 --separate-stderr find_min_max_view_angle --snd -m scene-bounding-box \
        "$DATA/box.adv" "$MESHES/two_materials.glb" --material-map "$MESHES/two_materials.map"
    assert_output --partial "24.0 26.4 0.2"
    run -0 --separate-stderr find_min_max_view_angle --origin 43.08333,-77.66667 "$DATA/box.adv" \
        t.asc --material-id 1
    assert_line --index 2 --regexp '^scene-bounding-box +[0-9.]+ +[0-9.]+'
}

@test "trace --shadow-history and therm take a mesh given as the scene" {
    write_plate
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
    run -0 --separate-stderr trace --shadow-history --sky-rays 16 "$SEED/hawkeye.snd" plate.obj \
        box_on_plane.mat --material-map plate.map -o p.shd
    run -0 --separate-stderr therm p.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat plate.obj \
        "$SEED/hawkeye.snd" --material-map plate.map -o p.tmp
    assert_equal "$stderr" ''
    run -0 sigchain-check p.tmp
    # The OBJ's facet ids (odb(5)): object 1, no g, faces 1 and 2.
    run -0 awk '$1 ~ /^[0-9]/ { printf "%s ", $1 }' p.tmp
    assert_output "1-0-1 1-0-2 "
}

# deg.ply: the plate (clean.ply) with three degenerate faces among its two: a repeated
# vertex (1-1-2), collinear vertices (1-1-3) and one point thrice (1-1-4).
write_degenerate() {
    local header='ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n'
    header+='property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n'
    header+='0 0 0\n20 0 0\n20 20 0\n0 20 0\n10 0 0\n'
    printf "$header"'3 0 1 2\n3 0 1 1\n3 0 4 1\n3 3 3 3\n3 0 2 3\n' 5 > deg.ply
    printf "$header"'3 0 1 2\n3 0 2 3\n' 2 > clean.ply
}

@test "a mesh's degenerate facets are skipped with one summary line; --strict-mesh refuses them" {
    write_degenerate
    run -0 --separate-stderr trace $(inputs deg.ply) --material-id 1 -o deg.img
    assert_equal "$stderr" "trace: warning: deg.ply: 3 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4)"
    # Embree never hits a zero-area triangle: the picture is the clean plate's.
    run -0 --separate-stderr trace $(inputs clean.ply) --material-id 1 -o clean.img
    run -0 cmp deg.img clean.img
    # --allow-degenerate is about .gdb files and DEMs: the same single line.
    run -0 --separate-stderr trace $(inputs deg.ply) --material-id 1 --allow-degenerate -o a.img
    assert_equal "$stderr" "trace: warning: deg.ply: 3 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4)"
    run -0 --separate-stderr trace -q $(inputs deg.ply) --material-id 1 -o q.img
    assert_equal "$stderr" ''
    run -1 --separate-stderr trace $(inputs deg.ply) --material-id 1 --strict-mesh -o x.img
    assert_equal "$stderr" "trace: deg.ply: mesh '' (1-1-0), facet '' (1-1-2): vertices 2 and 3 coincide (a degenerate facet; skipped without --strict-mesh)"
    [ ! -e x.img ] || fail "an output cube was written"
    # An OBJ's summary gives the lines of its f statements.
    printf 'v 0 0 0\nv 20 0 0\nv 20 20 0\nf 1 2 2\nf 1 2 3\n' > deg.obj
    run -0 --separate-stderr trace $(inputs deg.obj) --material-id 1 -o obj.img
    assert_equal "$stderr" "trace: warning: deg.obj: 1 degenerate facet skipped (0-0-1 at line 4)"
    assert_no_temp_files .
}

@test "a real mesh with degenerate facets (assimp-testmodels' spider) renders with one summary line" {
    local spider=/usr/share/assimp/models/STL/Spider_ascii.stl
    [ -r "$spider" ] || skip "assimp-testmodels is not installed"
    # The spider (about 6 x 8 x 3.3 m about its origin) stood on the box's target point.
    printf 'OBJECT {\n    MESH_FILENAME = %s\n    MATERIAL_ID = 37\n    UNITS = m\n' "$spider" > spider.odb
    printf '    INSTANCES {\n        10,10,1.65, 1,1,1, 0,0,0\n    }\n}\n' >> spider.odb
    run -0 --separate-stderr trace $(inputs spider.odb) -o spider.img
    assert_equal "$stderr" "trace: warning: $spider: 56 degenerate facets skipped (1-1-925, 1-1-928, 1-1-931, ...)"
    run -1 --separate-stderr trace $(inputs spider.odb) --strict-mesh -o x.img
    assert_equal "$stderr" "trace: $spider: mesh 'NoName_1' (1-1-0), facet '' (1-1-925): all vertices coincide (a degenerate facet; skipped without --strict-mesh)"
    [ ! -e x.img ] || fail "an output cube was written"
}

@test "trace --shadow-history and therm skip a mesh's degenerate facets as the render does" {
    write_degenerate
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
    run -0 --separate-stderr trace --shadow-history --sky-rays 16 "$SEED/hawkeye.snd" deg.ply \
        box_on_plane.mat --material-id 1 -o deg.shd
    assert_equal "$stderr" "trace: warning: deg.ply: 3 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4)"
    # therm reads the same facets (its note of them only with -v) and finds each history.
    run -0 --separate-stderr therm deg.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat deg.ply \
        "$SEED/hawkeye.snd" --material-id 1 -o deg.tmp
    assert_equal "$stderr" ''
    run -0 awk '$1 ~ /^[0-9]/ { printf "%s ", $1 }' deg.tmp
    assert_output "1-1-1 1-1-5 "
    # The render meets the same keys: no warning about unmatched ones.
    run -0 --separate-stderr trace $(inputs deg.ply) --material-id 1 --tmp deg.tmp -o t.img
    assert_equal "$stderr" "trace: warning: deg.ply: 3 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4)"
    run -1 --separate-stderr therm deg.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat deg.ply \
        "$SEED/hawkeye.snd" --material-id 1 --strict-mesh -o x.tmp
    [[ "$stderr" == "therm: deg.ply: mesh '' (1-1-0), facet '' (1-1-2): "* ]] || fail "stderr: $stderr"
}

# yup.ply: the plate stored +Y up, (x, y, z) -> (x, 0, -y); plate.gltf: the same four
# vertices (float32, base64: 0 0 0, 20 0 0, 20 0 -20, 0 0 -20) and triangles
# (uint16: 0 1 2, 0 2 3), as glTF 2.0 stores a +Y-up mesh.
write_y_up() {
    printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n' > yup.ply
    printf 'property float z\nelement face 2\nproperty list uchar int vertex_indices\n' >> yup.ply
    printf 'end_header\n0 0 0\n20 0 0\n20 0 -20\n0 0 -20\n3 0 1 2\n3 0 2 3\n' >> yup.ply
    cat > plate.gltf <<'EOF2'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACgQQAAAAAAAAAAAACgQQAAAAAAAKDBAAAAAAAAAAAAAKDBAAABAAIAAAACAAMA"}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                 {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [0, 0, -20], "max": [20, 0, 0]},
               {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
EOF2
}

@test "--up-axis +Y turns a PLY as the glTF route, a Z-up copy and a turned .odb place it" {
    write_degenerate
    write_y_up
    run -0 --separate-stderr trace $(inputs yup.ply) --material-id 1 --up-axis +Y -o yup.img
    assert_equal "$stderr" ''
    run -0 --separate-stderr trace $(inputs plate.gltf) --material-id 1 -o gltf.img
    run -0 cmp yup.img gltf.img
    run -0 --separate-stderr trace $(inputs clean.ply) --material-id 1 -o zup.img
    run -0 cmp yup.img zup.img
    printf 'OBJECT {\n    MESH_FILENAME = yup.ply\n    MATERIAL_ID = 1\n    UNITS = m\n' > turned.odb
    printf '    INSTANCES {\n        0,0,0, 1,1,1, 90,0,0\n    }\n}\n' >> turned.odb
    run -0 --separate-stderr trace $(inputs turned.odb) -o odb.img
    run -0 cmp yup.img odb.img
    # Without it the plate stands on the x axis, edge-on to nothing the camera sees.
    run -0 --separate-stderr trace $(inputs yup.ply) --material-id 1 -o standing.img
    [[ "$stderr" == *"no primary ray hit the scene"* ]] || fail "stderr: $stderr"
    # The shadow history and therm read it the same way (one scene option block).
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
    run -0 --separate-stderr trace --shadow-history --sky-rays 16 "$SEED/hawkeye.snd" yup.ply \
        box_on_plane.mat --material-id 1 --up-axis +Y -o yup.shd
    run -0 --separate-stderr trace --shadow-history --sky-rays 16 "$SEED/hawkeye.snd" clean.ply \
        box_on_plane.mat --material-id 1 -o zup.shd
    run -0 cmp yup.shd zup.shd
    run -0 --separate-stderr therm yup.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat yup.ply \
        "$SEED/hawkeye.snd" --material-id 1 --up-axis +Y -o yup.tmp
    run -0 --separate-stderr therm zup.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat clean.ply \
        "$SEED/hawkeye.snd" --material-id 1 -o zup.tmp
    run -0 cmp yup.tmp zup.tmp
}

@test "--up-axis is refused where it does not apply or contradicts the file's own axis" {
    write_y_up
    write_dem
    run -2 --separate-stderr trace $(inputs plate.gltf) --material-id 1 --up-axis +Z -o x.img
    assert_equal "$stderr" "trace: plate.gltf: --up-axis +Z contradicts the file's own up axis, +Y (glTF 2.0, section 3.4)
Try 'trace --help'."
    run -0 --separate-stderr trace $(inputs plate.gltf) --material-id 1 --up-axis +y -o agreed.img
    run -2 --separate-stderr trace $(inputs "$SEED/box_on_plane.gdb") --up-axis +Y -o x.img
    [[ "$stderr" == "trace: --up-axis does not apply to $SEED/box_on_plane.gdb: it turns a mesh given as the scene (an .odb turns its mesh objects by their INSTANCES)"* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr trace $(inputs t.asc) --material-id 1 --up-axis +Y -o x.img
    [[ "$stderr" == "trace: --up-axis does not apply to t.asc: it turns a mesh given as the scene"$'\n'* ]] ||
        fail "stderr: $stderr"
    run -2 --separate-stderr find_min_max_view_angle "$DATA/box.adv" yup.ply --up-axis up
    [[ "$stderr" == "find_min_max_view_angle: --up-axis: up: must be +X, -X, +Y, -Y, +Z or -Z"* ]] ||
        fail "stderr: $stderr"
    [ ! -e x.img ] || fail "an output cube was written"
}

@test "find_min_max_view_angle needs no materials, and a DEM GeoTIFF places itself about its centre" {
    write_degenerate
    write_dem
    # Geometry only: the mesh without --material-id gives the report it gives with one,
    # its degenerate facets told in one line as trace tells them.
    run -0 --separate-stderr find_min_max_view_angle "$DATA/box.adv" clean.ply --material-id 1
    local with="$output"
    run -0 --separate-stderr find_min_max_view_angle "$DATA/box.adv" deg.ply
    assert_equal "$output" "$with"
    assert_equal "$stderr" "find_min_max_view_angle: warning: deg.ply: 3 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4)"
    run -1 --separate-stderr find_min_max_view_angle --strict-mesh "$DATA/box.adv" deg.ply
    [[ "$stderr" == "find_min_max_view_angle: deg.ply: mesh '' (1-1-0), facet '' (1-1-2): "* ]] ||
        fail "stderr: $stderr"
    # t.asc's 6 x 6 cells of 0.0001 deg from 43.08323 N, 77.66677 W: centre 43.08353 N,
    # 77.66647 W. As a GeoTIFF without --origin the DEM is placed about that point.
    run -0 gdal_translate -q t.asc t.tif
    run -0 --separate-stderr find_min_max_view_angle --origin 43.08353,-77.66647 "$DATA/box.adv" \
        t.tif --material-id 1
    with="$output"
    run -0 --separate-stderr find_min_max_view_angle -v "$DATA/box.adv" t.tif
    assert_equal "$output" "$with"
    assert_line --index 2 --regexp '^scene-bounding-box +-?[0-9.]+ +[0-9.]+'
    [[ "$stderr" == *"t.tif: placed about its centre, latitude 43.083530 deg, longitude -77.666470 deg (no --origin)"* ]] ||
        fail "stderr: $stderr"
    # An .odb's DEM object still needs --origin (find_min_max_view_angle.bats): it is
    # placed with the scene's other objects.
}
