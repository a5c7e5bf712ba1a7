# Tests: trace
# Also requires: sigchain-check compare sensorize pkg-config
#
# trace on a tiny scene: tests/data/trace/box.adv (16 x 16 pixels, 4 samples per
# pixel) looking at tests/data/white1996/box_on_plane.gdb, two hand-written sigchain .rad
# bands of 3 samples each (band1.rad, band2.rad), grass and wood materials.

bats_require_minimum_version 1.5.0
load test_helper
load trace_helper

# The float32 planes of band B of an ENVI cube of ROWS x 16 pixels, as raw bytes.
band_bytes() {
    local file="$1" band="$2" rows="$3"
    dd if="$file" bs=64 skip=$((band * rows)) count="$rows" status=none
}

@test "trace --help prints usage and points to trace(1)" {
    run -0 --separate-stderr trace --help
    assert_line --index 0 --partial "Usage: trace "
    assert_line --partial "--sampling"
    assert_line --partial "--rows"
    assert_equal "${lines[-1]}" "See trace(1)."
}

@test "trace --version prints the project version" {
    local version
    version=$(sed -n 's/^project(sigchain VERSION \([0-9][0-9.]*\).*/\1/p' \
        "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt")
    run -0 --separate-stderr trace --version
    assert_output "trace (sigchain) $version"
}

@test "--version -v lists the libraries the tools were built with, as pkg-config knows them" {
    run -0 --separate-stderr sensorize --version -v
    assert_line --index 0 "sensorize (sigchain) $(trace --version | cut -d' ' -f3)"
    assert_line --index 1 "built with:"
    for lib in Embree GDAL OpenImageIO GeographicLib Assimp FFTW3 oneTBB Boost; do
        assert_line --regexp "^$lib [0-9]+\.[0-9]+"
    done
    assert_line --regexp "^(Open MPI [0-9]|MPI [0-9.]+ \(the standard's version\)|MPI: not built)"
    # The versions are the installed packages' own.
    assert_line "GDAL $(pkg-config --modversion gdal)"
    assert_line "FFTW3 $(pkg-config --modversion fftw3)"
    assert_line "GeographicLib $(pkg-config --modversion geographiclib)"
}

@test "trace renders the box scene as the golden ENVI cube" {
    # The golden cube is the golf ball at the .adv's 4 samples per pixel (White's
    # sampling); trace's own default is checked below (sampling by accuracy).
    trace_ok $(inputs) --sampling golfball -o out.img
    # Float rounding differs between compilers and libm builds by a few ulps of the
    # radiances (about 0.001 to 0.05 W cm-2 sr-1 um-1 here): 1e-6 is 20 ulps of the
    # largest value and far below any modelling change.
    GOLDEN_MAX_DIFF=1e-6 assert_golden out.img "$GOLDEN/trace/box.img"
    [ -f out.hdr ] || fail "no ENVI header"
}

@test "trace writes the wavelengths, units and band layout in the ENVI header" {
    trace_ok $(inputs) -o out.img
    run -0 grep -i '^samples *= 16' out.hdr
    run -0 grep -i '^lines *= 16' out.hdr
    run -0 grep -i '^bands *= 6' out.hdr
    run -0 grep -i '^data type = 4' out.hdr
    run -0 grep -i '^wavelength units = Micrometers' out.hdr
    run -0 grep -i '^data units = W cm-2 sr-1 um-1' out.hdr
    # Band order = .rad order, each band's samples by increasing wavelength.
    run -0 tr -d '\n' < out.hdr
    [[ "$output" == *"wavelength = {0.5, 0.526316, 0.555556, 0.625, 0.645161, 0.666667}"* ]] ||
        fail "wavelength list: $output"
    # ENVI shows it in true colour: red 0.666667 um (band 6), green nearest 0.55 um
    # (0.555556, band 3), blue 0.5 um (band 1).
    run -0 grep -x 'default bands = {6, 3, 1}' out.hdr
}

@test "trace writes GeoTIFF for a .tif name, with the same pixels" {
    trace_ok $(inputs) -o out.img
    trace_ok $(inputs) -o out.tif
    run -0 compare --pixelwise --fail-max 0 out.tif out.img
}

@test "trace -o NAME.hdr writes NAME.img beside the header" {
    trace_ok $(inputs) -o cube.hdr
    [ -f cube.img ] && [ -f cube.hdr ]
}

@test "trace --rows slices merge bit-identically into the whole image" {
    trace_ok $(inputs) -o whole.img
    trace_ok $(inputs) --rows 0:5 -o top.img
    trace_ok $(inputs) --rows 5:16 -o bottom.img
    run -0 grep -i '^lines *= 5' top.hdr
    run -0 grep -i '^lines *= 11' bottom.hdr
    # ENVI cubes are band-sequential: per band, the slices' planes in row order.
    for band in 0 1 2 3 4 5; do
        band_bytes top.img "$band" 5
        band_bytes bottom.img "$band" 11
    done > merged.img
    run -0 cmp merged.img whole.img
    # Monte Carlo too: its random numbers hash the pixel, not the slice.
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 16 -o mc_whole.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 16 --rows 0:9 -o mc_top.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 16 --rows 9:16 -o mc_bottom.img
    for band in 0 1 2 3 4 5; do
        band_bytes mc_top.img "$band" 9
        band_bytes mc_bottom.img "$band" 7
    done > mc_merged.img
    run -0 cmp mc_merged.img mc_whole.img
}

@test "trace gives identical cubes with 1 and 2 threads" {
    trace_ok $(inputs) --threads 1 -o one.img
    trace_ok $(inputs) --threads 2 -o two.img
    run -0 cmp one.img two.img
    trace_ok $(inputs) --threads 0 -o all.img
    run -0 cmp one.img all.img
}

@test "trace --seed: the same seed repeats, another seed jitters differently" {
    trace_ok $(inputs) --seed 7 -o a.img
    trace_ok $(inputs) --seed 7 -o b.img
    run -0 cmp a.img b.img
    trace_ok $(inputs) --seed 8 -o c.img
    run -1 cmp -s a.img c.img
}

