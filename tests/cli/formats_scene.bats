# Tests: sigchain-check (formats .mat .gdb .odb .shd)
# Also requires: tests/data/white1996/ (hawkeye.mat, box_on_plane.gdb, neighbourhood.odb,
#   box_on_plane.shd), tests/data/geom/ (plane_100m.gdb, tower.gdb), tests/data/bad/mat/,
#   tests/data/bad/gdb/, tests/data/bad/odb/, tests/data/bad/shd/,
#   tests/golden/sigchain-check/ (scene_messy.*)

bats_require_minimum_version 1.5.0
load test_helper

# check_golden FORMAT: --rewrite of scene_messy.FORMAT matches its canonical golden, which
# re-checks and rewrites to itself.
check_golden() {
    run -0 sigchain-check --rewrite -o "out.$1" "$GOLDEN/sigchain-check/scene_messy.$1"
    assert_golden "out.$1" "$GOLDEN/sigchain-check/scene_messy.canonical.$1"
    run -0 sigchain-check -q "out.$1"
    run -0 sigchain-check --rewrite -o "again.$1" "out.$1"
    run -0 cmp "out.$1" "again.$1"
    assert_no_temp_files .
}

# --- .mat: good input ---------------------------------------------------------
@test "mat: the sample of White (1996), fig. 4.34, is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/hawkeye.mat"
    assert_output "$SEED/hawkeye.mat: ok: 1 material"
    assert_equal "$stderr" ''
}

@test "mat: reads standard input with -f mat" {
    run -0 --separate-stderr sigchain-check -f mat - < "$SEED/hawkeye.mat"
    assert_output --partial "-: ok: 1 material"
}

@test "mat: --rewrite gives the canonical form (golden), which re-checks" {
    check_golden mat
}

# --- .mat: bad input (one test per class) -------------------------------------
@test "mat: bad: bad optical" {
    check_bad mat bad_optical.mat "11" "expected OPTICAL_DESCRIPTION OPAQUE, UNIFORM_TRANSMISSION or NONUNIFORM_TRANSMISSION, found 'CLEAR'"
}

@test "mat: bad: binary" {
    check_bad mat binary.mat "2" "binary data (NUL byte); expected a text file"
}

@test "mat: bad: brace missing" {
    check_bad mat brace_missing.mat "1" "expected 'MATERIAL_ENTRY {' (brace on the same line), found 'MATERIAL_ENTRY'"
}

@test "mat: bad: comments only" {
    check_bad mat comments_only.mat "" "empty file, expected a material entry (MATERIAL_ENTRY_BEGIN)"
}

@test "mat: bad: duplicate id" {
    check_bad mat duplicate_id.mat "17" "duplicate MATERIAL_ID 1 (first in the entry begun at line 1)"
}

@test "mat: bad: duplicate name" {
    check_bad mat duplicate_name.mat "16" "duplicate MATERIAL_NAME 'grass' (first in the entry begun at line 1)"
}

@test "mat: bad: empty" {
    check_bad mat empty.mat "" "empty file, expected a material entry (MATERIAL_ENTRY_BEGIN)"
}

@test "mat: bad: infinity" {
    check_bad mat infinity.mat "5" "expected THERMAL_CONDUCTIVITY (a finite number), found 'inf'"
}

@test "mat: bad: missing parameter" {
    check_bad mat missing_parameter.mat "13" "expected tag TABLE_FILE with REFLECTANCE_MODEL = table, found none in the entry"
}

@test "mat: bad: missing tag" {
    check_bad mat missing_tag.mat "12" "expected tag EMISSIVITY_FILE in the entry begun at line 1, found MATERIAL_ENTRY_END"
}

@test "mat: bad: model parameter" {
    check_bad mat model_parameter.mat "14" "unexpected tag PHONG_EXPONENT: it belongs to REFLECTANCE_MODEL = phong, this entry's model is cone"
}

@test "mat: bad: nan" {
    check_bad mat nan.mat "10" "expected EXPOSED_AREA (a finite number), found 'nan'"
}

