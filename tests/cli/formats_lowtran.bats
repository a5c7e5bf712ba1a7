# Tests: sigchain-check (formats .cdk .wth)
# Also requires: tests/data/white1996/flyover.cdk, tests/data/white1996/weather_30_Sep_95.wth,
#   tests/data/bad/cdk/, tests/data/bad/wth/, tests/golden/sigchain-check/ (lowtran_messy.*,
#   weather_fixed.*, weather_spaced.*)

bats_require_minimum_version 1.5.0
load test_helper

# --- .cdk: good input -------------------------------------------------------------------

@test "cdk: the deck of White (1996), fig. 4.31, is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/flyover.cdk"
    assert_output "$SEED/flyover.cdk: ok: 1 run, MODEL 7 (19 layers, HAWKEYE), IEMSCT 2, 2000-3333.333 cm-1 step 5"
    assert_equal "$stderr" ''
}

@test "cdk: rewriting the deck of White (1996) gives it back byte for byte" {
    run -0 sigchain-check --rewrite -o flyover.cdk "$SEED/flyover.cdk"
    run -0 cmp flyover.cdk "$SEED/flyover.cdk"
    assert_no_temp_files .
}

@test "cdk: reads standard input with -f cdk" {
    run -0 --separate-stderr sigchain-check -f cdk - < "$SEED/flyover.cdk"
    assert_output --partial "-: ok: 1 run, MODEL 7"
}

@test "cdk: --rewrite puts a deck in LOWTRAN 7's columns (golden), which re-checks" {
    run -0 sigchain-check --rewrite -o out.cdk "$GOLDEN/sigchain-check/lowtran_messy.cdk"
    assert_golden out.cdk "$GOLDEN/sigchain-check/lowtran_messy.canonical.cdk"
    run -0 sigchain-check -q out.cdk
    run -0 sigchain-check --rewrite -o again.cdk out.cdk
    run -0 cmp out.cdk again.cdk
    assert_no_temp_files .
}

# --- .cdk: bad input (one test per class) -----------------------------------------------

@test "cdk: empty file" {
    check_bad cdk empty.cdk "" "empty file, expected CARD 1"
}

@test "cdk: binary file" {
    check_bad cdk binary.cdk 2 "binary data (NUL byte)"
}

@test "cdk: non-number in a field names card, field and columns" {
    check_bad cdk not_a_number.cdk 2 "CARD 2 VIS (columns 31-40): expected a number (Fortran F10.3), found '       abc'"
}

@test "cdk: blank inside a number" {
    check_bad cdk embedded_blank.cdk 2 "CARD 2 VIS (columns 31-40): expected a number (Fortran F10.3), found '   2 3.000' (a blank inside the number)"
}

@test "cdk: NaN" {
    check_bad cdk nan.cdk 4 "CARD 2C1 (layer 1 of ML 2) P (columns 11-20): expected a number"
}

@test "cdk: infinity" {
    check_bad cdk infinity.cdk 4 "CARD 4 V1 (columns 1-10): expected a number"
}

@test "cdk: code out of range" {
    check_bad cdk model_out_of_range.cdk 1 "CARD 1 MODEL (columns 1-5): expected MODEL in 0..7, found '9'"
}

@test "cdk: value out of range" {
    check_bad cdk angle_out_of_range.cdk 3 "CARD 3 ANGLE (columns 21-30): expected ANGLE in [0, 180], found '181'"
}

@test "cdk: unit letter that LOWTRAN does not define" {
    check_bad cdk bad_jchar.cdk 4 "CARD 2C1 (layer 1 of ML 2) JCHAR (columns 63-63): expected the unit of H2O"
}

@test "cdk: negative layer count" {
    check_bad cdk negative_ml.cdk 3 "CARD 2C ML (columns 1-5): expected ML in 1..34, found '-2'"
}

@test "cdk: fewer layer cards than ML" {
    check_bad cdk too_few_layers.cdk 6 "CARD 2C1 (layer 3 of ML 3)"
}

@test "cdk: more layer cards than ML" {
    check_bad cdk too_many_layers.cdk 5 "CARD 3 LEN (columns 61-65): expected an integer, found 'ABG'"
}

@test "cdk: layer altitudes not increasing" {
    check_bad cdk altitude_not_increasing.cdk 5 "CARD 2C1 (layer 2 of ML 2) ZMDL (columns 1-10): expected an altitude above layer 1's 0.218 km, found '0.1'"
}

@test "cdk: spectral range not increasing" {
    check_bad cdk v2_below_v1.cdk 4 "CARD 4 V2 (columns 11-20): expected V2 above V1 (14285.714 cm-1), found '10000'"
}

@test "cdk: zero spectral step" {
    check_bad cdk dv_zero.cdk 4 "CARD 4 DV (columns 21-30): expected DV (cm-1) above 0, found '0'"
}

@test "cdk: a blank line where a card is expected is a card of blanks" {
    check_bad cdk blank_card4.cdk 4 "CARD 4 V2 (columns 11-20): expected V2 above V1 (0 cm-1)"
}

@test "cdk: truncated in the layers" {
    check_bad cdk truncated.cdk 4 "unexpected end of file, expected CARD 2C1 (layer 2 of ML 2)"
}

@test "cdk: missing IRPT card" {
    check_bad cdk missing_irpt.cdk 4 "unexpected end of file, expected CARD 5 (IRPT)"
}

@test "cdk: negative IRPT" {
    check_bad cdk negative_irpt.cdk 5 "CARD 5 IRPT (columns 1-5): expected IRPT 0 (end), 1 (all cards), 3 (CARD 3) or 4 (CARD 4), found '-1'"
}