@test "trace --samples-per-pixel overrides the .adv's samples_per_pixel" {
    # With a strategy named, the .adv's samples_per_pixel (4) is the count.
    trace_ok $(inputs) --sampling golfball -o four.img
    trace_ok $(inputs) --samples-per-pixel 4 -o four_again.img
    run -0 cmp four.img four_again.img
    trace_ok $(inputs) --samples-per-pixel 1 -o one.img
    run -1 cmp -s four.img one.img
}

@test "trace --sampling dirsig, montecarlo and proposed stay near golfball on a Lambertian scene" {
    trace_ok $(inputs) --sampling golfball -o golf.img
    trace_ok $(inputs) --sampling dirsig -o dirsig.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 256 -o mc.img
    # Lambertian materials: the strategies differ only in how they integrate the sky
    # (constant over 2 x 4 cells, a step at 45 deg zenith) and the box's walls; the
    # unit tests measure their accuracy. This test catches a lost or doubled term:
    # the reflected sky alone is about rho E_sky / pi = 2e-3 W cm-2 sr-1 um-1 on the
    # grass (the sun term about 5e-3), so 1e-3 is half the smallest term. (Measured:
    # max 9e-5; golfball is 0.4 % below the other two on average.)
    run -0 compare --pixelwise --fail-max 1e-3 dirsig.img golf.img
    run -0 compare --pixelwise --fail-max 1e-3 mc.img golf.img
    run -1 cmp -s mc.img golf.img
    # White's proposed model samples the primary hit with the golf ball; its 10 deg rule
    # acts only on glossy facets a hemisphere ray meets, and this scene has none: the
    # pixels are golfball's, byte for byte (the header records the other command).
    trace_ok $(inputs) --sampling proposed -o proposed.img
    run -0 cmp proposed.img golf.img
    run -2 trace $(inputs) --sampling white -o w.img
    [[ "$output" == *"unknown strategy 'white' (dirsig, golfball, montecarlo or proposed)"* ]]
}

@test "trace --golfball-jitter changes golfball's rays, repeatably" {
    trace_ok $(inputs) --sampling golfball -o centres.img
    trace_ok $(inputs) --golfball-jitter -o jitter.img
    trace_ok $(inputs) --golfball-jitter --threads 1 -o jitter_again.img
    run -1 cmp -s centres.img jitter.img
    run -0 cmp jitter.img jitter_again.img
    # Lambertian scene: the jittered golf ball is unbiased and averages 4 x 61 rays per
    # pixel; 1e-3 is half the smallest radiance term (see the --sampling test).
    run -0 compare --pixelwise --fail-max 1e-3 jitter.img centres.img
}

@test "trace --hemisphere-samples changes montecarlo's estimate" {
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 8 -o a.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 32 -o b.img
    run -1 cmp -s a.img b.img
}

@test "trace --max-transmissions: a clear box is seen through, or stops rays at 0" {
    # Opaque scene: nothing to cross.
    trace_ok $(inputs) -o a.img
    trace_ok $(inputs) --max-transmissions 0 -o b.img
    run -0 cmp a.img b.img
    # transmissive.mat makes the box a 5 cm slab of glass.ext (t = 0.999).
    run -0 --separate-stderr trace -v $(inputs "$GDB" "$DATA/transmissive.mat") -o glass.img
    [[ "$stderr" != *"not modelled: transmission"* ]] || fail "stderr: $stderr"
    trace_ok $(inputs "$GDB" "$DATA/transmissive.mat") --max-transmissions 0 -o stopped.img
    run -1 cmp -s glass.img stopped.img
    trace_ok $(inputs "$GDB" "$DATA/transmissive.mat") --max-transmissions 8 -o eight.img
    run -0 cmp glass.img eight.img
}

@test "trace renders an .odb assembly (three instances of box_on_plane.gdb)" {
    run -0 --separate-stderr trace -v $(inputs "$SEED/neighbourhood.odb") -o odb.img
    [[ "$stderr" == *"scene: 1 mesh(es), 3 placement(s), 18 facets, 36 triangles"* ]] ||
        fail "stderr: $stderr"
    [ -f odb.img ]
}

@test "trace --truth writes the truth layers with their channel names" {
    trace_ok $(inputs) -o out.img --truth truth.img
    run -0 grep -i '^lines *= 16' truth.hdr
    run -0 tr -d '\n' < truth.hdr
    [[ "$output" == *"band names = {"*"hit"*"material_id"*"shadow_fraction"*"sky_view_factor"* ]] ||
        fail "truth band names: $output"
    [[ "$output" == *"reflectance_band1"*"reflectance_band2"* ]] || fail "per-band layers: $output"
    # The radiance cube is the same with or without truth.
    trace_ok $(inputs) -o plain.img
    run -0 cmp out.img plain.img
}

@test "trace --tmp adds emission, negligible in visible bands at 300 K" {
    trace_ok $(inputs) -o plain.img
    trace_ok $(inputs) --tmp "$DATA/box.tmp" -o hot.img
    # eps B(300 K) at 0.5-0.67 um is below 1e-20 W cm-2 sr-1 um-1, far below a float32
    # ulp of the reflected radiance: the cubes agree to the last bit.
    run -0 compare --pixelwise --fail-max 0 hot.img plain.img
    run -0 --separate-stderr trace -v $(inputs) --tmp "$DATA/box.tmp" -o hot.img
    [[ "$stderr" == *"temperatures of 6 facet(s)"* ]] || fail "stderr: $stderr"
}

