#!/usr/bin/env bats
# Tests: sigchain-check (formats .adv .snd .rsd .sen .cpt .tmp .unc .brdf)
# Also requires: tests/data/white1996, tests/data/bad/{adv,snd,rsd,sen,cpt,tmp,unc,brdf}, tests/data/trace/training.unc, data/brdf,
# tests/golden/sigchain-check (the canonical rewrites of the samples of White (1996))

load test_helper
bats_require_minimum_version 1.5.0

# --- .adv ---------------------------------------------------------------------------
@test "adv: sample of White (1996) checks" {
    check_good "$SEED/hawkeye.adv" "512 x 512 pixels, frame sensor, focal length 40 mm, units ft"
}
@test "adv: stdin with -f adv" {
    run -0 --separate-stderr sigchain-check -f adv - < "$SEED/hawkeye.adv"
    assert_output "-: ok: 512 x 512 pixels, frame sensor, focal length 40 mm, units ft"
}
@test "adv: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/hawkeye.adv"; }
@test "adv: empty file" { check_bad adv empty.adv "" "empty file, expected an .adv"; }
@test "adv: binary file" { check_bad adv binary.adv 2 "binary data (NUL byte)"; }
@test "adv: truncated file" { check_bad adv truncated.adv 4 "unexpected end of file, expected image size"; }
@test "adv: wrong field count" { check_bad adv field_count.adv 1 "expected 3 fields (target point), found 2"; }
@test "adv: not a number" { check_bad adv not_number.adv 5 "expected image columns (an integer), found 'wide'"; }
@test "adv: NaN" { check_bad adv nan.adv 1 "expected target point z (a finite number), found 'nan'"; }
@test "adv: elevation out of range" { check_bad adv elevation_range.adv 3 "expected camera elevation (deg) in [-90, 90], found '95'"; }
@test "adv: zero rows" { check_bad adv zero_rows.adv 5 "expected image rows (an integer from 1 to 100000), found '0'"; }
@test "adv: camera at the target" { check_bad adv camera_at_target.adv 2 "expected a camera point different from the target point"; }
@test "adv: unknown key" { check_bad adv unknown_key.adv 6 "expected a key units, pixel_pitch_um, sensor, samples_per_pixel or a platform or scanner key of adv(5), found 'zoom'"; }
@test "adv: repeated key" { check_bad adv repeated_key.adv 7 "expected each key once, found 'units' again (first on line 6)"; }
@test "adv: bad units" { check_bad adv bad_units.adv 6 "expected units ft or m, found 'yards'"; }
@test "adv: extra line" { check_bad adv extra_line.adv 6 "expected 'key = value' after the image size, found '512 512'"; }

