# Tests: every tool (the reliability of options and outputs)
# Also requires: tests/data/trace, tests/data/therm, tests/data/cube, tests/data/white1996,
# tests/data/build_radiance, tests/golden/control7/hawkeye.cdk
#
# A bad-input campaign for what every tool shares: each numeric option of each tool
# refuses NaN, infinities and values outside its documented range (usage error, exit
# 2, "TOOL: --OPTION: VALUE: must be ..."); SIGTERM and SIGINT leave no temporary and
# the target unchanged or complete (exit 128 + N); a multi-file output killed at each
# of its renames is never a mix of old and new files; a symbolic link planted at any
# temporary name is never written through; an output that is one of the run's inputs
# is refused. At the end the catalogue's counts (runs, named errors, crashes, hangs)
# are printed.

bats_require_minimum_version 1.5.0
load ../cli/test_helper

TRACE="$SIGCHAIN_SOURCE_DIR/tests/data/trace"
THERM="$SIGCHAIN_SOURCE_DIR/tests/data/therm"
CUBE="$SIGCHAIN_SOURCE_DIR/tests/data/cube"
RADDATA="$SIGCHAIN_SOURCE_DIR/tests/data/build_radiance"
HAWKEYE_CDK="$GOLDEN/control7/hawkeye.cdk"
QUICK=(--streams 8 --sky-zenith-step 15 --sky-azimuth-step 30 --sky-subsamples 1)

# Every numeric option of every tool, with a value below and one above its documented
# range ('-' where the range is open on that side) and whether it takes integers only.
# The test "every numeric option of every tool is listed" keeps this list complete.
NUMERIC_OPTIONS='
build_radiance          streams                3     65                    int
build_radiance          stream-tolerance       0     1.1                   real
build_radiance          sky-zenith-step        0     90.5                  real
build_radiance          sky-azimuth-step       0     361                   real
build_radiance          sky-subsamples         0     9                     int
build_radiance          upwelled-azimuth-step  0     361                   real
build_radiance          view-azimuth           -361  361                   real
build_radiance          top                    0     1001                  real
build_radiance          merge-tau              -0.1  1.1                   real
build_radiance          thermal-from           -1    1001                  real
build_radiance          threads                -1    4097                  int
compare                 bins                   0     4097                  int
compare                 fail-rms               -1    -                     real
compare                 fail-roc               -1.5  1.5                   real
compare                 fail-max               -1    -                     real
find_min_max_view_angle grid                   0     100001                int
sensorize               bits                   7     17                    int
sensorize               shot-noise             0     -                     real
sensorize               read-noise             -1    -                     real
sensorize               psf-sigma              0     -                     real
sensorize               mtf-fnumber            0     1001                  real
sensorize               mtf-pitch              0     10001                 real
sensorize               mtf-fill               0     1.1                   real
sensorize               mtf-defocus            -1    10001                 real
sensorize               seed                   -1    18446744073709551616  int
sensorize               noise-seed             -1    18446744073709551616  int
soho_scene              seed                   -1    18446744073709551616  int
therm                   time-step              0     3601                  real
therm                   threads                -1    4097                  int
therm                   material-id            -1    16777217              int
find_min_max_view_angle material-id            -1    16777217              int
trace                   seed                   -1    18446744073709551616  int
trace                   threads                -1    4097                  int
trace                   samples-per-pixel      0     65537                 int
trace                   hemisphere-samples     0     1000001               int
trace                   max-transmissions      -1    1001                  int
trace                   adjacency-radius       0     1e8                   real
trace                   sun-images             -1    1001                  int
trace                   history-hours          0     8761                  real
trace                   history-step-minutes   0     1441                  real
trace                   points-per-facet       0     1000001               int
trace                   sky-rays               0     1000001               int
trace                   material-id            -1    16777217              int
landsat_sensor          altitude               -0.6  1000.5                real
landsat_sensor          samples                1     100001                int
landsat_sensor          increment              0     10001                 real
landsat_sensor          threshold              0     1.1                   real
landsat_scene           bands                  0     1001                  int
landsat_scene           buffer                 -1    101                   int
landsat_scene           pixel                  0     1000001               real
'
# Options with a value that is not a number (names, files, lists checked by their
# own parsers).
TEXT_OPTIONS='answer answers bands co data-dir output error-map plot format method origin
sampling bounces background rows truth tmp psf preview preview-stretch card1 card2 target1 target2
material-map landuse landuse-map up-axis crs like radiance-units write-decks from-tape7 mtf-smear mtf-electronics
convergence convergence-error tile igm glt uncertainty uncertainty-cube uncertainty-output rsr view-angles
name gain target mask points cloud dark sun heights'
TOOLS='build_radiance compare control7 find_min_max_view_angle hawkeye_scene merge_tiles
olinda_scene sensorize sigchain-check soho_scene therm trace landsat_sensor landsat_scene'