@test "trace -v reports the scene, the grid, the rays and what was left out" {
    run -0 --separate-stderr trace -v $(inputs) -o out.img
    assert_output ''
    [[ "$stderr" == *"trace: spectral grid: 6 samples in 2 band(s)"* ]] || fail "$stderr"
    [[ "$stderr" == *"trace: scene: "*" facets, "*" triangles; 2 material(s)"* ]] || fail "$stderr"
    [[ "$stderr" == *"emission is left out"* ]] || fail "$stderr"
    [[ "$stderr" == *" rays ("*" primary, "*"Mrays/s"* ]] || fail "$stderr"
    # The default sampling (by accuracy) says what it chose and the scale of its error.
    [[ "$stderr" == *"8 to 512 sample(s) per pixel, montecarlo sampling with 1 hemisphere ray per sample and the open sky integrated, chosen by accuracy (--sampling auto, the default)"* ]] ||
        fail "$stderr"
    assert_regex "$stderr" "open sky: integrated over each primary hit's hemisphere \([12] table\(s\) by facet normal, one per incoming fall-off, 3 x 6 deg, [0-9]+ of [0-9]+ nodes computed\).*for 2 of 2 material\(s\)"
    assert_regex "$stderr" "convergence scale \(radiance of a 20 % grey ground at nadir, W cm-2 sr-1 um-1, per band\): [0-9.e-]+ [0-9.e-]+"$'\n'
    # A count without a strategy: the golf ball, at that count.
    run -0 --separate-stderr trace -v $(inputs) --samples-per-pixel 4 -o out.img
    [[ "$stderr" == *"4 sample(s) per pixel, golfball sampling"* ]] || fail "$stderr"
    [[ "$stderr" == *"1024 primary"* ]] || fail "16 x 16 x 4 primary rays: $stderr"
    [[ "$stderr" != *"convergence scale"* ]] || fail "$stderr"
    [[ "$stderr" != *"open sky"* ]] || fail "$stderr"
}

@test "trace --sampling auto: the default, chosen by accuracy, repeatable, said by -v; not with a count of its own" {
    # montecarlo, 1 hemisphere ray, samples by the scene rule (trace(1) SAMPLING BY
    # ACCURACY); the same cube for any thread count.
    run -0 --separate-stderr trace -v --sampling auto $(inputs) -o auto.img --threads 1
    [[ "$stderr" == *"8 to 512 sample(s) per pixel, montecarlo sampling with 1 hemisphere ray per sample and the open sky integrated, chosen by accuracy (--sampling auto, the default)"* ]] ||
        fail "$stderr"
    [[ "$stderr" == *"primary sample(s) per pixel on average, at most "* ]] || fail "$stderr"
    trace_ok --sampling auto $(inputs) -o auto2.img --threads 2
    run -0 cmp auto.img auto2.img
    # Without --sampling it is the default, byte for byte.
    trace_ok $(inputs) -o default.img
    run -0 cmp auto.img default.img
    # It is --convergence 8,512,0.00625 --convergence-error scene with montecarlo, one
    # hemisphere ray and the open sky integrated, byte for byte.
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 1 --open-sky integrated \
        --convergence 8,512,0.00625 --convergence-error scene -o named.img
    run -0 cmp auto.img named.img
    trace_bad 2 "--sampling auto chooses its own samples: not with --convergence" \
        --sampling auto --convergence 4,8,0.1 $(inputs) -o out.img
}

@test "trace --open-sky: integrated by default with auto, sampled with montecarlo; bad values refused" {
    # montecarlo alone keeps the sampled sky, byte for byte.
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 4 -o mc.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 4 --open-sky sampled -o sampled.img
    run -0 cmp mc.img sampled.img
    # integrated: another cube, the same for any thread count.
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 4 --open-sky integrated \
        --threads 1 -o cv1.img
    trace_ok $(inputs) --sampling montecarlo --hemisphere-samples 4 --open-sky integrated \
        --threads 2 -o cv2.img
    run -0 cmp cv1.img cv2.img
    run -1 cmp -s cv1.img mc.img
    # auto with the sky sampled: no open-sky line, and not the default's cube.
    run -0 --separate-stderr trace -v $(inputs) --open-sky sampled -o autosampled.img
    [[ "$stderr" == *"1 hemisphere ray per sample, chosen by accuracy"* ]] || fail "$stderr"
    [[ "$stderr" != *"open sky"* ]] || fail "$stderr"
    trace_ok $(inputs) -o default.img
    run -1 cmp -s autosampled.img default.img
    trace_bad 2 "--open-sky: expected integrated or sampled, not 'yes'" \
        --open-sky yes $(inputs) -o out.img
    trace_bad 2 "--open-sky integrated: only with --sampling montecarlo or auto (golfball samples the sky in fixed directions)" \
        --sampling golfball --open-sky integrated $(inputs) -o out.img
    [ ! -e out.img ]
}

@test "trace -v splits the wall time into the set-up's phases and the render" {
    run -0 --separate-stderr trace -v $(inputs) -o v.img
    n='[0-9]+[.][0-9]{3}'
    assert_regex "$stderr" "trace: set-up $n s: [.]adv/[.]snd $n s, [.]rad tables $n s, materials $n s, scene files $n s, Embree build $n s, [.]tmp $n s, other $n s; render $n s"
    # Verbose only: without -v no such line, and the cube is the same.
    run -0 --separate-stderr trace $(inputs) -o plain.img
    [[ "$stderr" != *"set-up"* ]] || fail "$stderr"
    run -0 cmp v.img plain.img
}

@test "trace --progress draws a progress bar on stderr; -q silences warnings" {
    run -0 --separate-stderr trace --progress $(inputs) -o out.img
    [[ "$stderr" == *"trace: rendering ["* ]] || fail "stderr: $stderr"
    run -0 --separate-stderr trace -q --allow-degenerate $(inputs "$DATA/degenerate.gdb") -o q.img
    assert_equal "$stderr" ''
}

@test "trace rejects a degenerate facet, naming it; --allow-degenerate skips it" {
    trace_bad 1 "$DATA/degenerate.gdb:37: object 'box' (2-0-0), part 'house side' (2-1-0), facet 'top' (2-1-1)" \
        $(inputs "$DATA/degenerate.gdb") -o out.img
    run -0 --separate-stderr trace --allow-degenerate $(inputs "$DATA/degenerate.gdb") -o skip.img
    [[ "$stderr" == "trace: warning: $DATA/degenerate.gdb:37: "*"(2-1-1)"* ]] || fail "stderr: $stderr"
    [ -f skip.img ]
}

