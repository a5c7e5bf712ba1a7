#!/usr/bin/env python3
"""water_case1.py: the water-leaving reflectance of Case 1 sea water (README.md, "No fit
at all"), written once into ../../spectra/water_case1_chl03.txt (python3 water_case1.py
0.3 > ../../spectra/water_case1_chl03.txt; no dependencies).

R(0-), the irradiance reflectance just below the surface, is Morel's (1988, J. Geophys.
Res. 93(C9), 10749-10768) Case 1 model as the 6S code implements it (Vermote et al. 1997,
IEEE Trans. Geosci. Remote Sens. 35(3), 675-686; subroutine MORCASIWAT of 6SV1.0B,
OCEATOOLS.f): Kd = Kw + Xc C^e, bb = bw/2 + (0.002 + 0.02 (0.5 - 0.25 log10 C) 0.55/wl)
0.30 C^0.62, R = 0.33 bb / (u Kd) with u = 0.90 (1 - R) / (1 + 2.25 R) solved by
iteration; Kw, Xc, e, bw tabulated every 5 nm from 400 to 700 nm (the tables below are
6S's). Outside 400-700 nm 6S sets R = 0 (pure water absorbs 2.5 m-1 at 750 nm, so R is
below 1e-4 there).
The Lambertian-equivalent reflectance above the surface, rho_w = pi Lw / Ed(0+), is
rho_w = t_d t_u R / (n^2 (1 - 0.485 R)) (Austin 1974, the 6S ocean model's form), with
n = 1.34 and t_d = t_u = 0.979, 1 minus the Fresnel reflectance at normal incidence."""
import math
import sys

KW = [0.0209, 0.0200, 0.0196, 0.0189, 0.0183, 0.0182, 0.0171, 0.0170, 0.0168, 0.0166,
      0.0168, 0.0170, 0.0173, 0.0174, 0.0175, 0.0184, 0.0194, 0.0203, 0.0217, 0.0240,
      0.0271, 0.0320, 0.0384, 0.0445, 0.0490, 0.0505, 0.0518, 0.0543, 0.0568, 0.0615,
      0.0640, 0.0640, 0.0717, 0.0762, 0.0807, 0.0940, 0.1070, 0.1280, 0.1570, 0.2000,
      0.2530, 0.2790, 0.2960, 0.3030, 0.3100, 0.3150, 0.3200, 0.3250, 0.3300, 0.3400,
      0.3500, 0.3700, 0.4050, 0.4180, 0.4300, 0.4400, 0.4500, 0.4700, 0.5000, 0.5500,
      0.6500]
XC = [0.1100, 0.1110, 0.1125, 0.1135, 0.1126, 0.1104, 0.1078, 0.1065, 0.1041, 0.0996,
      0.0971, 0.0939, 0.0896, 0.0859, 0.0823, 0.0788, 0.0746, 0.0726, 0.0690, 0.0660,
      0.0636, 0.0600, 0.0578, 0.0540, 0.0498, 0.0475, 0.0467, 0.0450, 0.0440, 0.0426,
      0.0410, 0.0400, 0.0390, 0.0375, 0.0360, 0.0340, 0.0330, 0.0328, 0.0325, 0.0330,
      0.0340, 0.0350, 0.0360, 0.0375, 0.0385, 0.0400, 0.0420, 0.0430, 0.0440, 0.0445,
      0.0450, 0.0460, 0.0475, 0.0490, 0.0515, 0.0520, 0.0505, 0.0440, 0.0390, 0.0340,
      0.0300]
E = [0.668, 0.672, 0.680, 0.687, 0.693, 0.701, 0.707, 0.708, 0.707, 0.704,
     0.701, 0.699, 0.700, 0.703, 0.703, 0.703, 0.703, 0.704, 0.702, 0.700,
     0.700, 0.695, 0.690, 0.685, 0.680, 0.675, 0.670, 0.665, 0.660, 0.655,
     0.650, 0.645, 0.640, 0.630, 0.623, 0.615, 0.610, 0.614, 0.618, 0.622,
     0.626, 0.630, 0.634, 0.638, 0.642, 0.647, 0.653, 0.658, 0.663, 0.667,
     0.672, 0.677, 0.682, 0.687, 0.695, 0.697, 0.693, 0.665, 0.640, 0.620,
     0.600]