# --- .snd ---------------------------------------------------------------------------
@test "snd: sample of White (1996) checks" {
    check_good "$SEED/hawkeye.snd" "3 bands, 14400-25000 cm-1, 156 view angles, 1995-09-30 19 h GMT"
}
@test "snd: stdin with -f snd" {
    run -0 --separate-stderr sigchain-check -f snd - < "$SEED/hawkeye.snd"
    assert_output --partial "-: ok: 3 bands"
}
@test "snd: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/hawkeye.snd"; }
@test "snd: empty file" { check_bad snd empty.snd "" "empty file, expected an .snd"; }
@test "snd: binary file" { check_bad snd binary.snd 3 "binary data (NUL byte)"; }
@test "snd: truncated file" { check_bad snd truncated.snd 9 "unexpected end of file, expected latitude longitude of the target"; }
@test "snd: too few band lines for the count" { check_bad snd too_few_bands.snd 5 "expected band 3 minimum wavenumber (cm-1) greater than 0, found '-77' (the band count on line 2 says 3, so 8 lines should follow it, found 7)"; }
@test "snd: too many band lines for the count" { check_bad snd too_many_bands.snd 5 "expected minimum view angle (deg) in [-90, 90], found '20000' (the band count on line 2 says 2, so 7 lines should follow it, found 8)"; }
@test "snd: negative band count" { check_bad snd negative_count.snd 2 "expected number of spectral bands (a count, 0 or more), found '-3'"; }
@test "snd: extra line" { check_bad snd extra_line.snd 11 "unexpected content after the latitude longitude line"; }
@test "snd: wrong field count" { check_bad snd field_count.snd 4 "expected 3 fields (view angles: min max increment (deg)), found 2"; }
@test "snd: not a number" { check_bad snd not_number.snd 3 "expected band 1 wavenumber increment (cm-1) (a number), found 'sixty'"; }
@test "snd: infinity" { check_bad snd inf.snd 3 "expected band 1 maximum wavenumber (cm-1) (a finite number), found 'inf'"; }
@test "snd: band not increasing" { check_bad snd band_not_increasing.snd 3 "expected band 1 maximum wavenumber (cm-1) greater than the minimum '16800', found '14400'"; }
@test "snd: view angle out of range" { check_bad snd view_range.snd 4 "expected minimum view angle (deg) in [-90, 90], found '-95'"; }
@test "snd: day not in the month" { check_bad snd bad_date.snd 5 "expected day of month 2 (1-28), found '30'"; }
@test "snd: time of day 24" { check_bad snd time_24.snd 6 "expected time of day (decimal hours GMT) in [0, 24), found '24'"; }
@test "snd: wrong hemisphere letter" { check_bad snd bad_hemisphere.snd 8 "expected latitude (deg) hemisphere N or S, found 'E'"; }

# --- .rsd ---------------------------------------------------------------------------
@test "rsd: sample of White (1996) checks" { check_good "$SEED/30Sep95800L.rsd" "19 levels, 0.218-16.493 km, 998-100 mb"; }
@test "rsd: stdin with -f rsd" {
    run -0 --separate-stderr sigchain-check -f rsd - < "$SEED/30Sep95800L.rsd"
    assert_output "-: ok: 19 levels, 0.218-16.493 km, 998-100 mb"
}
@test "rsd: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/30Sep95800L.rsd"; }
@test "rsd: empty file" { check_bad rsd empty.rsd "" "empty file, expected an .rsd"; }
@test "rsd: binary file" { check_bad rsd binary.rsd 2 "binary data (NUL byte)"; }
@test "rsd: a single row" { check_bad rsd one_row.rsd 1 "expected at least 2 levels, found 1"; }
@test "rsd: wrong field count" { check_bad rsd field_count.rsd 2 "expected 4 fields"; }
@test "rsd: not a number" { check_bad rsd not_number.rsd 2 "expected temperature (C) (a number), found 'cold'"; }
@test "rsd: NaN" { check_bad rsd nan.rsd 2 "expected pressure (mb) (a finite number), found 'nan'"; }
@test "rsd: missing pressure" { check_bad rsd missing_pressure.rsd 2 "expected pressure (mb) greater than 0, found '-999'"; }
@test "rsd: below absolute zero" { check_bad rsd below_absolute_zero.rsd 2 "expected temperature (C) at or above -273.15, or -999 for missing, found '-300'"; }
@test "rsd: altitude not increasing" { check_bad rsd altitude_not_increasing.rsd 2 "expected altitude (km) above the previous row's 0.218, found '0.218'"; }
@test "rsd: pressure not decreasing" { check_bad rsd pressure_not_decreasing.rsd 2 "expected pressure (mb) below the previous row's 998, found '998'"; }
@test "rsd: dew point above temperature" { check_bad rsd dew_above_temperature.rsd 1 "expected dew point (C) at or below the temperature '23.8', found '27.8'"; }

