#!/usr/bin/env bats
# Tests: sigchain-check (formats .adv .snd .rsd .sen .cpt .tmp)
# Also requires: tests/data/seed, tests/data/bad/{adv,snd,rsd,sen,cpt,tmp},
# tests/golden/sigchain-check (the canonical rewrites of the seed samples)

load test_helper
bats_require_minimum_version 1.5.0

# bad FORMAT NAME LINE MESSAGE: sigchain-check rejects $BAD/FORMAT/NAME.FORMAT with
# exit 1, nothing on stdout, and "FILE:LINE: MESSAGE..." on stderr (LINE "" for a
# whole-file error).
bad() {
    local file="$BAD/$1/$2.$1" where
    where="$file${3:+:$3}"
    run -1 --separate-stderr sigchain-check "$file"
    assert_output ''
    [[ "$stderr" == "sigchain-check: $where: $4"* ]] ||
        { echo "stderr: $stderr"; echo "wanted: sigchain-check: $where: $4..."; return 1; }
}

# good FILE SUMMARY: the file checks with exit 0 and the summary line.
good() {
    run -0 --separate-stderr sigchain-check "$1"
    assert_output "$1: ok: $2"
    assert_equal "$stderr" ''
}

# golden FILE: --rewrite gives the golden canonical file, which itself re-checks and
# rewrites to itself.
golden() {
    local name
    name=$(basename "$1")
    run -0 --separate-stderr sigchain-check --rewrite -o "out.$name" "$1"
    assert_golden "out.$name" "$GOLDEN/sigchain-check/$name"
    run -0 sigchain-check -q "$GOLDEN/sigchain-check/$name"
    run -0 sigchain-check --rewrite -o "again.$name" "$GOLDEN/sigchain-check/$name"
    run -0 cmp "again.$name" "$GOLDEN/sigchain-check/$name"
    assert_no_temp_files .
}

# --- .adv ---------------------------------------------------------------------------
@test "adv: seed sample checks" {
    good "$SEED/hawkeye.adv" "512 x 512 pixels, frame sensor, focal length 40 mm, units ft"
}
@test "adv: stdin with -f adv" {
    run -0 --separate-stderr sigchain-check -f adv - < "$SEED/hawkeye.adv"
    assert_output "-: ok: 512 x 512 pixels, frame sensor, focal length 40 mm, units ft"
}
@test "adv: --rewrite gives the golden canonical file" { golden "$SEED/hawkeye.adv"; }
@test "adv: empty file" { bad adv empty "" "empty file, expected an .adv"; }
@test "adv: binary file" { bad adv binary 2 "binary data (NUL byte)"; }
@test "adv: truncated file" { bad adv truncated 4 "unexpected end of file, expected image size"; }
@test "adv: wrong field count" { bad adv field_count 1 "expected 3 fields (target point), found 2"; }
@test "adv: not a number" { bad adv not_number 5 "expected image columns (an integer), found 'wide'"; }
@test "adv: NaN" { bad adv nan 1 "expected target point z (a finite number), found 'nan'"; }
@test "adv: elevation out of range" { bad adv elevation_range 3 "expected camera elevation (deg) in [-90, 90], found '95'"; }
@test "adv: zero rows" { bad adv zero_rows 5 "expected image rows (an integer from 1 to 100000), found '0'"; }
@test "adv: camera at the target" { bad adv camera_at_target 2 "expected a camera point different from the target point"; }
@test "adv: unknown key" { bad adv unknown_key 6 "expected a key units, pixel_pitch_um, sensor or samples_per_pixel, found 'zoom'"; }
@test "adv: repeated key" { bad adv repeated_key 7 "expected each key once, found 'units' again (first on line 6)"; }
@test "adv: bad units" { bad adv bad_units 6 "expected units ft or m, found 'yards'"; }
@test "adv: extra line" { bad adv extra_line 6 "expected 'key = value' after the image size, found '512 512'"; }