@test "cdk: content after the final IRPT 0" {
    check_bad cdk after_final_irpt.cdk 7 "unexpected content after the final CARD 5 (IRPT 0), found '    0'"
}

@test "cdk: text beyond the card's columns" {
    check_bad cdk beyond_columns.cdk 5 "CARD 5: expected blanks from column 6 on"
}

@test "cdk: tab in a card" {
    check_bad cdk tab.cdk 4 "CARD 4: expected a fixed-column card of printable characters, found '\\x09' in column 1 (a tab; use spaces)"
}

@test "cdk: IHAZE 7 without its CARD 2D reads CARD 3 as CARD 2D and fails there" {
    check_bad cdk ihaze7_without_card2d.cdk 3 "CARD 2D IREG(2) (columns 6-10): expected an integer, found '0.500'"
}

# --- .wth: good input -------------------------------------------------------------------

@test "wth: the weather of White (1996), fig. 4.32 (header corrected to 49), is valid" {
    run -0 --separate-stderr sigchain-check "$SEED/weather_30_Sep_95.wth"
    assert_output "$SEED/weather_30_Sep_95.wth: ok: 49 rows at 1 h, 0-48 h, whitespace form"
}

@test "wth: the original header of White (1996) (48 rows, 49 present) is reported precisely" {
    check_bad wth seed_header_48.wth 50 "header (line 1) says 48 rows, found 49"
}

@test "wth: reads standard input with -f wth" {
    run -0 --separate-stderr sigchain-check -f wth - < "$SEED/weather_30_Sep_95.wth"
    assert_output "-: ok: 49 rows at 1 h, 0-48 h, whitespace form"
}

@test "wth: --rewrite of the whitespace form (golden), which re-checks" {
    run -0 sigchain-check --rewrite -o out.wth "$GOLDEN/sigchain-check/weather_spaced.wth"
    assert_golden out.wth "$GOLDEN/sigchain-check/weather_spaced.canonical.wth"
    run -0 sigchain-check -q out.wth
    assert_no_temp_files .
}

@test "wth: --rewrite keeps the fixed-width form, touching values and all (golden)" {
    run -0 sigchain-check --rewrite -o out.wth "$GOLDEN/sigchain-check/weather_fixed.wth"
    assert_golden out.wth "$GOLDEN/sigchain-check/weather_fixed.canonical.wth"
    run -0 --separate-stderr sigchain-check out.wth
    assert_output "out.wth: ok: 4 rows at 0.25 h, 0-0.75 h, fixed-width form"
    assert_no_temp_files .
}

# --- .wth: bad input (one test per class) -----------------------------------------------

@test "wth: empty file" {
    check_bad wth empty.wth "" "empty file, expected a .wth header"
}

@test "wth: binary file" {
    check_bad wth binary.wth 2 "binary data (NUL byte)"
}

@test "wth: header with the wrong field count" {
    check_bad wth header_fields.wth 1 "expected 2 header fields (row count, increment (h)), found 1"
}

@test "wth: negative row count" {
    check_bad wth negative_count.wth 1 "expected row count (a count, 0 or more), found '-3'"
}

@test "wth: zero increment" {
    check_bad wth zero_increment.wth 1 "expected increment (h) above 0, found '0'"
}

@test "wth: fewer rows than the header says" {
    check_bad wth too_few_rows.wth 3 "header (line 1) says 3 rows, found 2 (unexpected end of file)"
}

@test "wth: more rows than the header says" {
    check_bad wth too_many_rows.wth 4 "header (line 1) says 2 rows, found 3"
}

@test "wth: row with the wrong field count" {
    check_bad wth field_count.wth 3 "expected 13 fields (time, air temperature"
}

@test "wth: non-number" {
    check_bad wth not_a_number.wth 3 "expected air temperature (C) (a number), found 'warm'"
}

@test "wth: NaN" {
    check_bad wth nan.wth 3 "expected dew point (C) (a finite number), found 'nan'"
}

@test "wth: infinity" {
    check_bad wth infinity.wth 3 "expected pressure (mb) (a finite number), found 'inf'"
}

@test "wth: relative humidity out of range" {
    check_bad wth humidity_out_of_range.wth 3 "expected relative humidity (%) in [0, 100], or -1 to use the dew point, found '101'"
}

@test "wth: sky exposure out of range" {
    check_bad wth sky_exposure_out_of_range.wth 3 "expected sky exposure in [0, 1], found '1.5'"
}

@test "wth: negative wind speed" {
    check_bad wth negative_wind.wth 3 "expected wind speed (m/s) at least 0, found '-0.5'"
}

@test "wth: zero pressure" {
    check_bad wth zero_pressure.wth 3 "expected pressure (mb) above 0, found '0'"
}

@test "wth: negative insolation" {
    check_bad wth negative_insolation.wth 3 "expected diffuse insolation (Ly/h) at least 0, found '-1'"
}

@test "wth: cloud type that is not an integer" {
    check_bad wth cloud_type_not_integer.wth 3 "expected cloud type (an integer), found '1.5'"
}

@test "wth: time not increasing" {
    check_bad wth time_not_increasing.wth 3 "expected time (h) 1 (the previous row's 0 + the header's increment 1), found 0 (times must increase)"
}

@test "wth: time step different from the header's increment" {
    check_bad wth time_step.wth 3 "expected time (h) 1 (the previous row's 0 + the header's increment 1), found 1.5"
}

@test "wth: fixed-width row of the wrong length" {
    check_bad wth fixed_width_shifted.wth 3 "expected a row of 76 columns without tabs (the fixed-width form of line 2), found 77 columns"
}

@test "wth: fixed-width field with a blank inside" {
    check_bad wth fixed_width_blank.wth 3 "expected pressure (mb) in columns 13-20 (the fixed-width form of line 2), found '10 3.25'"
}
