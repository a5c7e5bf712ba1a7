// Exponential sums fitted to LOWTRAN 7's band model (see exp_sum.hpp).
#include "atmos/exp_sum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sigchain::atmos {

namespace {

constexpr int kPoints = 96;              // fit points, evenly spaced in log x
constexpr double kSumRowWeight = 100.0;  // weight of the sum w_i = 1 row
constexpr double kWiden = 2.5;           // see fit_band_model_terms
constexpr double kOpaqueDepth = 20.0;
constexpr double kClip = 0.1;  // clip where within kClip tol of 1 or 0

// The QR factors of the columns of A last solved for in one nnls: Lawson and Hanson's
// subproblems mostly add a column to the previous set, and modified Gram-Schmidt forms
// column j from the columns before it alone, so the columns up to the first that
// differs are the same numbers and are kept.
struct QrCache {
    std::vector<std::size_t> cols;  // the columns of A in q, in order
    std::vector<double> q;          // rows x cols.size(), column by column
    std::vector<double> r;          // R(l, j) at r[l * stride + j]
    std::size_t stride = 0;         // A's column count
};

// Least squares on the columns `cols` (ascending) of A (column-major: column c at
// at[c * rows]) by modified Gram-Schmidt QR: returns z (size cols.size()) minimising
// |A_P z - b|. Q is kept column by column, so each pass runs over contiguous memory.
std::vector<double> least_squares(const std::vector<double>& at, const std::vector<double>& b,
                                  std::size_t rows, const std::vector<std::size_t>& cols,
                                  QrCache& c) {
    const std::size_t p = cols.size(), n = c.stride;
    std::size_t same = 0;
    while (same < p && same < c.cols.size() && c.cols[same] == cols[same]) ++same;
    c.cols = cols;
    c.q.resize(rows * p);
    auto& q = c.q;
    auto& r = c.r;
    for (std::size_t j = same; j < p; ++j) {
        std::copy_n(at.begin() + static_cast<long>(cols[j] * rows), rows,
                    q.begin() + static_cast<long>(j * rows));
        for (std::size_t l = 0; l <= j; ++l) r[l * n + j] = 0;
    }
    for (std::size_t j = same; j < p; ++j) {
        double* qj = &q[j * rows];
        // Two Gram-Schmidt passes ("twice is enough", Giraud et al. 2005): the
        // exponentials are nearly collinear and one pass loses orthogonality.
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t l = 0; l < j; ++l) {
                const double* ql = &q[l * rows];
                double d = 0;
                for (std::size_t i = 0; i < rows; ++i) d += ql[i] * qj[i];
                r[l * n + j] += d;
                for (std::size_t i = 0; i < rows; ++i) qj[i] -= d * ql[i];
            }
        double norm = 0;
        for (std::size_t i = 0; i < rows; ++i) norm += qj[i] * qj[i];
        norm = std::sqrt(norm);
        r[j * n + j] = norm;
        if (norm > 0)
            for (std::size_t i = 0; i < rows; ++i) qj[i] /= norm;
    }
    std::vector<double> z(p, 0.0);
    for (std::size_t j = 0; j < p; ++j)
        for (std::size_t i = 0; i < rows; ++i) z[j] += q[j * rows + i] * b[i];
    for (std::size_t j = p; j-- > 0;) {  // back substitution R z = Q^T b
        for (std::size_t l = j + 1; l < p; ++l) z[j] -= r[j * n + l] * z[l];
        z[j] = r[j * n + j] > 0 ? z[j] / r[j * n + j] : 0.0;
    }
    return z;
}

// The band model exp(-x^a).
double band_model(double a, double x) { return x > 0 ? std::exp(-std::pow(x, a)) : 1.0; }

// One exponential matching the band model at x (the k of exp(-k x) = exp(-x^a)).
ExpSum single_term(double a, double x) {
    ExpSum s;
    s.weight = {1.0};
    s.k = {x > 0 ? std::pow(x, a) / x : 0.0};
    return s;
}

