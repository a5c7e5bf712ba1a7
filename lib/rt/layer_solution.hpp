// Per-layer, per-Fourier-mode solution of the discrete-ordinate equations: the
// homogeneous solution's eigenvalues and eigenvectors and the particular solutions for
// the beam and for thermal emission (Stamnes et al. 1988, Appl. Opt. 27, 2502, sec. II).
// Internal to lib/rt.
#pragma once

#include <vector>

namespace sigchain::rt::detail {

// The quadrature: nn Gauss points on (0, 1); direction a < nn is +mu[a] (upward),
// a >= nn is -mu[a - nn] (downward).
struct Quadrature {
    int nn = 0;
    std::vector<double> mu, weight;
};

// Optical properties of a (delta-M scaled) layer.
struct LayerOptics {
    double dtau = 0;                          // scaled optical thickness
    double ssa = 0;                           // scaled single-scattering albedo (dithered below 1)
    std::vector<double> g;                    // scaled Legendre moments g[0..N-1]
    double beam_top = 0;                      // beam_flux * exp(-scaled tau at the layer top / mu0)
    double planck_top = 0, planck_slope = 0;  // B(t) = planck_top + planck_slope * t
};

// Solution of one layer for one mode m. Homogeneous solution j (j < nn):
//   decaying  e^{-k_j t}:         value at direction a = dec(j, a)
//   growing   e^{-k_j (dtau - t)}: value at direction a = grow(j, a)
// (t = scaled depth below the layer top). Particular solution at direction a:
//   beam[a] e^{-t * inv_mu0} + thermal0[a] + planck_slope * t.
// Moment vectors give the source function at any direction mu through
//   sum_l Lambda_l^m(mu) moment[l]   (Stamnes et al. 1988, eq. 11 for user angles).
struct LayerSolution {
    int nn = 0, nl = 0;            // nl = number of moments (l = 0 .. nl-1)
    std::vector<double> k;         // eigenvalues, > 0
    std::vector<double> exp_k;     // e^{-k dtau}
    std::vector<double> gp, gm;    // gp[j * nn + i] = G+ at +mu_i, gm = G- at -mu_i
    std::vector<double> beam;      // beam particular solution at the top of the layer, N values
    std::vector<double> thermal0;  // thermal particular solution constant part, N values
    double inv_mu0 = 0;            // 1/mu0 used by the beam particular solution
    double exp_beam = 0;           // e^{-dtau inv_mu0}
    std::vector<double> hmom;      // hmom[l * nn + j]: scattering moments of solution j (decaying)
    std::vector<double> bmom;      // beam source moments (scattered particular + primary)
    std::vector<double> tmom;      // thermal scattered moments of thermal0

    double dec(int j, int a) const { return a < nn ? gp[j * nn + a] : gm[j * nn + a - nn]; }
    double grow(int j, int a) const { return a < nn ? gm[j * nn + a] : gp[j * nn + a - nn]; }
};

// Scratch space reused across layers and modes.
struct Scratch {
    std::vector<double> a, b, c, v, lam, ev, s, mat, rhs, work;
    std::vector<double> pb, pk, pq, fold;
    std::vector<int> piv, piv2;
};

// Normalised Legendre functions at the quadrature for mode m: lam[l * N + a], l < nl.
void quadrature_legendre(const Quadrature& q, int m, int nl, std::vector<double>& lam);

// Solves layer `optics` for mode m: eigen-solution, beam particular solution (when
// beam_top > 0; mu0 = beam cosine, lam0[l] = Lambda_l^m(-mu0)) and, for m = 0 with
// thermal, the thermal particular solution. lam from quadrature_legendre.
void solve_layer(const Quadrature& q, int m, const LayerOptics& optics, const double* lam,
                 double mu0, const double* lam0, bool thermal, LayerSolution& out,
                 Scratch& scratch);

}  // namespace sigchain::rt::detail
