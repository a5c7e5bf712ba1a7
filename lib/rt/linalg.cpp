// Small dense and banded linear algebra for the discrete-ordinate solver.
#include "rt/linalg.hpp"

#include <algorithm>
#include <cmath>

#include "core/vector_clones.hpp"

namespace sigchain::rt::linalg {

bool cholesky(double* a, int n) {
    for (int j = 0; j < n; ++j) {
        double d = a[j * n + j];
        for (int k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
        if (!(d > 0)) return false;
        d = std::sqrt(d);
        a[j * n + j] = d;
        for (int i = j + 1; i < n; ++i) {
            double s = a[i * n + j];
            for (int k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / d;
        }
    }
    return true;
}

namespace {

// Householder reduction of the symmetric a (n x n) to tridiagonal form, a = Q T Q^T
// (Golub & Van Loan, Matrix Computations, 4th ed., alg. 8.3.1), T overwriting a and Q
// accumulated in q.
void tridiagonalize(double* a, int n, double* q) {
    std::fill(q, q + n * n, 0.0);
    for (int i = 0; i < n; ++i) q[i * n + i] = 1;
    double v[128], p[128];
    for (int k = 0; k + 2 < n; ++k) {
        double norm = 0;
        for (int i = k + 1; i < n; ++i) norm += a[i * n + k] * a[i * n + k];
        norm = std::sqrt(norm);
        if (norm == 0) continue;
        const double alpha = a[(k + 1) * n + k] > 0 ? -norm : norm;
        for (int i = k + 1; i < n; ++i) v[i] = a[i * n + k];
        v[k + 1] -= alpha;
        double vv = 0;
        for (int i = k + 1; i < n; ++i) vv += v[i] * v[i];
        if (vv == 0) continue;
        const double beta = 2 / vv;
        // A <- H A H with H = 1 - beta v v^T on rows/columns k+1..n-1:
        // p = beta A v, w = p - (beta p.v / 2) v, A <- A - v w^T - w v^T.
        double pv = 0;
        for (int i = k + 1; i < n; ++i) {
            double s = 0;
            for (int j = k + 1; j < n; ++j) s += a[i * n + j] * v[j];
            p[i] = beta * s;
            pv += p[i] * v[i];
        }
        for (int i = k + 1; i < n; ++i) p[i] -= 0.5 * beta * pv * v[i];
        for (int i = k + 1; i < n; ++i)
            for (int j = k + 1; j < n; ++j) a[i * n + j] -= v[i] * p[j] + p[i] * v[j];
        a[(k + 1) * n + k] = a[k * n + k + 1] = alpha;
        for (int i = k + 2; i < n; ++i) a[i * n + k] = a[k * n + i] = 0;
        // Q <- Q H.
        for (int r = 0; r < n; ++r) {
            double s = 0;
            for (int j = k + 1; j < n; ++j) s += q[r * n + j] * v[j];
            s *= beta;
            for (int j = k + 1; j < n; ++j) q[r * n + j] -= s * v[j];
        }
    }
}

}  // namespace

// Tridiagonalisation, then implicit symmetric QR steps with the Wilkinson shift and
// deflation (Golub & Van Loan, algs. 8.3.2-8.3.3) on the diagonal d and off-diagonal e
// (e[i] couples i and i + 1), chasing the bulge down with Givens rotations
// G = [[c, s], [-s, c]] (T <- G^T T G). The rotations update the rows of Q^T, which are
// contiguous, and Q^T is transposed back into v at the end.
SIGCHAIN_VECTOR_CLONES
void symmetric_eigen(double* a, int n, double* eval, double* v) {
    tridiagonalize(a, n, v);
    double d[128], e[128], qt[128 * 128];
    for (int i = 0; i < n; ++i) {
        d[i] = a[i * n + i];
        e[i] = i + 1 < n ? a[(i + 1) * n + i] : 0.0;
        for (int j = 0; j < n; ++j) qt[j * n + i] = v[i * n + j];
    }
    constexpr double kEps = 2.2e-16;
    for (int iter = 0; iter < 60 * n; ++iter) {
        for (int i = 0; i + 1 < n; ++i)
            if (std::abs(e[i]) <= kEps * (std::abs(d[i]) + std::abs(d[i + 1]))) e[i] = 0;
        int hi = n - 1;
        while (hi > 0 && e[hi - 1] == 0) --hi;
        if (hi == 0) break;
        int lo = hi - 1;
        while (lo > 0 && e[lo - 1] != 0) --lo;
        const double eh = e[hi - 1];
        const double delta = 0.5 * (d[hi - 1] - d[hi]);
        const double shift =
            d[hi] - eh * eh / (delta + (delta >= 0 ? 1 : -1) * std::sqrt(delta * delta + eh * eh));
        double x = d[lo] - shift, z = e[lo];
        for (int k = lo; k < hi; ++k) {
            // G^T [x; z] = [r; 0]: c = x / r, s = -z / r.
            const double r = std::sqrt(x * x + z * z);
            const double c = r == 0 ? 1.0 : x / r, s = r == 0 ? 0.0 : -z / r;
            if (k > lo) e[k - 1] = r;  // the bulge below it is annihilated
            const double p = d[k], q = d[k + 1], b = e[k];
            d[k] = p * c * c - 2 * b * c * s + q * s * s;
            d[k + 1] = p * s * s + 2 * b * c * s + q * c * c;
            e[k] = (p - q) * c * s + b * (c * c - s * s);
            if (k + 1 < hi) {
                z = -s * e[k + 1];  // new bulge at (k + 2, k)
                e[k + 1] *= c;
                x = e[k];
            }
            double* r0 = &qt[k * n];
            double* r1 = &qt[(k + 1) * n];
            for (int i = 0; i < n; ++i) {
                const double u = r0[i], w = r1[i];
                r0[i] = c * u - s * w;
                r1[i] = s * u + c * w;
            }
        }
    }
    for (int i = 0; i < n; ++i) {
        eval[i] = d[i];
        for (int j = 0; j < n; ++j) v[i * n + j] = qt[j * n + i];
    }
}

bool lu_factor(double* a, int n, int* piv) {
    for (int k = 0; k < n; ++k) {
        int p = k;
        for (int i = k + 1; i < n; ++i)
            if (std::abs(a[i * n + k]) > std::abs(a[p * n + k])) p = i;
        piv[k] = p;
        if (a[p * n + k] == 0) return false;
        if (p != k)
            for (int j = 0; j < n; ++j) std::swap(a[k * n + j], a[p * n + j]);
        const double inv = 1 / a[k * n + k];
        for (int i = k + 1; i < n; ++i) {
            const double l = a[i * n + k] * inv;
            a[i * n + k] = l;
            if (l == 0) continue;
            for (int j = k + 1; j < n; ++j) a[i * n + j] -= l * a[k * n + j];
        }
    }
    return true;
}

void lu_solve(const double* a, int n, const int* piv, double* b) {
    // lu_factor swaps whole rows (L included), so apply every interchange first.
    for (int k = 0; k < n; ++k) std::swap(b[k], b[piv[k]]);
    for (int k = 0; k < n; ++k)
        for (int i = k + 1; i < n; ++i) b[i] -= a[i * n + k] * b[k];
    for (int i = n - 1; i >= 0; --i) {
        double s = b[i];
        for (int j = i + 1; j < n; ++j) s -= a[i * n + j] * b[j];
        b[i] = s / a[i * n + i];
    }
}

void lu_solve_columns(const double* a, int n, const int* piv, double* b, int ncol) {
    for (int k = 0; k < n; ++k)
        if (piv[k] != k)
            for (int c = 0; c < ncol; ++c) std::swap(b[k * ncol + c], b[piv[k] * ncol + c]);
    for (int k = 0; k < n; ++k)
        for (int i = k + 1; i < n; ++i) {
            const double l = a[i * n + k];
            for (int c = 0; c < ncol; ++c) b[i * ncol + c] -= l * b[k * ncol + c];
        }
    for (int i = n - 1; i >= 0; --i) {
        for (int j = i + 1; j < n; ++j) {
            const double u = a[i * n + j];
            for (int c = 0; c < ncol; ++c) b[i * ncol + c] -= u * b[j * ncol + c];
        }
        const double inv = 1 / a[i * n + i];
        for (int c = 0; c < ncol; ++c) b[i * ncol + c] *= inv;
    }
}

void BandMatrix::reset(int n, int kl, int ku) {
    m_n = n;
    m_kl = kl;
    m_ku = ku;
    m_kv = kl + ku;
    m_ld = 2 * kl + ku + 1;
    m_ab.assign(static_cast<std::size_t>(m_ld) * n, 0.0);
    m_piv.assign(n, 0);
    m_km.assign(n, 0);
}

// Right-looking LU with partial pivoting restricted to the band; row interchanges
// widen the upper band to kl + ku (hence the kl extra rows of storage).
bool BandMatrix::factor() {
    int ju = 0;  // last column touched by the U part so far
    for (int j = 0; j < m_n; ++j) {
        // Rows below the last structural nonzero of column j never fill in (no earlier
        // pivot row reaches them), so the elimination stops there.
        int km = std::min(m_kl, m_n - 1 - j);
        while (km > 0 && at(j + km, j) == 0) --km;
        m_km[j] = km;
        int jp = 0;
        double big = std::abs(at(j, j));
        for (int i = 1; i <= km; ++i)
            if (std::abs(at(j + i, j)) > big) big = std::abs(at(j + i, j)), jp = i;
        m_piv[j] = j + jp;
        if (big == 0) return false;
        ju = std::max(ju, std::min(j + m_ku + jp, m_n - 1));
        if (jp != 0)
            for (int c = j; c <= ju; ++c) std::swap(at(j, c), at(j + jp, c));
        const double inv = 1 / at(j, j);
        double* lcol = &m_ab[index(j + 1, j)];
        for (int i = 0; i < km; ++i) lcol[i] *= inv;
        for (int c = j + 1; c <= ju; ++c) {
            const double u = at(j, c);
            if (u == 0) continue;
            double* col = &m_ab[index(j + 1, c)];
            for (int i = 0; i < km; ++i) col[i] -= lcol[i] * u;
        }
    }
    return true;
}

SIGCHAIN_VECTOR_CLONES
void BandMatrix::solve(double* b) const {
    auto get = [&](int r, int c) { return m_ab[index(r, c)]; };
    for (int j = 0; j < m_n; ++j) {
        const int km = m_km[j];
        if (m_piv[j] != j) std::swap(b[j], b[m_piv[j]]);
        for (int i = 1; i <= km; ++i) b[j + i] -= get(j + i, j) * b[j];
    }
    for (int j = m_n - 1; j >= 0; --j) {
        b[j] /= get(j, j);
        const int top = std::max(0, j - m_kv);
        for (int i = top; i < j; ++i) b[i] -= get(i, j) * b[j];
    }
}

}  // namespace sigchain::rt::linalg
