# Tests: trace find_min_max_view_angle (coordinates, meshes and DEMs that are wrong)
# Also requires: tests/data/trace, tests/data/white1996, tests/data/scene/flat.prj
#
# Every source of coordinates refuses what Embree cannot take (NaN, infinities, beyond
# +-1e9 scene units: a ray origin of 1e20 made Embree abort) with the file and line:
# .trj, .adv, .gdb, meshes (OBJ, STL, PLY), .odb instances. A PLY whose header or body
# is cut short is refused (Assimp looped forever on one, dropped faces of the other),
# as is a face index out of range. A DEM too large for the machine's memory, an ASCII
# grid with values missing or left over, and a negative cell size are refused by name.

bats_require_minimum_version 1.5.0
load ../cli/test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/trace"

inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "$1" "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad"
}

# refused WHAT CMD...: CMD exits 1 within 20 s with one line on stderr starting "WHAT";
# no output cube.
refused() {
    local want="$1"
    shift
    run --separate-stderr timeout 20 "$@"
    [ "$status" = 1 ] || fail "exit $status (wanted 1): $stderr"
    [[ "$stderr" == "$want"* ]] || fail "stderr: $stderr (wanted '$want...')"
    [ "$(printf '%s\n' "$stderr" | wc -l)" = 1 ] || fail "more than one line: $stderr"
    [ ! -e x.img ] || fail "an output cube was written"
}

# line.adv: a line scanner flying flight/roll.trj over box_on_plane.gdb.
scanner() {
    mkdir -p flight
    printf '# sigchain-trj 1\n0 10 0.5 %s 5 0 0\n10 10 40.5 30 5 0 0\n' "$1" > flight/roll.trj
    printf '10 10 0\n10 0 30\n90 -90 0\n32\n24 40\nunits = m\npixel_pitch_um = 500\n' > line.adv
    printf 'sensor = line\ntrajectory = flight/roll.trj\nscan_half_angle_deg = 20\n' >> line.adv
    printf 'scan_period_s = 0.5\ndetectors_per_scan = 4\n' >> line.adv
}

@test "a platform or camera position beyond what Embree handles is refused at its line" {
    local z
    for z in 1e+20 1e+300; do
        scanner $z
        refused "trace: flight/roll.trj:2: the position (10, 0.5, $z) lies beyond +-1e9" \
            trace line.adv "$DATA/box.snd" "$SEED/box_on_plane.gdb" "$DATA/box.mat" \
            "$DATA/band1.rad" "$DATA/band2.rad" -o x.img
        refused "find_min_max_view_angle: flight/roll.trj:2: the position" \
            find_min_max_view_angle line.adv "$SEED/box_on_plane.gdb"
    done
    # 1e9 itself is taken (a platform far away, but a number Embree handles).
    scanner 1e9
    run -0 --separate-stderr trace -q line.adv "$DATA/box.snd" "$SEED/box_on_plane.gdb" \
        "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o ok.img
    sed '4s/^10 -10 30/10 -10 1e20/' "$DATA/box.adv" > far.adv
    refused "trace: far.adv:4: camera point (10, -10, 1e+20) lies beyond" \
        trace far.adv "$DATA/box.snd" "$SEED/box_on_plane.gdb" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o x.img
}

@test "mesh and .gdb vertices that are NaN, infinite or beyond +-1e9 are refused" {
    local v
    for v in nan inf 1e300 -2e9; do
        printf 'o p\nv 0 0 0\nv 20 0 0\nv 20 20 %s\nusemtl grass\nf 1 2 3\n' "$v" > p.obj
        refused "trace: p.obj:6: object 'p'" trace $(inputs p.obj) --material-id 1 -o x.img
        printf 'solid p\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 20 0 0\n' > p.stl
        printf 'vertex 20 20 %s\nendloop\nendfacet\nendsolid p\n' "$v" >> p.stl
        refused "trace: p.stl: mesh" trace $(inputs p.stl) --material-id 1 -o x.img
        printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n' > p.ply
        printf 'property float z\nelement face 1\nproperty list uchar int vertex_indices\n' >> p.ply
        printf 'end_header\n0 0 0\n20 0 0\n20 20 %s\n3 0 1 2\n' "$v" >> p.ply
        case $v in
            nan | inf) refused "trace: p.ply:12: vertex 2: property z: '$v' is not a finite number" \
                trace $(inputs p.ply) --material-id 1 -o x.img ;;
            *) refused "trace: p.ply: mesh" trace $(inputs p.ply) --material-id 1 -o x.img ;;
        esac
    done
    # The .gdb's first vertex of the lawn (its line named).
    awk 'done == 0 && $0 == "0 0 0" { print "0 0 1e300"; done = 1; next } { print }' \
        "$SEED/box_on_plane.gdb" > far.gdb
    local line
    line=$(grep -n '^0 0 1e300$' far.gdb | cut -d: -f1)
    refused "trace: far.gdb:$line: expected vertex coordinates within +-1e+08, found 1e+300" \
        trace $(inputs far.gdb) -o x.img
}

@test "an .odb instance that carries its object beyond +-1e9 is refused at its line" {
    # Within the .odb's bounds (scale to 1e6, translation to 1e8), but 1e5 x 1e5 = 1e10.
    printf 'o p\nv 0 0 0\nv 1e5 0 0\nv 1e5 1e5 0\nusemtl grass\nf 1 2 3\n' > p.obj
    printf 'grass 1\n' > p.map
    {
        printf 'OBJECT {\n    MESH_FILENAME = p.obj\n    MATERIAL_MAP = p.map\n    UNITS = m\n'
        printf '    INSTANCES {\n        0,0,0, 1e5,1e5,1e5, 0,0,0\n    }\n}\n'
    } > far.odb
    run --separate-stderr trace $(inputs far.odb) -o x.img
    assert_equal "$status" 1
    [[ "$stderr" == "trace: far.odb:1: the instance places the object's vertex at ("*"), beyond +-1e9 scene units"* ]] ||
        fail "stderr: $stderr"
}