@test "mat: bad: negative density" {
    check_bad mat negative_density.mat "6" "expected MASS_DENSITY 0 or more, found '-1'"
}

@test "mat: bad: negative id" {
    check_bad mat negative_id.mat "3" "expected MATERIAL_ID (a count, 0 or more), found '-1'"
}

@test "mat: bad: nested" {
    check_bad mat nested.mat "13" "expected a tag or MATERIAL_ENTRY_END for the entry begun at line 1, found 'MATERIAL_ENTRY_BEGIN'"
}

@test "mat: bad: no extinction" {
    check_bad mat no_extinction.mat "11" "expected tag EXTINCTION_FILE with OPTICAL_DESCRIPTION = UNIFORM_TRANSMISSION, found none in the entry"
}

@test "mat: bad: not number" {
    check_bad mat not_number.mat "6" "expected MASS_DENSITY (a number), found 'heavy'"
}

@test "mat: bad: not tag value" {
    check_bad mat not_tag_value.mat "7" "expected TAG = value or MATERIAL_ENTRY_END, found 'SPECULARITY 0.0'"
}

@test "mat: bad: outside entry" {
    check_bad mat outside_entry.mat "1" "expected MATERIAL_ENTRY_BEGIN or 'MATERIAL_ENTRY {', found 'MATERIAL_NAME = grass'"
}

@test "mat: bad: repeated tag" {
    check_bad mat repeated_tag.mat "13" "repeated tag SPECULARITY (first at line 7)"
}

@test "mat: bad: specularity range" {
    check_bad mat specularity_range.mat "7" "expected SPECULARITY in [0, 1], found '1.5'"
}

@test "mat: bad: unknown tag" {
    check_bad mat unknown_tag.mat "7" "expected a material tag (see mat(5)), found unknown tag 'SPECULARTY'"
}

@test "mat: bad: unterminated" {
    check_bad mat unterminated.mat "12" "unexpected end of file, expected MATERIAL_ENTRY_END for the entry begun at line 1"
}

@test "mat: bad: wrong end" {
    check_bad mat wrong_end.mat "13" "expected a tag or MATERIAL_ENTRY_END for the entry begun at line 1, found '}'"
}

# --- .gdb: good input ---------------------------------------------------------
@test "gdb: the training scene (box on a plane) is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/box_on_plane.gdb"
    assert_output "$SEED/box_on_plane.gdb: ok: 2 objects, 2 parts, 6 facets"
    assert_equal "$stderr" ''
}

@test "gdb: the view-angle test scenes are valid" {
    run -0 --separate-stderr sigchain-check "$SIGCHAIN_SOURCE_DIR/tests/data/geom/plane_100m.gdb" "$SIGCHAIN_SOURCE_DIR/tests/data/geom/tower.gdb"
    assert_line --index 0 --partial "plane_100m.gdb: ok: 1 object, 1 part, 1 facet"
    assert_line --index 1 --partial "tower.gdb: ok: 2 objects, 2 parts, 6 facets"
    assert_equal "$stderr" ''
}

@test "gdb: reads standard input with -f gdb" {
    run -0 --separate-stderr sigchain-check -f gdb - < "$SEED/box_on_plane.gdb"
    assert_output --partial "-: ok: 2 objects, 2 parts, 6 facets"
}

@test "gdb: --rewrite gives the canonical form (golden), which re-checks" {
    check_golden gdb
}

@test "gdb: degenerate facets are legal, and counted in the summary" {
    # A triangle with two equal vertices: legal (gdb(5)), reported by gdb_problems.
    printf '%s\n' OBJECT o 1-0-0 PART p 1-1-0 FACE f 1-1-1 grass 1 p -1 5 -1 -1 null null null \
        3 '0 0 0' '1 0 0' '1 0 0' '0 0 1' 0 0 null END > degenerate.gdb
    run -0 --separate-stderr sigchain-check degenerate.gdb
    assert_output "degenerate.gdb: ok: 1 object, 1 part, 1 facet, 2 geometry problems"
}

