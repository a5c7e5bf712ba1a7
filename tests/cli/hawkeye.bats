#!/usr/bin/env bats
# Tests: hawkeye_scene and data/scenes/hawkeye/Makefile (the hawkeye scene)
# Also requires: sigchain-check, and for the chain control7, find_min_max_view_angle,
# build_radiance, trace, sensorize
# The hawkeye scene: a generated .odb of .gdb files (terrain, pavement, instanced
# houses, garages, trees and vehicles, larger buildings, plant, bridge).

load test_helper

HAWKEYE="$SIGCHAIN_SOURCE_DIR/data/scenes/hawkeye"

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    # hawkeye_scene (tools/hawkeye_scene) is built into the build's bin/.
    command -v hawkeye_scene > /dev/null || skip "hawkeye_scene not built in $SIGCHAIN_BIN"
}

# Instance lines of the OBJECTs whose GDB_FILENAME matches the regex $2, in .odb $1,
# counted from the file's text independently of the generator's report.
odb_instances() {
    awk -v re="$2" '/GDB_FILENAME/ { on = $3 ~ re } /INSTANCES \{/ { inst = 1; next }
        inst && /^[ \t]*\}/ { inst = 0; next } inst && on && NF { n++ } END { print n + 0 }' "$1"
}

@test "hawkeye: the generated .odb and every .gdb pass sigchain-check; counts match" {
    mkdir s
    run -0 --separate-stderr hawkeye_scene 4 s
    [[ "$stderr" =~ ([0-9]+)\ structures\ \(([0-9]+)\ houses,\ ([0-9]+)\ garages,\ ([0-9]+)\ larger\ buildings,\ 1\ plant,\ 1\ bridge\),\ ([0-9]+)\ trees,\ ([0-9]+)\ vehicles\;\ ([0-9]+)\ files ]]
    structures=${BASH_REMATCH[1]} houses=${BASH_REMATCH[2]} garages=${BASH_REMATCH[3]}
    large=${BASH_REMATCH[4]} trees=${BASH_REMATCH[5]} vehicles=${BASH_REMATCH[6]}
    files=${BASH_REMATCH[7]}
    # "about 850 structures" and "about 3000 trees" (the scene's targets).
    [ "$structures" -ge 750 ] && [ "$structures" -le 950 ]
    [ "$trees" -ge 2800 ] && [ "$trees" -le 3200 ]
    [ "$structures" -eq $((houses + garages + large + 2)) ]
    [ "$(ls s | wc -l)" -eq "$files" ]
    # Three house types and a garage in ten colours.
    [ "$(ls s/fancy-*.gdb s/house1-*.gdb s/house2-*.gdb s/garage-*.gdb | wc -l)" -eq 40 ]
    run -0 --separate-stderr sigchain-check s/hawkeye.odb
    assert_output --regexp "^s/hawkeye.odb: ok: $((files - 1)) objects, [0-9]+ placements$"
    for f in s/*.gdb; do
        run -0 --separate-stderr sigchain-check "$f"
        assert_output --regexp "^$f: ok: "
    done
    [ "$(odb_instances s/hawkeye.odb '^(fancy|house1|house2)-')" -eq "$houses" ]
    [ "$(odb_instances s/hawkeye.odb '^garage-')" -eq "$garages" ]
    [ "$(odb_instances s/hawkeye.odb '^tree[.]gdb$')" -eq "$trees" ]
    [ "$(odb_instances s/hawkeye.odb '^vehicle-')" -eq "$vehicles" ]
    # Every tree is the same 20-facet mesh (the budget per tree of White (1996)).
    [ "$(grep -c '^FACE$' s/tree.gdb)" -eq 20 ]
}

@test "hawkeye: same seed, same files; another seed, another scene" {
    mkdir a b c
    run -0 hawkeye_scene 4 a
    run -0 hawkeye_scene 4 b
    run -0 diff -r a b
    run -0 hawkeye_scene 5 c
    run -1 cmp -s a/terrain.gdb c/terrain.gdb
}

@test "hawkeye: hawkeye_scene --help, --version, usage and I/O errors" {
    run -0 --separate-stderr hawkeye_scene --help
    assert_line --index 0 "Usage: hawkeye_scene [OPTIONS] SEED OUTDIR"
    assert_line "See hawkeye_scene(1)."
    run -0 --separate-stderr hawkeye_scene --version
    assert_output --regexp "^hawkeye_scene \(sigchain\) [0-9]+[.][0-9]+[.][0-9]+$"
    run -2 --separate-stderr hawkeye_scene 4
    [ "$stderr" = "hawkeye_scene: expected SEED (a non-negative integer) and OUTDIR
Try 'hawkeye_scene --help'." ]
    run -2 --separate-stderr hawkeye_scene four out
    [[ "$stderr" == "hawkeye_scene: expected SEED (a non-negative integer) and OUTDIR, found SEED 'four'"* ]]
    run -2 --separate-stderr hawkeye_scene 99999999999999999999 out
    [[ "$stderr" == "hawkeye_scene: SEED 99999999999999999999 is larger than 2^64 - 1"* ]]
    run -2 --separate-stderr hawkeye_scene --frobnicate 4 out
    run -1 --separate-stderr hawkeye_scene 4 no/such/dir
    [[ "$stderr" == "hawkeye_scene: no/such/dir/"* ]]
    # -q silences the report.
    mkdir q
    run -0 --separate-stderr hawkeye_scene -q 4 q
    [ -z "$stderr" ] && [ -s q/hawkeye.odb ]
}

@test "hawkeye: make runs the chain to counts and a preview (both views, reduced size)" {
    # The views at 64 x 64 pixels (the pixels 8 times larger) to keep the test short.
    for v in nadir oblique; do
        sed 's/^512 512\t/64 64\t/; s/^pixel_pitch_um = 21.5/pixel_pitch_um = 172/' \
            "$HAWKEYE/$v.adv" > "$v.adv"
        run -0 make -C "$HAWKEYE" -j2 VIEW=$v ADV="$BATS_TEST_TMPDIR/$v.adv" \
            OUT="$BATS_TEST_TMPDIR/out/$v" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
            HAWKEYE_SCENE="$(command -v hawkeye_scene)"
        [ -s out/scene-4/hawkeye.odb ] && [ -s out/$v/hawkeye.tif ] && [ -s out/$v/hawkeye.png ]
        run -0 --separate-stderr sigchain-check out/$v/hawkeye.snd out/$v/hawkeye-1.rad
    done
    # A second make runs no stage.
    run -0 make -C "$HAWKEYE" VIEW=nadir ADV="$BATS_TEST_TMPDIR/nadir.adv" \
        OUT="$BATS_TEST_TMPDIR/out/nadir" SIGCHAIN_BIN="$SIGCHAIN_BIN" \
        HAWKEYE_SCENE="$(command -v hawkeye_scene)"
    refute_output --regexp "hawkeye_scene |build_radiance |trace |sensorize "
}
