# Shared set-up for sigchain's Bats tests: tools on PATH, a scratch directory,
bats_require_minimum_version 1.5.0
# bats-support/bats-assert, and golden-file helpers.
bats_load_library() { :; }
load '/usr/lib/bats/bats-support/load.bash'
load '/usr/lib/bats/bats-assert/load.bash'

: "${SIGCHAIN_SOURCE_DIR:=$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
: "${SIGCHAIN_BIN:=$SIGCHAIN_SOURCE_DIR/build/bin}"
export PATH="$SIGCHAIN_BIN:$PATH"
SEED="$SIGCHAIN_SOURCE_DIR/tests/data/white1996"
GOLDEN="$SIGCHAIN_SOURCE_DIR/tests/golden"
BAD="$SIGCHAIN_SOURCE_DIR/tests/data/bad"
# Scenes made through pipelines/scene.mk run their tools with -q in the tests, as
# the tests were written for (scene.mk's defaults show the tools' warnings); a make
# argument such as TRACE_FLAGS=... still takes precedence.
export CONTROL7_FLAGS=-q BUILD_RADIANCE_FLAGS=-q TRACE_FLAGS=-q THERM_FLAGS=-q \
    CALIBRATE_FLAGS=-q SENSORIZE_FLAGS=-q

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
}

# assert_golden ACTUAL_FILE GOLDEN_FILE: text comparison with diff -u, images with
# compare --pixelwise and a tolerance (GOLDEN_MAX_DIFF);
# UPDATE_GOLDEN=1 rewrites the golden file instead.
assert_golden() {
    local actual="$1" golden="$2"
    if [ "${UPDATE_GOLDEN:-0}" = 1 ]; then
        mkdir -p "$(dirname "$golden")"
        cp "$actual" "$golden"
        return 0
    fi
    case "$golden" in
        *.png | *.tif | *.tiff | *.pgm | *.ppm | *.img)
            # Images: never byte for byte; our own compare with an explicit tolerance
            # (largest allowed pixel difference, GOLDEN_MAX_DIFF, default 0).
            run compare --pixelwise --fail-max "${GOLDEN_MAX_DIFF:-0}" "$actual" "$golden"
            ;;
        *) run diff -u "$golden" "$actual" ;;
    esac
    assert_success
}

# assert_no_temp_files DIR: nothing half-written (FILE.tmp.PID) is left behind.
assert_no_temp_files() {
    run find "${1:-.}" -name '*.tmp.*'
    assert_output ''
}

# check_bad FORMAT FILE LINE MESSAGE: sigchain-check rejects $BAD/FORMAT/FILE with exit 1,
# nothing on stdout, and "sigchain-check: $BAD/FORMAT/FILE:LINE: MESSAGE..." on stderr
# (LINE empty for an error about the whole file).
check_bad() {
    local file="$BAD/$1/$2"
    local want="sigchain-check: $file${3:+:$3}: $4"
    run -1 --separate-stderr sigchain-check "$file"
    assert_output ''
    [[ "$stderr" == "$want"* ]] || { echo "stderr: $stderr"; echo "wanted: $want..."; return 1; }
}

# check_good FILE SUMMARY: sigchain-check accepts FILE with exit 0, printing its summary.
check_good() {
    run -0 --separate-stderr sigchain-check "$1"
    assert_output "$1: ok: $2"
    assert_equal "$stderr" ''
}

# check_rewrite_golden FILE: --rewrite gives $GOLDEN/sigchain-check/BASENAME, which itself
# re-checks and rewrites to itself; nothing half-written is left.
check_rewrite_golden() {
    local name
    name=$(basename "$1")
    run -0 --separate-stderr sigchain-check --rewrite -o "out.$name" "$1"
    assert_golden "out.$name" "$GOLDEN/sigchain-check/$name"
    run -0 sigchain-check -q "$GOLDEN/sigchain-check/$name"
    run -0 sigchain-check --rewrite -o "again.$name" "$GOLDEN/sigchain-check/$name"
    run -0 cmp "again.$name" "$GOLDEN/sigchain-check/$name"
    assert_no_temp_files .
}
