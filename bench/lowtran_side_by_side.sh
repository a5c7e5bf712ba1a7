#!/bin/sh
# bench/lowtran_side_by_side.sh BUILD [LOWTRAN7_F]: build_radiance for one line of sight
# against LOWTRAN 7 on the same deck and the same machine, alternating, as a ratio, and
# each one's path radiance against 32 streams.
#
# The deck: the Hawkeye deck of White (1996), section 4.2.3 (tests/golden/control7/
# hawkeye.cdk: MODEL 7 radiosonde, rural aerosols at 23 km, IEMSCT 2 with multiple
# scattering, 14285 to 25000 cm-1 in 25 cm-1 steps), its CARD 3 changed to the scene's
# line of sight: from the sensor at 1.000 km straight down to the ground at 0.218 km.
# LOWTRAN 7 runs it as a whole process (430 wavenumbers, its two-stream multiple
# scattering). build_radiance runs the same deck with tests/data/white1996/hawkeye.snd
# cut to the nadir view (`0 0 1`), one sky cell and one upwelled cell, --streams auto,
# --threads 1, as a whole process (start-up, tables and files included; 123 samples in
# three bands, IPH 2 Mie phase functions, the coupling terms).
#
# LOWTRAN 7 is not part of sigchain and is not fetched: LOWTRAN7_F (or $LOWTRAN7_F) names
# a LOWTRAN 7 Fortran source, either AFGL's program (its main program reads TAPE5) or
# the subroutine LWTRN7 of github.com/space-physics/lowtran's src/lowtran/fortran/
# lowtran7.f, which this script drives with a six-line main program that sets its Python
# flag false (it then reads TAPE5 and writes out/TAPE6, out/TAPE7 and out/TAPE8). Its
# TAPE7 must list one line per wavenumber, the wavenumber first ("14285." ...).
# It is compiled with gfortran -O2. Without a source, gfortran or python3 the script
# prints "skipped: ..." and exits 0.
#
# Accuracy ("at equal or better accuracy against 32 streams"): build_radiance also runs
# the line of sight once with 32 streams, and each program's nadir path radiance (L_us;
# LOWTRAN 7's PATH per um, times nu^2 / 1e4, linear in wavenumber between its lines) is
# compared with it sample by sample. The same atmosphere: LOWTRAN 7's ground-to-sensor
# transmission is printed against build_radiance's too.
#
# Prints for each program (LOWTRAN 7; build_radiance --streams auto at its default 1 %
# and at TOLERANCE, default 0.05; all on one thread) the median and the best wall time
# of RUNS runs (default 20), the three run in turn, and the worst and median error of
# its path radiance against 32 streams; then the ratios to LOWTRAN 7 of the medians and
# of the bests (the machine is shared: a ratio of runs made side by side holds where a
# time alone does not), and whether build_radiance at TOLERANCE is as accurate as
# LOWTRAN 7 or more: its worst and its median error both at most LOWTRAN 7's
# (bench/lowtran_side_by_side.py; sample by sample would ask more than LOWTRAN 7
# itself gives where its error crosses zero, so that count is printed beside). WORK
# (default BUILD/lowtran_side_by_side) keeps the work files. Needs python3 too.
set -eu
build="${1:?usage: bench/lowtran_side_by_side.sh BUILD [LOWTRAN7_F]}"
source_f="${2:-${LOWTRAN7_F:-}}"
runs="${RUNS:-20}"
tolerance="${TOLERANCE:-0.05}"
src="$(cd "$(dirname "$0")/.." && pwd)"
work="${WORK:-$build/lowtran_side_by_side}"

if [ -z "$source_f" ] || [ ! -r "$source_f" ]; then
    echo "skipped: no LOWTRAN 7 source (give LOWTRAN7_F)"
    exit 0
fi
if ! command -v gfortran >/dev/null 2>&1; then
    echo "skipped: gfortran not found"
    exit 0
fi
if ! command -v python3 >/dev/null 2>&1; then
    echo "skipped: python3 not found"
    exit 0
fi
br="$(cd "$build" && pwd)/bin/build_radiance"
[ -x "$br" ] || { echo "lowtran_side_by_side: $br: not built" >&2; exit 2; }

mkdir -p "$work/lowtran/out" "$work/sigchain"
work="$(cd "$work" && pwd)"
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
    tape7=out/TAPE7
else
    gfortran -O2 -std=legacy -w -o "$lt/lowtran7" "$source_f"
    tape7=TAPE7
fi
: > "$lt/out/TAPE6"; : > "$lt/out/TAPE7"; : > "$lt/out/TAPE8"
# CARD 3: H1 1.000 km, H2 0.218 km (the ground), ANGLE 180 deg (nadir). CARD 3A2's TIME:
# 19 h, the Greenwich time LOWTRAN 7 reads there (the deck holds the scene's local 14 h,
# as DIRSIG's decks did; build_radiance takes the sun from the .snd, 19 h GMT), so that
# both put the sun at the same place (53.2 deg from the zenith).
sed -e 's/^     0.237     0.218   109.290/     1.000     0.218   180.000/' \
    -e 's/^\(    43.083    77.667     0.000     0.000\)    14.000/\1    19.000/' \
    "$src/tests/golden/control7/hawkeye.cdk" > "$lt/TAPE5"
grep -q '^     1.000     0.218   180.000' "$lt/TAPE5" &&
    grep -q '^    43.083    77.667     0.000     0.000    19.000' "$lt/TAPE5" ||
    { echo "lowtran_side_by_side: hawkeye.cdk's CARD 3 or 3A2 has changed" >&2; exit 1; }
sed 's/^-77.0 78.0 1.0\(.*\)/0 0 1\1/' "$src/tests/data/white1996/hawkeye.snd" \
    > "$work/sigchain/nadir.snd"
grep -q '^0 0 1' "$work/sigchain/nadir.snd" ||
    { echo "lowtran_side_by_side: hawkeye.snd's view line has changed" >&2; exit 1; }

run_lowtran() { (cd "$lt" && ./lowtran7 < /dev/null > /dev/null 2>&1 && [ -s "$tape7" ]); }
# run_sigchain NAME [OPTION...]: the line of sight into $work/sigchain/NAME-%d.rad.
run_sigchain() {
    name="$1"
    shift
    "$br" --sky-zenith-step 90 --sky-azimuth-step 360 --sky-subsamples 1 \
        --upwelled-azimuth-step 360 -q "$@" "$lt/TAPE5" "$work/sigchain/nadir.snd" \
        -o "$work/sigchain/$name-%d.rad"
}
run_default() { run_sigchain default --threads 1 --streams auto; }
run_loose() { run_sigchain loose --threads 1 --streams auto --stream-tolerance "$tolerance"; }
now_us() { echo $(($(date +%s%N) / 1000)); }
rm -f "$lt/TAPE7"
run_lowtran || { echo "lowtran_side_by_side: LOWTRAN 7 wrote no $lt/$tape7" >&2; exit 1; }
run_sigchain ref --streams 32  # the reference, on every core

: > "$work/times"
i=0
while [ "$i" -lt "$runs" ]; do
    for prog in lowtran default loose; do
        t0=$(now_us)
        "run_$prog"
        t1=$(now_us)
        echo "$prog $((t1 - t0))" >> "$work/times"
    done
    i=$((i + 1))
done
python3 "$src/bench/lowtran_side_by_side.py" "$work" "$lt/$tape7" "$runs" "$tolerance"