# --- .snd ---------------------------------------------------------------------------
@test "snd: seed sample checks" {
    good "$SEED/hawkeye.snd" "3 bands, 14400-25000 cm-1, 156 view angles, 1995-09-30 19 h GMT"
}
@test "snd: stdin with -f snd" {
    run -0 --separate-stderr sigchain-check -f snd - < "$SEED/hawkeye.snd"
    assert_output --partial "-: ok: 3 bands"
}
@test "snd: --rewrite gives the golden canonical file" { golden "$SEED/hawkeye.snd"; }
@test "snd: empty file" { bad snd empty "" "empty file, expected an .snd"; }
@test "snd: binary file" { bad snd binary 3 "binary data (NUL byte)"; }
@test "snd: truncated file" { bad snd truncated 9 "unexpected end of file, expected latitude longitude of the target"; }
@test "snd: too few band lines for the count" { bad snd too_few_bands 5 "expected band 3 minimum wavenumber (cm-1) greater than 0, found '-77' (the band count on line 2 says 3, so 8 lines should follow it, found 7)"; }
@test "snd: too many band lines for the count" { bad snd too_many_bands 5 "expected minimum view angle (deg) in [-90, 90], found '20000' (the band count on line 2 says 2, so 7 lines should follow it, found 8)"; }
@test "snd: negative band count" { bad snd negative_count 2 "expected number of spectral bands (a count, 0 or more), found '-3'"; }
@test "snd: extra line" { bad snd extra_line 11 "unexpected content after the latitude longitude line"; }
@test "snd: wrong field count" { bad snd field_count 4 "expected 3 fields (view angles: min max increment (deg)), found 2"; }
@test "snd: not a number" { bad snd not_number 3 "expected band 1 wavenumber increment (cm-1) (a number), found 'sixty'"; }
@test "snd: infinity" { bad snd inf 3 "expected band 1 maximum wavenumber (cm-1) (a finite number), found 'inf'"; }
@test "snd: band not increasing" { bad snd band_not_increasing 3 "expected band 1 maximum wavenumber (cm-1) greater than the minimum '16800', found '14400'"; }
@test "snd: view angle out of range" { bad snd view_range 4 "expected minimum view angle (deg) in [-90, 90], found '-95'"; }
@test "snd: day not in the month" { bad snd bad_date 5 "expected day of month 2 (1-28), found '30'"; }
@test "snd: time of day 24" { bad snd time_24 6 "expected time of day (decimal hours GMT) in [0, 24), found '24'"; }
@test "snd: wrong hemisphere letter" { bad snd bad_hemisphere 8 "expected latitude (deg) hemisphere N or S, found 'E'"; }

# --- .rsd ---------------------------------------------------------------------------
@test "rsd: seed sample checks" { good "$SEED/30Sep95800L.rsd" "19 levels, 0.218-16.493 km, 998-100 mb"; }
@test "rsd: stdin with -f rsd" {
    run -0 --separate-stderr sigchain-check -f rsd - < "$SEED/30Sep95800L.rsd"
    assert_output "-: ok: 19 levels, 0.218-16.493 km, 998-100 mb"
}
@test "rsd: --rewrite gives the golden canonical file" { golden "$SEED/30Sep95800L.rsd"; }
@test "rsd: empty file" { bad rsd empty "" "empty file, expected an .rsd"; }
@test "rsd: binary file" { bad rsd binary 2 "binary data (NUL byte)"; }
@test "rsd: a single row" { bad rsd one_row 1 "expected at least 2 levels, found 1"; }
@test "rsd: wrong field count" { bad rsd field_count 2 "expected 4 fields"; }
@test "rsd: not a number" { bad rsd not_number 2 "expected temperature (C) (a number), found 'cold'"; }
@test "rsd: NaN" { bad rsd nan 2 "expected pressure (mb) (a finite number), found 'nan'"; }
@test "rsd: missing pressure" { bad rsd missing_pressure 2 "expected pressure (mb) greater than 0, found '-999'"; }
@test "rsd: below absolute zero" { bad rsd below_absolute_zero 2 "expected temperature (C) at or above -273.15, or -999 for missing, found '-300'"; }
@test "rsd: altitude not increasing" { bad rsd altitude_not_increasing 2 "expected altitude (km) above the previous row's 0.218, found '0.218'"; }
@test "rsd: pressure not decreasing" { bad rsd pressure_not_decreasing 2 "expected pressure (mb) below the previous row's 998, found '998'"; }
@test "rsd: dew point above temperature" { bad rsd dew_above_temperature 1 "expected dew point (C) at or below the temperature '23.8', found '27.8'"; }

# --- .sen ---------------------------------------------------------------------------
@test "sen: seed sample checks" { good "$SEED/dcs420_band1.sen" "7 spectral samples, gain 1, bias 0"; }
@test "sen: stdin with -f sen" {
    run -0 --separate-stderr sigchain-check -f sen - < "$SEED/dcs420_band1.sen"
    assert_output "-: ok: 7 spectral samples, gain 1, bias 0"
}
@test "sen: --rewrite gives the golden canonical file" { golden "$SEED/dcs420_band1.sen"; }
@test "sen: empty file" { bad sen empty "" "empty file, expected a .sen"; }
@test "sen: binary file" { bad sen binary 3 "binary data (NUL byte)"; }
@test "sen: too few responses" { bad sen too_few 9 "unexpected end of file, expected relative response 7 of 7 (the count on line 1)"; }
@test "sen: too many responses" { bad sen too_many 11 "unexpected content after 7 relative responses (the count on line 1), found '0.65'"; }
@test "sen: negative count" { bad sen negative_count 1 "expected number of spectral samples (a count, 0 or more), found '-7'"; }
@test "sen: wrong field count" { bad sen field_count 4 "expected 1 field (relative response 1 of 2"; }
@test "sen: not a number" { bad sen not_number 3 "expected bias (a number), found 'zero'"; }
@test "sen: negative response" { bad sen negative_response 5 "expected relative response 2 of 2 (the count on line 1) at or above 0, found '-0.5'"; }
@test "sen: zero gain" { bad sen zero_gain 2 "expected gain greater than 0, found '0'"; }

