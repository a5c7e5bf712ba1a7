# Tests: therm
# Also requires: sigchain-check
#
# therm on the training scene of White (1996): tests/data/white1996/box_on_plane.gdb with
# its hand-built box_on_plane.shd, the Rochester weather of White (1996)
# (weather_30_Sep_95.wth) and scene node (hawkeye.snd), and tests/data/therm/box_on_plane.mat
# (the .mat of White (1996) has grass only; the box is wood, material 37).

bats_require_minimum_version 1.5.0
load test_helper

DATA="$SIGCHAIN_SOURCE_DIR/tests/data/therm"
SHD="$SEED/box_on_plane.shd"
WTH="$SEED/weather_30_Sep_95.wth"
MAT="$DATA/box_on_plane.mat"
GDB="$SEED/box_on_plane.gdb"
SND="$SEED/hawkeye.snd"

# therm_bad PREFIX ARGS...: exit 1, nothing on stdout, stderr beginning with
# "therm: PREFIX", no out.tmp and nothing half-written.
therm_bad() {
    local prefix="$1"
    shift
    run -1 --separate-stderr therm "$@" -o out.tmp
    assert_output ''
    [[ "$stderr" == "therm: $prefix"* ]] || fail "stderr: $stderr (wanted 'therm: $prefix...')"
    [ ! -e out.tmp ] || fail "out.tmp was written"
    assert_no_temp_files .
}

# weather_rows FIRST LAST: the weather of White (1996) cut to the rows FIRST..LAST h, with the
# header's row count to match.
weather_rows() {
    awk -v a="$1" -v b="$2" '/^#/ { print; next }
        !seen++ { printf "%d\t1\n", b - a + 1; next }
        $1 >= a && $1 <= b' "$WTH"
}

# assert_tmp_near ACTUAL GOLDEN: same facets in the same order and the same time line,
# temperatures within 1e-6 K (the arithmetic is deterministic; the tolerance only
# absorbs libm differences between platforms, far below any model change).
assert_tmp_near() {
    if [ "${UPDATE_GOLDEN:-0}" = 1 ]; then cp "$1" "$2"; return 0; fi
    run -0 diff <(grep -v '^[0-9]' "$2") <(grep -v '^[0-9]' "$1")
    run -0 awk 'NR == FNR { if ($1 ~ /^[0-9]/) want[++n] = $0; next }
        $1 ~ /^[0-9]/ { split(want[++m], w, " ");
            if (w[1] != $1 || (w[2] - $2) > 1e-6 || ($2 - w[2]) > 1e-6) {
                print "facet " $1 ": " $2 " K, golden " want[m]; bad = 1 } }
        END { if (m != n) { print m " facets, golden " n; bad = 1 }; exit bad }' "$2" "$1"
}

@test "therm --help prints usage and points to therm(1)" {
    run -0 --separate-stderr therm --help
    assert_line --index 0 --partial "Usage: therm "
    assert_line --partial "--time-step"
    assert_line --partial "--threads"
    assert_equal "${lines[-1]}" "See therm(1)."
    assert_equal "$stderr" ""
}

@test "therm --version prints the project version" {
    local version
    version=$(sed -n 's/^project(sigchain VERSION \([0-9][0-9.]*\).*/\1/p' \
        "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt")
    run -0 --separate-stderr therm --version
    assert_output "therm (sigchain) $version"
}

@test "therm rejects an unknown option with exit 2" {
    run -2 --separate-stderr therm --no-such-option
    assert_output ""
    [[ "$stderr" == "therm: "*"no-such-option"* ]] || fail "stderr: $stderr"
    assert_equal "${stderr##*$'\n'}" "Try 'therm --help'."
}

@test "therm wants exactly five inputs and a sane time step (exit 2)" {
    run -2 --separate-stderr therm "$SHD" "$WTH" "$MAT" "$GDB" -o out.tmp
    [[ "$stderr" == "therm: expected SHD WTH MAT SCENE SND"* ]] || fail "stderr: $stderr"
    run -2 --separate-stderr therm --time-step 0 "$SHD" "$WTH" "$MAT" "$GDB" "$SND" -o out.tmp
    [[ "$stderr" == "therm: --time-step"* ]] || fail "stderr: $stderr"
    [ ! -e out.tmp ]
}

@test "therm on the box_on_plane of White (1996) writes a valid .tmp matching the golden" {
    run -0 --separate-stderr therm "$SHD" "$WTH" "$MAT" "$GDB" "$SND" -o out.tmp
    assert_output ''
    assert_equal "$stderr" ''
    assert_no_temp_files .
    run -0 sigchain-check out.tmp
    assert_output "out.tmp: ok: 6 facets, $(awk '/^2-1-4/ {print $2}' out.tmp)-$(awk '/^2-1-2/ {print $2}' out.tmp) K, time 38 h"
    assert_tmp_near out.tmp "$GOLDEN/therm/box_on_plane.tmp"
}

