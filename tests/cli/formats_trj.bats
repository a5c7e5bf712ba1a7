#!/usr/bin/env bats
# Tests: sigchain-check (format .trj, trj(5))
# Also requires: tests/fuzz/corpus/parsers/*.trj (also the fuzz harness's seeds),
# tests/data/bad/trj

load test_helper
bats_require_minimum_version 1.5.0

CORPUS="$SIGCHAIN_SOURCE_DIR/tests/fuzz/corpus/parsers"

@test "trj: a scene trajectory with velocities checks" {
    check_good "$CORPUS/flight.trj" "3 records, 0 to 10 s, with velocities"
}
@test "trj: a geodetic trajectory checks" {
    check_good "$CORPUS/orbit.trj" "2 records, 0 to 1 s, geodetic"
}
@test "trj: listed among the formats" {
    run -0 sigchain-check --list-formats
    run -0 grep -c '^trj' <<< "$output"
}
@test "trj: the rewrite reads back to itself" {
    for f in flight orbit; do
        run -0 --separate-stderr sigchain-check --rewrite -o "a.trj" "$CORPUS/$f.trj"
        run -0 --separate-stderr sigchain-check --rewrite -o "b.trj" a.trj
        run -0 cmp a.trj b.trj
    done
}
@test "trj: stdin with -f trj" {
    run -0 --separate-stderr sigchain-check -f trj - < "$CORPUS/flight.trj"
    assert_output "-: ok: 3 records, 0 to 10 s, with velocities"
}
@test "trj: wrong field count" { check_bad trj field_count.trj 2 "expected 7 fields (time x y z roll pitch yaw) or 10 (and vx vy vz), found 6"; }
@test "trj: NaN" { check_bad trj nan.trj 2 "expected roll (deg) (a finite number), found 'nan'"; }
@test "trj: one record" { check_bad trj one_record.trj 2 "expected at least 2 trajectory records, found 1"; }
@test "trj: time going back" { check_bad trj time_backward.trj 4 "expected a time after 2 s (line 3): times must increase, found 1"; }
@test "trj: velocity on some rows only" { check_bad trj velocity_some_rows.trj 3 "expected velocities on every row or on none (line 2 differs)"; }
@test "trj: a geodetic row with velocity" { check_bad trj geodetic_velocity.trj 3 "expected 7 fields in a geodetic trajectory (no velocity), found 10"; }
@test "trj: truncated (end count wrong)" { check_bad trj truncated.trj 4 "expected '# sigchain-end 2' (2 rows read; a truncated file?), found '# sigchain-end 3'"; }