setup_file() {
    export CATALOGUE="$BATS_FILE_TMPDIR/catalogue"
    : >"$CATALOGUE"
    # slow_trace ARGS...: a trace run of about a second (the box scene at $SPP, default
    # 64, samples per pixel), as a command so that timeout, env and & can run it; not
    # georeferenced (--crs none), so that the ENVI pair is the whole output.
    mkdir -p "$BATS_FILE_TMPDIR/bin"
    {
        echo '#!/bin/sh'
        echo "exec trace --crs none --threads 1 --samples-per-pixel \${SPP:-64} '$TRACE/box.adv' '$TRACE/box.snd' \\"
        echo "    '$SEED/box_on_plane.gdb' '$TRACE/box.mat' '$TRACE/band1.rad' '$TRACE/band2.rad' \"\$@\""
    } >"$BATS_FILE_TMPDIR/bin/slow_trace"
    chmod +x "$BATS_FILE_TMPDIR/bin/slow_trace"
    # The old and new cubes of the signal and rename tests: made once.
    mkdir -p "$BATS_FILE_TMPDIR/old" "$BATS_FILE_TMPDIR/new"
    SPP=1 "$BATS_FILE_TMPDIR/bin/slow_trace" -o "$BATS_FILE_TMPDIR/old/out.img"
    SPP=2 "$BATS_FILE_TMPDIR/bin/slow_trace" -o "$BATS_FILE_TMPDIR/new/out.img"
}

# The old and new cubes of setup_file, here as old/ and new/.
old_and_new() {
    cp -r "$BATS_FILE_TMPDIR/old" "$BATS_FILE_TMPDIR/new" .
}

setup() {
    cd "$BATS_TEST_TMPDIR" || return 1
    export PATH="$BATS_FILE_TMPDIR/bin:$PATH"
}

teardown_file() {
    local runs named crashes hangs
    runs=$(wc -l <"$CATALOGUE")
    named=$(grep -c '^named' "$CATALOGUE" || true)
    crashes=$(grep -c '^crash' "$CATALOGUE" || true)
    hangs=$(grep -c '^hang' "$CATALOGUE" || true)
    echo "# catalogue: $runs runs, $named named errors, $crashes crashes, $hangs hangs" >&3
}

# probe WANT PREFIX CMD...: runs CMD (30 s at most) and files the run in the catalogue:
# a hang (timeout), a crash (killed by a signal the test did not send), a named error (exit WANT with stderr starting "PREFIX"), or other. Sets status, stderr.
probe() {
    local want="$1" prefix="$2"
    shift 2
    run --separate-stderr timeout 30 "$@"
    local kind=other
    if [ "$status" = 124 ]; then
        kind=hang
    elif [ "$status" = "$want" ] && [[ "$stderr" == "$prefix"* ]]; then
        kind=named  # also 137, 143, 130 where a test sends the signal
    elif [ "$status" -gt 128 ]; then
        kind=crash
    fi
    echo "$kind $status $1" >>"$CATALOGUE"
    [ "$kind" = named ] || fail "$* -> exit $status, stderr: $stderr (wanted exit $want, '$prefix...')"
}

@test "every numeric option of every tool is listed (from each tool's --help)" {
    local tool opt listed=0
    for tool in $TOOLS; do
        run -0 "$tool" --help
        # Options that take a value: "--name VALUE" or "-x [ --name ] VALUE" in --help.
        for opt in $(grep -E '^ +(-[a-zA-Z] \[ )?--[a-z0-9-]+( \])? [A-Z]' <<<"$output" |
                     sed -E 's/^ +(-[a-zA-Z] \[ )?--([a-z0-9-]+).*/\2/' | sort -u); do
            if grep -qE "^$tool +$opt " <<<"$NUMERIC_OPTIONS"; then
                listed=$((listed + 1))
            elif ! grep -qw -- "$opt" <<<"$TEXT_OPTIONS"; then
                fail "$tool --$opt takes a value and is in neither list of this file"
            fi
        done
    done
    # noise-seed is hidden (deprecated); every other listed option was seen in a --help.
    [ "$listed" -eq $(($(grep -c '[a-z]' <<<"$NUMERIC_OPTIONS") - 1)) ] ||
        fail "$listed numeric options seen in --help"
}

