#!/usr/bin/env bats
# Tests: bench/scaling_doc (docs/scaling.md from bench/mpi_scaling's measurements)
# Also requires: python3, bench/scaling.md.in, docs/scaling.raw (the measurements of the
# run behind the committed page), docs/scaling.md
#
# No MPI is run: the page is written from the committed raw file, so that a figure
# typed into the page by hand, or a template edited without rewriting the page, fails
# here. The Amdahl figures are checked against an independent awk computation.
bats_require_minimum_version 1.5.0
load test_helper

DOC="$SIGCHAIN_SOURCE_DIR/bench/scaling_doc"
RAW="$SIGCHAIN_SOURCE_DIR/docs/scaling.raw"
PAGE="$SIGCHAIN_SOURCE_DIR/docs/scaling.md"
TEMPLATE="$SIGCHAIN_SOURCE_DIR/bench/scaling.md.in"

@test "scaling_doc: docs/scaling.raw gives docs/scaling.md byte for byte" {
    run -0 --separate-stderr "$DOC" "$RAW" page.md
    assert_equal "$stderr" "scaling_doc: wrote page.md"
    run -0 cmp page.md "$PAGE"
    run -1 grep -n '@@[A-Za-z_]*@@' page.md
    # The page keeps the run's printed summary: the one bench/mpi_scaling prints.
    run -0 "$DOC" --summary "$RAW"
    assert_line --index 0 --regexp '^mpi_scaling: box scene 128 x 128 pixels, '
    awk '/^```$/ { f = !f; next } f && /^(mpi_scaling:|  )/' "$PAGE" > fenced
    [ "$(cat fenced)" = "$output" ]
}

@test "scaling_doc: a doubled per-row cost changes W and S(N) as Amdahl says" {
    # The per-row cost is (one_cpu - row_cpu) / (rows - 1): doubled by moving one_cpu.
    awk -F '\t' -v OFS='\t' '
        $1 == "row_cpu" { row = $2 } $1 == "rows" { rows = $2 }
        $1 == "one_cpu" { $2 = sprintf("%.4f", row + 2 * ($2 - row)) } { print }' "$RAW" > doubled.raw
    run -0 "$DOC" doubled.raw page.md
    run -1 cmp -s page.md "$PAGE"
    # Amdahl by hand: W = image_px^2 x c / cols; serial = set-up (row_cpu - c) + launch +
    # gather + write of image_px^2 x spectral x 4 B; f = serial / (serial + W / node_cores);
    # S(N) = 1 / (f + (1 - f) / N), N the last of the template's node counts.
    read -r w s n < <(awk '
        FILENAME ~ /\.in$/ { if ($1 == "@@param") p[$2] = $4; next }
        { v[$1] = $2 }
        END {
            c = (v["one_cpu"] - v["row_cpu"]) / (v["rows"] - 1)
            w = p["image_px"] ^ 2 * c / v["cols"]
            bytes = p["image_px"] ^ 2 * p["spectral"] * 4
            serial = v["row_cpu"] - c + p["launch_s"] + bytes / (p["net_gbit"] / 8 * 1e9) \
                + bytes / (p["write_gbs"] * 1e9)
            f = serial / (serial + w / p["node_cores"])
            n = split(p["nodes"], nodes, ","); n = nodes[n]
            s = 1 / (f + (1 - f) / n)
            # The page writes W >= 1000 as a whole number, 10 <= S < 100 with one decimal.
            if (w < 1000 || s < 10 || s >= 100) exit 1
            printf "%.0f %.1f %d\n", w, s, n
        }' "$TEMPLATE" doubled.raw)
    grep -q "W = 4096^2 x [0-9.e-]* = $w CPU s" page.md || fail "no W = $w in the page"
    grep -q "^| $n *| [0-9.]* s | $s |" page.md || fail "no S($n) = $s in the page"
    # And the committed page's W is about half of it.
    old=$(sed -n 's/.*W = 4096^2 x [0-9.e-]* = \([0-9]*\) CPU s.*/\1/p' "$PAGE")
    awk -v a="$old" -v b="$w" 'BEGIN { exit !(b > 1.9 * a && b < 2.1 * a) }'
}

@test "scaling_doc: a missing or garbled raw file exits 1, naming it, and writes no page" {
    echo old > page.md
    run -1 --separate-stderr "$DOC" no_such.raw page.md
    assert_equal "$stderr" "scaling_doc: no_such.raw: cannot read: No such file or directory"
    sed 's/^np3_cpu\t.*/np3_cpu\t2.8x/' "$RAW" > bad.raw
    line=$(grep -n '^np3_cpu' bad.raw | cut -d: -f1)
    run -1 --separate-stderr "$DOC" bad.raw page.md
    assert_equal "$stderr" "scaling_doc: bad.raw:$line: np3_cpu: not a number: 2.8x"
    grep -v '^row_cpu' "$RAW" > bad.raw
    run -1 --separate-stderr "$DOC" bad.raw page.md
    assert_equal "$stderr" "scaling_doc: bad.raw: no row_cpu"
    { echo 'mpi_scaling: box scene 128 x 128 pixels'; cat "$RAW"; } > bad.raw
    run -1 --separate-stderr "$DOC" bad.raw page.md
    assert_equal "$stderr" "scaling_doc: bad.raw:1: not a bench/mpi_scaling raw file (no '# sigchain mpi_scaling raw 1' line)"
    run -1 --separate-stderr "$DOC" --summary bad.raw
    [ "$(cat page.md)" = old ]
    assert_no_temp_files .
}

@test "mpi_scaling: a usage error exits 2, a build without MPI exits 1, before any run" {
    run -2 --separate-stderr "$SIGCHAIN_SOURCE_DIR/bench/mpi_scaling" build --doc
    assert_equal "$stderr" "usage: bench/mpi_scaling [BUILD] [--doc PAGE]"
    mkdir -p nompi/bin
    run -1 --separate-stderr "$SIGCHAIN_SOURCE_DIR/bench/mpi_scaling" nompi
    assert_equal "$stderr" "mpi_scaling: nompi/bin/trace is built without MPI"
    run -2 "$DOC"
}