@test "trace warns when the image's view angles leave the .rad tables" {
    run -0 --separate-stderr trace "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/narrow_band1.rad" "$DATA/narrow_band2.rad" -o out.img
    # The camera looks atan(20/30) = 33.69 deg off nadir with a half field of view of
    # atan(8 mm / 32 mm) = 14.04 deg: 19.65 deg at the bottom edge's middle; the top
    # corners (32, 8, 8 mm along forward, right, up) are 49.18 deg off nadir.
    assert_equal "$stderr" "trace: warning: the image spans view angles 20.50 to 49.18 deg but the .rad files cover 0.00 to 45.00 deg: path terms are clamped at the ends"
}

@test "trace warns when a .rad's sample count differs from its .snd band" {
    run -0 --separate-stderr trace "$DATA/box.adv" "$DATA/mismatch.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o out.img
    assert_equal "$stderr" "trace: warning: $DATA/band1.rad: 3 spectral samples, but band 1 of $DATA/mismatch.snd has 5"
}

@test "trace: .rad files with different view angles are refused, naming both" {
    trace_bad 1 "$DATA/narrow_band2.rad: view angles differ from those of $DATA/band1.rad" \
        "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/box.mat" "$DATA/band1.rad" \
        "$DATA/narrow_band2.rad" -o out.img
}

@test "trace: a missing material id names the facet and its line" {
    trace_bad 1 "$GDB:44: object 'box' (2-0-0), part 'house side' (2-1-0), facet 'top' (2-1-1): material 37" \
        $(inputs "$GDB" "$DATA/missing_wood.mat") -o out.img
}

@test "trace: a missing .ems names the .mat line of its EMISSIVITY_FILE and the material" {
    trace_bad 1 "$DATA/missing_ems.mat:30: material 'wood' (37): cannot read EMISSIVITY_FILE" \
        $(inputs "$GDB" "$DATA/missing_ems.mat") -o out.img
    [[ "$stderr" == *"no_such_wood.ems"* ]] || fail "stderr: $stderr"
}

@test "trace: a missing input file is an I/O error naming it" {
    trace_bad 1 "no_such.adv" no_such.adv "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$DATA/band2.rad" -o out.img
    trace_bad 1 "no_such.gdb" $(inputs no_such.gdb) -o out.img
}

@test "trace: a bad .adv line is reported with its file and line" {
    trace_bad 1 "$DATA/bad.adv:5: expected focal length" "$DATA/bad.adv" "$DATA/box.snd" \
        "$GDB" "$DATA/box.mat" "$DATA/band1.rad" "$DATA/band2.rad" -o out.img
}

@test "trace: the .rad count must equal the .snd's band count" {
    trace_bad 2 "$DATA/box.snd has 2 band(s) but 1 .rad file(s)" "$DATA/box.adv" \
        "$DATA/box.snd" "$GDB" "$DATA/box.mat" "$DATA/band1.rad" -o out.img
    [[ "$stderr" == *"Try 'trace --help'."* ]]
}

@test "trace: a DIRSIG .rad (no SIGCHAIN_RAD block) renders with the sun from the .snd and no sky" {
    # NREL SPA for 30 Sep 1995 19 h GMT at 43.08333 N 77.66667 W (lib/atmos tests
    # check SPA against NREL's worked example): zenith 53.178 deg, azimuth 218.346.
    run -0 --separate-stderr trace "$DATA/box.adv" "$DATA/dirsig.snd" "$GDB" "$DATA/box.mat" \
        "$SEED/hawkeye_band3.rad" -o out.img
    [[ "$stderr" == *"hawkeye_band3.rad: a DIRSIG .rad (no SIGCHAIN_RAD block): the sun is placed from"*"(zenith 53.178 deg, azimuth 218.346 deg) and the downwelled sky is zero"* ]] ||
        fail "stderr: $stderr"
    assert [ -s out.img ]
    # One float32 band per spectral sample of the DIRSIG .rad (7).
    assert_equal "$(grep -E '^bands *=' out.hdr | tr -d ' ')" "bands=7"
}

@test "trace: a DIRSIG .rad mixed with sigchain .rad files is refused" {
    run -1 --separate-stderr trace "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/box.mat" \
        "$DATA/band1.rad" "$SEED/hawkeye_band3.rad" -o out.img
    assert_output ''
    # After a warning about its sample count, the error names the file that differs.
    [[ "${stderr_lines[-1]}" == "trace: $SEED/hawkeye_band3.rad: "* ]] || fail "stderr: $stderr"
    assert [ ! -e out.img ]
    assert_no_temp_files
}

@test "trace: bad --rows values are usage errors" {
    trace_bad 2 "--rows: expected A:B" $(inputs) --rows 5 -o out.img
    trace_bad 2 "--rows: expected A:B" $(inputs) --rows a:b -o out.img
    trace_bad 2 "--rows: expected A:B" $(inputs) --rows -1:4 -o out.img
    trace_bad 2 "--rows: the end row must be greater" $(inputs) --rows 5:3 -o out.img
    trace_bad 2 "--rows 0:17: the image has 16 rows" $(inputs) --rows 0:17 -o out.img
}

@test "trace: bad --sampling and counts are usage errors" {
    trace_bad 2 "--sampling: unknown strategy 'mcmc'" $(inputs) --sampling mcmc -o out.img
    trace_bad 2 "--samples-per-pixel: 0: must be an integer from 1 to 65536" $(inputs) --samples-per-pixel 0 -o out.img
    trace_bad 2 "--hemisphere-samples: 0: must be an integer from 1 to 1000000" $(inputs) \
        --hemisphere-samples 0 -o out.img
    trace_bad 2 "--max-transmissions: -1: must be an integer from 0 to 1000" $(inputs) \
        --max-transmissions=-1 -o out.img
}

@test "trace refuses standard output, a missing -o and unknown cube extensions" {
    trace_bad 2 "a radiance cube cannot be written to standard output" $(inputs) -o -
    trace_bad 2 "no output cube: give -o CUBE" $(inputs)
    trace_bad 2 "out.png: unknown cube format" $(inputs) -o out.png
    trace_bad 2 "--truth: " $(inputs) -o out.img --truth out.hdr
}

