#!/usr/bin/env bash
# What trace --sky-lookup table:N buys and costs, side by side in one run.
#   bench/sky_lookup.sh BUILD [N...]        (default N: 32 64 128)
# Environment: ROUNDS [7] rounds, SIZE [128] pixels on the image's longer side, SCENES
# ["training hawkeye"] (hawkeye: its oblique camera), TRACE_FLAGS ["--sampling
# golfball"] options for every render (e.g. "--sampling montecarlo").
#
# For each scene of data/scenes, its trace inputs made by the scene's own rules (into a
# temporary folder: the source tree is not written), the camera cut or grown to SIZE
# pixels on its longer side (the same field of view), rendered by trace on one thread
# (--threads 1: CPU seconds vary least) with --sky-lookup exact and with table:N for
# each N, in an order that turns round every round (exact first, then last), so that
# the machine's load falls on all of them alike. Printed per scene and lookup, medians
# over the rounds: the process's CPU seconds (user + system; set-up included) and the
# render's seconds (trace -v), the ratios exact / table of each (of two renders of one
# round; above 1: the table is faster; the CPU ratio's range over the rounds beside it),
# and the accuracy cost: the relative RMS difference of the cube from the exact cube,
# sqrt(sum d^2 / sum L^2) over every pixel and spectral sample, and the largest
# |d| / L among pixels with L above a tenth of the mean. For scale, the sampling
# noise of the same render: the relative RMS difference between the exact cube and one
# rendered with another --seed, over sqrt(2) (two independent draws), at the camera's
# own samples per pixel.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 BUILD [N...]" >&2; exit 2; }
BIN=$(cd "$1/bin" && pwd)
shift
SIDES=("${@:-32 64 128}")
read -r -a SIDES <<< "${SIDES[*]}"
ROUNDS=${ROUNDS:-7} SIZE=${SIZE:-128} TRACE_FLAGS=${TRACE_FLAGS---sampling golfball} SCENES=${SCENES:-training hawkeye}
SRC=$(cd "$(dirname "$0")/.." && pwd)
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT

cat > "$W/vars.mk" << 'EOF'
bench-vars:
	@echo 'adv=$(ADV); inputs="$(TRACE_INPUTS)"; tmp="$(TRACE_TMP)"'
EOF

# resize ADV OUT: the camera with its longer side SIZE pixels, the pitch scaled to keep
# the field of view (the 5th value line holds rows and columns).
resize() {
    awk -v size="$SIZE" '
        !/^[ \t]*(#|$)/ && !/=/ { if (++k == 5) { r = $1; c = $2; m = (r > c ? r : c)
            f = m / size; print int(r / f + 0.5), int(c / f + 0.5); next } }
        /^[ \t]*pixel_pitch_um[ \t]*=/ { split($0, a, "="); print "pixel_pitch_um = " a[2] * f; next }
        { print }' "$1" > "$2"
}

# median: the median of the numbers on stdin.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

# timed FILE CMD...: runs CMD (trace -v), writes "CPU RENDER" to FILE: the process's
# user + system seconds and the render's seconds (-v's "render S s").
timed() {
    local f=$1
    shift
    /usr/bin/time -f '%U %S' -o "$f.t" "$@" > /dev/null 2> "$f.v" ||
        { cat "$f.v" >&2; exit 1; }
    echo "$(awk '{ print $1 + $2 }' "$f.t") $(sed -n 's/.*; render \([0-9.]*\) s$/\1/p' "$f.v")" > "$f"
}

# difference A B: "relative-RMS largest-relative" of cube A against cube B (float32).
difference() {
    paste <(od -An -v -tf4 -w4 "$1") <(od -An -v -tf4 -w4 "$2") | awk '
        { a[NR] = $1; b[NR] = $2; d = $1 - $2; sd += d * d; sb += $2 * $2; mean += $2 }
        END { mean /= NR; for (i = 1; i <= NR; i++) if (b[i] > 0.1 * mean) {
                  r = (a[i] - b[i]) / b[i]; if (r < 0) r = -r; if (r > worst) worst = r }
              printf "%.3g %.3g\n", sqrt(sd / sb), worst }'
}

