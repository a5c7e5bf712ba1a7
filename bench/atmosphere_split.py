"""The split table of bench/atmosphere_split.sh (docs/atmosphere.md).

Usage: atmosphere_split.py WORK LOWTRAN
WORK holds br0-N.rad, br1-N.rad and br32-N.rad (build_radiance with IMULT 0, IMULT 1 and
IMULT 1 at 32 streams, bands N = 1-4, one nadir view) and, unless LOWTRAN (a "skipped:
..." sentence) is not empty, lt0.tp7, lt1.tp7 and lt1.tp8 (LOWTRAN 7 with IMULT 0 and 1;
TAPE7 per cm-1, TAPE8 its fluxes, NOPRT -1). Prints per band the means over its samples
of the single-scattered (SS) and multiply scattered (MS = IMULT 1 - IMULT 0) nadir path
radiance, and in the gas bands the same at the most absorbing sample (lowest tau2);
radiances in 1e-4 W cm-2 sr-1 um-1 (TAPE7's per cm-1 times nu^2 / 1e4).
"""
import sys

BANDS = ("0.55", "0.72", "0.76", "0.82")
MU0 = 0.766043  # cos(40.0001 deg)


def rad(path):
    """{wavenumber: (Es, tau2, L_us)} of a .rad's first view (rad(5))."""
    rows = [l.split() for l in open(path) if l.strip() and not l.lstrip().startswith("#")]
    n = int(rows[6][0])
    samples = rows[12:12 + n]
    view = rows[12 + n + 1:12 + 2 * n + 1]
    return {round(float(s[1])): (float(s[2]), float(v[0]), float(v[2])) for s, v in zip(samples, view)}


def tape7(path):
    """{wavenumber: (TRANS, PATH, SINGLE)} per um, of an IEMSCT 2 TAPE7."""
    out = {}
    for line in open(path):
        f = line.split()
        if len(f) >= 8 and f[0].endswith(".") and f[0][:-1].isdigit():
            nu = float(f[0])
            k = nu * nu / 1e4
            out[round(nu)] = (float(f[1]), float(f[3]) * k, float(f[4]) * k)
    return out


def tape8(path, nu):
    """{altitude label: (UFLXS, DFLXS, DIRS)} at nu; the row labelled with the observer's
    altitude holds the values at the top of the atmosphere (TRANS's last WRITE)."""
    out = {}
    for line in open(path):
        f = line.split()
        if len(f) == 8 and f[0] == f"{nu}.":
            out[f[1]] = (float(f[3]), float(f[5]), float(f[6]))
    return out


def mean(values):
    values = list(values)
    return sum(values) / len(values)


def main():
    work, lowtran = sys.argv[1], sys.argv[2]
    have_lt = lowtran == ""
    if have_lt:
        l0, l1 = tape7(f"{work}/lt0.tp7"), tape7(f"{work}/lt1.tp7")
        worst = max(abs(l1[n][2] / l0[n][1] - 1) for n in l0 if l0[n][1] > 0)
    print("Nadir path radiance from 3 km, mid-latitude summer, rural 23 km, sun at 40 deg "
          "(1e-4 W cm-2 sr-1 um-1)")
    print()
    print("| band | SS build_radiance | SS LOWTRAN 7 | ratio | MS build_radiance | "
          "MS 32 / 16 streams | MS LOWTRAN 7 | ratio | total ratio |")
    print("|---|---|---|---|---|---|---|---|---|")
    for b, name in enumerate(BANDS, 1):
        r0, r1, r32 = (rad(f"{work}/{p}-{b}.rad") for p in ("br0", "br1", "br32"))
        nus = sorted(r1)
        strongest = min(nus, key=lambda n: r1[n][1])
        rows = [(f"{name} um ({nus[0]}-{nus[-1]} cm-1)", nus)]
        if b > 1:  # the gas bands: also their most absorbing sample
            rows.append((f"  {strongest} cm-1 (tau2 {r1[strongest][1]:.3f})", [strongest]))
        for label, keys in rows:
            ss = mean(r0[n][2] for n in keys)
            ms = mean(r1[n][2] - r0[n][2] for n in keys)
            ms32 = mean(r32[n][2] - r0[n][2] for n in keys)
            cells = [label, f"{ss * 1e4:.4f}"]
            if have_lt:
                lss = mean(l0[n][1] for n in keys)
                lms = mean(l1[n][1] - l0[n][1] for n in keys)
                cells += [f"{lss * 1e4:.4f}", f"{ss / lss:.3f}", f"{ms * 1e4:.4f}",
                          f"{ms32 / ms:.4f}", f"{lms * 1e4:.4f}", f"{ms / lms:.3f}",
                          f"{(ss + ms) / (lss + lms):.3f}"]
            else:
                cells += ["skipped", "-", f"{ms * 1e4:.4f}", f"{ms32 / ms:.4f}", "skipped", "-", "-"]
            print("| " + " | ".join(cells) + " |")
    print()
    if not have_lt:
        print(f"LOWTRAN 7: {lowtran}")
        return
    print(f"LOWTRAN 7's SINGLE column (IMULT 1) against its IMULT 0 PATH: within {worst:.2e}")
    f = tape8(f"{work}/lt1.tp8", 18180)
    if not f:
        print("LOWTRAN 7's TAPE8 lists no fluxes at 18180 cm-1")
        return
    es = f["3.00"][2]  # the top row's DIRS: the exoatmospheric irradiance (TX 1)
    print("LOWTRAN 7's two-stream diffuse fluxes at 18180 cm-1 per unit mu0 Es, level: up, down")
    for label, name in (("3.00", "top"), ("2.00", "2.00 km"), ("1.00", "1.00 km"), ("0.00", "0.00 km")):
        if label in f:
            print(f"  {name:>8} {f[label][0] / (MU0 * es):.5f} {f[label][1] / (MU0 * es):.5f}")


main()