@test "every numeric option refuses NaN, infinities, junk and values out of its range" {
    # Three runs per option (a process reports its first error only): NaN, one of the
    # other non-numbers in turn, and one end of the range in turn. The parser's unit
    # tests (tests/unit/cli) try every one of them on one range.
    local tool opt below above kind value i=0 odd
    local others=(inf -inf infinity 1e999 12abc NaN 0x10)
    while read -r tool opt below above kind; do
        [ -n "$tool" ] || continue
        i=$((i + 1))
        odd="${others[$((i % ${#others[@]}))]}"
        [ "$kind" = real ] || [ $((i % 2)) = 1 ] || odd=1.5  # integers: a fraction
        for value in nan "$odd" "$([ $((i % 2)) = 0 ] && [ "$above" != - ] && echo "$above" || echo "$below")"; do
            [ "$value" != - ] || continue
            probe 2 "$tool: --$opt: $value: must be " "$tool" "--$opt=$value"
            [[ "$stderr" == *"Try '$tool --help'."* ]] || fail "$tool --$opt=$value: $stderr"
        done
    done <<<"$NUMERIC_OPTIONS"
}

@test "the campaign's cases: compare's thresholds, sensorize's noise, trace --threads -1" {
    probe 2 "compare: --fail-rms: nan: must be a number from 0" compare --fail-rms nan a b c
    probe 2 "compare: --fail-roc: nan: must be a number from -1 to 1" compare --fail-roc nan a b c
    probe 2 "compare: --fail-max: nan: must be" compare --pixelwise --fail-max nan a b
    probe 2 "sensorize: --read-noise: nan: must be a number >= 0" \
        sensorize --read-noise nan "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.tif
    probe 2 "sensorize: --read-noise: inf: must be" \
        sensorize --read-noise inf "$CUBE/tiny.img" "$CUBE/blue.sen" -o out.tif
    probe 2 "trace: --threads: -1: must be an integer from 0 to 4096" trace --threads -1
    probe 2 "build_radiance: --view-azimuth: nan: must be" build_radiance --view-azimuth nan
    probe 2 "build_radiance: --top: inf: must be" build_radiance --top inf
    [ ! -e out.tif ]
}

# ---- Signals ----

# terminated_ok STATUS OLD NEW FILE...: the run ended by the signal (143 or 130) or
# finished (0); no temporary is left; each FILE is as in OLD/ or as in NEW/.
terminated_ok() {
    local status="$1" old="$2" new="$3"
    shift 3
    [ "$status" = 143 ] || [ "$status" = 130 ] || [ "$status" = 0 ] || fail "exit $status"
    assert_no_temp_files .
    local f same_old=1 same_new=1
    for f in "$@"; do
        cmp -s "$f" "$old/$f" || same_old=0
        cmp -s "$f" "$new/$f" || same_new=0
    done
    [ $same_old = 1 ] || [ $same_new = 1 ] || fail "exit $status: neither the old nor the new output"
}

@test "SIGTERM and SIGINT at random times leave the target unchanged or complete, no temporary" {
    old_and_new
    local i pid status delay
    for i in 1 2 3; do
        cp old/out.img old/out.hdr .
        delay=$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", r % 30 / 100 }')
        SPP=2 slow_trace -o out.img &
        pid=$!
        sleep "$delay"
        if [ $((i % 2)) = 0 ]; then kill -INT "$pid" 2>/dev/null || true; else kill -TERM "$pid" 2>/dev/null || true; fi
        status=0
        wait "$pid" || status=$?
        echo "named $status signal after $delay s" >>"$CATALOGUE"
        terminated_ok "$status" old new out.img out.hdr
    done
}