@test "gdb: --rewrite of a bad file fails and writes nothing" {
    run -1 --separate-stderr sigchain-check --rewrite -o out.gdb "$BAD/gdb/missing_end.gdb"
    [[ "$stderr" == *"missing_end.gdb:28: unexpected end of file"* ]]
    [ ! -e out.gdb ]
    assert_no_temp_files .
}

# --- .gdb: bad input (one test per class) -------------------------------------
@test "gdb: bad: after end" {
    check_bad gdb after_end.gdb "30" "unexpected content after END, found 'OBJECT'"
}

@test "gdb: bad: bad id" {
    check_bad gdb bad_id.gdb "9" "expected facet id (three dash-separated integers such as 1-1-0), found '1-1'"
}

@test "gdb: bad: binary" {
    check_bad gdb binary.gdb "2" "binary data (NUL byte); expected a text file"
}

@test "gdb: bad: empty" {
    check_bad gdb empty.gdb "" "empty file, expected OBJECT or END"
}

@test "gdb: bad: face outside part" {
    check_bad gdb face_outside_part.gdb "4" "expected PART before FACE, found FACE outside a PART"
}

@test "gdb: bad: field count" {
    check_bad gdb field_count.gdb "23" "expected 3 fields (vertex x y z), found 2: '1 1'"
}

@test "gdb: bad: missing end" {
    check_bad gdb missing_end.gdb "28" "unexpected end of file, expected OBJECT, PART, FACE or END (a .gdb ends with END)"
}

@test "gdb: bad: missing field" {
    check_bad gdb missing_field.gdb "28" "expected facet spare field, found keyword 'END'"
}

@test "gdb: bad: nan" {
    check_bad gdb nan.gdb "23" "expected vertex x y z (a finite number), found 'nan'"
}

@test "gdb: bad: negative material id" {
    check_bad gdb negative_material_id.gdb "11" "expected material id (a count, 0 or more), found '-1'"
}

@test "gdb: bad: not number" {
    check_bad gdb not_number.gdb "23" "expected vertex x y z (a number), found 'one'"
}

@test "gdb: bad: part outside object" {
    check_bad gdb part_outside_object.gdb "1" "expected OBJECT before PART, found PART outside an OBJECT"
}

@test "gdb: bad: temperature range" {
    check_bad gdb temperature_range.gdb "13" "expected temperature (C) -1 or at least -273.15, found -300"
}

@test "gdb: bad: truncated" {
    check_bad gdb truncated.gdb "22" "unexpected end of file, expected vertex x y z"
}

@test "gdb: bad: unknown keyword" {
    check_bad gdb unknown_keyword.gdb "4" "expected OBJECT, PART, FACE or END (a .gdb ends with END), found 'PARTS'"
}

@test "gdb: bad: vertex count" {
    check_bad gdb vertex_count.gdb "20" "expected vertex count 3 or 4, found '5'"
}

@test "gdb: bad: zenith range" {
    check_bad gdb zenith_range.gdb "26" "expected slope zenith (deg) in [0, 180], found '200'"
}

@test "gdb: bad: zero normal" {
    check_bad gdb zero_normal.gdb "25" "expected a non-zero normal, found 0 0 0"
}

# --- .odb: good input ---------------------------------------------------------
@test "odb: the neighbourhood sample is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/neighbourhood.odb"
    assert_output "$SEED/neighbourhood.odb: ok: 1 object, 3 placements"
    assert_equal "$stderr" ''
}

@test "odb: reads standard input with -f odb" {
    run -0 --separate-stderr sigchain-check -f odb - < "$SEED/neighbourhood.odb"
    assert_output --partial "-: ok: 1 object, 3 placements"
}

@test "odb: --rewrite gives the canonical form (golden), which re-checks" {
    check_golden odb
}

# --- .odb: bad input (one test per class) -------------------------------------
@test "odb: bad: bad units" {
    check_bad odb bad_units.odb "3" "expected UNITS m or ft, found 'yards'"
}

@test "odb: bad: binary" {
    check_bad odb binary.odb "2" "binary data (NUL byte); expected a text file"
}

