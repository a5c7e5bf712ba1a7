#!/usr/bin/env bats
# Tests: bench/lowtran_side_by_side.sh (build_radiance for one line of sight against
# LOWTRAN 7, side by side). LOWTRAN 7 itself is not part of sigchain: a stand-in Fortran
# program of its form (reads TAPE5, writes TAPE7) checks the script's flow; gfortran
# for that (skipped without it).
# Also requires: build_radiance

load test_helper

SBS="$SIGCHAIN_SOURCE_DIR/bench/lowtran_side_by_side.sh"
BUILD="$SIGCHAIN_BIN/.."

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
}

@test "lowtran_side_by_side: without a LOWTRAN 7 source it says skipped and exits 0" {
    run -0 --separate-stderr env -u LOWTRAN7_F sh "$SBS" "$BUILD"
    assert_output "skipped: no LOWTRAN 7 source (give LOWTRAN7_F)"
    run -0 --separate-stderr sh "$SBS" "$BUILD" "$PWD/missing.f"
    assert_output "skipped: no LOWTRAN 7 source (give LOWTRAN7_F)"
}

@test "lowtran_side_by_side: a stand-in program gets the nadir deck; times, errors and ratios" {
    command -v gfortran > /dev/null || skip "gfortran not installed"
    command -v python3 > /dev/null || skip "python3 not installed"
    # The stand-in copies TAPE5's CARD 3 (line 23 of the Hawkeye deck) to TAPE7, then
    # lists two wavenumbers around the bands as LOWTRAN 7's TAPE7 does (FREQ TRANS ATMOS
    # PATH ...): a transmission of 0.9 and a path radiance of 1e-9 W cm-2 sr-1 (cm-1)-1.
    cat > standin.f <<'EOF'
      PROGRAM STANDIN
      CHARACTER*80 LINE
      INTEGER I
      OPEN(5, FILE='TAPE5', STATUS='OLD')
      OPEN(7, FILE='TAPE7', STATUS='UNKNOWN')
      DO 10 I = 1, 23
        READ(5, '(A)') LINE
   10 CONTINUE
      WRITE(7, '(A)') LINE
      WRITE(7, '(A)') ' 14285.  0.9000 0.00E+00 1.00E-09 0.00E+00'
      WRITE(7, '(A)') ' 25010.  0.9000 0.00E+00 1.00E-09 0.00E+00'
      END
EOF
    run -0 --separate-stderr env RUNS=2 WORK="$PWD/w" sh "$SBS" "$BUILD" standin.f
    local n='[0-9.]+' times='[0-9.]+ ms +[0-9.]+ ms'
    assert_line --index 0 \
        "one line of sight, Hawkeye deck, 2 alternating runs, whole processes, 1 thread"
    assert_line --regexp "^LOWTRAN 7 \(2 wavenumbers\) +$times   worst $n %, median $n %$"
    assert_line --regexp "^build_radiance --streams auto \(1 %\) +$times   worst $n %"
    assert_line --regexp "^build_radiance --streams auto \(5 %\) +$times   worst $n %"
    assert_line --regexp \
        "^ratio to LOWTRAN 7, build_radiance --streams auto \(1 %\): $n \(medians\), $n \(bests\)"
    assert_line --regexp "^at 5 %: worst $n % and median $n % against LOWTRAN 7's $n % and $n %: "
    assert_line --regexp \
        "(as accurate or more|less accurate) \(closer than LOWTRAN 7 in [0-9]+ of 123 samples\)$"
    # The stand-in's transmission 0.9 against build_radiance's own.
    assert_line --regexp \
        "^LOWTRAN 7's ground-to-sensor transmission against build_radiance's: worst $n %"
    # The deck's line of sight is the scene's: 1 km straight down to the ground.
    run -0 sed -n '1s/ *$//p' w/lowtran/TAPE7
    assert_output "     1.000     0.218   180.000     0.000     0.000     0.000    0"
    # build_radiance wrote its three bands for the one nadir view, and the reference.
    for n in default loose ref; do
        for b in 1 2 3; do [ -s "w/sigchain/$n-$b.rad" ]; done
    done
    grep -q '^0 0 1' w/sigchain/nadir.snd
    [ "$(grep -c '^lowtran ' w/times)" -eq 2 ]
    [ "$(grep -c '^default ' w/times)" -eq 2 ]
    [ "$(grep -c '^loose ' w/times)" -eq 2 ]
}

@test "lowtran_side_by_side: a program that writes no TAPE7 fails with a message" {
    command -v gfortran > /dev/null || skip "gfortran not installed"
    command -v python3 > /dev/null || skip "python3 not installed"
    printf '      PROGRAM NOTHING\n      END\n' > nothing.f
    run -1 --separate-stderr env RUNS=1 WORK="$PWD/w" sh "$SBS" "$BUILD" nothing.f
    [[ "$stderr" == *"LOWTRAN 7 wrote no "*"/lowtran/TAPE7"* ]]
}