// A fit's range and sample points: [lo, hi] is [x_lo, x_hi] clipped to where the band
// model is more than tol / 10 from 1 and from 0; `single` is set where one term is the
// fit (the model transparent or opaque over the range, or nothing left after the
// clip). x: kPoints points evenly spaced in log x over [lo, hi]; model: exp(-x^a) there.
struct FitRange {
    double lo = 0, hi = 0;
    bool single = false;
    ExpSum single_fit;
    std::vector<double> x, model;
};

FitRange fit_range(double a, double x_lo, double x_hi, double tol) {
    if (!(a > 0 && a <= 1) || !(x_lo >= 0 && x_hi > x_lo) || !(tol > 0 && tol < 1))
        throw std::invalid_argument("fit_band_model: bad arguments");
    FitRange r;
    r.lo = std::max(x_lo, std::pow(-std::log1p(-kClip * tol), 1 / a));
    r.hi = std::min(x_hi, std::pow(-std::log(kClip * tol), 1 / a));
    r.single = true;
    if (band_model(a, x_hi) >= 1 - tol)
        r.single_fit = single_term(a, x_hi);  // transparent
    else if (band_model(a, x_lo) <= tol)
        r.single_fit = single_term(a, x_lo);  // opaque
    else if (!(r.hi > r.lo))
        r.single_fit = single_term(a, r.lo);
    else
        r.single = false;
    if (r.single) return r;
    r.x.resize(kPoints);
    r.model.resize(kPoints);
    for (int p = 0; p < kPoints; ++p) {
        r.x[p] = r.lo * std::pow(r.hi / r.lo, static_cast<double>(p) / (kPoints - 1));
        r.model[p] = band_model(a, r.x[p]);
    }
    return r;
}

// The fit with `terms` candidate k_i over the range r (not single) of [x_lo, ...].
ExpSum fit_terms(double a, double x_lo, const FitRange& r, int terms) {
    if (terms < 1 || terms > 32) throw std::invalid_argument("fit_band_model: bad arguments");
    const double lo = r.lo, hi = r.hi;
    // Where the range starts inside the band model's drop (x_lo above the clip), an
    // opaque term (exp(-k x_lo) = exp(-20)) holds the weight that vanishes before x_lo,
    // so the weights still sum to 1 (a Planck source must keep its full weight).
    const bool opaque = lo == x_lo && x_lo > 0;
    const auto n = static_cast<std::size_t>(terms);
    std::vector<double> k(n);
    // The k_i: from the slowest decay the tail at hi needs (exp(-k x) matches the band
    // model at x for k = x^(a - 1)) to the fastest the drop at lo needs (k ~ 1 / lo),
    // widened by kWiden at both ends; one term matches the middle of the range.
    const double k_lo = std::pow(hi, a - 1) / kWiden, k_hi = kWiden / lo;
    for (std::size_t i = 0; i < n; ++i)
        k[i] = n == 1 ? std::pow(std::sqrt(lo * hi), a - 1)  // matched mid-range
                      : k_lo * std::pow(k_hi / k_lo, static_cast<double>(i) / (n - 1));
    if (opaque) k.push_back(kOpaqueDepth / x_lo);
    const std::size_t n_all = k.size();
    const std::size_t rows = kPoints + 1;
    std::vector<double> mat(rows * n_all), rhs(rows);
    for (int p = 0; p < kPoints; ++p) {
        rhs[p] = r.model[p];
        for (std::size_t i = 0; i < n_all; ++i) mat[p * n_all + i] = std::exp(-k[i] * r.x[p]);
    }
    for (std::size_t i = 0; i < n_all; ++i) mat[kPoints * n_all + i] = kSumRowWeight;
    rhs[kPoints] = kSumRowWeight;
    const std::vector<double> w = nnls(mat, rhs, rows, n_all);
    ExpSum s;
    std::vector<std::size_t> kept;
    double total = 0;
    for (std::size_t i = 0; i < n_all; ++i)
        if (w[i] > 0) {
            s.weight.push_back(w[i]);
            s.k.push_back(k[i]);
            kept.push_back(i);
            total += w[i];
        }
    for (double& v : s.weight) v /= total;  // exactly 1 (the row held it within ~1e-6)
    // The sum at each point (ExpSum::operator(), its exponentials taken from the matrix).
    for (int p = 0; p < kPoints; ++p) {
        double t = 0;
        for (std::size_t j = 0; j < kept.size(); ++j)
            t += s.weight[j] * mat[p * n_all + kept[j]];
        s.max_error = std::max(s.max_error, std::abs(t - r.model[p]));
    }
    return s;
}

}  // namespace