# --- .sen ---------------------------------------------------------------------------
@test "sen: sample of White (1996) checks" { check_good "$SEED/dcs420_band1.sen" "7 spectral samples, gain 1, bias 0"; }
@test "sen: stdin with -f sen" {
    run -0 --separate-stderr sigchain-check -f sen - < "$SEED/dcs420_band1.sen"
    assert_output "-: ok: 7 spectral samples, gain 1, bias 0"
}
@test "sen: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/dcs420_band1.sen"; }
@test "sen: empty file" { check_bad sen empty.sen "" "empty file, expected a .sen"; }
@test "sen: binary file" { check_bad sen binary.sen 3 "binary data (NUL byte)"; }
@test "sen: too few responses" { check_bad sen too_few.sen 9 "unexpected end of file, expected relative response 7 of 7 (the count on line 1)"; }
@test "sen: too many responses" { check_bad sen too_many.sen 11 "unexpected content after 7 relative responses (the count on line 1), found '0.65'"; }
@test "sen: negative count" { check_bad sen negative_count.sen 1 "expected number of spectral samples (a count, 0 or more), found '-7'"; }
@test "sen: wrong field count" { check_bad sen field_count.sen 4 "expected 1 field (relative response 1 of 2"; }
@test "sen: not a number" { check_bad sen not_number.sen 3 "expected bias (a number), found 'zero'"; }
@test "sen: negative response" { check_bad sen negative_response.sen 5 "expected relative response 2 of 2 (the count on line 1) at or above 0, found '-0.5'"; }
@test "sen: zero gain" { check_bad sen zero_gain.sen 2 "expected gain greater than 0, found '0'"; }

# --- .cpt ---------------------------------------------------------------------------
@test "cpt: example checks" { check_good "$SEED/hawkeye_nadir.cpt" "4 control points"; }
@test "cpt: stdin with -f cpt" {
    run -0 --separate-stderr sigchain-check -f cpt - < "$SEED/hawkeye_nadir.cpt"
    assert_output "-: ok: 4 control points"
}
@test "cpt: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/hawkeye_nadir.cpt"; }
@test "cpt: empty file" { check_bad cpt empty.cpt "" "empty file, expected '# sigchain-cpt 1'"; }
@test "cpt: binary file" { check_bad cpt binary.cpt 2 "binary data (NUL byte)"; }
@test "cpt: no magic line" { check_bad cpt no_magic.cpt 1 "expected '# sigchain-cpt 1' as the first line, found 'grass 1 2 3 4 0'"; }
@test "cpt: another major version" { check_bad cpt version_2.cpt 1 "expected sigchain-cpt version 1 or 1.N, found '2'"; }
@test "cpt: no points" { check_bad cpt no_points.cpt 2 "unexpected end of file, expected a control point line"; }
@test "cpt: wrong field count" { check_bad cpt field_count.cpt 2 "expected 6 fields or more"; }
@test "cpt: not a number" { check_bad cpt not_number.cpt 2 "expected reference row (pixels) (a number), found 'three'"; }
@test "cpt: negative position" { check_bad cpt negative.cpt 2 "expected synthetic column (pixels) at or above 0, found '-2'"; }
@test "cpt: duplicate name" { check_bad cpt duplicate.cpt 3 "expected a unique control point name, found 'grass' again (first on line 2)"; }