bench_scene() {
    local name=$1 dir=$SRC/data/scenes/$1 view=() out=$W/$1
    [ "$name" = hawkeye ] && view=(VIEW=oblique)
    make --no-print-directory -s -C "$dir" -f Makefile -f "$W/vars.mk" SIGCHAIN_BIN="$BIN" \
        OUT="$out" "${view[@]}" bench-vars > "$W/vars"
    local adv inputs tmp
    eval "$(cat "$W/vars")"
    # shellcheck disable=SC2086
    make --no-print-directory -s -C "$dir" SIGCHAIN_BIN="$BIN" OUT="$out" "${view[@]}" \
        $inputs $tmp > /dev/null 2>> "$W/log" || { cat "$W/log" >&2; exit 1; }
    resize "$dir/$adv" "$W/$name.adv"
    local rest=() f
    for f in $inputs; do [ "$f" = "$adv" ] || rest+=("$f"); done
    local opts=(-v --threads 1)
    read -r -a extra <<< "$TRACE_FLAGS"
    opts+=("${extra[@]}")
    [ -n "$tmp" ] && opts+=(--tmp "$tmp")
    run() { # run LOOKUP OUTPUT [OPTIONS...]
        local l=$1 o=$2
        shift 2
        (cd "$dir" && timed "$o.sec" "$BIN/trace" "${opts[@]}" "$@" --sky-lookup "$l" \
            "$W/$name.adv" "${rest[@]}" -o "$o.img")
    }
    local lookups=(exact) s r l
    for s in "${SIDES[@]}"; do lookups+=("table:$s"); done
    for ((r = 1; r <= ROUNDS; r++)); do
        local order=("${lookups[@]}")
        if ((r % 2 == 0)); then
            order=()
            for ((i = ${#lookups[@]} - 1; i >= 0; i--)); do order+=("${lookups[i]}"); done
        fi
        for l in "${order[@]}"; do
            run "$l" "$W/$name-$l"
            cat "$W/$name-$l.sec" >> "$W/$name-$l.secs"
        done
        for s in "${SIDES[@]}"; do
            paste "$W/$name-exact.sec" "$W/$name-table:$s.sec" |
                awk '{ print $1 / $3, $2 / $4 }' >> "$W/$name-table:$s.ratios"
        done
    done
    run exact "$W/$name-seed2" --seed 2
    read -r noise _ < <(difference "$W/$name-seed2.img" "$W/$name-exact.img")
    local rows cols
    read -r rows cols < <(awk '!/^[ \t]*(#|$)/ && !/=/ { if (++k == 5) { print $1, $2; exit } }' \
        "$W/$name.adv")
    echo "== $name: ${rows}x$cols pixels, $ROUNDS rounds, one thread${TRACE_FLAGS:+, $TRACE_FLAGS};" \
        "medians over the rounds"
    printf '%-10s %8s %8s %10s %12s %10s %10s %8s\n' lookup cpu_s render_s cpu_ratio \
        "(range)" render_ratio rel_rms max_rel
    col() { awk -v k="$1" '{ print $k }' "$2" | median; }
    spread() { awk -v k="$1" 'NR == 1 || $k < lo { lo = $k } NR == 1 || $k > hi { hi = $k }
        END { printf "%.2f-%.2f", lo, hi }' "$2"; }
    printf '%-10s %8s %8s %10s %12s %10s %10s %8s\n' exact "$(col 1 "$W/$name-exact.secs")" \
        "$(col 2 "$W/$name-exact.secs")" - - - 0 0
    for s in "${SIDES[@]}"; do
        l=table:$s
        read -r rms worst < <(difference "$W/$name-$l.img" "$W/$name-exact.img")
        printf '%-10s %8s %8s %10.3f %12s %10.3f %10s %8s\n' "$l" "$(col 1 "$W/$name-$l.secs")" \
            "$(col 2 "$W/$name-$l.secs")" "$(col 1 "$W/$name-$l.ratios")" \
            "$(spread 1 "$W/$name-$l.ratios")" "$(col 2 "$W/$name-$l.ratios")" "$rms" "$worst"
    done
    awk -v n="$noise" 'BEGIN { printf "sampling noise of the exact render (another --seed, / sqrt 2): rel_rms %.3g\n", n / sqrt(2) }'
}

for scene in $SCENES; do bench_scene "$scene"; done