@test "odb: bad: brace missing" {
    check_bad odb brace_missing.odb "1" "expected 'OBJECT {' (brace on the same line), found 'OBJECT'"
}

@test "odb: bad: empty" {
    check_bad odb empty.odb "" "empty file, expected 'OBJECT {'"
}

@test "odb: bad: empty instances" {
    check_bad odb empty_instances.odb "5" "expected at least one instance in INSTANCES (omit the block for one identity instance), found '}'"
}

@test "odb: bad: field count" {
    check_bad odb field_count.odb "5" "expected an instance x,y,z, sx,sy,sz, rx,ry,rz (9 numbers) or MATRIX, found 8 fields: '10,20,0, 1,1,1, 0,0'"
}

@test "odb: bad: infinity" {
    check_bad odb infinity.odb "5" "expected instance value (a finite number), found 'inf'"
}

@test "odb: bad: map on gdb" {
    check_bad odb map_on_gdb.odb "4" "unexpected key MATERIAL_MAP: it belongs to OBJ_FILENAME and MESH_FILENAME objects"
}

@test "odb: bad: matrix last row" {
    check_bad odb matrix_last_row.odb "5" "expected MATRIX last row 0 0 0 1, found 0 0 1 1"
}

@test "odb: bad: matrix singular" {
    check_bad odb matrix_singular.odb "5" "expected an invertible MATRIX, found a singular 3x3 part"
}

@test "odb: bad: matrix too few" {
    check_bad odb matrix_too_few.odb "8" "expected MATRIX element (a number), found '}'"
}

@test "odb: bad: matrix too many" {
    check_bad odb matrix_too_many.odb "8" "expected 16 MATRIX numbers, found 17"
}

@test "odb: bad: negative material id" {
    check_bad odb negative_material_id.odb "4" "expected MATERIAL_ID (a count, 0 or more), found '-2'"
}

@test "odb: bad: nested" {
    check_bad odb nested.odb "4" "expected a key or '}' closing the OBJECT begun at line 1, found 'OBJECT {'"
}

@test "odb: bad: no source" {
    check_bad odb no_source.odb "6" "expected GDB_FILENAME, OBJ_FILENAME, MESH_FILENAME or DEM_FILENAME in the OBJECT begun at line 1, found '}'"
}

@test "odb: bad: no units" {
    check_bad odb no_units.odb "6" "expected key UNITS (m or ft) in the OBJECT begun at line 1, found '}'"
}

@test "odb: bad: not number" {
    check_bad odb not_number.odb "5" "expected instance value (a number), found 'ninety'"
}

@test "odb: bad: obj without map" {
    check_bad odb obj_without_map.odb "2" "expected key MATERIAL_MAP with OBJ_FILENAME, found none in the OBJECT"
}

@test "odb: bad: outside object" {
    check_bad odb outside_object.odb "1" "expected 'OBJECT {', found 'GDB_FILENAME = box.gdb'"
}

@test "odb: bad: repeated key" {
    check_bad odb repeated_key.odb "4" "repeated key UNITS (first at line 3)"
}

@test "odb: bad: two sources" {
    check_bad odb two_sources.odb "4" "expected only one of GDB_FILENAME, OBJ_FILENAME, MESH_FILENAME and DEM_FILENAME, found a second one"
}

@test "odb: bad: unknown key" {
    check_bad odb unknown_key.odb "3" "expected an OBJECT key (see odb(5)), found unknown key 'UNIT'"
}

@test "odb: bad: unterminated" {
    check_bad odb unterminated.odb "6" "unexpected end of file, expected '}' closing the OBJECT begun at line 1"
}

@test "odb: bad: zero scale" {
    check_bad odb zero_scale.odb "5" "expected non-zero scale factors sx,sy,sz, found '1','0','1'"
}

# --- .shd: good input ---------------------------------------------------------
@test "shd: the box-on-plane sample is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/box_on_plane.shd"
    assert_output "$SEED/box_on_plane.shd: ok: 6 facets, 5 steps of 1 h ending at 38 h"
    assert_equal "$stderr" ''
}

