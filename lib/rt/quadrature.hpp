// Gauss-Legendre quadrature and normalised associated Legendre functions for the
// discrete-ordinate solver.
#pragma once

#include <vector>

namespace sigchain::rt {

// n-point Gauss-Legendre rule on [0, 1] (half of DISORT's double-Gauss rule):
// nodes ascending in mu, weights summing to 1.
void gauss_half_range(int n, std::vector<double>& mu, std::vector<double>& weight);

// Normalised associated Legendre functions Lambda_l^m(mu) = sqrt((l-m)!/(l+m)!) P_l^m(mu)
// for l = m .. lmax (Stamnes et al. 1988, eq. 5; recurrence of DISORT's LEPOLY derived
// from the standard P_l^m recurrence). out[l] for l < m is set to 0.
void normalized_legendre(int m, int lmax, double mu, double* out);

}  // namespace sigchain::rt
