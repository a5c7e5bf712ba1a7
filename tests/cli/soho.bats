#!/usr/bin/env bats
# Tests: soho_scene and data/scenes/soho/Makefile (the Soho scene)
# Also requires: sigchain-check, python3 (its sqlite3 module reads the GeoPackage as an
# independent count), and for the chain control7, find_min_max_view_angle,
# build_radiance, trace, sensorize
# The Soho scene: 158 building footprints extruded by the seeded storey rule.

load test_helper

SOHO="$SIGCHAIN_SOURCE_DIR/data/scenes/soho"

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    # soho_scene (tools/soho_scene) is built into the same bin/ as the other tools.
    command -v soho_scene > /dev/null || skip "soho_scene not built in $SIGCHAIN_BIN"
}

# Footprints and their distinct vertices (ring points less the closing one), read from
# the GeoPackage's WKB with sqlite3, independently of GDAL and of the generator.
gpkg_counts() {
    python3 - "$1" <<'PY'
import sqlite3, struct, sys
rings = vertices = 0
for (g,) in sqlite3.connect(sys.argv[1]).execute("select geom from buildings"):
    envelope = {0: 0, 1: 32, 2: 48, 3: 48, 4: 64}[(g[3] >> 1) & 7]
    w = g[8 + envelope:]
    bo = "<" if w[0] == 1 else ">"
    assert struct.unpack(bo + "I", w[1:5])[0] == 3  # polygon
    assert struct.unpack(bo + "I", w[5:9])[0] == 1  # no holes
    rings += 1
    vertices += struct.unpack(bo + "I", w[9:13])[0] - 1
print(rings, vertices)
PY
}

@test "soho: the generated .gdb passes sigchain-check and has a facet per footprint edge" {
    run -0 --separate-stderr soho_scene "$SOHO/buildings.gpkg" -o soho.gdb
    read -r footprints vertices < <(gpkg_counts "$SOHO/buildings.gpkg")
    [ "$footprints" -eq 158 ]
    # Each footprint of n vertices: n wall quads and n - 2 roof triangles; plus the ground.
    facets=$((1 + 2 * vertices - 2 * footprints))
    [[ "$stderr" == *"$footprints footprints, $footprints buildings (0 skipped"* ]]
    [[ "$stderr" == *"$facets facets: $((vertices - 2 * footprints)) roof triangles, $vertices wall quads"* ]]
    run -0 --separate-stderr sigchain-check soho.gdb
    assert_output "soho.gdb: ok: $((footprints + 1)) objects, $((2 * footprints + 1)) parts, $facets facets"
    [ "$(grep -c '^FACE$' soho.gdb)" -eq "$facets" ]
}

@test "soho: roof heights follow the storey rule (3 to 7 storeys of 3.2 m) and the seed" {
    run -0 soho_scene --seed 7 "$SOHO/buildings.gpkg" -o a.gdb
    run -0 soho_scene --seed 7 "$SOHO/buildings.gpkg" -o b.gdb
    run -0 cmp a.gdb b.gdb
    # The default seed is the scene's 7; "-o -" writes the same bytes to stdout.
    run -0 soho_scene "$SOHO/buildings.gpkg" -o d.gdb
    run -0 cmp a.gdb d.gdb
    soho_scene -q "$SOHO/buildings.gpkg" -o - > e.gdb
    run -0 cmp a.gdb e.gdb
    run -0 soho_scene --seed 8 "$SOHO/buildings.gpkg" -o c.gdb
    run -1 cmp -s a.gdb c.gdb
    # Every roof vertex's z (field 13 after FACE is the vertex count, the vertices
    # follow; field 3 the material) is a storey height; all five storey counts occur.
    run -0 awk '$0 == "FACE" { k = 0; next } { k++ } k == 3 { roof = $0 == "roof" }
        k == 13 { n = $1 } roof && k > 13 && k <= 13 + n { h[sprintf("%.9g", $3)] = 1 }
        END { for (z in h) print z }' a.gdb
    run -0 sort -n <<< "$output"
    assert_output "$(printf '9.6\n12.8\n16\n19.2\n22.4')"
}

@test "soho: soho_scene --help, --version, usage and data errors" {
    run -0 --separate-stderr soho_scene --help
    assert_line --index 0 "Usage: soho_scene [OPTIONS] FOOTPRINTS -o GDB"
    assert_line "See soho_scene(1)."
    run -0 --separate-stderr soho_scene --version
    assert_output --regexp "^soho_scene \(sigchain\) [0-9]+[.][0-9]+[.][0-9]+$"
    run -2 --separate-stderr soho_scene "$SOHO/buildings.gpkg"
    [ "$stderr" = "soho_scene: -o FILE is required
Try 'soho_scene --help'." ]
    run -2 --separate-stderr soho_scene --frobnicate "$SOHO/buildings.gpkg" -o x.gdb
    echo "not a vector file" > bad.gpkg
    run -1 --separate-stderr soho_scene bad.gpkg -o x.gdb
    [[ "$stderr" == "soho_scene: bad.gpkg"* ]]
    [ ! -e x.gdb ]
}

@test "soho: make runs the chain to counts and a preview" {
    run -0 make -C "$SOHO" -j2 OUT="$BATS_TEST_TMPDIR/out" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
        SOHO_SCENE="$(command -v soho_scene)"
    [ -s out/soho.gdb ] && [ -s out/soho.tif ] && [ -s out/soho.png ]
    run -0 --separate-stderr sigchain-check out/soho.snd out/soho-1.rad out/soho-2.rad out/soho-3.rad
    # A second make runs no stage.
    run -0 make -C "$SOHO" OUT="$BATS_TEST_TMPDIR/out" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
        SOHO_SCENE="$(command -v soho_scene)"
    refute_output --regexp "soho_scene |build_radiance |trace |sensorize "
}
