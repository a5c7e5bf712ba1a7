// Exponential sums (k-distributions) for LOWTRAN 7's band model, so a scattering solver
// that needs Beer's law can carry band-model absorption: T(x) = exp(-x^a) is written as
// T(x) ~ sum_i w_i exp(-k_i x), w_i >= 0, sum w_i = 1, with x = C W the band's scaled
// amount times 10^C' (gas_absorption.hpp). Because exp(-x^a) is completely monotone for
// 0 < a <= 1 it is an exact mixture of exponentials (a Laplace transform), which a few
// terms approximate over a finite range of x. LOWTRAN 7 itself uses a k-distribution in
// its multiple-scattering source (Isaacs et al. 1987; Kneizys et al. 1988, section 3),
// as SBDART and libRadtran's LOWTRAN parameterisation do with 3-term sums.
//
// The fit: the k_i are spaced evenly in log k over [x_hi'^(a-1) / 2.5, 2.5 / x_lo'],
// where [x_lo', x_hi'] is the requested range clipped to where the band model is neither
// within tol / 10 of 1 nor within tol / 10 of 0 (outside it any monotone sum within
// 0.9 tol at the clip points stays within tol: both functions are monotone); the weights
// solve a non-negative least-squares problem (Lawson & Hanson 1974, ch. 23) on 64 points
// spaced evenly in log x, with sum w_i = 1 enforced as a heavily weighted row (where
// x_lo itself cuts into the band model's drop, one more, opaque, term holds the weight
// lost before x_lo). The term count grows until the largest error on the points is
// within 0.9 tol. Measured: 0.005 over the column amounts of the US standard
// atmosphere takes up to 13 terms (gas_absorption_test).
//
// Why hand-written: the non-negative least squares is ~60 lines on problems of at most
// 64 unknowns; no Debian library in the dependency set offers it (Eigen's NNLS is in
// its unsupported tree and Eigen is not a dependency).
//
// Dimensionless throughout: the caller multiplies k_i by 10^C' to get a coefficient per
// unit of scaled amount.
#pragma once

#include <vector>

namespace sigchain::atmos {

struct ExpSum {
    std::vector<double> weight;         // w_i >= 0, summing to 1
    std::vector<double> k;              // k_i > 0 per unit x, ascending
    double max_error = 0;               // largest |sum - exp(-x^a)| on the fit's points
    double operator()(double x) const;  // the sum at x >= 0
};

// The fewest terms (1 to max_terms) reproducing exp(-x^a) (0 < a <= 1) on
// [x_lo, x_hi] (0 <= x_lo < x_hi) within tol (absolute, in transmittance); when
// max_terms are not enough, the max_terms fit (its max_error says by how much). One
// term with k = 0 when the band model stays within tol of 1 over the range.
ExpSum fit_band_model(double a, double x_lo, double x_hi, double tol, int max_terms);

// The fit with exactly `terms` candidate k_i (some weights may come out 0 and are
// dropped), tol only setting the clipped range as above.
ExpSum fit_band_model_terms(double a, double x_lo, double x_hi, double tol, int terms);

// Non-negative least squares: x >= 0 minimising |A x - b| (A row-major, rows x cols),
// by Lawson & Hanson's active-set algorithm (1974, ch. 23, algorithm NNLS) with
// Gram-Schmidt (two passes) for the passive-set subproblems (cols <= 64).
std::vector<double> nnls(const std::vector<double>& a, const std::vector<double>& b,
                         std::size_t rows, std::size_t cols);

}  // namespace sigchain::atmos