@test "shd: reads standard input with -f shd" {
    run -0 --separate-stderr sigchain-check -f shd - < "$SEED/box_on_plane.shd"
    assert_output --partial "-: ok: 6 facets, 5 steps"
}

@test "shd: --rewrite gives the canonical form (golden), which re-checks" {
    check_golden shd
}

# --- .shd: bad input (one test per class) -------------------------------------
@test "shd: bad: binary" {
    check_bad shd binary.shd "2" "binary data (NUL byte); expected a text file"
}

@test "shd: bad: duplicate id" {
    check_bad shd duplicate_id.shd "11" "duplicate facet id '1-1-1'"
}

@test "shd: bad: facet key" {
    check_bad shd facet_key.shd "6" "expected a facet id such as 1-1-1 or 2.3/1-1-1, found 'roof'"
}

@test "shd: bad: empty" {
    check_bad shd empty.shd "" "empty file, expected '# sigchain-shd 1'"
}

@test "shd: bad: field count" {
    check_bad shd field_count.shd "9" "expected 3 fields (time, then sunlit fraction and transmittance for each of 1 points), found 2: '37.5 0.5'"
}

@test "shd: bad: missing key" {
    check_bad shd missing_key.shd "6" "expected header key steps before the first FACET, found none"
}

@test "shd: bad: nan" {
    check_bad shd nan.shd "9" "expected sunlit fraction (a finite number), found 'nan'"
}

@test "shd: bad: negative facets" {
    check_bad shd negative_facets.shd "5" "expected facets (a count, 0 or more), found '-1'"
}

@test "shd: bad: no magic" {
    check_bad shd no_magic.shd "1" "expected '# sigchain-shd 1' as the first line, found 'scene_time_hours = 38'"
}

@test "shd: bad: not number" {
    check_bad shd not_number.shd "9" "expected sunlit fraction (a number), found 'half'"
}

@test "shd: bad: repeated key" {
    check_bad shd repeated_key.shd "4" "repeated key steps (first at line 3)"
}

@test "shd: bad: sky view range" {
    check_bad shd sky_view_range.shd "7" "expected sky view factor in [0, 1], found '1.2'"
}

@test "shd: bad: sunlit range" {
    check_bad shd sunlit_range.shd "9" "expected sunlit fraction in [0, 1], found '1.5'"
}

@test "shd: bad: time grid" {
    check_bad shd time_grid.shd "9" "expected time 37.5 (hours, time step 2 of 3 for facet '1-1-1'), found '37.4'"
}

@test "shd: bad: too few facets" {
    check_bad shd too_few_facets.shd "14" "unexpected end of file, expected FACET 3 of 3 (facets = 3)"
}

@test "shd: bad: too few steps" {
    check_bad shd too_few_steps.shd "10" "expected time step 3 of 3 for facet '1-1-1', found 'FACET 2-1-1 1 2'"
}

@test "shd: bad: too many facets" {
    check_bad shd too_many_facets.shd "11" "expected end of file (facets = 1), found 'FACET 2-1-1 1 2'"
}

@test "shd: bad: too many steps" {
    check_bad shd too_many_steps.shd "15" "expected end of file (the last facet already has its steps = 3 time rows), found '38.5 1 1 1 1'"
}

@test "shd: bad: unknown key" {
    check_bad shd unknown_key.shd "3" "expected a header key (scene_time_hours, steps, step_hours, facets) or FACET, found 'stepz = 3'"
}

@test "shd: bad: version 2" {
    check_bad shd version_2.shd "1" "expected sigchain-shd version 1 or 1.N, found '2'"
}

@test "shd: bad: zero points" {
    check_bad shd zero_points.shd "7" "expected points 1 or more, found '0'"
}

@test "shd: bad: zero step hours" {
    check_bad shd zero_step_hours.shd "4" "expected step_hours greater than 0, found '0'"
}

@test "shd: bad: zero steps" {
    check_bad shd zero_steps.shd "3" "expected steps 1 or more, found '0'"
}