@test "trace: too few arguments and unknown options are usage errors" {
    trace_bad 2 "expected ADV SND SCENE MAT and at least one RAD" "$DATA/box.adv" \
        "$DATA/box.snd" "$GDB" "$DATA/box.mat" -o out.img
    run -2 --separate-stderr trace --no-such-option
    assert_equal "${stderr##*$'\n'}" "Try 'trace --help'."
}

@test "trace --background: mean by default, none, a material, and usage errors" {
    run -0 --separate-stderr trace -v $(inputs) -o mean.img
    [[ "$stderr" == *"background world: mean of the scene seen from above"* ]] ||
        fail "stderr: $stderr"
    [[ "$stderr" == *"primary sample(s) saw the sky"* ]] || fail "stderr: $stderr"
    run -0 --separate-stderr trace -v --background none $(inputs) -o none.img
    [[ "$stderr" == *"background world: none (--background none)"* ]] || fail "stderr: $stderr"
    trace_bad 2 "--background: expected mean, none or a MATERIAL_ID, not 'grass'" $(inputs) \
        -o out.img --background grass
    trace_bad 1 "--background: material 999 is not in the material file" $(inputs) \
        -o out.img --background 999
    run -2 --separate-stderr trace --shadow-history --background none "$DATA/box.snd" "$GDB" \
        "$DATA/box.mat" -o out.shd
    [[ "$stderr" == *"--background does not apply to --shadow-history"* ]] || fail "$stderr"
}

@test "trace leaves no temporary file when the output cannot be written" {
    trace_bad 1 "no_such_dir/out.img: cannot create" $(inputs) -o no_such_dir/out.img
    [ ! -e no_such_dir ]
}

@test "trace: a TEXTURE_FILE brightens the grass it maps to curve 1, and nothing else" {
    trace_ok "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/box.mat" "$DATA/band1.rad" \
        "$DATA/band2.rad" -o plain.img
    trace_ok "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/textured.mat" "$DATA/band1.rad" \
        "$DATA/band2.rad" -o textured.img
    # Curve 1 reflects 0.8 where curve 0 reflects 0.1-0.4: the mapped ground (about a
    # quarter of the square) raises the mean radiance.
    run -0 compare --pixelwise textured.img plain.img
    bias="$(awk '$1 == "all" { print $5 }' <<<"$output")"
    awk -v b="$bias" 'BEGIN { exit !(b > 0.001) }' || fail "bias $bias"
}

@test "trace --bounces: 0 makes neighbours black, 3 follows paths, -1 and 65 are usage errors" {
    trace_ok $(inputs) --bounces 1 -o one.img
    # The box on the lawn needs no more than one bounce: auto (the default) picks 1.
    trace_ok $(inputs) -o auto.img
    cmp one.img auto.img
    trace_ok $(inputs) --bounces auto -o auto_again.img
    cmp one.img auto_again.img
    trace_ok $(inputs) --bounces 0 -o zero.img
    # Light reflected by the box and the lawn is gone: the mean radiance drops.
    run -0 compare --pixelwise zero.img one.img
    bias="$(awk '$1 == "all" { print $5 }' <<<"$output")"
    awk -v b="$bias" 'BEGIN { exit !(b < 0) }' || fail "bias $bias"
    # Paths three hits deep replace the one-bounce closure of the neighbours (an open
    # sky): a different image, the same on every run and thread count.
    trace_ok $(inputs) --bounces 3 -o three.img
    trace_ok $(inputs) --bounces 3 --threads 1 -o three_again.img
    cmp three.img three_again.img
    ! cmp -s three.img one.img || fail "--bounces 3 rendered the --bounces 1 image"
    trace_bad 2 "--bounces: expected auto or 0 to 64, found '65'" $(inputs) --bounces 65 -o out.img
    trace_bad 2 "--bounces: expected auto or 0 to 64, found '-1'" $(inputs) --bounces -1 -o out.img
    trace_bad 2 "--bounces: expected auto or 0 to 64, found 'deep'" $(inputs) --bounces deep -o out.img
}

@test "trace -v says how many bounces it followed and what the estimate gives" {
    run -0 --separate-stderr trace -v $(inputs) -o auto.img
    [[ "$stderr" == *"bounces 1 (auto): by estimate, paths of more facet reflections carry "* ]] ||
        fail "stderr: $stderr"
    run -0 --separate-stderr trace -v $(inputs) --bounces 3 -o three.img
    [[ "$stderr" == *"bounces 3: by estimate"*"--bounces auto keeps it under 0.1 % with 1)"* ]] ||
        fail "stderr: $stderr"
}

# --- trace --shadow-history: the sun/shadow history therm reads --------------------------

SHADOW="$SIGCHAIN_SOURCE_DIR/tests/data/shadow"

# box_on_plane.mat of the therm tests beside the .ems it names (white1996/fall_grass.ems):
# --shadow-history reads the .mat's curves as trace does.
therm_materials() {
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/therm/box_on_plane.mat" "$SEED/fall_grass.ems" .
}

@test "trace --shadow-history writes a valid .shd, the same with 1 and 2 threads, and therm reads it" {
    therm_materials
    trace_ok --shadow-history --points-per-facet 4 --threads 1 "$SEED/hawkeye.snd" "$GDB" \
        box_on_plane.mat -o one.shd
    trace_ok --shadow-history --points-per-facet 4 --threads 2 "$SEED/hawkeye.snd" "$GDB" \
        box_on_plane.mat -o two.shd
    cmp one.shd two.shd
    run -0 sigchain-check one.shd
    assert_output "one.shd: ok: 6 facets, 97 steps of 0.25 h ending at 38 h"
    # The box's top sees the whole sky; at the scene time (14:00 local) it is sunlit,
    # at midnight (24 h) not.
    grep -q '^FACET 2-1-1 1 4$' one.shd
    grep -q '^38 1 1 1 1 1 1 1 1$' <(sed -n '/^FACET 2-1-1/,/^FACET/p' one.shd)
    grep -q '^24 0 1 0 1 0 1 0 1$' <(sed -n '/^FACET 2-1-1/,/^FACET/p' one.shd)
    run -0 --separate-stderr therm one.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat \
        "$GDB" "$SEED/hawkeye.snd" -o box.tmp
    assert_equal "$stderr" ''
    run -0 sigchain-check box.tmp
    assert_output --partial "box.tmp: ok: 6 facets"
    assert_no_temp_files .
}