double ExpSum::operator()(double x) const {
    double t = 0;
    for (std::size_t i = 0; i < k.size(); ++i) t += weight[i] * std::exp(-k[i] * x);
    return t;
}

std::vector<double> nnls(const std::vector<double>& a, const std::vector<double>& b,
                         std::size_t rows, std::size_t cols) {
    if (a.size() != rows * cols || b.size() != rows || cols > 64)
        throw std::invalid_argument("nnls: bad dimensions");
    std::vector<double> x(cols, 0.0), w(cols);
    std::vector<bool> passive(cols, false);
    std::vector<double> at(rows * cols);  // A column-major
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) at[j * rows + i] = a[i * cols + j];
    std::vector<double> res(rows);
    QrCache qr;
    qr.stride = cols;
    qr.r.assign(cols * cols, 0.0);
    auto gradient = [&] {  // w = A^T (b - A x)
        std::copy(b.begin(), b.end(), res.begin());
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = 0; j < cols; ++j) res[i] -= a[i * cols + j] * x[j];
        for (std::size_t j = 0; j < cols; ++j) {
            const double* aj = &at[j * rows];
            double s = 0;
            for (std::size_t i = 0; i < rows; ++i) s += aj[i] * res[i];
            w[j] = s;
        }
    };
    double scale = 0;  // tolerance on the gradient, relative to A and b
    for (double v : a) scale = std::max(scale, std::abs(v));
    for (double v : b) scale = std::max(scale, std::abs(v));
    const double eps = 1e-12 * scale * scale * static_cast<double>(rows);
    gradient();
    for (std::size_t iter = 0; iter < 3 * cols + 3; ++iter) {
        std::size_t t = cols;
        for (std::size_t j = 0; j < cols; ++j)
            if (!passive[j] && w[j] > eps && (t == cols || w[j] > w[t])) t = j;
        if (t == cols) break;
        passive[t] = true;
        for (std::size_t inner = 0; inner < 3 * cols + 3; ++inner) {
            std::vector<std::size_t> p;
            for (std::size_t j = 0; j < cols; ++j)
                if (passive[j]) p.push_back(j);
            const std::vector<double> z = least_squares(at, b, rows, p, qr);
            double alpha = 2;  // step toward z, limited by the first x_j reaching 0
            for (std::size_t l = 0; l < p.size(); ++l)
                if (z[l] <= 0) alpha = std::min(alpha, x[p[l]] / (x[p[l]] - z[l]));
            if (alpha >= 2) {
                for (std::size_t l = 0; l < p.size(); ++l) x[p[l]] = z[l];
                break;
            }
            for (std::size_t l = 0; l < p.size(); ++l) {
                x[p[l]] += alpha * (z[l] - x[p[l]]);
                if (x[p[l]] <= 1e-15) {
                    x[p[l]] = 0;
                    passive[p[l]] = false;
                }
            }
        }
        gradient();
    }
    return x;
}

ExpSum fit_band_model_terms(double a, double x_lo, double x_hi, double tol, int terms) {
    if (terms < 1 || terms > 32) throw std::invalid_argument("fit_band_model: bad arguments");
    const FitRange r = fit_range(a, x_lo, x_hi, tol);
    return r.single ? r.single_fit : fit_terms(a, x_lo, r, terms);
}

// The range and its points are the same for every number of terms: made once.
ExpSum fit_band_model(double a, double x_lo, double x_hi, double tol, int max_terms) {
    if (max_terms < 1) throw std::invalid_argument("fit_band_model: bad arguments");
    const FitRange r = fit_range(a, x_lo, x_hi, tol);
    if (r.single) return r.single_fit;
    ExpSum best;
    for (int n = 1; n <= max_terms; ++n) {
        best = fit_terms(a, x_lo, r, n);
        if (best.max_error <= (1 - kClip) * tol) break;
    }
    return best;
}

}  // namespace sigchain::atmos