@test "SIGHUP: ignored under nohup, so the run completes; otherwise handled as SIGTERM (exit 129)" {
    old_and_new
    local pid status
    # nohup starts the run with SIGHUP ignored; the tool keeps it so. The run (1.4 s at
    # 1024 samples per pixel on one core of the development machine) is still going
    # 0.3 s in, when the hangup comes; the test then checks that it was.
    SPP=1024 nohup slow_trace -o hup.img > /dev/null 2>&1 &
    pid=$!
    sleep 0.3
    kill -HUP "$pid" || fail "the run had ended before the hangup: make it longer"
    status=0
    wait "$pid" || status=$?
    [ "$status" = 0 ] || fail "under nohup, SIGHUP ended the run with status $status"
    [ -s hup.img ] && [ -s hup.hdr ]
    # Without nohup (SIGHUP at its default, whatever the test harness inherited) a
    # hangup ends the run: exit 129, no temporary, no output.
    SPP=1024 env --default-signal=HUP slow_trace -o hup2.img &
    pid=$!
    sleep 0.3
    kill -HUP "$pid" || fail "the run had ended before the hangup: make it longer"
    status=0
    wait "$pid" || status=$?
    [ "$status" = 129 ] || fail "SIGHUP without nohup: status $status"
    [ ! -e hup2.img ]
    assert_no_temp_files .
}

@test "SIGTERM at known points: while reading, with the temporaries written, at each rename" {
    old_and_new
    cp old/out.img old/out.hdr .
    # While reading the inputs (at once): exit 143, target unchanged.
    SPP=2 slow_trace -o out.img &
    kill -TERM $!
    local status=0
    wait $! || status=$?
    terminated_ok "$status" old new out.img out.hdr
    [ "$status" != 143 ] || cmp out.img old/out.img
    # The temporaries written, before the first rename (the writer's test hook, N=0):
    # the handler removes the private folder with GDAL's files; target unchanged. (The
    # run above may have finished before its signal came: start again from the old cube.)
    cp old/out.img old/out.hdr .
    probe 143 "" env SIGCHAIN_TEST_KILL_AT_RENAME=0:TERM SPP=2 slow_trace -o out.img
    terminated_ok 143 old new out.img out.hdr
    cmp out.img old/out.img
    # At each step of the commit, SIGTERM waits for the commit: the new output.
    local n
    for n in 1 2 3 4; do
        cp old/out.img old/out.hdr .
        probe 143 "" env SIGCHAIN_TEST_KILL_AT_RENAME=$n:TERM SPP=2 slow_trace -o out.img
        terminated_ok 143 old new out.img out.hdr
        cmp out.img new/out.img
    done
    # therm and build_radiance (text outputs) too.
    probe 130 "" env SIGCHAIN_TEST_KILL_AT_RENAME=0:INT therm "$SEED/box_on_plane.shd" \
        "$SEED/weather_30_Sep_95.wth" "$THERM/box_on_plane.mat" "$SEED/box_on_plane.gdb" \
        "$SEED/hawkeye.snd" -o t.tmp
    [ ! -e t.tmp ]
    assert_no_temp_files .
}


# ---- Multi-file outputs killed at each rename ----

