# Tests: trace find_min_max_view_angle therm
# Also requires: sigchain-check
#
# Meshes (through Assimp) and DEM rasters given directly as the scene argument, against
# the same files placed by an .odb (odb(5) SCENE ARGUMENT, MESH_FILENAME, DEM_FILENAME):
# trace's box.adv camera (tests/data/trace) over a 20 m plate of two triangles (grass
# and wood of box.mat) or a 6 x 6-cell DEM written here about box.snd's point.

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
    run -1 --separate-stderr find_min_max_view_angle "$DATA/box.adv" t.asc --material-id 1
    [[ "$stderr" == *"t.asc: a DEM given as the scene needs the scene's geodetic origin"* ]] ||
        fail "stderr: $stderr"
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
