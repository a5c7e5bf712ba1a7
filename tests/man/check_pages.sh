#!/bin/sh
# Checks the man pages: each scdoc source builds without error; every tool has a
# section-1 page and every file format a section-5 page; every section-5 page has
# NAME, DESCRIPTION, LAYOUT, EXAMPLE and SEE ALSO sections, and its EXAMPLE (the
# first literal block after "# EXAMPLE") parses with sigchain-check.
set -u
src="$1"
bin="$2"
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for page in "$src"/man/*.scd; do
    if ! scdoc < "$page" > "$tmp/out" 2> "$tmp/err"; then
        echo "FAIL: scdoc: $page: $(cat "$tmp/err")"
        fail=1
    fi
done
for tool in control7 build_radiance therm find_min_max_view_angle trace sensorize compare \
            hawkeye_scene olinda_scene soho_scene merge_tiles landsat_scene \
            sigchain-check landsat_sensor sigchain-config sigchain-atmosphere; do
    [ -f "$src/man/$tool.1.scd" ] || { echo "FAIL: no man page for tool $tool"; fail=1; }
done
for fmt in adv snd rsd cdk wth rad mat ems sen ext gdb odb shd tmp cpt brdf t7m trj unc mtl rsr; do
    page="$src/man/$fmt.5.scd"
    if [ ! -f "$page" ]; then
        echo "FAIL: no man page for format .$fmt"
        fail=1
        continue
    fi
    for section in NAME DESCRIPTION LAYOUT EXAMPLE "SEE ALSO"; do
        grep -q "^# $section" "$page" || { echo "FAIL: $page: no '# $section' section"; fail=1; }
    done
    # The first ``` block after "# EXAMPLE" is the example file.
    awk '/^# EXAMPLE/{e=1; next} e && /^```/{ if (inb) exit; inb=1; next } inb{print}' \
        "$page" > "$tmp/example.$fmt"
    if [ ! -s "$tmp/example.$fmt" ]; then
        echo "FAIL: $page: EXAMPLE has no \`\`\` block"
        fail=1
    elif ! (cd "$tmp" && "$bin/sigchain-check" -q "example.$fmt" > /dev/null 2> "$tmp/err"); then
        echo "FAIL: $page: EXAMPLE does not parse: $(cat "$tmp/err")"
        fail=1
    fi
done
[ $fail -eq 0 ] && echo "man pages ok"
exit $fail
