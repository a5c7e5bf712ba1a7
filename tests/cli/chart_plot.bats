#!/usr/bin/env bats
# Tests: scripts/chart-plot (the chart of make chart, from its data)
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
    # One label per point, or per group of points of one label whose markers overlap.
    CHART_PLOT_DEBUG=plot.gp run -0 "$SIGCHAIN_SOURCE_DIR/scripts/chart-plot" .
    [ "$(grep -c '^set label' plot.gp)" -ge 40 ]
}

@test "chart-plot: a missing data file exits 1 naming it" {
    run -1 --separate-stderr "$SIGCHAIN_SOURCE_DIR/scripts/chart-plot" .
    assert_equal "$stderr" "chart-plot: ./data.tsv: cannot read it"
}
