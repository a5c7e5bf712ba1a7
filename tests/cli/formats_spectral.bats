#!/usr/bin/env bats
# Tests: sigchain-check (formats .rad .ems .ext)
# Also requires: tests/data/seed, tests/data/bad/{rad,ems,ext},
# tests/golden/sigchain-check (the canonical rewrites of the samples)

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

# --- .rad ---------------------------------------------------------------------------
@test "rad: seed sample checks" {
    good "$SEED/hawkeye_band3.rad" "7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: sample with the sigchain sky block checks" {
    good "$SEED/example_sky.rad" "3 samples, 18000-20000 cm-1, 2 view angles, sky 2x2 cells"
}
@test "rad: numbered band name (NAME.rad3) is a .rad" {
    cp "$SEED/hawkeye_band3.rad" hawkeye.rad3
    good hawkeye.rad3 "7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: stdin with -f rad" {
    run -0 --separate-stderr sigchain-check -f rad - < "$SEED/hawkeye_band3.rad"
    assert_output "-: ok: 7 samples, 14400-16800 cm-1, 1 view angle, no sky hemisphere"
}
@test "rad: stdin error names <stdin>:LINE" {
    run -1 --separate-stderr sigchain-check -f rad - < "$BAD/rad/out_of_range.rad"
    [[ "$stderr" == "sigchain-check: <stdin>:14: expected tau1"* ]]
}
@test "rad: --rewrite gives the golden canonical file (legacy)" { golden "$SEED/hawkeye_band3.rad"; }
@test "rad: --rewrite gives the golden canonical file (sky)" { golden "$SEED/example_sky.rad"; }
@test "rad: empty file" { bad rad empty "" "empty file, expected a radiance table (12 header lines)"; }
@test "rad: binary file" { bad rad binary 2 "binary data (NUL byte)"; }
@test "rad: wrong field count" { bad rad field_count 4 "expected 1 field (max wavelength (um)), found 2"; }
@test "rad: not a number" { bad rad not_a_number 2 "expected sensor altitude (km) (a number), found 'one'"; }
@test "rad: NaN" { bad rad nan 14 "expected Es (W cm-2 um-1) (spectral sample 1 of 1) (a finite number), found 'nan'"; }
@test "rad: inf" { bad rad inf 16 "expected L_us (W cm-2 sr-1 um-1) (view angle 0 deg, spectral sample 1 of 1) (a finite number), found 'inf'"; }
@test "rad: negative count" { bad rad negative_count 13 "expected number of view angles (a count, 0 or more), found '-1'"; }
@test "rad: count disagrees with the header's grid" { bad rad count_mismatch 8 "expected number of spectral samples 1 + (20000 - 20000) / 1000 = 1, found '2'"; }
@test "rad: too few rows" { bad rad too_few_rows 15 "expected 4 fields (wavelength, wavenumber, Es and tau1 (spectral sample 2 of 2)), found 2"; }
@test "rad: too many rows" { bad rad too_many_rows 17 "expected SIGCHAIN_RAD or the end of the file after the 1 view-angle block(s) declared on line 13, found '1 2.5'"; }
@test "rad: truncated file" { bad rad truncated 10 "unexpected end of file, expected view angle increment (deg)"; }
@test "rad: transmission out of range" { bad rad out_of_range 14 "expected tau1 (spectral sample 1 of 1) in [0, 1], found '1.5'"; }
@test "rad: negative radiance" { bad rad negative_radiance 16 "expected L_us (W cm-2 sr-1 um-1) (view angle 0 deg, spectral sample 1 of 1) >= 0, found '-0.003'"; }
@test "rad: samples not in decreasing wavenumber" { bad rad not_monotonic 14 "expected wavenumber (decreasing from the header's max by its increment) (spectral sample 1 of 2) 20000, found '19000'"; }
@test "rad: wavelength is not 1e4 / wavenumber" { bad rad wavelength_mismatch 14 "expected wavelength 1e4 / 20000 = 0.5 um (within 1e-5 relative), found '0.6'"; }
@test "rad: unknown SIGCHAIN_RAD major version" { bad rad sky_version 17 "expected SIGCHAIN_RAD version 1 or 1.x (the version this reader knows), found '2'"; }
@test "rad: other units" { bad rad sky_units 18 "expected UNITS irradiance=W/cm2/um radiance=W/cm2/sr/um (the units of every .rad), found 'irradiance=W/m2/nm"; }
@test "rad: solid angles do not cover the hemisphere" { bad rad sky_solid_angle 20 "expected solid angles summing to 2 pi = 6.283185307179586 sr (within 0.1%), found 6.141592653589793"; }
@test "rad: sky cells not on a grid" { bad rad sky_grid 24 "expected zenith 45 (as the first cell of its ring), found '50'"; }

# --- .ems ---------------------------------------------------------------------------
@test "ems: seed sample checks" { good "$SEED/fall_grass.ems" "1 curve, 350-39850 cm-1, no specular lobe"; }
@test "ems: stdin with -f ems" {
    run -0 --separate-stderr sigchain-check -f ems - < "$SEED/fall_grass.ems"
    assert_output "-: ok: 1 curve, 350-39850 cm-1, no specular lobe"
}
@test "ems: --rewrite gives the golden canonical file" { golden "$SEED/fall_grass.ems"; }
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
@test "ems: empty file" { bad ems empty "" "empty file, expected number of emissivity curves"; }
@test "ems: binary file" { bad ems binary 3 "binary data (NUL byte)"; }
@test "ems: wrong field count" { bad ems field_count 5 "expected 1 field (fall-off value at 2 deg), found 2"; }
@test "ems: not a number" { bad ems not_a_number 96 "expected emissivity (a number), found 'high'"; }
@test "ems: NaN" { bad ems nan 11 "expected fall-off value at 8 deg (a finite number), found 'nan'"; }
@test "ems: inf" { bad ems inf 96 "expected wavenumber (cm-1) (a finite number), found 'inf'"; }
@test "ems: negative count" { bad ems negative_count 2 "expected number of emissivity curves (a count, 0 or more), found '-1'"; }
@test "ems: zero curves" { bad ems zero_curves 2 "expected number of emissivity curves >= 1, found '0'"; }
@test "ems: too few curves" { bad ems too_few_curves 97 "unexpected end of file, expected curve 1 of 2"; }
@test "ems: too many curves" { bad ems too_many_curves 98 "unexpected content after the 1 curve(s) declared on line 2, found '1'"; }
@test "ems: truncated fall-off table" { bad ems truncated 51 "unexpected end of file, expected fall-off value at 49 deg"; }
@test "ems: emissivity out of range" { bad ems out_of_range 96 "expected emissivity in [0, 1], found '1.2'"; }
@test "ems: fall-off out of range" { bad ems fall_off_range 3 "expected fall-off value at 0 deg in [0, 1], found '-0.1'"; }
@test "ems: lobe row with 3 columns" { bad ems lobe_fields 95 "expected 4 fields (depth, base radius and 2 spares (specular lobe at 15 deg)), found 3"; }
@test "ems: negative lobe radius" { bad ems lobe_radius 94 "expected lobe base radius (deg) (specular lobe at 0 deg) >= 0, found '-36.5'"; }
@test "ems: wavenumbers not monotonic" { bad ems not_monotonic 97 "expected wavenumber (cm-1) less than 10000 (strictly decreasing like the rows before), found '15000'"; }
@test "ems: CURVE_BEGIN wavelengths not increasing" { bad ems wavelength_order 96 "expected wavelength (um) greater than 0.5 (strictly increasing), found '0.3'"; }
@test "ems: wrong curve index" { bad ems curve_index 94 "expected curve index 0 (start of curve 0 of 1), found '1'"; }
@test "ems: mixed curve layouts" { bad ems mixed_layout 98 "expected curve index 1 (start of curve 1 of 2), found 'CURVE_BEGIN'"; }
@test "ems: curve without rows" { bad ems empty_curve 94 "unexpected end of file, expected at least one row of wavenumber (cm-1) and emissivity of curve 0 of 1"; }

# --- .ext ---------------------------------------------------------------------------
@test "ext: example canopy checks" { good "$SEED/tree_canopy.ext" "2 curves, 0.4-2.5 um"; }
@test "ext: stdin with -f ext" {
    run -0 --separate-stderr sigchain-check -f ext - < "$SEED/tree_canopy.ext"
    assert_output "-: ok: 2 curves, 0.4-2.5 um"
}
@test "ext: --rewrite gives the golden canonical file" { golden "$SEED/tree_canopy.ext"; }
@test "ext: empty file" { bad ext empty "" "empty file, expected number of extinction curves"; }
@test "ext: binary file" { bad ext binary 3 "binary data (NUL byte)"; }
@test "ext: wrong field count" { bad ext field_count 5 "expected 2 fields (wavelength (um) and extinction coefficient (1/km) of curve 0 of 2), found 3"; }
@test "ext: not a number" { bad ext not_a_number 4 "expected extinction coefficient (1/km) (a number), found 'lots'"; }
@test "ext: NaN" { bad ext nan 4 "expected wavelength (um) (a finite number), found 'nan'"; }
@test "ext: inf" { bad ext inf 4 "expected extinction coefficient (1/km) (a finite number), found 'inf'"; }
@test "ext: negative count" { bad ext negative_count 2 "expected number of extinction curves (a count, 0 or more), found '-2'"; }
@test "ext: zero curves" { bad ext zero_curves 2 "expected number of extinction curves >= 1, found '0'"; }
@test "ext: too few curves" { bad ext too_few_curves 8 "unexpected end of file, expected CURVE_BEGIN of curve 2 of 3"; }
@test "ext: too many curves" { bad ext too_many_curves 7 "unexpected content after the 1 curve(s) declared on line 2, found 'CURVE_BEGIN'"; }
@test "ext: missing CURVE_BEGIN" { bad ext missing_curve_begin 3 "expected CURVE_BEGIN (start of curve 0 of 2), found 'CURVE_START'"; }
@test "ext: truncated file" { bad ext truncated 7 "unexpected end of file, expected at least one row of wavelength (um) and extinction coefficient (1/km) of curve 1 of 2"; }
@test "ext: negative extinction" { bad ext negative_extinction 5 "expected extinction coefficient (1/km) >= 0, found '-3'"; }
@test "ext: wavelengths not increasing" { bad ext not_increasing 6 "expected wavelength (um) greater than 0.7 (strictly increasing), found '0.7'"; }