@test "trace --shadow-history keys an .odb's facets as therm does (object.instance/FACE)" {
    therm_materials
    trace_ok --shadow-history --history-hours 24 --history-step-minutes 60 --sky-rays 64 \
        "$SEED/hawkeye.snd" "$SEED/neighbourhood.odb" box_on_plane.mat -o odb.shd
    run -0 sigchain-check odb.shd
    assert_output "odb.shd: ok: 18 facets, 25 steps of 1 h ending at 38 h"
    grep -q '^FACET 1.3/2-1-5 ' odb.shd
    run -0 --separate-stderr therm odb.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat \
        "$SEED/neighbourhood.odb" "$SEED/hawkeye.snd" -o odb.tmp
    run -0 sigchain-check odb.tmp
    assert_output --partial "odb.tmp: ok: 18 facets"
}

@test "trace --shadow-history: bad usage exits 2, a missing input 1, and nothing is written" {
    therm_materials
    local args=("$SEED/hawkeye.snd" "$GDB" box_on_plane.mat)
    trace_bad 2 "--history-step-minutes: 7 min does not divide" --shadow-history \
        --history-step-minutes 7 "${args[@]}" -o out.shd
    trace_bad 2 "--history-hours: 0: must be a number > 0" --shadow-history --history-hours 0 \
        "${args[@]}" -o out.shd
    trace_bad 2 "--shadow-history: expected SND SCENE MAT" --shadow-history \
        "$SEED/hawkeye.snd" "$GDB" -o out.shd
    trace_bad 2 "no output: give -o" --shadow-history "${args[@]}"
    trace_bad 2 "--points-per-facet: 0: must be an integer from 1 to 1000000" --shadow-history --points-per-facet 0 \
        "${args[@]}" -o out.shd
    trace_bad 2 "--truth does not apply to --shadow-history" --shadow-history --truth t.img \
        "${args[@]}" -o out.shd
    trace_bad 2 "--points-per-facet needs --shadow-history" --points-per-facet 4 $(inputs) \
        -o out.shd
    trace_bad 1 "no_such.gdb: cannot open" --shadow-history "$SEED/hawkeye.snd" no_such.gdb \
        box_on_plane.mat -o out.shd
    trace_bad 1 "no_such_dir/out.shd: cannot create" --shadow-history "${args[@]}" \
        -o no_such_dir/out.shd
}

@test "trace --help documents --shadow-history" {
    run -0 trace --help
    assert_output --partial "or: trace --shadow-history [OPTIONS] SND SCENE MAT -o FILE.shd"
    assert_output --partial "--points-per-facet N"
}

@test "trace warns that emission is left out of a thermal band without --tmp, not with it" {
    run -0 --separate-stderr trace "$DATA/box.adv" "$SHADOW/lwir.snd" "$GDB" "$DATA/box.mat" \
        "$SHADOW/lwir.rad" -o lwir.img
    assert_output ''
    [[ "$stderr" == "trace: warning: the spectral grid reaches 10 um but no facet temperatures (--tmp) were given: facet emission is left out" ]] ||
        fail "stderr: $stderr"
    trace_ok "$DATA/box.adv" "$SHADOW/lwir.snd" "$GDB" "$DATA/box.mat" "$SHADOW/lwir.rad" \
        --tmp "$DATA/box.tmp" -o lwir.img
    # Visible bands: no warning (trace_ok wants an empty stderr).
    trace_ok $(inputs) -o visible.img
}

@test "trace --shadow-history: a glass box lets the sun through attenuated; --progress draws a bar" {
    # transmissive.mat makes the box a 5 cm slab of glass.ext (t = 0.999 at normal
    # incidence): lawn points behind it stay sunlit, with a transmittance below 1 (two
    # walls, slanted: 0.99 to 1); every other value is 1 or the sunlit 0/1.
    run -0 --separate-stderr trace --shadow-history --progress --points-per-facet 16 \
        "$DATA/box.snd" "$GDB" "$DATA/transmissive.mat" -o glass.shd
    assert_output ''
    [[ "$stderr" == *"shadow history ["*"100%"* ]] || fail "no progress bar: $stderr"
    run -0 sigchain-check glass.shd
    run -0 awk '/^FACET 1-1-1 /{f=1; next} /^FACET/{f=0} f { for (i = 3; i <= NF; i += 2)
            if ($i < 1) { n++; if ($(i-1) != 1 || $i < 0.99) bad++ } }
        END { print n + 0, bad + 0 }' glass.shd
    [[ "$output" =~ ^([0-9]+)\ 0$ ]] && [ "${BASH_REMATCH[1]}" -gt 0 ] || fail "attenuated, bad: $output"
}

@test "trace --shadow-history --allow-degenerate reports a degenerate facet but keeps it for therm" {
    therm_materials
    local deg="$DATA/degenerate.gdb"
    run -1 --separate-stderr trace --shadow-history "$SEED/hawkeye.snd" "$deg" box_on_plane.mat \
        -o out.shd
    [[ "$stderr" == "trace: $deg:37: "*"(2-1-1)"* ]] || fail "stderr: $stderr"
    [ ! -e out.shd ]
    run -0 --separate-stderr trace --shadow-history --allow-degenerate "$SEED/hawkeye.snd" "$deg" \
        box_on_plane.mat -o deg.shd
    [[ "$stderr" == "trace: warning: $deg:37: "*"(2-1-1): "*"(kept)" ]] ||
        fail "stderr: $stderr"
    grep -q '^FACET 2-1-1 ' deg.shd
    run -0 --separate-stderr therm deg.shd "$SEED/weather_30_Sep_95.wth" box_on_plane.mat "$deg" \
        "$SEED/hawkeye.snd" -o deg.tmp
    run -0 sigchain-check deg.tmp
    assert_output --partial "deg.tmp: ok: 6 facets"
}

