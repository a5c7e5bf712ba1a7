// Tests for the exponential sums fitted to LOWTRAN 7's band model (lib/atmos/exp_sum):
// the non-negative least-squares solver against its optimality (Karush-Kuhn-Tucker)
// conditions, and the fits against exp(-x^a) itself on a dense grid.
#include "atmos/exp_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace sigchain::atmos;

namespace {

// A^T (b - A x), the negative gradient of |A x - b|^2 / 2.
std::vector<double> gradient(const std::vector<double>& a, const std::vector<double>& b,
                             const std::vector<double>& x, std::size_t rows, std::size_t cols) {
    std::vector<double> w(cols, 0.0);
    for (std::size_t i = 0; i < rows; ++i) {
        double r = b[i];
        for (std::size_t j = 0; j < cols; ++j) r -= a[i * cols + j] * x[j];
        for (std::size_t j = 0; j < cols; ++j) w[j] += a[i * cols + j] * r;
    }
    return w;
}

// Largest |sum - exp(-x^a)| on 4001 points evenly spaced in log x over [lo, hi], and at 0.
double dense_error(const ExpSum& s, double a, double lo, double hi) {
    double e = std::abs(s(0) - 1);
    for (int i = 0; i <= 4000; ++i) {
        const double x = lo * std::pow(hi / lo, i / 4000.0);
        e = std::max(e, std::abs(s(x) - std::exp(-std::pow(x, a))));
    }
    return e;
}

}  // namespace

// A consistent system with a positive solution: NNLS returns it (rounding: 1e-10).
TEST(Nnls, RecoversAPositiveExactSolution) {
    const std::vector<double> a = {1, 2, 0, 0, 1, 1, 3, 0, 1, 1, 1, 1};  // 4 x 3
    const std::vector<double> x0 = {0.5, 2.0, 1.5};
    std::vector<double> b(4, 0.0);
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 3; ++j) b[i] += a[i * 3 + j] * x0[j];
    const auto x = nnls(a, b, 4, 3);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(x[j], x0[j], 1e-10);
}

// Where the unconstrained least squares goes negative, the result satisfies the KKT
// conditions of min |Ax - b| subject to x >= 0: x >= 0, gradient A^T(b - Ax) <= 0 on the
// zero components and = 0 on the positive ones (1e-10: rounding), and some component
// is held at zero.
TEST(Nnls, SatisfiesTheOptimalityConditionsWhenConstraintsBind) {
    const std::size_t rows = 6, cols = 4;
    std::vector<double> a(rows * cols), b(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        for (std::size_t j = 0; j < cols; ++j) a[i * cols + j] = std::exp(-0.7 * (j + 1.0) * i);
        b[i] = (i % 2 ? -1.0 : 1.0) + 0.3 * i;  // oscillating: no non-negative fit
    }
    const auto x = nnls(a, b, rows, cols);
    const auto w = gradient(a, b, x, rows, cols);
    int zeros = 0;
    for (std::size_t j = 0; j < cols; ++j) {
        EXPECT_GE(x[j], 0.0);
        if (x[j] == 0) {
            ++zeros;
            EXPECT_LE(w[j], 1e-10) << j;
        } else {
            EXPECT_NEAR(w[j], 0.0, 1e-10) << j;
        }
    }
    EXPECT_GT(zeros, 0);
}

// The fits of the band exponents LOWTRAN 7 uses (0.47 to 0.92, band_model_constants.txt)
// over ranges of 1 to 10 decades of x = C W, from nearly transparent to opaque: within
// the requested 0.005 in transmittance on a grid 60 times denser than the fit's
// (both are monotone, so between the points the error cannot grow much; measured
// largest 0.0045), weights >= 0 summing to 1 (1e-12: rounding).
TEST(ExpSumFit, ReproducesTheBandModelWithinTheTolerance) {
    int most = 0;
    for (double a : {0.47, 0.5641, 0.6508, 0.7593, 0.8559, 0.9175})
        for (double hi : {0.01, 0.3, 3.0, 30.0, 1e3, 1e5})
            for (double decades : {1.0, 4.0, 10.0}) {
                const double lo = hi * std::pow(10.0, -decades);
                const ExpSum s = fit_band_model(a, lo, hi, 0.005, 16);
                double sum = 0;
                for (double w : s.weight) {
                    EXPECT_GE(w, 0.0);
                    sum += w;
                }
                EXPECT_NEAR(sum, 1.0, 1e-12);
                EXPECT_LE(dense_error(s, a, lo, hi), 0.005)
                    << "a " << a << " x " << lo << ".." << hi << ", " << s.k.size() << " terms";
                most = std::max(most, static_cast<int>(s.k.size()));
            }
    std::printf("most terms needed: %d of 16\n", most);
}