@test "therm writes to standard output by default and reruns identically, on any threads" {
    run -0 --separate-stderr therm "$SHD" "$WTH" "$MAT" "$GDB" "$SND"
    assert_line --index 0 "# sigchain-tmp 1.1"
    echo "$output" > first.tmp
    therm "$SHD" "$WTH" "$MAT" "$GDB" "$SND" -o second.tmp
    run -0 cmp first.tmp second.tmp
    therm --threads 3 "$SHD" "$WTH" "$MAT" "$GDB" "$SND" -o threads.tmp
    run -0 cmp first.tmp threads.tmp
}

@test "therm reads one input from standard input ('-'), not two" {
    run -0 --separate-stderr therm - "$WTH" "$MAT" "$GDB" "$SND" -o out.tmp < "$SHD"
    assert_tmp_near out.tmp "$GOLDEN/therm/box_on_plane.tmp"
    run -2 --separate-stderr therm - - "$MAT" "$GDB" "$SND" -o two.tmp < "$SHD"
    [[ "$stderr" == "therm: only one input can be standard input"* ]] || fail "stderr: $stderr"
    [ ! -e two.tmp ]
}

@test "therm --verbose says what it assumed and the spin-up residual" {
    run -0 --separate-stderr therm -v "$SHD" "$WTH" "$MAT" "$GDB" "$SND" -o out.tmp
    [[ "$stderr" == *"insolation computed"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"Brutsaert"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"taken as unshadowed"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"back face insulated"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"spin-up: up to "*" runs per facet; residual "* ]] || fail "stderr: $stderr"
}

@test "therm keeps a temperature the .gdb fixes" {
    # Facet 2-1-1 (the box top): temperature 40 C instead of -1 (line 50 of the .gdb).
    sed -n 50p "$GDB" | grep -qx -- '-1' || fail "line 50 of the .gdb is not 2-1-1's temperature"
    sed '50s/^-1$/40/' "$GDB" > fixed.gdb
    run -0 --separate-stderr therm "$SHD" "$WTH" "$MAT" fixed.gdb "$SND" -o out.tmp
    run -0 awk '$1 == "2-1-1" { print $2 }' out.tmp
    assert_output "313.15"
}

@test "therm refuses a weather window that does not cover the scene time" {
    weather_rows 0 30 > short.wth  # the scene is at 38 h
    therm_bad "short.wth: the weather window (0 to 30 h) does not cover 38 h" \
        "$SHD" short.wth "$MAT" "$GDB" "$SND"
}

@test "therm refuses a weather window starting less than 24 h before the scene" {
    weather_rows 15 48 > late.wth
    therm_bad "late.wth: the weather window starts at 15 h, less than 24 h before" \
        "$SHD" late.wth "$MAT" "$GDB" "$SND"
}

@test "therm refuses facets whose material is missing from the .mat" {
    # The hawkeye.mat of White (1996) has grass (1) only; the box is wood (37).
    therm_bad "$GDB:44: facet 2-1-1: material 37 is not in $SEED/hawkeye.mat" \
        "$SHD" "$WTH" "$SEED/hawkeye.mat" "$GDB" "$SND"
}

@test "therm refuses non-physical material properties" {
    sed 's/^MASS_DENSITY = 0.64$/MASS_DENSITY = 0/' "$MAT" > zero.mat
    # Line 25: the entry's MATERIAL_ENTRY_BEGIN (mat(5) keeps no line per tag).
    therm_bad "zero.mat:25: material 'pine wood' (id 37): MASS_DENSITY 0 must be above 0" \
        "$SHD" "$WTH" zero.mat "$GDB" "$SND"
}

@test "therm refuses a missing thickness" {
    # Facet 2-1-1 takes the material's thickness (-1 on line 51), and wood has none.
    sed -n 51p "$GDB" | grep -qx 5 || fail "line 51 of the .gdb is not 2-1-1's thickness"
    sed '51s/^5$/-1/' "$GDB" > nothick.gdb
    sed '/^THICKNESS = 5$/d' "$MAT" > nothick.mat
    therm_bad "nothick.gdb:44: facet 2-1-1: no thickness" \
        "$SHD" "$WTH" nothick.mat nothick.gdb "$SND"
}

@test "therm refuses a facet without a sun/shadow history" {
    sed 's/^facets = 6$/facets = 5/' "$SHD" | sed '/^FACET 2-1-5/,$d' > five.shd
    therm_bad "five.shd: no history for facet 2-1-5" five.shd "$WTH" "$MAT" "$GDB" "$SND"
}

@test "therm reports a malformed input with its file and line" {
    sed 's/^FACET 2-1-1 1 1$/FACET 2-1-1 1.5 1/' "$SHD" > bad.shd
    therm_bad "bad.shd:" bad.shd "$WTH" "$MAT" "$GDB" "$SND"
}