# coupled BAND: $DATA/BAND.rad as block version 1.2 with COUPLING terms (S 0.2, t_d_down
# 0.15, t_d_up 0.1 at its five view angles), written to BAND.rad here.
coupled() {
    sed 's/^SIGCHAIN_RAD 1$/SIGCHAIN_RAD 1.2/' "$DATA/$1.rad" > "$1.rad"
    {
        echo COUPLING
        echo SPHERICAL_ALBEDO 0.2 0.2 0.2
        echo DIFFUSE_DOWN 0.15 0.15 0.15
        for v in -90 -45 0 45 90; do echo "DIFFUSE_UP $v 0.1 0.1 0.1"; done
    } >> "$1.rad"
    sigchain-check -q "$1.rad"
}

coupled_inputs() {
    echo "$DATA/box.adv" "$DATA/box.snd" "$GDB" "$DATA/box.mat" band1.rad band2.rad
}

@test "trace couples the scene with the atmosphere when the .rad has COUPLING terms" {
    coupled band1
    coupled band2
    trace_ok $(inputs) -o black.img
    trace_ok $(coupled_inputs) -o coupled.img
    trace_ok --no-adjacency $(coupled_inputs) -o off.img
    # Coupling brightens every pixel; --no-adjacency gives back the black-ground cube.
    ! cmp -s black.img coupled.img
    cmp black.img off.img
    # The same cube with 1 and 2 threads.
    trace_ok --threads 1 $(coupled_inputs) -o one.img
    trace_ok --threads 2 $(coupled_inputs) -o two.img
    cmp one.img two.img
    cmp one.img coupled.img
}

@test "trace --adjacency-radius changes the environment; -v says when the coupling is skipped" {
    coupled band1
    coupled band2
    trace_ok $(coupled_inputs) -o wide.img
    trace_ok --adjacency-radius 1 $(coupled_inputs) -o narrow.img
    ! cmp -s wide.img narrow.img
    run -0 --separate-stderr trace -v $(inputs) -o out.img
    [[ "$stderr" == *"not modelled: adjacency and ground-sky coupling (no COUPLING terms in the .rad)"* ]] ||
        fail "$stderr"
    run -0 --separate-stderr trace -v --no-adjacency $(coupled_inputs) -o out.img
    [[ "$stderr" == *"not modelled: adjacency and ground-sky coupling (--no-adjacency)"* ]] ||
        fail "$stderr"
    run -0 --separate-stderr trace -v $(coupled_inputs) -o out.img
    [[ "$stderr" != *"adjacency"* ]] || fail "$stderr"
}

@test "trace: bad --adjacency-radius values and misplaced adjacency options are usage errors" {
    trace_bad 2 "--adjacency-radius: 0: must be a number > 0" \
        --adjacency-radius 0 $(inputs) -o out.img
    trace_bad 2 "--adjacency-radius: -5: must be a number > 0" \
        --adjacency-radius=-5 $(inputs) -o out.img
    trace_bad 2 "--adjacency-radius does not apply with --no-adjacency" \
        --no-adjacency --adjacency-radius 10 $(inputs) -o out.img
    trace_bad 2 "--no-adjacency does not apply to --shadow-history" \
        --shadow-history --no-adjacency "$SEED/hawkeye.snd" "$GDB" "$DATA/box.mat" -o out.shd
}

# GeoTIFF cubes through GDAL (cube(5)); gdalinfo is from gdal-bin (scripts/install-deps).
@test "--co reaches a GeoTIFF cube; every cube records version and command" {
    mkdir sub
    trace_ok $(inputs) --co COMPRESS=DEFLATE --threads 1 -o sub/c.tif
    run -0 gdalinfo sub/c.tif
    assert_output --partial "COMPRESSION=DEFLATE"
    assert_output --partial "wavelength=0.5"
    assert_output --partial "wavelength_units=Micrometers"
    refute_output --partial "ColorInterp=Alpha"
    assert_output --regexp "SIGCHAIN_VERSION=[0-9]+\.[0-9]+\.[0-9]+"
    assert_output --partial "SIGCHAIN_COMMAND=trace box.adv box.snd box_on_plane.gdb box.mat band1.rad band2.rad --co COMPRESS=DEFLATE -o c.tif"
    trace_ok $(inputs) -o e.img
    run grep -A1 '^description' e.hdr
    assert_output --regexp $'description = \\{\nsigchain [0-9.]+: trace box.adv .* -o e.img\\}'
    run -2 --separate-stderr trace $(inputs) --co COMPRESS=DEFLATE -o e2.img
    [[ "$stderr" == *"--co applies to GeoTIFF (.tif) outputs only"* ]] || fail "stderr: $stderr"
    [ ! -e e2.img ]
}

@test "trace warns when .tmp keys match no facet or facets have no temperature; --strict fails" {
    # box.tmp with facet 2-1-5 renamed to a key of no facet of box_on_plane.gdb.
    sed 's/^2-1-5 .*/9-9-9   298/' "$DATA/box.tmp" > odd.tmp
    run -0 --separate-stderr trace $(inputs) --tmp odd.tmp -o odd.img
    assert_equal "$stderr" "trace: warning: odd.tmp: 5 of 6 facet key(s) match a facet of the scene, 1 match none (the first: 9-9-9); 1 of 6 facet(s) have no temperature (0 take the .gdb TEMPERATURE, 1 emit nothing)"
    trace_bad 1 "odd.tmp:10: 5 of 6 facet key(s) match" $(inputs) --tmp odd.tmp --strict -o out.img
    [[ "$stderr" == *"(--strict)" ]] || fail "stderr: $stderr"
    # A .tmp that names every facet, and only those, passes --strict silently.
    trace_ok $(inputs) --tmp "$DATA/box.tmp" --strict -o all.img
    # Keys that match no facet at all: the error names the first, at its line.
    printf '# sigchain-tmp 1\n7-7-7 300\n' > none.tmp
    trace_bad 1 "none.tmp:2: 0 of 1 facet key(s) match" $(inputs) --tmp none.tmp --strict -o out.img
    trace_bad 2 "--strict" --shadow-history --strict "$DATA/box.snd" "$GDB" "$DATA/box.mat" -o out.shd
}