# --- .cpt ---------------------------------------------------------------------------
@test "cpt: example checks" { good "$SEED/hawkeye_nadir.cpt" "4 control points"; }
@test "cpt: stdin with -f cpt" {
    run -0 --separate-stderr sigchain-check -f cpt - < "$SEED/hawkeye_nadir.cpt"
    assert_output "-: ok: 4 control points"
}
@test "cpt: --rewrite gives the golden canonical file" { golden "$SEED/hawkeye_nadir.cpt"; }
@test "cpt: empty file" { bad cpt empty "" "empty file, expected '# sigchain-cpt 1'"; }
@test "cpt: binary file" { bad cpt binary 2 "binary data (NUL byte)"; }
@test "cpt: no magic line" { bad cpt no_magic 1 "expected '# sigchain-cpt 1' as the first line, found 'grass 1 2 3 4 0'"; }
@test "cpt: another major version" { bad cpt version_2 1 "expected sigchain-cpt version 1 or 1.N, found '2'"; }
@test "cpt: no points" { bad cpt no_points 2 "unexpected end of file, expected a control point line"; }
@test "cpt: wrong field count" { bad cpt field_count 2 "expected 6 fields or more"; }
@test "cpt: not a number" { bad cpt not_number 2 "expected reference row (pixels) (a number), found 'three'"; }
@test "cpt: negative position" { bad cpt negative 2 "expected synthetic column (pixels) at or above 0, found '-2'"; }
@test "cpt: duplicate name" { bad cpt duplicate 3 "expected a unique control point name, found 'grass' again (first on line 2)"; }

# --- .tmp ---------------------------------------------------------------------------
@test "tmp: example checks" { good "$SEED/hawkeye.tmp" "4 facets, 288-310.9 K, time 38 h"; }
@test "tmp: stdin with -f tmp" {
    run -0 --separate-stderr sigchain-check -f tmp - < "$SEED/hawkeye.tmp"
    assert_output "-: ok: 4 facets, 288-310.9 K, time 38 h"
}
@test "tmp: --rewrite gives the golden canonical file" { golden "$SEED/hawkeye.tmp"; }
@test "tmp: empty file" { bad tmp empty "" "empty file, expected '# sigchain-tmp 1'"; }
@test "tmp: binary file" { bad tmp binary 2 "binary data (NUL byte)"; }
@test "tmp: no magic line" { bad tmp no_magic 1 "expected '# sigchain-tmp 1' as the first line"; }
@test "tmp: another major version" { bad tmp version_2 1 "expected sigchain-tmp version 1 or 1.N, found '2'"; }
@test "tmp: wrong field count" { bad tmp field_count 2 "expected 2 fields (facet id, temperature K), found 3"; }
@test "tmp: not a number" { bad tmp not_number 2 "expected temperature (K) (a number), found 'warm'"; }
@test "tmp: temperature out of range" { bad tmp out_of_range 2 "expected temperature (K) above 0 and below 10000, found '-5'"; }
@test "tmp: duplicate facet" { bad tmp duplicate 3 "expected each facet once, found '1-1-1' again (first on line 2)"; }
@test "tmp: not a facet id" { bad tmp bad_id 2 "expected a facet id such as 1-1-1 or 2.3/1-1-1, found 'roof'"; }
@test "tmp: unknown header key" { bad tmp bad_key 2 "expected key time_hours, found 'date'"; }

# --- all six ------------------------------------------------------------------------
@test "the six formats are listed" {
    run -0 sigchain-check --list-formats
    for ext in adv cpt rsd sen snd tmp; do
        [[ "$output" == *"$ext	"* ]] || { echo "missing $ext"; return 1; }
    done
}
@test "a failed --rewrite leaves no output and no temporary file" {
    run -1 --separate-stderr sigchain-check --rewrite -o out.adv "$BAD/adv/truncated.adv"
    [ ! -e out.adv ]
    assert_no_temp_files .
}
