// Small dense and banded linear algebra for the discrete-ordinate solver.
#include "rt/linalg.hpp"

#include <algorithm>
#include <cmath>

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

// One Jacobi rotation annihilating a[p][q] (Golub & Van Loan, Matrix Computations,
// algorithm 8.4.1, symmetric Schur decomposition), applied to a and accumulated in v.
void rotate(double* a, int n, double* v, int p, int q) {
    const double apq = a[p * n + q];
    const double theta = (a[q * n + q] - a[p * n + p]) / (2 * apq);
    const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
    const double c = 1 / std::sqrt(t * t + 1);
    const double s = t * c;
    for (int k = 0; k < n; ++k) {
        const double akp = a[k * n + p], akq = a[k * n + q];
        a[k * n + p] = c * akp - s * akq;
        a[k * n + q] = s * akp + c * akq;
    }
    for (int k = 0; k < n; ++k) {
        const double apk = a[p * n + k], aqk = a[q * n + k];
        a[p * n + k] = c * apk - s * aqk;
        a[q * n + k] = s * apk + c * aqk;
    }
    for (int k = 0; k < n; ++k) {
        const double vkp = v[k * n + p], vkq = v[k * n + q];
        v[k * n + p] = c * vkp - s * vkq;
        v[k * n + q] = s * vkp + c * vkq;
    }
}

}  // namespace

void symmetric_eigen(double* a, int n, double* eval, double* v) {
    std::fill(v, v + n * n, 0.0);
    for (int i = 0; i < n; ++i) v[i * n + i] = 1;
    double total = 0;
    for (int i = 0; i < n * n; ++i) total += a[i] * a[i];
    for (int sweep = 0; sweep < 60; ++sweep) {
        double off = 0;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
        if (off <= 1e-32 * total) break;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q)
                if (a[p * n + q] != 0) rotate(a, n, v, p, q);
    }
    for (int i = 0; i < n; ++i) eval[i] = a[i * n + i];
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