@test "a PLY cut short in its header or body, or with a face index out of range" {
    local plate="$SIGCHAIN_SOURCE_DIR/tests/data/meshes/two_triangles.ply" n
    # Cut in the header: Assimp looped forever.
    for n in 2 8 9; do
        head -$n "$plate" > t.ply
        refused "trace: t.ply:$n: the header has no end_header line (a truncated file?)" \
            trace $(inputs t.ply) --material-id 1 -o x.img
    done
    # Cut in the body: Assimp dropped the faces (15 lines: one face missing, exit 0).
    head -15 "$plate" > t.ply
    refused "trace: t.ply:15: the file ends after 1 of the 2 face lines (a truncated file?)" \
        trace $(inputs t.ply) --material-id 1 -o x.img
    head -12 "$plate" > t.ply
    refused "trace: t.ply:12: the file ends after 2 of the 4 vertex lines" \
        trace $(inputs t.ply) --material-id 1 -o x.img
    # A line more than the header counts.
    { cat "$plate"; echo "3 0 1 2"; } > t.ply
    refused "trace: t.ply:17: data after the last element" \
        trace $(inputs t.ply) --material-id 1 -o x.img
    # A face index of 99 ("internal error: vector::_M_range_check" before).
    sed 's/^3 0 2 3$/3 0 2 99/' "$plate" > t.ply
    grep -q ' 99$' t.ply
    refused "trace: t.ply: mesh" trace $(inputs t.ply) --material-id 1 -o x.img
    [[ "$stderr" == *"vertex index 99 is out of range: the mesh has 4 vertices" ]] ||
        fail "stderr: $stderr"
    # A binary PLY cut short.
    {
        printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n'
        printf 'property float y\nproperty float z\nelement face 1\n'
        printf 'property list uchar int vertex_indices\nend_header\n'
        printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\240A\0\0\0\0\0\0\0\0'
    } > b.ply
    refused "trace: b.ply: the file ends inside vertex 2 of 3 (a truncated file?)" \
        trace $(inputs b.ply) --material-id 1 -o x.img
}

# g.asc (+ g.prj): HEADER then the values given.
grid() {
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/scene/flat.prj" g.prj
    printf '%b' "$1" > g.asc
}

@test "a DEM larger than memory, an ASCII grid with values missing or extra, a negative cell" {
    # 100000 x 100000 cells: "out of memory" before, naming nothing.
    grid 'ncols 100000\nnrows 100000\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize 0.0001\n0 0\n'
    refused "trace: g.asc: 100000 x 100000 cells need about " \
        trace $(inputs g.asc) --material-id 1 -o x.img
    [[ "$stderr" == *"as terrain (two triangles per cell), more than this machine's "*" GiB of memory: crop it (gdal_translate -srcwin) or coarsen it (gdalwarp -tr)" ]] ||
        fail "stderr: $stderr"
    local head='ncols 2\nnrows 2\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize 0.0001\n'
    grid "${head}1 2\n3 4\n"
    run -0 --separate-stderr trace -q $(inputs g.asc) --material-id 1 -o ok.img
    grid "${head}1 2\n3 4\n5\n"
    refused "trace: g.asc:8: more values than the header's 2 x 2 (trailing data?)" \
        trace $(inputs g.asc) --material-id 1 -o x.img
    grid "${head}1 2\n3\n"
    refused "trace: g.asc:7: the file ends after 3 of the header's 2 x 2 values" \
        trace $(inputs g.asc) --material-id 1 -o x.img
    grid "${head}1 2\n3 x\n"
    refused "trace: g.asc:7: expected a height (a number), found 'x'" \
        trace $(inputs g.asc) --material-id 1 -o x.img
    grid 'ncols 2\nnrows 2\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize -0.0001\n1 2\n3 4\n'
    refused "trace: g.asc: the cell size is not positive (geotransform dx -1e-04, dy 1e-04)" \
        trace $(inputs g.asc) --material-id 1 -o x.img
}

@test "a DEM's bad .prj is named, with why, not blamed on the DEM" {
    local head='ncols 2\nnrows 2\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize 0.0001\n'
    grid "${head}1 2\n3 4\n"
    echo 'GEOGCS["broken' > g.prj
    refused "trace: g.prj: not a coordinate reference system GDAL reads (ESRI or OGC WKT): " \
        trace $(inputs g.asc) --material-id 1 -o x.img
    [[ "$stderr" == *"(so g.asc has none)" ]] || fail "stderr: $stderr"
    : > g.prj
    refused "trace: g.prj: the file is empty (so g.asc has none)" \
        trace $(inputs g.asc) --material-id 1 -o x.img
    rm g.prj
    refused "trace: g.asc: the DEM has no coordinate reference system" \
        trace $(inputs g.asc) --material-id 1 -o x.img
    # A directory named by an .odb is named with the .odb line that names it.
    mkdir sub.gdb
    printf 'OBJECT {\n    GDB_FILENAME = sub.gdb\n    UNITS = m\n}\n' > dir.odb
    refused "trace: dir.odb:1: sub.gdb: " trace $(inputs dir.odb) -o x.img
}
