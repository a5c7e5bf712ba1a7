# Tests: sigchain-check (generic behaviour; each format's cases are in formats_*.bats)
# Also requires: CMakeLists.txt (the version in its project() line), tests/data/white1996/
#
# These tests do not depend on which formats exist: they take the formats from
# `sigchain-check --list-formats` and skip, saying so, when a case needs one and the
# list is empty.

bats_require_minimum_version 1.5.0
load test_helper

project_version() {
    sed -n 's/^project(sigchain VERSION \([0-9][0-9.]*\).*/\1/p' \
        "$SIGCHAIN_SOURCE_DIR/CMakeLists.txt"
}

# The known format extensions, one per line, in --list-formats order.
known_formats() {
    sigchain-check --list-formats | cut -f1
}

# Sets $ext to the first known format, or skips the test.
need_a_format() {
    ext="$(known_formats | head -n 1)"
    [ -n "$ext" ] || skip "no formats registered yet (sigchain-check --list-formats is empty)"
}

# Sets $sample to a seed file whose format is known, and $ext to its format, or skips.
need_a_seed_sample() {
    local f e
    for f in "$SEED"/*; do
        [ -f "$f" ] || continue
        e="${f##*.}"
        e="${e,,}"
        if known_formats | grep -qx -- "$e"; then
            sample="$f"
            ext="$e"
            return 0
        fi
    done
    skip "no sample in tests/data/white1996/ has a registered format yet"
}

# Runs sigchain-check with ARGS, failing with its stderr unless it exits 0.
check_ok() {
    run --separate-stderr sigchain-check "$@"
    [ "$status" -eq 0 ] || fail "sigchain-check $* exited $status: $stderr"
}

# Usage errors: exit 2, nothing on stdout, MESSAGE and "Try ..." on stderr.
assert_usage_error() {
    local message="$1"
    assert_output ""
    [[ "$stderr" == "sigchain-check: "*"$message"* ]] || fail "stderr: $stderr"
    assert_equal "${stderr##*$'\n'}" "Try 'sigchain-check --help'."
}

@test "--help prints usage on stdout and points to sigchain-check(1)" {
    run -0 --separate-stderr sigchain-check --help
    assert_line --index 0 --partial "Usage: sigchain-check "
    assert_line --partial "--list-formats"
    assert_line --partial "--rewrite"
    assert_equal "${lines[-1]}" "See sigchain-check(1)."
    assert_equal "$stderr" ""
}

@test "--version prints the project version" {
    run -0 --separate-stderr sigchain-check --version
    assert_output "sigchain-check (sigchain) $(project_version)"
    assert_equal "$stderr" ""
}

@test "an unknown option exits 2" {
    run -2 --separate-stderr sigchain-check --no-such-option x.adv
    assert_usage_error "no-such-option"
}

@test "no input files exits 2" {
    run -2 --separate-stderr sigchain-check
    assert_usage_error "no input files"
}

@test "an unknown extension exits 2 naming the format" {
    printf 'anything\n' > notes.nosuchformat
    run -2 --separate-stderr sigchain-check notes.nosuchformat
    assert_usage_error "unknown format 'nosuchformat'"
}

@test "an unknown --format exits 2 naming the format" {
    printf 'anything\n' > notes.txt
    run -2 --separate-stderr sigchain-check -f nosuchformat notes.txt
    assert_usage_error "unknown format 'nosuchformat'"
}

@test "a name without an extension exits 2 and asks for --format" {
    printf 'anything\n' > README
    run -2 --separate-stderr sigchain-check README
    assert_usage_error "README: cannot tell the format from the name; use --format"
}

@test "standard input without --format exits 2" {
    run -2 --separate-stderr sigchain-check - < /dev/null
    assert_usage_error "cannot tell the format from the name; use --format"
}

@test "--rewrite with two files exits 2" {
    printf 'x\n' > a.adv
    printf 'x\n' > b.adv
    run -2 --separate-stderr sigchain-check --rewrite a.adv b.adv
    assert_usage_error "--rewrite takes exactly one FILE"
}

@test "--list-formats exits 0 and prints EXTENSION<TAB>DESCRIPTION lines sorted" {
    run -0 --separate-stderr sigchain-check --list-formats
    assert_equal "$stderr" ""
    [ "${#lines[@]}" -gt 0 ] || skip "no formats registered yet (the list is empty)"
    local line
    for line in "${lines[@]}"; do
        [[ "$line" =~ ^[a-z0-9]+$'\t'[^[:space:]].*$ ]] || fail "malformed line: '$line'"
    done
    assert_equal "$(known_formats)" "$(known_formats | LC_ALL=C sort -u)"
}

@test "--list-formats names a section-5 man page for every format" {
    need_a_format
    local e
    for e in $(known_formats); do
        [ -f "$SIGCHAIN_SOURCE_DIR/man/$e.5.scd" ] || fail "format '$e' has no man/$e.5.scd"
    done
}

@test "a missing file exits 1 naming the file" {
    need_a_format
    run -1 --separate-stderr sigchain-check "missing.$ext"
    assert_output ""
    assert_equal "$stderr" "sigchain-check: missing.$ext: cannot open: No such file or directory"
}

@test "an empty file exits 1 naming the file, for every format" {
    need_a_format
    local e
    for e in $(known_formats); do
        : > "empty.$e"
        run -1 --separate-stderr sigchain-check "empty.$e"
        assert_output ""
        [[ "$stderr" == "sigchain-check: empty.$e"[:\ ]* ]] || fail "$e: stderr: $stderr"
    done
}

@test "a binary file (NUL byte) exits 1 naming file, line and 'binary', for every format" {
    need_a_format
    local e
    for e in $(known_formats); do
        printf 'text\nmore\0text\n' > "data.$e"
        run -1 --separate-stderr sigchain-check "data.$e"
        assert_output ""
        [[ "$stderr" == "sigchain-check: data.$e:2: binary"* ]] || fail "$e: stderr: $stderr"
    done
}

@test "a binary standard input is reported as <stdin>" {
    need_a_format
    printf 'a\0b' > nul.bin
    run -1 --separate-stderr sigchain-check -f "$ext" - < nul.bin
    assert_output ""
    [[ "$stderr" == "sigchain-check: <stdin>:1: binary"* ]] || fail "stderr: $stderr"
}

@test "the extension is read case-insensitively" {
    need_a_format
    : > "EMPTY.${ext^^}"
    # Exit 1 (an empty file of a known format), not 2 (an unknown format).
    run -1 --separate-stderr sigchain-check "EMPTY.${ext^^}"
    [[ "$stderr" == "sigchain-check: EMPTY.${ext^^}"[:\ ]* ]] || fail "stderr: $stderr"
}

@test "DIRSIG's numbered radiance files NAME.radN are read as .rad" {
    known_formats | grep -qx rad || skip "format rad not registered yet"
    : > scene.rad2
    run -1 --separate-stderr sigchain-check scene.rad2
    [[ "$stderr" == "sigchain-check: scene.rad2"[:\ ]* ]] || fail "stderr: $stderr"
}

@test "every file is checked: a bad file does not stop the others" {
    need_a_seed_sample
    : > "first.$ext"
    cp "$sample" "second.$ext"
    : > "third.$ext"
    run -1 --separate-stderr sigchain-check "first.$ext" "second.$ext" "third.$ext"
    assert_output --regexp "^second\.$ext: ok: "
    [[ "$stderr" == *"first.$ext"* ]] || fail "stderr: $stderr"
    [[ "$stderr" == *"third.$ext"* ]] || fail "stderr: $stderr"
}

@test "a valid file prints FILE: ok: SUMMARY, and -q prints nothing" {
    need_a_seed_sample
    cp "$sample" "sample.$ext"
    run -0 --separate-stderr sigchain-check "sample.$ext"
    assert_output --regexp "^sample\.$ext: ok: .+$"
    assert_equal "$stderr" ""
    run -0 --separate-stderr sigchain-check -q "sample.$ext"
    assert_output ""
    assert_equal "$stderr" ""
}

@test "standard input is read with -f" {
    need_a_seed_sample
    run -0 --separate-stderr sigchain-check -f "$ext" - < "$sample"
    assert_output --regexp "^-: ok: .+$"
}

@test "--format overrides the extension" {
    need_a_seed_sample
    cp "$sample" sample.txt
    run -0 --separate-stderr sigchain-check --format "$ext" sample.txt
    assert_output --regexp "^sample\.txt: ok: .+$"
}

@test "--rewrite of every sample of White (1996) re-checks and is idempotent" {
    need_a_seed_sample
    local f e n=0
    for f in "$SEED"/*; do
        e="${f##*.}"
        e="${e,,}"
        known_formats | grep -qx -- "$e" || continue
        check_ok --rewrite -o "once.$e" "$f"
        check_ok "once.$e"
        check_ok --rewrite -o "twice.$e" "once.$e"
        run diff -u "once.$e" "twice.$e"
        assert_success
        n=$((n + 1))
    done
    [ "$n" -gt 0 ]
    assert_no_temp_files .
}

@test "--rewrite to standard output equals --rewrite -o FILE" {
    need_a_seed_sample
    run -0 --separate-stderr sigchain-check --rewrite -o "out.$ext" "$sample"
    run -0 --separate-stderr sigchain-check --rewrite "$sample"
    assert_equal "$output" "$(cat "out.$ext")"
}

@test "a failed --rewrite leaves no output and keeps an existing one" {
    need_a_format
    : > "empty.$ext"
    run -1 --separate-stderr sigchain-check --rewrite -o "new.$ext" "empty.$ext"
    [ ! -e "new.$ext" ] || fail "a failed rewrite created new.$ext"
    printf 'keep me\n' > "old.$ext"
    run -1 --separate-stderr sigchain-check --rewrite -o "old.$ext" "empty.$ext"
    assert_equal "$(cat "old.$ext")" "keep me"
    assert_no_temp_files .
}

@test "every sample of White (1996) with DOS line endings (CRLF) reads as with LF" {
    need_a_seed_sample
    local f e n=0
    for f in "$SEED"/*; do
        e="${f##*.}"
        e="${e,,}"
        known_formats | grep -qx -- "$e" || continue
        sed 's/$/\r/' "$f" > "dos.$e"
        check_ok --rewrite -o "unix-rewritten.$e" "$f"
        check_ok --rewrite -o "dos-rewritten.$e" "dos.$e"
        run diff -u "unix-rewritten.$e" "dos-rewritten.$e"
        assert_success
        n=$((n + 1))
    done
    [ "$n" -gt 0 ]
}
