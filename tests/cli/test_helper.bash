# Shared set-up for sigchain's Bats tests: tools on PATH, a scratch directory,
bats_require_minimum_version 1.5.0
# bats-support/bats-assert, and golden-file helpers.
bats_load_library() { :; }
load '/usr/lib/bats/bats-support/load.bash'
load '/usr/lib/bats/bats-assert/load.bash'

: "${SIGCHAIN_SOURCE_DIR:=$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
: "${SIGCHAIN_BIN:=$SIGCHAIN_SOURCE_DIR/build/bin}"
export PATH="$SIGCHAIN_BIN:$PATH"
SEED="$SIGCHAIN_SOURCE_DIR/tests/data/seed"
GOLDEN="$SIGCHAIN_SOURCE_DIR/tests/golden"
BAD="$SIGCHAIN_SOURCE_DIR/tests/data/bad"

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