# state_of OLD NEW FILE...: "old" (every FILE as in OLD/), "new" (every one as in NEW/),
# "incomplete" (some missing, the others all old or all new) or "mixed".
state_of() {
    local old="$1" new="$2"
    shift 2
    local f n_old=0 n_new=0 n_missing=0
    for f in "$@"; do
        if [ ! -e "$f" ]; then n_missing=$((n_missing + 1))
        elif cmp -s "$f" "$old/$f"; then n_old=$((n_old + 1))
        elif cmp -s "$f" "$new/$f"; then n_new=$((n_new + 1))
        else echo mixed; return; fi
    done
    if [ $n_old = $# ]; then echo old
    elif [ $n_new = $# ]; then echo new
    elif [ $n_old -gt 0 ] && [ $n_new -gt 0 ]; then echo mixed
    else echo incomplete; fi
}

@test "an ENVI cube killed at each rename is old, new or without its header, never mixed" {
    old_and_new
    local n want state states=
    for n in 1 2 3 4 5; do
        cp old/out.img old/out.hdr .
        want=137  # SIGKILL; at 5 there is no fifth step and the run ends normally
        [ $n != 5 ] || want=0
        probe $want "" env SIGCHAIN_TEST_KILL_AT_RENAME=$n SPP=2 slow_trace -o out.img
        state=$(state_of old new out.img out.hdr)
        states="$states $state"
        [ "$state" != mixed ] || fail "killed at step $n: old and new files side by side"
        # Without its header the cube is unreadable: a reader reports it missing.
        if [ ! -e out.hdr ]; then
            run -2 --separate-stderr compare --pixelwise out.img new/out.img
        fi
        rm -rf out.img.tmp.*  # SIGKILL leaves the private folder (no handler runs)
    done
    # Removing the old header, the old data, renaming the data, the header; 5: done.
    assert_equal "$states" " old incomplete incomplete incomplete new"
}

@test "build_radiance's bands killed at each rename are all old, all new or incomplete" {
    mkdir old new
    build_radiance -q "${QUICK[@]}" "$HAWKEYE_CDK" "$RADDATA/small.snd" -o 'old/b-%d.rad'
    build_radiance -q "${QUICK[@]}" --top 50 "$HAWKEYE_CDK" "$RADDATA/small.snd" -o 'new/b-%d.rad'
    local n want state states=
    for n in 1 2 3 4 5; do
        cp old/b-1.rad old/b-2.rad .
        want=137
        [ $n != 5 ] || want=0
        probe $want "" env SIGCHAIN_TEST_KILL_AT_RENAME=$n \
            build_radiance -q "${QUICK[@]}" --top 50 "$HAWKEYE_CDK" "$RADDATA/small.snd" -o 'b-%d.rad'
        state=$(state_of old new b-1.rad b-2.rad)
        states="$states $state"
        rm -f b-*.rad.tmp.*
    done
    assert_equal "$states" " old incomplete incomplete incomplete new"
}

# ---- Symbolic links planted at temporary names ----

# plant TARGET PID: links to ./victim at every temporary name a writer of TARGET could
# have used: the old TARGET.tmp.PID (and ENVI's BASE.tmp.PID.img/.hdr) and ten
# names of the new pattern TARGET.tmp.XXXXXX (mkostemp skips a taken name).
plant() {
    local target="$1" pid="$2" base="${1%.*}" i
    ln -s victim "$target.tmp.$pid"
    ln -s victim "$base.tmp.$pid.img"
    ln -s victim "$base.tmp.$pid.hdr"
    for i in $(awk -v seed="$pid" 'BEGIN { srand(seed); c = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"
            for (n = 0; n < 10; n++) { s = ""; for (k = 0; k < 6; k++) s = s substr(c, int(rand() * 62) + 1, 1); print s } }'); do
        ln -s victim "$target.tmp.$i"
    done
}

@test "a symbolic link planted at a temporary name is never written through" {
    echo precious >victim
    # The tool runs with the shell's process id (exec), so the old name is the one it
    # would have used.
    probe 0 "" sh -c "$(declare -f plant); plant out.tmp \$\$; exec therm -q '$SEED/box_on_plane.shd' \
        '$SEED/weather_30_Sep_95.wth' '$THERM/box_on_plane.mat' '$SEED/box_on_plane.gdb' \
        '$SEED/hawkeye.snd' -o out.tmp"
    probe 0 "" sh -c "$(declare -f plant); plant cube.img \$\$; export SPP=1; exec slow_trace -o cube.img"
    probe 0 "" sh -c "$(declare -f plant); plant h.shd \$\$; exec trace -q --shadow-history \
        --sky-rays 4 '$TRACE/box.snd' '$SEED/box_on_plane.gdb' '$TRACE/box.mat' -o h.shd"
    probe 0 "" sh -c "$(declare -f plant); plant c.png \$\$; exec sensorize -q '$CUBE/tiny.img' \
        '$CUBE/blue.sen' '$CUBE/red.sen' -o c.png"
    probe 0 "" sh -c "$(declare -f plant); plant r-1.rad \$\$; plant r-2.rad \$\$; exec build_radiance -q \
        ${QUICK[*]} '$HAWKEYE_CDK' '$RADDATA/small.snd' -o 'r-%d.rad'"
    assert_equal "$(cat victim)" precious
    # A link at the target itself is replaced, not written through.
    ln -s victim t2.tmp
    probe 0 "" therm -q "$SEED/box_on_plane.shd" "$SEED/weather_30_Sep_95.wth" \
        "$THERM/box_on_plane.mat" "$SEED/box_on_plane.gdb" "$SEED/hawkeye.snd" -o t2.tmp
    assert_equal "$(cat victim)" precious
    [ ! -L t2.tmp ] && cmp t2.tmp out.tmp
    [ -s cube.img ] && [ -s cube.hdr ] && [ -s h.shd ] && [ -s c.png ] && [ -s r-2.rad ]
}

# ---- An output that is an input ----

# refused TOOL ARGS...: exit 2 naming the clash; every file here unchanged.
refused() {
    local before after
    before=$(cat ./* 2>/dev/null | cksum)
    probe 2 "$1: " "$@"
    [[ "$stderr" == *"is also the input"* ]] || fail "$*: $stderr"
    after=$(cat ./* 2>/dev/null | cksum)
    [ "$before" = "$after" ] || fail "$*: a file changed"
}

@test "every tool refuses an output that is one of its inputs (same file or same path)" {
    mkdir w && cd w  # bats keeps files of its own in the test's folder
    cp "$SEED/box_on_plane.shd" "$SEED/weather_30_Sep_95.wth" "$SEED/hawkeye.snd" .
    refused therm box_on_plane.shd weather_30_Sep_95.wth "$THERM/box_on_plane.mat" \
        "$SEED/box_on_plane.gdb" hawkeye.snd -o box_on_plane.shd
    refused therm box_on_plane.shd weather_30_Sep_95.wth "$THERM/box_on_plane.mat" \
        "$SEED/box_on_plane.gdb" hawkeye.snd -o ./sub/../weather_30_Sep_95.wth
    ln box_on_plane.shd hard.tmp
    refused therm box_on_plane.shd weather_30_Sep_95.wth "$THERM/box_on_plane.mat" \
        "$SEED/box_on_plane.gdb" hawkeye.snd -o hard.tmp
    ln -s hawkeye.snd link.tmp
    refused therm box_on_plane.shd weather_30_Sep_95.wth "$THERM/box_on_plane.mat" \
        "$SEED/box_on_plane.gdb" hawkeye.snd -o link.tmp
    cp "$TRACE/box.adv" box.img
    refused trace box.img "$TRACE/box.snd" "$SEED/box_on_plane.gdb" "$TRACE/box.mat" \
        "$TRACE/band1.rad" -o box.img
    cp "$TRACE/box.mat" box.hdr
    refused trace "$TRACE/box.adv" "$TRACE/box.snd" "$SEED/box_on_plane.gdb" box.hdr \
        "$TRACE/band1.rad" -o box.img
    refused trace --shadow-history hawkeye.snd "$SEED/box_on_plane.gdb" "$TRACE/box.mat" \
        -o hawkeye.snd
    cp "$HAWKEYE_CDK" deck-2.rad
    refused build_radiance "${QUICK[@]}" deck-2.rad "$RADDATA/small.snd" -o 'deck-%d.rad'
    cp "$CUBE/blue.sen" blue.tif
    refused sensorize "$CUBE/tiny.img" blue.tif -o blue.tif
    cp "$CUBE/blue.sen" blue.png
    refused sensorize "$CUBE/tiny.img" blue.png --preview blue.png -o c.tif
    refused find_min_max_view_angle "$TRACE/box.adv" hawkeye.snd -o hawkeye.snd
    refused sigchain-check --rewrite hawkeye.snd -o hawkeye.snd
    cp "$SIGCHAIN_SOURCE_DIR/tests/data/control7/hawkeye.answers" a.txt
    refused control7 --answers a.txt -o a.txt
    printf 'P5\n1 1\n255\n\001' >g.pgm
    refused compare --pixelwise g.pgm g.pgm --error-map g.pgm
    refused compare g.pgm g.pgm hawkeye.snd -o hawkeye.snd
    refused soho_scene hawkeye.snd -o hawkeye.snd
    refused olinda_scene preview g.pgm hawkeye.snd g.pgm
}

@test "landsat_scene: a write that fails with ENOSPC exits non-zero and leaves no output" {
    command -v strace > /dev/null || skip "no strace (scripts/install-deps installs it)"
    local pa="$SIGCHAIN_SOURCE_DIR/data/scenes/pennsylvania"
    printf '1 all\n' > all.classes
    run -0 landsat_scene classify all.classes - classes.tif "$pa/etm_20020720.tif"
    # Every write from the first on fails (the GeoTIFFs' data, then the error message):
    # before the class and terrain rasters checked GDAL's close, classify exited 0 with a
    # truncated GeoTIFF on a full disk.
    run strace -f -o /dev/null -e inject=write:error=ENOSPC:when=1+ \
        landsat_scene terrain "$pa/dem.tif" classes.tif .
    [ "$status" -ne 0 ] || fail "terrain exited 0 on a full disk"
    [ ! -e terrain.tif ] && [ ! -e landuse.tif ]
    run strace -f -o /dev/null -e inject=write:error=ENOSPC:when=1+ \
        landsat_scene points all.classes classes.tif - 5 1 5 p
    [ "$status" -ne 0 ] || fail "points exited 0 on a full disk"
    [ ! -e p_fit.cpt ] && [ ! -e p_held.cpt ]
    assert_no_temp_files .
}
