// LOWTRAN 7's Mie aerosol phase functions (CARD 3A1 IPH 2; subroutine PHASEF): 70
// functions tabulated at 34 scattering angles, chosen by aerosol model, wavelength and
// humidity (data/atmosphere/lowtran7/aerosol_phase_functions_mie.txt and
// aerosol_phase_function_index.txt, whose headers state the rules followed here), and
// their Legendre moments for the discrete-ordinate solver. Angles in degrees,
// wavelengths in um, phase functions in sr-1 (integral over 4 pi sr = 1).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sigchain::atmos {

// A phase function tabulated at ascending angles from 0 to 180 deg; between two nodes
// ln P is linear in angle (linear in P where a value is <= 0), as PHASEF interpolates.
struct TabulatedPhase {
    std::vector<double> angle_deg;
    std::vector<double> p_sr1;
    double at(double angle_deg) const;
    // at() at the angles start + j step (deg, clamped to the table), j from `from` to
    // `to` - 1, into out[j - from]. Within a table interval (ln P linear in angle) the
    // first value is an exp and each next one the last times exp(slope x step): one
    // logarithm per node and two exps per interval instead of a search and a pow per
    // value. Each product adds a rounding (~1 ulp a step), so the values are at() to
    // within 1e-14 relative over 100 steps an interval (mie_phase_test).
    void at_steps(double start_deg, double step_deg, std::size_t from, std::size_t to,
                  double* out) const;
};

// The solver's grid of a phase function's values (mie_layers.hpp's MieOptics): 0.1 deg
// steps to 20 deg, where the forward peak is steep, 0.5 deg beyond; 521 angles.
namespace phase_grid {
inline constexpr std::size_t kSize = 200 + 320 + 1;
double angle_deg(std::size_t i);
double position(double angle_deg);  // fractional index
// 4 pi P / integral at every grid angle into out[0 .. kSize) (TabulatedPhase::at_steps).
void normalized(const TabulatedPhase& p, double integral, double* out);
}  // namespace phase_grid

// Legendre moments chi_0..chi_nmom of `p` in DISORT's convention,
// P(cos t) / (integral over 4 pi) = sum (2k+1) chi_k P_k(cos t) / (4 pi), chi_0 = 1:
// chi_k = 2 pi int P P_k(cos t) sin t dt / (2 pi int P sin t dt), each interval between
// nodes integrated by a 64-point Gauss rule in angle. Between nodes ln P is linear in
// angle, except in the two intervals touching the poles, where ln P is quadratic in the
// distance from the pole and flat there: a phase function is smooth on the sphere, and
// a kink at a pole (a cusp) would make the series converge only as N^-2. Dividing by
// the integral renormalises the table (its coarse grid sums to 0.94-2.35; the data
// file's header). Also returns that integral (2 pi int P sin t dt) in `integral`.
// Measured against the table outside a 16-deg cone (after truncate_forward_peak): 512
// moments reproduce 65 of the 70 functions within 1 %, the other five within 2.8 %.
// gauss_points: the rule's points per interval; 64 serves 512 moments, 16 is as exact
// (1e-12, mie_phase_test) up to 64 moments at a quarter of the cost, 8 within 2e-7 up
// to 32 (the integral within 1e-6 of itself) at half the cost of 16.
std::vector<double> phase_moments(const TabulatedPhase& p, int nmom, double* integral = nullptr,
                                  int gauss_points = 64);

// The phase function with its forward peak cut off (Potter 1970, J. Atmos. Sci. 27,
// 943): inside the cone t < cone_deg (a tabulated angle) ln P continues the slope of the
// first interval beyond the cone, so the function is smooth and its Legendre series
// short; the part cut off, a fraction `forward` of the total (as a delta function in the
// forward direction, which the solver treats as unscattered), is returned. With
// normalise, P is divided by its integral first (the table's grid does not integrate
// to 1). The moments of the whole are chi_k = forward + (1 - forward) chi*_k, chi* the
// moments of the truncated function (phase_moments of the result).
TabulatedPhase truncate_forward_peak(const TabulatedPhase& p, double cone_deg, double& forward);

// sum_k (2k+1) chi_k P_k(cos t) / (4 pi): the phase function (sr-1) the moments represent.
double phase_from_moments(const std::vector<double>& chi, double angle_deg);

class MiePhaseTable {
public:
    // Reads both files from DATA_DIR/atmosphere/lowtran7/. Throws DataError / IoError.
    static MiePhaseTable load(const std::string& data_dir);

    // Phase function `number` (1-70) as tabulated.
    TabulatedPhase function(int number) const;

    // Aerosol model `model` (1-26, the index table's rows) at a wavelength: ln P linear
    // in wavelength between the two bracketing index wavelengths (PHASEF), clamped to
    // the index's 0.2-40 um.
    TabulatedPhase model(int model, double wavelength_um) const;

    // The phase function of one of the aerosol's four regions (0 boundary layer, 1
    // troposphere, 2 stratosphere, 3 upper atmosphere; AerosolModel's) for the deck's
    // IHAZE and IVULCN and the boundary layer's RH (percent), at a wavelength, as PHASEF
    // selects it: boundary layer IHAZE 1-2 rural (models 1-4), 3-4 maritime (5-8), 5
    // urban (9-12), 6 tropospheric (17-20), linear in RH between the bracketing models
    // (RH 0, 70, 80, 99 %); IHAZE 8 model 24, 9 model 25; troposphere model 18;
    // stratosphere 21 (IVULCN 0, 1, 6, 7), 22 (2, 4) or 23 (3, 5, 8); upper atmosphere
    // 26. No value (Henyey-Greenstein with the model's g, as LOWTRAN 7 does) for the
    // desert model (IHAZE 10) and above 40 um.
    std::optional<TabulatedPhase> region(int region, int ihaze, int ivulcn, double rh_percent,
                                         double wavelength_um) const;
    // Whether region() gives a function (without building it).
    bool has_region(int region, int ihaze, double wavelength_um) const;
    // The index wavelengths (um) whose functions model() and region() interpolate
    // between at this wavelength: within them each is a smooth function of the
    // wavelength (ln P linear in it, as PHASEF interpolates); clamped at the ends.
    std::pair<double, double> wavelength_interval(double wavelength_um) const;

private:
    std::vector<double> m_angles;                  // 34
    std::vector<std::vector<double>> m_functions;  // [number - 1][angle]
    std::vector<double> m_wavelengths;             // 27
    std::vector<std::vector<int>> m_index;         // [model - 1][wavelength]
};

}  // namespace sigchain::atmos