# --- .tmp ---------------------------------------------------------------------------
@test "tmp: example checks" { check_good "$SEED/hawkeye.tmp" "4 facets, 288-310.9 K, time 38 h"; }
@test "tmp: stdin with -f tmp" {
    run -0 --separate-stderr sigchain-check -f tmp - < "$SEED/hawkeye.tmp"
    assert_output "-: ok: 4 facets, 288-310.9 K, time 38 h"
}
@test "tmp: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/hawkeye.tmp"; }
@test "tmp: empty file" { check_bad tmp empty.tmp "" "empty file, expected '# sigchain-tmp 1'"; }
@test "tmp: binary file" { check_bad tmp binary.tmp 2 "binary data (NUL byte)"; }
@test "tmp: no magic line" { check_bad tmp no_magic.tmp 1 "expected '# sigchain-tmp 1' as the first line"; }
@test "tmp: another major version" { check_bad tmp version_2.tmp 1 "expected sigchain-tmp version 1 or 1.N, found '2'"; }
@test "tmp: wrong field count" { check_bad tmp field_count.tmp 2 "expected 2 fields (facet id, temperature K), found 3"; }
@test "tmp: not a number" { check_bad tmp not_number.tmp 2 "expected temperature (K) (a number), found 'warm'"; }
@test "tmp: temperature out of range" { check_bad tmp out_of_range.tmp 2 "expected temperature (K) above 0 and below 10000, found '-5'"; }
@test "tmp: duplicate facet" { check_bad tmp duplicate.tmp 3 "expected each facet once, found '1-1-1' again (first on line 2)"; }
@test "tmp: not a facet id" { check_bad tmp bad_id.tmp 2 "expected a facet id such as 1-1-1 or 2.3/1-1-1, found 'roof'"; }
@test "tmp: unknown header key" { check_bad tmp bad_key.tmp 2 "expected key time_hours, found 'date'"; }

# --- .unc ---------------------------------------------------------------------------
UNC="$SIGCHAIN_SOURCE_DIR/tests/data/trace/training.unc"
@test "unc: example checks" { check_good "$UNC" "8 uncertainties (2 of materials)"; }
@test "unc: stdin with -f unc" {
    run -0 --separate-stderr sigchain-check -f unc - < "$UNC"
    assert_output "-: ok: 8 uncertainties (2 of materials)"
}
@test "unc: --rewrite gives the golden canonical file" { check_rewrite_golden "$UNC"; }
@test "unc: empty file" { check_bad unc empty.unc "" "empty file, expected '# sigchain-unc 1'"; }
@test "unc: unknown term" { check_bad unc unknown_term.unc 3 "expected Es, tau1, tau2, L_us, L_ds, sun_zenith or material, found 'foo'"; }
@test "unc: negative sigma" { check_bad unc negative.unc 3 "expected sigma at or above 0, found '-0.1'"; }
@test "unc: absolute Es" { check_bad unc absolute_es.unc 2 "Es takes a relative sigma only (per cent: it is a spectrum), found an absolute one"; }
@test "unc: relative sun zenith" { check_bad unc relative_zenith.unc 2 "sun_zenith takes an absolute sigma only, found per cent"; }
@test "unc: duplicate term" { check_bad unc duplicate.unc 4 "expected each term once, found 'tau2' again (first on line 2)"; }
@test "unc: unknown material quantity" { check_bad unc bad_quantity.unc 2 "expected reflectance or specularity, found 'colour'"; }
@test "unc: not a number" { check_bad unc not_number.unc 2 "expected sigma (a number), found 'lots'"; }
@test "unc: truncated version 1.1" { check_bad unc truncated.unc 3 "expected '# sigchain-end 2' as the last line"; }

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

# --- .brdf --------------------------------------------------------------------------
@test "brdf: shipped RPV example checks" {
    check_good "$SIGCHAIN_SOURCE_DIR/data/brdf/rpv_grassland.brdf" "18 x 18 x 37 angles"
}
@test "brdf: --rewrite reads back to the same table" {
    run -0 --separate-stderr sigchain-check --rewrite -o "$BATS_TEST_TMPDIR/r.brdf" \
        "$SIGCHAIN_SOURCE_DIR/data/brdf/rpv_grassland.brdf"
    run -0 --separate-stderr sigchain-check "$BATS_TEST_TMPDIR/r.brdf"
    assert_output --partial "ok: 18 x 18 x 37 angles"
}
@test "brdf: repeated grid point" { check_bad brdf repeated.brdf 6 "repeated grid point (first on line 5)"; }
@test "brdf: missing grid point" { check_bad brdf missing.brdf 5 "expected a row for theta_i 0, theta_o 0, phi 180, found none in the file"; }
@test "brdf: unknown major version" { check_bad brdf version.brdf 1 "expected sigchain-brdf version 1 or 1.N, found '2'"; }
