#!/usr/bin/env bats
# Tests: --help of every tool
load test_helper

# The option parser wraps each description in its own column: a continuation line starts
# where the description of its option starts (a description carrying its own line
# breaks and padding would land elsewhere).
@test "every tool's --help: option descriptions continue in their own column" {
    for t in build_radiance compare control7 find_min_max_view_angle hawkeye_scene \
        landsat_scene landsat_sensor merge_tiles olinda_scene sensorize sigchain-check soho_scene therm trace; do
        run -0 "$t" --help
        bad=$(awk '
            /^Options:/ { on = 1; next }
            on && /^  -/ {
                # the description starts after the option and its value, at 2+ spaces
                if (match($0, /^  -[^ ].*[^ ]  +[^ ]/)) col = RLENGTH - 1; else col = -1
                next
            }
            on && /^ +[^ ]/ && col >= 0 {
                match($0, /^ +/)
                if (RLENGTH != col) print
            }' <<< "$output")
        [ -z "$bad" ] || fail "$t --help: misaligned lines:"$'\n'"$bad"
    done
}
