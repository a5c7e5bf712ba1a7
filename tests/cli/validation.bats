#!/usr/bin/env bats
# Tests: data/scenes/pennsylvania/Makefile and scripts/validation (make validate; the
# Marburg and Olinda no-fit scenes' own checks are tests/cli/marburg.bats and
# tests/cli/olinda_nofit.bats)
# Also requires: landsat_sensor, landsat_scene, control7, build_radiance,
# find_min_max_view_angle, trace, sensorize, olinda_scene, hawkeye_scene, soho_scene,
# gdalwarp, gdallocationinfo, gnuplot
# The date-transfer validation on real Landsat-7 images runs from a clean copy and
# writes its tables, evidence and pictures; docs/validation.md, the README's results
# blocks and the scene READMEs' generated blocks are written from them (a few minutes
# on 2 cores).

load test_helper

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    for t in landsat_sensor landsat_scene olinda_scene hawkeye_scene soho_scene; do
        [ -x "$SIGCHAIN_BIN/$t" ] || skip "$t not built in $SIGCHAIN_BIN"
    done
    command -v gnuplot > /dev/null || skip "no gnuplot"
}

@test "validation: make validate writes docs/validation.md and the README blocks from one run" {
    # A copy of what the run reads (the test writes nothing into the source tree).
    mkdir -p repo/data/scenes repo/docs
    cp -r "$SIGCHAIN_SOURCE_DIR/scripts" "$SIGCHAIN_SOURCE_DIR/pipelines" repo/
    cp -r "$SIGCHAIN_SOURCE_DIR/data/spectra" repo/data/
    for s in pennsylvania marburg olinda hawkeye soho; do
        cp -r "$SIGCHAIN_SOURCE_DIR/data/scenes/$s" repo/data/scenes/
    done
    rm -rf repo/data/scenes/*/out
    cp "$SIGCHAIN_SOURCE_DIR/README.md" repo/README.md
    # The READMEs with generated blocks, as committed (the source tree's).
    readmes="README.md data/scenes/olinda/README.md data/scenes/marburg/README.md
        data/scenes/hawkeye/README.md data/scenes/soho/README.md"
    for f in $readmes; do
        mkdir -p "committed/$(dirname "$f")"
        cp "repo/$f" "committed/$f"
    done
    run -0 env JOBS=2 repo/scripts/validation "$SIGCHAIN_BIN/.." repo/docs/validation.md
    v=repo/data/scenes/pennsylvania/out/validation.txt
    # Every render, scope and band is there (points under a mask of the scored date are
    # left out: November -> July keeps those clear of July's clouds).
    for r in july/self july/to-november july/spectra-july july/spectra-november \
             november/self november/to-july november/spectra-july november/spectra-november; do
        for b in 1 2 3 4 5 6; do
            run -0 grep -c "^$r points $b [0-9]" "$v"
            run -0 grep -c "^$r image $b " "$v"
            run -0 grep -c "^$r class:forest $b " "$v"
        done
    done
    # Every ROC a number in [-1, 1], every RMS finite and non-negative.
    run -0 awk '!/^#/ && !($5 >= -1 && $5 <= 1 && $6 >= 0 && $6 < 1000) { print; bad = 1 }
        END { exit bad }' "$v"
    # The self-fits reproduce what they were fitted to: held-out ROC above 0.6 in every
    # band (measured 0.70-0.92; a broken fit, geometry or calibration gives < 0.3).
    run -0 awk '($1 == "july/self" || $1 == "november/self") && $2 == "points" && $5 < 0.6 {
        print; bad = 1 } END { exit bad }' "$v"
    # The November relief within the forest, from the DEM and the sun alone: ROC above
    # 0.75 in bands 4 and 5 (measured 0.85 and 0.87; the camera turned the wrong way by
    # the grid convergence gave 0.70 and 0.78, a one-pixel shift 0.84-0.86 in band 5).
    run -0 awk '$1 == "july/to-november" && $2 == "class:forest" && ($3 == 4 || $3 == 5) &&
        $5 < 0.75 { print; bad = 1 } END { exit bad }' "$v"
    # The thermal band: its table and brightness temperatures, from the DEM, the shadow
    # history and therm. Within the forest the relief orders the temperatures: ROC above
    # 0.7 (measured 0.84; with the facets at one temperature it would be near 0).
    t=repo/data/scenes/pennsylvania/out/thermal
    run -0 awk '$1 == "class:forest" && $4 > 0.7 { ok = 1 } END { exit !ok }' "$t/score.txt"
    run -0 awk '!/^#/ && $4 > 250 && $4 < 320 && $5 > 250 && $5 < 320 { n++ } END { exit !(n == 4) }' \
        "$t/brightness.txt"
    # The document and the README block come from that table.
    run -0 grep -c "^| \*\*July → November (transfer)\*\* |" repo/docs/validation.md
    run -0 grep -c "^| \*\*ETM+ 2001 → OLI 2013 (transfer)\*\* | 0[.][0-9]" repo/docs/validation.md
    run -0 grep -c "^| ocean (DEM mask) | [0-9]" repo/docs/validation.md
    run -0 grep -F "$(awk '$1 == "july/to-november" && $2 == "points" && $3 == 4 { printf "%.3f", $5 }' "$v")" \
        repo/README.md
    # The Olinda self-fit's table, from its compare report.
    roc=$(awk '/^band 1:/ { b = 1 } /^ROC / && b == 1 { printf "%.3f", $2; exit }' \
        repo/data/scenes/olinda/out/olinda.report)
    run -0 grep -c "^| 1 blue | $roc | " repo/README.md
    # The scene READMEs' blocks, from the same run: every block is filled.
    run -0 grep -c "^| 2 vegetation | [0-9.]*% | [0-9.]*% |$" repo/data/scenes/olinda/README.md
    run -0 grep -c "^| 3 red | 0[.][0-9]* | 0[.][0-9]* | " repo/data/scenes/olinda/README.md
    run -0 grep -c "^| ETM+ 2001-07-30 | 53.878 / 144.058 | " repo/data/scenes/marburg/README.md
    run -0 grep -c "^Totals for seed 4: [0-9]* structures" repo/data/scenes/hawkeye/README.md
    run -0 grep -c "^With the default seed: [0-9]* footprints" repo/data/scenes/soho/README.md
    blocks() { awk '/^<!-- [a-z-]+:begin -->$/ { name = $2; n = 0; next }
        /^<!-- [a-z-]+:end -->$/ { print name, n; name = ""; next } name != "" { n++ }' "$1"; }
    for f in $readmes; do
        run -0 awk '{ print } $2 == 0 { bad = 1 } END { exit bad || NR == 0 }' <(blocks "repo/$f")
    done
    # Only the blocks change, and the committed READMEs' figures are today's: every
    # number of their blocks within 0.01 of this run's (ROC, scales up to 1; a last-digit
    # change) or 0.3 (DN, percentages, scales, degrees), every whole number (counts,
    # band numbers) equal, so that a change that moves a result fails here until `make
    # validate` is run and its READMEs committed.
    outside() { awk '/^<!-- [a-z-]+:begin -->$/ { s = 1 } !s { print }
        /^<!-- [a-z-]+:end -->$/ { s = 0 }' "$1"; }
    numbers() { awk '/^<!-- [a-z-]+:begin -->$/ { s = 1; next } /^<!-- [a-z-]+:end -->$/ { s = 0 }
        s' "$1" | grep -oE -- '-?[0-9]+([.][0-9]+)?'; }
    for f in $readmes; do
        run -0 diff <(outside "committed/$f") <(outside "repo/$f")
        [ "$(numbers "committed/$f" | wc -l)" -eq "$(numbers "repo/$f" | wc -l)" ]
        run -0 awk -v f="$f" '{ d = $1 - $2; if (d < 0) d = -d
            tol = ($1 !~ /[.]/ || $2 !~ /[.]/) ? 0 : ($1 >= -1 && $1 <= 1) ? 0.01 : 0.3
            if (d > tol) { print f ": figure " $1 ", today " $2; bad = 1 } } END { exit bad }' \
            <(paste <(numbers "committed/$f") <(numbers "repo/$f"))
    done
    for p in side_by_side false_colour difference_b4 scatter_b4; do
        [ -s "repo/docs/images/validation/pennsylvania_july_to-november_$p.png" ]
    done
    # A rerun changes nothing (renders and tables are deterministic): the transfer's
    # render again, byte for byte, and the document from it.
    cp repo/data/scenes/pennsylvania/out/july/to-november/counts.tif first.tif
    cp repo/docs/validation.md first.md
    rm -rf repo/data/scenes/pennsylvania/out/july/to-november
    run -0 env JOBS=2 repo/scripts/validation "$SIGCHAIN_BIN/.." repo/docs/validation.md
    run -0 cmp first.tif repo/data/scenes/pennsylvania/out/july/to-november/counts.tif
    run -0 cmp first.md repo/docs/validation.md
}
