#!/usr/bin/env bats
# Tests: scripts/chart-plot and scripts/chart-summary (the chart of make chart and the page
# that reads it, from its data)
# Also requires: gnuplot, docs/chart/data.tsv and refs.tsv (the committed run)
#
# The committed chart's data are drawn again: every point's label finds a place that
# overlaps no other label, no point and not the key (chart-plot names a label it
# cannot place on stderr), and the picture has one 700 x 520 panel per scene.
bats_require_minimum_version 1.5.0
load test_helper

@test "chart-plot: the committed run's chart, every label placed" {
    command -v gnuplot > /dev/null || skip "gnuplot is not installed"
    cp "$SIGCHAIN_SOURCE_DIR/docs/chart/data.tsv" "$SIGCHAIN_SOURCE_DIR/docs/chart/refs.tsv" .
    run -0 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-plot" .
    assert_equal "$stderr" ''
    # PNG width and height (IHDR, big-endian, bytes 17-24): two scenes side by side.
    [ "$(od -An -tu1 -j16 -N8 chart.png | awk '{ print $3 * 256 + $4, $7 * 256 + $8 }')" = "1400 520" ]
    # One label per point, or per group of points of one label whose markers overlap:
    # every label text of a scene's points is set in that scene's panel (the panels in
    # refs.tsv's order, each opened by "unset label"), and no more labels than points.
    # (How many groups there are depends on where the points fall: not a fixed count.)
    CHART_PLOT_DEBUG=plot.gp run -0 "$SIGCHAIN_SOURCE_DIR/scripts/chart-plot" .
    run -0 awk -F '\t' '
        FILENAME ~ /\.tsv$/ && FNR == 1 { next }
        FILENAME ~ /refs\.tsv$/ { order[++ns] = $1; next }
        FILENAME ~ /data\.tsv$/ { lab = $3; if ($10 != "-") { lab = $10; sub(/.*,/, "T=", lab) }
                                  want[$1 SUBSEP lab] = 1; points++; next }
        /^unset label/ { panel++; next }
        /^set label/ { match($0, /"[^"]*"/); labels++
                       got[order[panel] SUBSEP substr($0, RSTART + 1, RLENGTH - 2)] = 1 }
        END { for (k in want) if (!(k in got)) { split(k, a, SUBSEP); print "no label " a[2] " in " a[1]; bad = 1 }
              n = 0; for (k in want) n++
              print labels " labels for " points " points, " n " texts"
              exit bad || labels > points || labels < n }' refs.tsv data.tsv plot.gp
}

@test "chart-plot: a missing data file exits 1 naming it" {
    run -1 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-plot" .
    assert_equal "$stderr" "chart-plot: ./data.tsv: cannot read it"
}

# scripts/chart-summary writes the page that reads the run from its files alone: the
# committed page is what the committed run's files give now (no figure typed by hand),
# and each quoted figure is one of data.tsv's.
@test "chart-summary: docs/chart/README.md is what the committed run gives, byte for byte" {
    cp "$SIGCHAIN_SOURCE_DIR"/docs/chart/{data.tsv,refs.tsv,where.md,bands_cost.tsv} .
    run -0 "$SIGCHAIN_SOURCE_DIR/scripts/chart-summary" .
    run -0 cmp README.md "$SIGCHAIN_SOURCE_DIR/docs/chart/README.md"
    # The 64-spp row of soho's montecarlo-b3 is data.tsv's, rounded as printed.
    row=$(awk -F '\t' '$1 == "soho" && $2 == "montecarlo-b3" && $3 == 64 {
              printf "| soho | montecarlo-b3 | %.1f | %.3g | %.2f | %.3f |", $9, $5, $7, $8 }' data.tsv)
    run -0 grep -cF -- "$row" README.md
}

@test "chart-summary: a changed run changes the page; a missing file exits 1 naming it" {
    cp "$SIGCHAIN_SOURCE_DIR"/docs/chart/{data.tsv,refs.tsv,where.md} .
    awk -F '\t' 'BEGIN { OFS = "\t" } $1 == "soho" && $2 == "golfball" && $3 == 64 { $5 = 99.5 } { print }' \
        data.tsv > d && mv d data.tsv
    run -0 "$SIGCHAIN_SOURCE_DIR/scripts/chart-summary" .
    # The row's CPU seconds and montecarlo's RMS are the run's, as data.tsv holds them.
    cpu=$(awk -F '\t' '$1 == "soho" && $2 == "golfball" && $3 == 64 { printf "%.1f", $9 }' data.tsv)
    mc=$(awk -F '\t' '$1 == "soho" && $2 == "montecarlo" && $3 == 64 { printf "%.3g", $5 }' data.tsv)
    run -0 grep -cF "| soho | golfball | $cpu | 99.5 |" README.md
    run -0 grep -cF "golfball 99.5 RMS against montecarlo's $mc" README.md
    rm refs.tsv
    run -1 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-summary" .
    [[ "$stderr" == "chart-summary: ./refs.tsv: cannot read it"* ]]
}

# The bands axis: bench/bands_cost.sh's medians (bands_cost.tsv) drawn by chart-bands and
# tabulated by chart-summary with each stage's seconds per band (a least-squares slope).
@test "chart-bands, chart-summary: the bands axis from bands_cost.tsv" {
    command -v gnuplot > /dev/null || skip "gnuplot is not installed"
    cp "$SIGCHAIN_SOURCE_DIR"/docs/chart/{data.tsv,refs.tsv,where.md} .
    cat > bands_cost.tsv <<'TSV'
bands control7_s build_radiance_s build_radiance_per_band_s trace_s trace_setup_s trace_rad_tables_s trace_render_s sensorize_s
3 0.02 0.30 0.45 1.03 0.70 0.01 0.10 0.30
30 0.02 3.00 4.50 1.30 0.80 0.10 0.20 0.33
100 0.02 10.00 - 2.00 1.10 0.33 0.40 0.40
TSV
    run -0 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-bands" .
    [ "$(od -An -tu1 -j16 -N8 bands.png | awk '{ print $3 * 256 + $4, $7 * 256 + $8 }')" = "640 420" ]
    run -0 "$SIGCHAIN_SOURCE_DIR/scripts/chart-summary" .
    run -0 grep -cF "| build_radiance, one run | 0.30 | 3.00 | 10.00 | 0.1000 |" README.md
    run -0 grep -cF "| build_radiance, one run per band | 0.45 | 4.50 | - | 0.1500 |" README.md
    run -0 grep -cF "| trace: the .rad tables | 0.01 | 0.10 | 0.33 | 0.0033 |" README.md
    rm bands_cost.tsv
    run -1 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-bands" .
    assert_equal "$stderr" "chart-bands: ./bands_cost.tsv: cannot read it"
}
