// The discrete-ordinate solver's internal state and steps, shared by
// discrete_ordinates.cpp (layers, boundary problem, fluxes) and user_angles.cpp
// (intensities at user angles, intensity correction). Internal to lib/rt.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "rt/discrete_ordinates.hpp"
#include "rt/layer_solution.hpp"
#include "rt/linalg.hpp"

namespace sigchain::rt::detail {

constexpr double kPi = std::numbers::pi;

// Delta-M scaling (Wiscombe 1977, J. Atmos. Sci. 34, 1408, eqs. 13-15): f = pmom[N],
// tau* = (1 - omega f) tau, omega* = omega (1 - f)/(1 - omega f), g*_l = (g_l - f)/(1 - f).
struct Scaled {
    std::vector<LayerOptics> optics;
    std::vector<double> f;            // truncation fraction per layer
    std::vector<double> tau_level;    // unscaled optical depth of each level
    std::vector<double> tau_s_level;  // scaled optical depth of each level
};

// Where each output depth lies: layer index (the upper one at an interface) and the
// scaled depth below that layer's top.
struct Position {
    int layer = 0;
    double t = 0;  // scaled depth below the layer top
    bool up = true, down = true;  // intensities wanted here (Problem::want)
    bool wants(double mu) const { return mu > 0 ? up : down; }
};

// Stable integral int_0^L exp(base + c s) ds, for base <= 0 and base + c L <= 0
// (both ends bounded by 1); a series near c L = 0 covers the resonances of user angles
// with eigenvalues or the beam.
inline double exp_integral(double base, double c, double len) {
    const double z = c * len;
    if (std::abs(z) < 1e-3) return std::exp(base) * len * (1 + z * (0.5 + z * (1.0 / 6 + z / 24)));
    if (c > 0) return std::exp(base + z) * -std::expm1(-z) / c;
    return std::exp(base) * -std::expm1(z) / -c;
}

// Integral of exp(-a s - b (L - s)) over [0, L] = (e_a - e_b) / (b - a), from the
// precomputed ends e_a = exp(-a L), e_b = exp(-b L); a series when a L and b L nearly
// coincide (resonance of a user angle with an eigenvalue or the beam).
inline double two_exp(double ea, double eb, double a, double b, double len) {
    const double d = (b - a) * len;
    if (std::abs(d) < 1e-3) return ea * len * (1 - d * (0.5 - d * (1.0 / 6 - d / 24)));
    return (ea - eb) / (b - a);
}

// Source function of one layer at one user direction mu for one mode:
//   J(t) = sum_j C+_j hd_j e^{-k_j t} + C-_j hg_j e^{-k_j (dtau - t)} + hb e^{-t/mu0'}
//          + a0 + a1 t.
struct UserSource {
    std::vector<double> hd, hg;
    double hb = 0, a0 = 0, a1 = 0;
};

// One solve() call: setup() scales the layers and locates the output depths; then for
// each Fourier mode m, solve_mode() solves every layer and the boundary-value problem,
// fluxes() (m = 0) and user_intensities() evaluate it, and run() sums the modes with
// cos(m (phi - phi0)) until they converge; intensity_correction() closes. One instance
// per call; what it keeps for the next call (the last mode 0, its storage) is the
// calling thread's own (discrete_ordinates.cpp: ModeZero, Spare), so threads may solve
// at once.
class Solver {
public:
    explicit Solver(const Problem& p) : m_p(p) {}
    Result run();

private:
    void setup();
    void solve_mode(int m);
    void fluxes();
    void user_intensities(int m, std::vector<double>& im);
    bool interior(const Position& ps) const;  // strictly inside its layer (not at a level)
    void user_source(int n, int m, const double* lam_mu, UserSource& up, UserSource& down) const;
    double segment(int n, double mu, const UserSource& us, double ta, double tb) const;
    void full_layer_pair(int n, int m, const double* lam_mu, double amu, double et, double& up,
                         double& down) const;
    double quad_intensity(int n, int a, double t) const;
    double bottom_intensity(int m) const;
    std::vector<std::size_t> prepare_user_cosines(int m);
    void sweep_up(std::size_t u, std::size_t k, double bottom, std::vector<double>& im);
    void sweep_down(std::size_t d, std::size_t k, double top, std::vector<double>& im);
    void intensity_correction();
    struct CorrectionScratch {  // per-azimuth Legendre recursion and its sums
        std::vector<double> cs, p0, p1, corr, rec_a, rec_b;
        std::vector<double> cos_dphi;  // cos(phi - phi0) per azimuth (exact_phase, IMS)
    };
    std::vector<double> moment_differences(std::size_t nmom) const;
    void beam_path_integrals(std::size_t u, const Position& ps, std::vector<double>& tn) const;
    void add_correction(std::size_t u, const std::vector<double>& e, std::size_t nmom,
                        CorrectionScratch& w);
    std::vector<double> exact_weights() const;
    std::vector<double> cos_dphi() const;
    void add_exact_correction(std::size_t u, const std::vector<double>& e, CorrectionScratch& w);
    void add_mean_correction(std::size_t u, const std::vector<double>& e, std::size_t nmom,
                             const std::vector<double>& ex, const std::vector<double>& p0);
    void secondary_correction();

    const Problem& m_p;
    int m_N = 0, m_L = 0;
    Quadrature m_q;
    Scaled m_s;
    std::vector<Position> m_pos;
    std::vector<LayerSolution> m_sol;
    detail::Scratch m_scratch;
    linalg::BandMatrix m_band;
    std::vector<double> m_x;  // boundary-value solution of the current mode
    std::vector<double> m_mode_zero_key;  // what mode 0's system depends on (ModeZero)
    std::vector<double> m_lam, m_lam0;
    std::vector<UserSource> m_us, m_us_down;  // per layer, for +|mu| and -|mu|
    std::vector<std::ptrdiff_t> m_mirror;     // index of -umu[u] in umu, or -1
    std::vector<double> m_level_int;
    std::vector<double> m_lam_user;              // Lambda_l^m(|umu|) of the computed cosines
    std::vector<double> m_full_up, m_full_down;  // full-layer integrals, [cosine * L + layer]
    std::vector<double> m_beam_mu0;  // per layer: the beam's decay cosine (1 / air mass)
    std::vector<double> m_slant_s;   // per level: the beam's scaled slant optical depth
    std::vector<double> m_trans;     // m_trans[n * umu.size() + u] = exp(-dtau_n / |umu_u|)
    Result m_result;
    bool m_thermal = false;
};

}  // namespace sigchain::rt::detail
