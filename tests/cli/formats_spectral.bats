#!/usr/bin/env bats
# Tests: sigchain-check (formats .rad .ems .ext)
# Also requires: tests/data/white1996, tests/data/bad/{rad,ems,ext},
# tests/golden/sigchain-check (the canonical rewrites of the samples)

load test_helper
bats_require_minimum_version 1.5.0

# --- .rad ---------------------------------------------------------------------------
@test "rad: sample of White (1996) checks" {
    check_good "$SEED/hawkeye_band3.rad" "7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: sample with the sigchain sky block checks" {
    check_good "$SEED/example_sky.rad" "3 samples, 18000-20000 cm-1, 2 view angles, sky 2x2 cells"
}
@test "rad: numbered band name (NAME.rad3) is a .rad" {
    cp "$SEED/hawkeye_band3.rad" hawkeye.rad3
    check_good hawkeye.rad3 "7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: stdin with -f rad" {
    run -0 --separate-stderr sigchain-check -f rad - < "$SEED/hawkeye_band3.rad"
    assert_output "-: ok: 7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: stdin error names <stdin>:LINE" {
    run -1 --separate-stderr sigchain-check -f rad - < "$BAD/rad/out_of_range.rad"
    [[ "$stderr" == "sigchain-check: <stdin>:14: expected tau1"* ]]
}
@test "rad: --rewrite gives the golden canonical file (legacy)" { check_rewrite_golden "$SEED/hawkeye_band3.rad"; }
@test "rad: --rewrite gives the golden canonical file (sky)" { check_rewrite_golden "$SEED/example_sky.rad"; }
@test "rad: empty file" { check_bad rad empty.rad "" "empty file, expected a radiance table (12 header lines)"; }
@test "rad: binary file" { check_bad rad binary.rad 2 "binary data (NUL byte)"; }
@test "rad: wrong field count" { check_bad rad field_count.rad 4 "expected 1 field (max wavelength (um)), found 2"; }
@test "rad: not a number" { check_bad rad not_a_number.rad 2 "expected sensor altitude (km) (a number), found 'one'"; }
@test "rad: NaN" { check_bad rad nan.rad 14 "expected Es (W cm-2 um-1) (spectral sample 1 of 1) (a finite number), found 'nan'"; }
@test "rad: inf" { check_bad rad inf.rad 16 "expected L_us (W cm-2 sr-1 um-1) (view angle 0 deg, spectral sample 1 of 1) (a finite number), found 'inf'"; }
@test "rad: negative count" { check_bad rad negative_count.rad 13 "expected number of view angles (a count, 0 or more), found '-1'"; }
@test "rad: count disagrees with the header's grid" { check_bad rad count_mismatch.rad 8 "expected number of spectral samples 1 + (20000 - 20000) / 1000 = 1, found '2'"; }
@test "rad: too few rows" { check_bad rad too_few_rows.rad 15 "expected 4 fields (wavelength, wavenumber, Es and tau1 (spectral sample 2 of 2)), found 2"; }
@test "rad: too many rows" { check_bad rad too_many_rows.rad 17 "expected SIGCHAIN_RAD or the end of the file after the 1 view-angle block(s) declared on line 13, found '1 2.5'"; }
@test "rad: truncated file" { check_bad rad truncated.rad 10 "unexpected end of file, expected view angle increment (deg)"; }
@test "rad: transmission out of range" { check_bad rad out_of_range.rad 14 "expected tau1 (spectral sample 1 of 1) in [0, 1], found '1.5'"; }
@test "rad: negative radiance" { check_bad rad negative_radiance.rad 16 "expected L_us (W cm-2 sr-1 um-1) (view angle 0 deg, spectral sample 1 of 1) >= 0, found '-0.003'"; }
@test "rad: samples not in decreasing wavenumber" { check_bad rad not_monotonic.rad 14 "expected wavenumber (decreasing from the header's max by its increment) (spectral sample 1 of 2) 20000, found '19000'"; }
@test "rad: wavelength is not 1e4 / wavenumber" { check_bad rad wavelength_mismatch.rad 14 "expected wavelength 1e4 / 20000 = 0.5 um (within 1e-5 relative), found '0.6'"; }
@test "rad: unknown SIGCHAIN_RAD major version" { check_bad rad sky_version.rad 17 "expected SIGCHAIN_RAD version 1 or 1.x (the version this reader knows), found '2'"; }
@test "rad: other units" { check_bad rad sky_units.rad 18 "expected UNITS irradiance=W/cm2/um radiance=W/cm2/sr/um (the units of every .rad), found 'irradiance=W/m2/nm"; }
@test "rad: solid angles do not cover the hemisphere" { check_bad rad sky_solid_angle.rad 20 "expected solid angles summing to 2 pi = 6.283185307179586 sr (within 0.1%), found 6.141592653589793"; }
@test "rad: sky cells not on a grid" { check_bad rad sky_grid.rad 24 "expected zenith 45 (as the first cell of its ring), found '50'"; }

# --- .ems ---------------------------------------------------------------------------
@test "ems: sample of White (1996) checks" { check_good "$SEED/fall_grass.ems" "1 curve, 350-39850 cm-1, no specular lobe"; }
@test "ems: stdin with -f ems" {
    run -0 --separate-stderr sigchain-check -f ems - < "$SEED/fall_grass.ems"
    assert_output "-: ok: 1 curve, 350-39850 cm-1, no specular lobe"
}
@test "ems: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/fall_grass.ems"; }
@test "ems: --rewrite keeps the CURVE_BEGIN layout and the lobe table" {
    { echo 1; for i in $(seq 0 90); do echo 1; done
      for i in 1 2 3 4 5 6 7; do echo "0.4 36.5 -999 -999"; done
      printf 'CURVE_BEGIN\n0.4 0.2\n0.8 0.6\nCURVE_END\n'; } > lobe.ems
    run -0 --separate-stderr sigchain-check --rewrite -o - lobe.ems
    assert_line --index 92 "0.4 36.5 -999 -999"
    assert_line --index 99 "CURVE_BEGIN"
    assert_line --index 101 "0.8 0.6"
    assert_equal "${#lines[@]}" 102
}
@test "ems: empty file" { check_bad ems empty.ems "" "empty file, expected number of emissivity curves"; }
@test "ems: binary file" { check_bad ems binary.ems 3 "binary data (NUL byte)"; }
@test "ems: wrong field count" { check_bad ems field_count.ems 5 "expected 1 field (fall-off value at 2 deg), found 2"; }
@test "ems: not a number" { check_bad ems not_a_number.ems 96 "expected emissivity (a number), found 'high'"; }
@test "ems: NaN" { check_bad ems nan.ems 11 "expected fall-off value at 8 deg (a finite number), found 'nan'"; }
@test "ems: inf" { check_bad ems inf.ems 96 "expected wavenumber (cm-1) (a finite number), found 'inf'"; }
@test "ems: negative count" { check_bad ems negative_count.ems 2 "expected number of emissivity curves (a count, 0 or more), found '-1'"; }
@test "ems: zero curves" { check_bad ems zero_curves.ems 2 "expected number of emissivity curves >= 1, found '0'"; }
@test "ems: too few curves" { check_bad ems too_few_curves.ems 97 "unexpected end of file, expected curve 1 of 2"; }
@test "ems: too many curves" { check_bad ems too_many_curves.ems 98 "unexpected content after the 1 curve(s) declared on line 2, found '1'"; }
@test "ems: truncated fall-off table" { check_bad ems truncated.ems 51 "unexpected end of file, expected fall-off value at 49 deg"; }
@test "ems: emissivity out of range" { check_bad ems out_of_range.ems 96 "expected emissivity in [0, 1], found '1.2'"; }
@test "ems: fall-off out of range" { check_bad ems fall_off_range.ems 3 "expected fall-off value at 0 deg in [0, 1], found '-0.1'"; }
@test "ems: lobe row with 3 columns" { check_bad ems lobe_fields.ems 95 "expected 4 fields (depth, base radius and 2 spares (specular lobe at 15 deg)), found 3"; }
@test "ems: negative lobe radius" { check_bad ems lobe_radius.ems 94 "expected lobe base radius (deg) (specular lobe at 0 deg) >= 0, found '-36.5'"; }
@test "ems: wavenumbers not monotonic" { check_bad ems not_monotonic.ems 97 "expected wavenumber (cm-1) less than 10000 (strictly decreasing like the rows before), found '15000'"; }
@test "ems: CURVE_BEGIN wavelengths not increasing" { check_bad ems wavelength_order.ems 96 "expected wavelength (um) greater than 0.5 (strictly increasing), found '0.3'"; }
@test "ems: wrong curve index" { check_bad ems curve_index.ems 94 "expected curve index 0 (start of curve 0 of 1), found '1'"; }
@test "ems: mixed curve layouts" { check_bad ems mixed_layout.ems 98 "expected curve index 1 (start of curve 1 of 2), found 'CURVE_BEGIN'"; }
@test "ems: curve without rows" { check_bad ems empty_curve.ems 94 "unexpected end of file, expected at least one row of wavenumber (cm-1) and emissivity of curve 0 of 1"; }

# --- .ext ---------------------------------------------------------------------------
@test "ext: example canopy checks" { check_good "$SEED/tree_canopy.ext" "2 curves, 0.4-2.5 um"; }
@test "ext: stdin with -f ext" {
    run -0 --separate-stderr sigchain-check -f ext - < "$SEED/tree_canopy.ext"
    assert_output "-: ok: 2 curves, 0.4-2.5 um"
}
@test "ext: --rewrite gives the golden canonical file" { check_rewrite_golden "$SEED/tree_canopy.ext"; }
@test "ext: empty file" { check_bad ext empty.ext "" "empty file, expected number of extinction curves"; }
@test "ext: binary file" { check_bad ext binary.ext 3 "binary data (NUL byte)"; }
@test "ext: wrong field count" { check_bad ext field_count.ext 5 "expected 2 fields (wavelength (um) and extinction coefficient (1/km) of curve 0 of 2), found 3"; }
@test "ext: not a number" { check_bad ext not_a_number.ext 4 "expected extinction coefficient (1/km) (a number), found 'lots'"; }
@test "ext: NaN" { check_bad ext nan.ext 4 "expected wavelength (um) (a finite number), found 'nan'"; }
@test "ext: inf" { check_bad ext inf.ext 4 "expected extinction coefficient (1/km) (a finite number), found 'inf'"; }
@test "ext: negative count" { check_bad ext negative_count.ext 2 "expected number of extinction curves (a count, 0 or more), found '-2'"; }
@test "ext: zero curves" { check_bad ext zero_curves.ext 2 "expected number of extinction curves >= 1, found '0'"; }
@test "ext: too few curves" { check_bad ext too_few_curves.ext 8 "unexpected end of file, expected CURVE_BEGIN of curve 2 of 3"; }
@test "ext: too many curves" { check_bad ext too_many_curves.ext 7 "unexpected content after the 1 curve(s) declared on line 2, found 'CURVE_BEGIN'"; }
@test "ext: missing CURVE_BEGIN" { check_bad ext missing_curve_begin.ext 3 "expected CURVE_BEGIN (start of curve 0 of 2), found 'CURVE_START'"; }
@test "ext: truncated file" { check_bad ext truncated.ext 7 "unexpected end of file, expected at least one row of wavelength (um) and extinction coefficient (1/km) of curve 1 of 2"; }
@test "ext: negative extinction" { check_bad ext negative_extinction.ext 5 "expected extinction coefficient (1/km) >= 0, found '-3'"; }
@test "ext: wavelengths not increasing" { check_bad ext not_increasing.ext 6 "expected wavelength (um) greater than 0.7 (strictly increasing), found '0.7'"; }

# --- .rad: the COUPLING terms (SIGCHAIN_RAD 1.2) --------------------------------------

# The rad(5) EXAMPLE (block 1.2 with COUPLING) into example.rad.
man_example() {
    sed -n '/^# EXAMPLE/,/^# /p' "$SIGCHAIN_SOURCE_DIR/man/rad.5.scd" |
        sed -n '/^```$/,/^```$/p' | sed '1d;$d' > example.rad
}

@test "rad: the coupling terms check and round-trip through --rewrite" {
    man_example
    check_good example.rad "3 samples, 18000-20000 cm-1, 2 view angles, sky 2x2 cells, coupling terms"
    run -0 --separate-stderr sigchain-check --rewrite -o once.rad example.rad
    grep -q '^SIGCHAIN_RAD 1.2$' once.rad
    grep -q '^DIFFUSE_UP 10 0.073 0.067 0.062$' once.rad
    run -0 --separate-stderr sigchain-check --rewrite -o twice.rad once.rad
    cmp once.rad twice.rad
}

@test "rad: older blocks (1.0, 1.1) still read; COUPLING in one is refused at its line" {
    check_good "$SEED/example_sky.rad" "3 samples, 18000-20000 cm-1, 2 view angles, sky 2x2 cells"
    man_example
    sed 's/^SIGCHAIN_RAD 1.2$/SIGCHAIN_RAD 1.1/' example.rad > old.rad
    local line
    line=$(grep -n '^COUPLING$' old.rad | cut -d: -f1)
    run -1 --separate-stderr sigchain-check old.rad
    assert_output ''
    [[ "$stderr" == "sigchain-check: old.rad:$line: expected the end of the file: COUPLING needs SIGCHAIN_RAD 1.2, found version 1.1" ]] ||
        fail "$stderr"
}

@test "rad: a malformed COUPLING line names its file and line, exit 1" {
    man_example
    sed 's/^DIFFUSE_DOWN .*/DIFFUSE_DOWN 0.142 0.131/' example.rad > short.rad
    local line
    line=$(grep -n '^DIFFUSE_DOWN' short.rad | cut -d: -f1)
    run -1 --separate-stderr sigchain-check short.rad
    [[ "$stderr" == "sigchain-check: short.rad:$line: expected 4 fields (DIFFUSE_DOWN ONE_PER_SPECTRAL_SAMPLE), found 3"* ]] ||
        fail "$stderr"
    sed 's/^DIFFUSE_UP 10 /DIFFUSE_UP 20 /' example.rad > angle.rad
    line=$(grep -n '^DIFFUSE_UP 20' angle.rad | cut -d: -f1)
    run -1 --separate-stderr sigchain-check angle.rad
    [[ "$stderr" == "sigchain-check: angle.rad:$line: expected view angle 10"* ]] || fail "$stderr"
    sed 's/^SPHERICAL_ALBEDO 0.171/SPHERICAL_ALBEDO 1.171/' example.rad > big.rad
    line=$(grep -n '^SPHERICAL_ALBEDO' big.rad | cut -d: -f1)
    run -1 --separate-stderr sigchain-check big.rad
    [[ "$stderr" == "sigchain-check: big.rad:$line: expected spherical albedo S (sample 1)"* ]] ||
        fail "$stderr"
}