@test "therm leaves an existing output untouched when it fails" {
    echo "previous" > out.tmp
    run -1 --separate-stderr therm "$SHD" "$WTH" "$SEED/hawkeye.mat" "$GDB" "$SND" -o out.tmp
    run -0 cat out.tmp
    assert_output "previous"
    assert_no_temp_files .
}

@test "therm on an .odb names facets by placement and turns their normals" {
    # neighbourhood.odb: box_on_plane.gdb as built (1.1), turned 90 deg about z (1.2),
    # stretched x2 in z (1.3); neighbourhood.shd repeats box_on_plane.shd per copy.
    run -0 --separate-stderr therm "$DATA/neighbourhood.shd" "$WTH" "$MAT" \
        "$SEED/neighbourhood.odb" "$SND" -o out.tmp
    run -0 sigchain-check out.tmp
    # The unturned copies (same normals, same histories) match the lone .gdb's golden.
    for copy in 1.1 1.3; do
        # The copy's rows, with its own end line (.tmp 1.1, tmp(5)).
        { grep -v '^[0-9]' out.tmp | grep -v '^# sigchain-end'
          grep "^$copy/" out.tmp | sed "s|^$copy/||"
          echo "# sigchain-end $(grep -c "^$copy/" out.tmp)"; } > copy.tmp
        assert_tmp_near copy.tmp "$GOLDEN/therm/box_on_plane.tmp"
    done
    # Turned a quarter turn counter-clockwise, the east wall (2-1-3) faces north: no
    # direct sun all day, like the unturned north wall (2-1-4), whatever its history.
    run -0 awk '$1 == "1.2/2-1-3" { a = $2 } $1 == "1.1/2-1-4" { b = $2 }
        END { d = a - b; if (d < 0) d = -d; exit !(a != "" && d < 1e-9) }' out.tmp
    # The turned south wall faces east: cooler in the afternoon than the unturned one.
    run -0 awk '$1 == "1.2/2-1-2" { a = $2 } $1 == "1.1/2-1-2" { b = $2 }
        END { exit !(a + 5 < b) }' out.tmp
}

@test "therm warns when the spin-up has not converged" {
    # The box made of 2 m of concrete (material 41, thickness 200 cm on every box
    # facet): its surface keeps changing from one repeated first day to the next.
    awk 'NR >= 40 && $0 == "37" { print "41"; next }
         NR >= 40 && $0 == "5" { print "200"; next } { print }' "$GDB" > thick.gdb
    run -0 --separate-stderr therm "$SHD" "$WTH" "$MAT" thick.gdb "$SND" -o out.tmp
    [[ "$stderr" == "therm: warning: spin-up residual "*" K at facet 2-1-"*" after 8 runs"* ]] ||
        fail "stderr: $stderr"
    run -0 sigchain-check out.tmp
}

@test "therm reads an .odb's OBJ objects, named as trace names them" {
    # quad_tri.odb's OBJ (a grass quad 1-1-1 and a triangle 1-2-2, both level) placed
    # as it is (1.1) and doubled (1.2); the triangle's asphalt taken as wood here. Each
    # facet gets the history of box_on_plane.shd's sunlit ground under trace's key.
    local scene="$SIGCHAIN_SOURCE_DIR/tests/data/scene"
    printf 'grass 1\nasphalt 37\n' > quad_tri.map
    sed "s|^    OBJ_FILENAME = |&$scene/|; s|^    MATERIAL_MAP = .*|    MATERIAL_MAP = quad_tri.map|" \
        "$scene/quad_tri.odb" > quad_tri.odb
    {
        printf '# sigchain-shd 1\nscene_time_hours = 38\nsteps = 5\nstep_hours = 1\nfacets = 4\n'
        for key in 1.1/1-1-1 1.1/1-2-2 1.2/1-1-1 1.2/1-2-2; do
            sed -n '/^FACET 1-1-1 /,/^$/p' "$SHD" | sed "s|^FACET 1-1-1 |FACET $key |"
        done
    } > quad_tri.shd
    run -0 --separate-stderr therm quad_tri.shd "$WTH" "$MAT" quad_tri.odb "$SND" -o out.tmp
    assert_equal "$stderr" ''
    run -0 sigchain-check out.tmp
    run -0 awk '$1 ~ /^[0-9]/ { printf "%s ", $1 }' out.tmp
    assert_output "1.1/1-1-1 1.1/1-2-2 1.2/1-1-1 1.2/1-2-2 "
    # The doubled copy faces the same way with the same history: the same answers.
    run -0 awk '{ t[$1] = $2 } END { exit !(t["1.1/1-1-1"] == t["1.2/1-1-1"] &&
        t["1.1/1-2-2"] == t["1.2/1-2-2"] && t["1.1/1-1-1"] != t["1.1/1-2-2"]) }' out.tmp
}