@test "trace: a black cube (a visibility of 0.01 km) is said even with -q" {
    # hawkeye's deck with VIS (CARD 2, columns 31-40) 0.01 km: no light gets through.
    awk 'NR == 2 { $0 = substr($0, 1, 30) "     0.010" substr($0, 41) } { print }' \
        "$GOLDEN/control7/hawkeye.cdk" > fog.cdk
    local small="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance/small.snd"
    run -0 build_radiance -q --streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 \
        --sky-subsamples 1 fog.cdk "$small" -o 'fog-%d.rad'
    run -0 --separate-stderr trace -q --samples-per-pixel 1 "$DATA/box.adv" "$small" "$GDB" \
        "$DATA/box.mat" fog-1.rad fog-2.rad -o fog.img
    [[ "$stderr" == "trace: warning: fog.img: the image is black: its largest radiance is "*" W cm-2 sr-1 um-1, nothing a sensor records"* ]] ||
        fail "stderr: $stderr"
    [ -e fog.img ]  # written all the same: it is what the inputs give
    # A clear day says nothing under -q.
    run -0 --separate-stderr trace -q --samples-per-pixel 1 $(inputs "$GDB") -o clear.img
    assert_equal "$stderr" ''
}

@test "trace --radiance-units W/m2/sr/um: the cube and the truth's radiance layers x 1e4; the same counts" {
    trace_ok $(inputs) --truth t.img -o cube.img
    mkdir si
    trace_ok $(inputs) --radiance-units W/m2/sr/um --truth si/t.img -o si/cube.img
    run -0 grep -x 'data units = W m-2 sr-1 um-1' si/cube.hdr
    run -0 grep -x 'data units = W cm-2 sr-1 um-1' cube.hdr
    # ratio FILE1 FILE2 BAND: the largest |FILE2 / FILE1 / 1e4 - 1| over the band's
    # pixels; within 1e-6: a float32 product (6e-8) printed by XYZ to 7 digits.
    ratio() {
        paste <(gdal_translate -q -of XYZ -b "$3" "$1" /vsistdout/) \
            <(gdal_translate -q -of XYZ -b "$3" "$2" /vsistdout/) |
            awk '$3 != 0 { d = $6 / $3 / 1e4 - 1; if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }'
    }
    local r
    r=$(ratio cube.img si/cube.img 1)
    awk -v r="$r" 'BEGIN { exit !(r < 1e-6) }' || fail "band 1: $r"
    # Truth layers: upwelled_band1 (radiance) scaled, reflectance_band1 not.
    local names up refl
    names=$(gdalinfo t.img | sed -n 's/^  Description = //p')
    up=$(echo "$names" | grep -nx 'upwelled_band1' | cut -d: -f1)
    refl=$(echo "$names" | grep -nx 'reflectance_band1' | cut -d: -f1)
    r=$(ratio t.img si/t.img "$up")
    awk -v r="$r" 'BEGIN { exit !(r < 1e-6) }' || fail "upwelled_band1: $r"
    run -0 cmp <(gdal_translate -q -of XYZ -b "$refl" t.img /vsistdout/) \
        <(gdal_translate -q -of XYZ -b "$refl" si/t.img /vsistdout/)
    # sensorize reads the unit: the .sen's gain is per W cm-2 sr-1 um-1 either way.
    printf '3\n100000\n0\n1\n1\n1\n' > b.sen
    run -0 sensorize -q --bits 16 cube.img b.sen b.sen -o c.tif
    run -0 sensorize -q --bits 16 si/cube.img b.sen b.sen -o si/c.tif
    run -0 compare --pixelwise --fail-max 1 c.tif si/c.tif
    run -2 --separate-stderr trace $(inputs) --radiance-units W/sr -o x.img
    [[ "$stderr" == *"--radiance-units W/sr: expected W/cm2/sr/um or W/m2/sr/um"* ]]
}

@test "trace: a mirror box lights the lawn with the sun's image; --sun-images 0 leaves it out and -v says so" {
    # box.mat with the box (pine wood, 37) a mirror: SPECULARITY 1 and the default
    # REFLECTANCE_MODEL dirsig (a delta lobe). Its sunlit walls show the sun's image to
    # the lawn in front of them (trace(1), RADIOMETRY: the sun in a mirror).
    sed '/MATERIAL_ID = 37/,/MATERIAL_ENTRY_END/ s/^SPECULARITY = 0.0/SPECULARITY = 1.0/' \
        "$DATA/box.mat" > mirror.mat
    cp "$DATA/grass.ems" "$DATA/wood.ems" .
    run -0 --separate-stderr trace -v $(inputs "$GDB" mirror.mat) -o with.img
    [[ "$stderr" != *"sun's images"* ]] || fail "stderr: $stderr"
    run -0 --separate-stderr trace -v --sun-images 0 $(inputs "$GDB" mirror.mat) -o without.img
    [[ "$stderr" == *"trace: not modelled: the sun's images in mirror facets (they lie in more than 0 planes: --sun-images)"* ]] ||
        fail "stderr: $stderr"
    run -1 cmp -s with.img without.img
    # dirsig (DIRSIG 3) traces no image, and says why.
    run -0 --separate-stderr trace -v --sampling dirsig $(inputs "$GDB" mirror.mat) -o d.img
    [[ "$stderr" == *"not modelled: the sun's images in mirror facets (dirsig: DIRSIG 3's sun enters every specular part)"* ]] ||
        fail "stderr: $stderr"
    # The option belongs to the render, not to the shadow history.
    run -2 --separate-stderr trace --shadow-history --sun-images 4 "$DATA/box.snd" "$GDB" \
        mirror.mat -o out.shd
    [[ "$stderr" == *"--sun-images does not apply to --shadow-history"* ]] || fail "stderr: $stderr"
    assert_no_temp_files .
}