// a = 1 is Beer's law: one term, k = 1, exact (1e-12: rounding).
TEST(ExpSumFit, BeersLawIsOneExactTerm) {
    const ExpSum s = fit_band_model(1.0, 1e-3, 10, 0.005, 8);
    ASSERT_EQ(s.k.size(), 1u);
    EXPECT_NEAR(s.k[0], 1.0, 1e-12);
    EXPECT_LE(dense_error(s, 1.0, 1e-3, 10), 1e-12);
}

// More terms, smaller error: the error of the n-term fit falls as n grows (printed),
// from a poor single exponential to within 0.001 by 12 terms.
TEST(ExpSumFit, ErrorFallsAsTermsAreAdded) {
    const double a = 0.5641, lo = 1e-4, hi = 100;  // O2, four to six decades
    std::printf("terms  max error (O2 band exponent, x 1e-4..100)\n");
    double first = 0, last = 0;
    for (int n : {1, 2, 3, 4, 6, 8, 12}) {
        const ExpSum s = fit_band_model_terms(a, lo, hi, 0.001, n);
        const double e = dense_error(s, a, lo, hi);
        std::printf("%5d  %.5f\n", n, e);
        if (n == 1) first = e;
        last = e;
    }
    EXPECT_GT(first, 0.05);
    EXPECT_LT(last, 0.001);
}

// fit_band_model is the first fit_band_model_terms fit within 0.9 tol, bit for bit
// (it makes the range's points once for every number of terms), and a fit's max_error
// is the largest |sum - exp(-x^a)| over its 96 points (evenly spaced in log x over the
// range clipped to where exp(-x^a) is within [tol / 10, 1 - tol / 10]), the sum
// evaluated by ExpSum itself; 16 of the 18 cases are fitted, 2 opaque.
TEST(ExpSumFit, FitIsTheFirstSufficientTermsFit) {
    for (double a : {0.47, 0.6508, 0.9175})
        for (double hi : {0.3, 30.0, 1e5})
            for (double tol : {0.001, 0.005}) {
                const double lo = hi * 1e-4;
                const ExpSum fit = fit_band_model(a, lo, hi, tol, 16);
                ExpSum first;
                for (int n = 1; n <= 16; ++n) {
                    first = fit_band_model_terms(a, lo, hi, tol, n);
                    if (first.max_error <= 0.9 * tol) break;
                }
                EXPECT_EQ(fit.weight, first.weight) << a << " " << hi << " " << tol;
                EXPECT_EQ(fit.k, first.k);
                EXPECT_EQ(fit.max_error, first.max_error);
                // One term and no error where the model is transparent or opaque over it.
                if (std::exp(-std::pow(hi, a)) >= 1 - tol || std::exp(-std::pow(lo, a)) <= tol) {
                    EXPECT_EQ(fit.k.size(), 1u);
                    continue;
                }
                const double c_lo = std::max(lo, std::pow(-std::log1p(-0.1 * tol), 1 / a));
                const double c_hi = std::min(hi, std::pow(-std::log(0.1 * tol), 1 / a));
                double worst = 0;
                for (int p = 0; p < 96; ++p) {
                    const double x = c_lo * std::pow(c_hi / c_lo, p / 95.0);
                    worst = std::max(worst, std::abs(fit(x) - std::exp(-std::pow(x, a))));
                }
                EXPECT_EQ(fit.max_error, worst) << a << " " << hi << " " << tol;
            }
}

TEST(ExpSumFit, RejectsBadArguments) {
    EXPECT_THROW(fit_band_model(0, 1, 2, 0.01, 4), std::invalid_argument);
    EXPECT_THROW(fit_band_model(1.2, 1, 2, 0.01, 4), std::invalid_argument);
    EXPECT_THROW(fit_band_model(0.5, 2, 1, 0.01, 4), std::invalid_argument);
    EXPECT_THROW(fit_band_model(0.5, 1, 2, 0, 4), std::invalid_argument);
    EXPECT_THROW(fit_band_model(0.5, 1, 2, 0.01, 0), std::invalid_argument);
}