BW = [0.0076, 0.0072, 0.0068, 0.0064, 0.0061, 0.0058, 0.0055, 0.0052, 0.0049, 0.0047,
      0.0045, 0.0043, 0.0041, 0.0039, 0.0037, 0.0036, 0.0034, 0.0033, 0.0031, 0.0030,
      0.0029, 0.0027, 0.0026, 0.0025, 0.0024, 0.0023, 0.0022, 0.0022, 0.0021, 0.0020,
      0.0019, 0.0018, 0.0018, 0.0017, 0.0017, 0.0016, 0.0016, 0.0015, 0.0015, 0.0014,
      0.0014, 0.0013, 0.0013, 0.0012, 0.0012, 0.0011, 0.0011, 0.0010, 0.0010, 0.0010,
      0.0010, 0.0009, 0.0008, 0.0008, 0.0008, 0.0007, 0.0007, 0.0007, 0.0007, 0.0007,
      0.0007]
N_WATER = 1.34
T_FRESNEL = 1.0 - ((N_WATER - 1.0) / (N_WATER + 1.0)) ** 2


HEADER = """\
# Case 1 sea water, chlorophyll {chl} mg m-3: water-leaving reflectance above the surface
#   (Lambertian equivalent, pi Lw / Ed(0+)), without the surface's own (Fresnel) reflection.
# Source: computed by data/scenes/olinda/water_case1.py (python3 water_case1.py {chl}) from
#   published coefficients: Morel, A. (1988). Optical modeling of the upper ocean in relation
#   to its biogenous matter content (Case I waters). J. Geophys. Res. 93(C9), 10749-10768
#   (Kw, Xc, e, bw every 5 nm, 400-700 nm, as tabulated in the 6S code: Vermote, E. F.,
#   Tanre, D., Deuze, J. L., Herman, M., Morcrette, J.-J. (1997). Second Simulation of the
#   Satellite Signal in the Solar Spectrum, 6S: an overview. IEEE Trans. Geosci. Remote Sens.
#   35(3), 675-686; subroutine MORCASIWAT of 6SV1.0B, OCEATOOLS.f), and the transfer through
#   the surface of Austin, R. W. (1974), in Optical Aspects of Oceanography, Academic Press,
#   317-344: rho_w = t^2 R / (n^2 (1 - 0.485 R)), n = 1.34, t = 0.979.
# Terms: the coefficients are published scientific data; the numbers here are sigchain's
#   computation from them.
# Processing: R(0-) iterated as 6S does; 0 beyond 700 nm as in 6S (pure water absorbs
#   2.5 m-1 at 750 nm: R < 1e-4); a row at 2.5 um holds the 0 to the end of ETM+ band 7.
# Range: 0.400-2.500 um, 63 points
# wavelength_um reflectance
"""


def r_below(i, chl):
    """Irradiance reflectance R(0-) at 400 + 5 i nm for chlorophyll chl (mg m-3)."""
    wl = 0.400 + 0.005 * i
    bbt = 0.002 + 0.02 * (0.5 - 0.25 * math.log10(chl)) * 0.550 / wl
    bb = 0.5 * BW[i] + bbt * 0.30 * chl ** 0.62
    kd = KW[i] + XC[i] * chl ** E[i]
    r = 0.33 * bb / 0.75 / kd
    while True:
        u = 0.90 * (1.0 - r) / (1.0 + 2.25 * r)
        r_new = 0.33 * bb / u / kd
        if abs(r_new - r) < 1e-4 * r_new:
            return r_new
        r = r_new


def rho_above(r):
    """Lambertian-equivalent water-leaving reflectance above the surface."""
    return T_FRESNEL * T_FRESNEL * r / (N_WATER ** 2 * (1.0 - 0.485 * r))


def main():
    chl = float(sys.argv[1])
    print(HEADER.format(chl=chl), end="")

    rows = [(0.400 + 0.005 * i, rho_above(r_below(i, chl))) for i in range(61)]
    rows += [(0.705, 0.0), (2.500, 0.0)]
    for wl, rho in rows:
        print(f"{wl:.3f} {rho:.6f}")


if __name__ == "__main__":
    main()
