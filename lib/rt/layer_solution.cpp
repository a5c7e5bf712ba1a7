// Per-layer, per-mode discrete-ordinate solutions (Stamnes et al. 1988, sec. II).
#include "rt/layer_solution.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "rt/linalg.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::rt::detail {
namespace {

constexpr double kPi = std::numbers::pi;

double sign_lm(int l, int m) { return (l + m) % 2 == 0 ? 1.0 : -1.0; }

// D+ + D- (sc.a) and D+ - D- (sc.b) of the homogeneous problem, unsymmetrised:
// sum over l of (omega/2)(2l+1) g_l * 2 Lambda_l(mu_i) Lambda_l(mu_j), split by parity.
void phase_sums(const Quadrature& q, int m, const LayerOptics& o, const double* lam, int nl,
                Scratch& sc) {
    const int nn = q.nn, n2 = 2 * nn;
    auto& dsum = sc.a;
    auto& ddif = sc.b;
    dsum.assign(nn * nn, 0.0);
    ddif.assign(nn * nn, 0.0);
    for (int l = m; l < nl; ++l) {
        const double c = o.ssa * (2 * l + 1) * o.g[l];  // (omega/2)(2l+1)g_l * 2
        if (c == 0) continue;
        auto& d = ((l + m) % 2 == 0) ? dsum : ddif;
        const double* lm = lam + l * n2;
        for (int i = 0; i < nn; ++i)
            for (int j = 0; j < nn; ++j) d[i * nn + j] += c * lm[i] * lm[j];
    }
}

// X = -M^-1 B~ M^-1 factored X = L L^T (lower triangle of sc.c) and the symmetric
// C = L^T Y L (sc.v) with Y = -A~, from the phase sums in sc.a and sc.b.
void reduced_matrix(const Quadrature& q, int m, const double* sqrt_w, Scratch& sc) {
    const int nn = q.nn;
    const auto& dsum = sc.a;
    const auto& ddif = sc.b;
    auto& x = sc.c;
    auto& y = sc.mat;
    x.resize(nn * nn);  // every entry is written below (as are yl's and cm's)
    y.resize(nn * nn);
    for (int i = 0; i < nn; ++i)
        for (int j = 0; j < nn; ++j) {
            const double sw = sqrt_w[i] * sqrt_w[j];
            const double delta = i == j ? 1.0 : 0.0;
            x[i * nn + j] = (delta - sw * ddif[i * nn + j]) / (q.mu[i] * q.mu[j]);
            y[i * nn + j] = delta - sw * dsum[i * nn + j];
        }
    if (!linalg::cholesky(x.data(), nn))
        throw Error("discrete-ordinate solver: homogeneous problem not positive definite (mode " +
                    std::to_string(m) + ")");
    auto& yl = sc.work;  // Y L
    yl.resize(nn * nn);
    for (int i = 0; i < nn; ++i)
        for (int j = 0; j < nn; ++j) {
            double s = 0;
            for (int k = j; k < nn; ++k) s += y[i * nn + k] * x[k * nn + j];
            yl[i * nn + j] = s;
        }
    auto& cm = sc.v;
    cm.resize(nn * nn);
    for (int i = 0; i < nn; ++i)
        for (int j = 0; j <= i; ++j) {
            double s = 0;
            for (int k = i; k < nn; ++k) s += x[k * nn + i] * yl[k * nn + j];
            cm[i * nn + j] = cm[j * nn + i] = s;
        }
}

// From C's eigenvalues k^2 (sc.lam) and eigenvectors v (sc.ev): k, exp(-k dtau) and
// G+-, with S = W^-1/2 L v and D = G+ - G- = M^-1 (Dsum W - 1) S / k.
void eigenvectors(const Quadrature& q, const LayerOptics& o, const double* sqrt_w, Scratch& sc,
                  LayerSolution& out) {
    const int nn = q.nn;
    const auto& x = sc.c;
    const auto& dsum = sc.a;
    sc.s.resize(nn);  // written for every j before it is read
    for (int j = 0; j < nn; ++j) {
        const double k = std::sqrt(std::max(sc.lam[j], 1e-300));
        out.k[j] = k;
        out.exp_k[j] = std::exp(-k * o.dtau);
        for (int i = 0; i < nn; ++i) {
            double s = 0;
            for (int r = 0; r <= i; ++r) s += x[i * nn + r] * sc.ev[r * nn + j];
            sc.s[i] = s / sqrt_w[i];
        }
        for (int i = 0; i < nn; ++i) {
            double as = -sc.s[i];
            for (int r = 0; r < nn; ++r) as += dsum[i * nn + r] * q.weight[r] * sc.s[r];
            const double d = as / (q.mu[i] * k);
            out.gp[j * nn + i] = 0.5 * (sc.s[i] + d);
            out.gm[j * nn + i] = 0.5 * (sc.s[i] - d);
        }
    }
}

// Homogeneous solution: with alpha = M^-1 (D+ W - 1), beta = M^-1 D- W, the eigenproblem
// reduces to (alpha - beta)(alpha + beta) S = k^2 S, S = G+ + G- (Stamnes & Swanson 1981,
// J. Atmos. Sci. 38, 387; Stamnes et al. 1988 eq. 8). Symmetrised with W^1/2: with
// A~ = W^1/2 (D+ + D-) W^1/2 - 1 and B~ likewise with D+ - D-, X = -M^-1 B~ M^-1 is
// positive definite and Y = -A~ positive semi-definite; X = L L^T and the symmetric
// C = L^T Y L has eigenvalues k^2 and eigenvectors v with S = W^-1/2 L v.
void homogeneous(const Quadrature& q, int m, const LayerOptics& o, const double* lam,
                 LayerSolution& out, Scratch& sc) {
    const int nn = q.nn;
    phase_sums(q, m, o, lam, out.nl, sc);
    double sqrt_w[64];
    for (int i = 0; i < nn; ++i) sqrt_w[i] = std::sqrt(q.weight[i]);
    reduced_matrix(q, m, sqrt_w, sc);
    sc.ev.assign(nn * nn, 0.0);
    sc.lam.assign(nn, 0.0);
    linalg::symmetric_eigen(sc.v.data(), nn, sc.lam.data(), sc.ev.data());
    eigenvectors(q, o, sqrt_w, sc, out);
}

// (omega/2)(2l+1) g_l sum_a w_a Lambda_l(mu_a) v_a for l = m .. nl-1: the moments of the
// scattering source of a quadrature vector v (N values).
void scatter_moments(const Quadrature& q, int m, const LayerOptics& o, const double* lam, int nl,
                     const double* v, double* mom) {
    const int nn = q.nn, n2 = 2 * nn;
    for (int l = 0; l < nl; ++l) {
        mom[l] = 0;
        if (l < m) continue;
        const double c = 0.5 * o.ssa * (2 * l + 1) * o.g[l];
        if (c == 0) continue;
        const double* lm = lam + l * n2;
        double s = 0;
        for (int a = 0; a < nn; ++a) s += q.weight[a] * (lm[a] * v[a] + lm[nn + a] * v[nn + a]);
        mom[l] = c * s;
    }
}

double signed_mu(const Quadrature& q, int a) { return a < q.nn ? q.mu[a] : -q.mu[a - q.nn]; }

// Particular solution of (1 + mu_a c) Z_a - sum_b w_b p_ab Z_b = X_a over the N
// directions (c = 1/mu0 for the beam, 0 for thermal emission), reduced to nn x nn as the
// homogeneous problem is: with S = Z+ + Z-, D = Z+ - Z-, A' = 1 - (D+ + D-) W and
// B' = 1 - (D+ - D-) W,  A' S + c M D = X+ + X-  and  B' D + c M S = X+ - X-, so
// D = B'^-1 (Xd - c M S) and (A' - c M B'^-1 c M) S = Xs - c M B'^-1 Xd.
// sc.a / sc.b must hold D+ + D- and D+ - D- (left there by homogeneous()). Returns false
// when singular.
bool reduced_particular(const Quadrature& q, double c, const double* xp, const double* xm,
                        double* z, Scratch& sc) {
    const int nn = q.nn;
    sc.pb.resize(nn * nn);
    sc.pk.resize(nn * nn);
    sc.pq.resize(nn * nn);
    sc.piv.resize(nn);
    sc.piv2.resize(nn);
    for (int i = 0; i < nn; ++i)
        for (int j = 0; j < nn; ++j) {
            const double delta = i == j ? 1.0 : 0.0;
            sc.pb[i * nn + j] = delta - sc.b[i * nn + j] * q.weight[j];
            sc.pk[i * nn + j] = delta - sc.a[i * nn + j] * q.weight[j];
        }
    if (!linalg::lu_factor(sc.pb.data(), nn, sc.piv.data())) return false;
    double y[64], rhs[64];
    // Q = B'^-1 c M (all columns at once).
    for (int i = 0; i < nn; ++i)
        for (int j = 0; j < nn; ++j) sc.pq[i * nn + j] = i == j ? c * q.mu[j] : 0.0;
    linalg::lu_solve_columns(sc.pb.data(), nn, sc.piv.data(), sc.pq.data(), nn);
    for (int i = 0; i < nn; ++i) y[i] = xp[i] - xm[i];
    linalg::lu_solve(sc.pb.data(), nn, sc.piv.data(), y);
    for (int i = 0; i < nn; ++i) {
        rhs[i] = xp[i] + xm[i] - c * q.mu[i] * y[i];
        for (int j = 0; j < nn; ++j) sc.pk[i * nn + j] -= c * q.mu[i] * sc.pq[i * nn + j];
    }
    if (!linalg::lu_factor(sc.pk.data(), nn, sc.piv2.data())) return false;
    linalg::lu_solve(sc.pk.data(), nn, sc.piv2.data(), rhs);
    for (int i = 0; i < nn; ++i) {
        double d = y[i];
        for (int j = 0; j < nn; ++j) d -= sc.pq[i * nn + j] * rhs[j];
        z[i] = 0.5 * (rhs[i] + d);
        z[nn + i] = 0.5 * (rhs[i] - d);
    }
    return true;
}

// The same particular solution through the homogeneous problem's eigen-decomposition
// (O(nn^2) instead of two LU factorisations): in the W^1/2-symmetrised variables of
// homogeneous() (S~ = W^1/2 S, X = L L^T, C = L^T Y L = V diag(k^2) V^T) the reduced
// equations become (X Y - c^2) S~ = X Xs~ - c M^-1 Xd~ and M D~ = X^-1 (M^-1 Xd~ - c S~);
// with S~ = L v and q = L^-1 M^-1 Xd~:  v = V (k^2 - c^2)^-1 V^T (L^T Xs~ - c q),
// M D~ = L^-T (q - c v). Needs sc.c (L), sc.ev (V) and sc.lam (k^2) from homogeneous(),
// and c^2 away from every k^2 (beam_particular moves mu0 off a resonance).
void eigen_particular(const Quadrature& q, double c, const double* xp, const double* xm, double* z,
                      const Scratch& sc) {
    const int nn = q.nn;
    const double* el = sc.c.data();  // L in the lower triangle, row-major
    double sw[64], xs[64], qv[64], r[64], t[64], v[64], sv[64], dv[64];
    for (int i = 0; i < nn; ++i) {
        sw[i] = std::sqrt(q.weight[i]);
        xs[i] = sw[i] * (xp[i] + xm[i]);
        qv[i] = sw[i] * (xp[i] - xm[i]) / q.mu[i];
    }
    for (int i = 0; i < nn; ++i) {  // q = L^-1 M^-1 Xd~
        double s = qv[i];
        for (int k = 0; k < i; ++k) s -= el[i * nn + k] * qv[k];
        qv[i] = s / el[i * nn + i];
    }
    for (int i = 0; i < nn; ++i) {  // r = L^T Xs~ - c q
        double s = 0;
        for (int k = i; k < nn; ++k) s += el[k * nn + i] * xs[k];
        r[i] = s - c * qv[i];
    }
    for (int j = 0; j < nn; ++j) {  // t = (k^2 - c^2)^-1 V^T r
        double s = 0;
        for (int i = 0; i < nn; ++i) s += sc.ev[i * nn + j] * r[i];
        t[j] = s / (sc.lam[j] - c * c);
    }
    for (int i = 0; i < nn; ++i) {  // v = V t
        double s = 0;
        for (int j = 0; j < nn; ++j) s += sc.ev[i * nn + j] * t[j];
        v[i] = s;
    }
    for (int i = 0; i < nn; ++i) {  // S~ = L v
        double s = 0;
        for (int k = 0; k <= i; ++k) s += el[i * nn + k] * v[k];
        sv[i] = s;
    }
    for (int i = nn - 1; i >= 0; --i) {  // M D~ = L^-T (q - c v)
        double s = qv[i] - c * v[i];
        for (int k = i + 1; k < nn; ++k) s -= el[k * nn + i] * dv[k];
        dv[i] = s / el[i * nn + i];
    }
    for (int i = 0; i < nn; ++i) {
        const double s = sv[i] / sw[i], d = dv[i] / (q.mu[i] * sw[i]);
        z[i] = 0.5 * (s + d);
        z[nn + i] = 0.5 * (s - d);
    }
}

// Beam particular solution Z e^{-t/mu0}: (1 + mu_a/mu0) Z_a - sum_b w_b p_ab Z_b = X0_a,
// X0_a = (omega F/4pi)(2 - delta_m0) sum_l (2l+1) g_l Lambda_l(mu_a) Lambda_l(-mu0)
// (Stamnes et al. 1988, eqs. 12-13). Near a resonance k_j = 1/mu0 the beam cosine used
// here is moved by a relative 1e-4 (the particular solution then carries an O(1e-4 t/mu0)
// relative error in that layer only).
void beam_particular(const Quadrature& q, int m, const LayerOptics& o, const double* lam,
                     double mu0, const double* lam0, LayerSolution& out, Scratch& sc) {
    const int nn = q.nn, n2 = 2 * nn, nl = out.nl;
    double inv_mu0 = 1 / mu0;
    for (int j = 0; j < nn; ++j)
        if (std::abs(out.k[j] * mu0 - 1) < 1e-4) inv_mu0 = 1 / (mu0 * (1 + 2e-4));
    out.inv_mu0 = inv_mu0;
    const double factor = o.ssa * o.beam_top / (4 * kPi) * (m == 0 ? 1 : 2);
    double x[128] = {};
    double x0mom[128] = {};
    for (int l = m; l < nl; ++l) {
        x0mom[l] = factor * (2 * l + 1) * o.g[l] * lam0[l];
        for (int a = 0; a < n2; ++a) x[a] += x0mom[l] * lam[l * n2 + a];
    }
    out.beam.resize(n2);
    eigen_particular(q, inv_mu0, x, x + nn, out.beam.data(), sc);
    scatter_moments(q, m, o, lam, nl, out.beam.data(), out.bmom.data());
    for (int l = m; l < nl; ++l) out.bmom[l] += x0mom[l];
}

// Thermal particular solution for B(t) = b0 + b1 t (m = 0): Y1 = b1 exactly (the
// quadrature integrates the isotropic part exactly) and (1 - W p) Y0 = (1-omega) b0 + mu b1
// (Stamnes et al. 1988, eqs. 14-15; DISORT's thermal source).
void thermal_particular(const Quadrature& q, const LayerOptics& o, const double* lam,
                        LayerSolution& out, Scratch& sc) {
    const int nn = q.nn, n2 = 2 * nn, nl = out.nl;
    double x[128];
    for (int a = 0; a < n2; ++a)
        x[a] = (1 - o.ssa) * o.planck_top + signed_mu(q, a) * o.planck_slope;
    out.thermal0.resize(n2);
    if (!reduced_particular(q, 0.0, x, x + nn, out.thermal0.data(), sc))
        throw Error("discrete-ordinate solver: singular thermal particular-solution system");
    scatter_moments(q, 0, o, lam, nl, out.thermal0.data(), out.tmom.data());
}

}  // namespace

void quadrature_legendre(const Quadrature& q, int m, int nl, std::vector<double>& lam) {
    const int nn = q.nn, n2 = 2 * nn;
    lam.assign(nl * n2, 0.0);
    std::vector<double> col(nl);
    for (int i = 0; i < nn; ++i) {
        normalized_legendre(m, nl - 1, q.mu[i], col.data());
        for (int l = 0; l < nl; ++l) {
            lam[l * n2 + i] = col[l];
            lam[l * n2 + nn + i] = sign_lm(l, m) * col[l];
        }
    }
}

void solve_layer(const Quadrature& q, int m, const LayerOptics& optics, const double* lam,
                 double mu0, const double* lam0, bool thermal, LayerSolution& out,
                 Scratch& scratch) {
    const int nn = q.nn, n2 = 2 * nn, nl = n2;
    out.nn = nn;
    out.nl = nl;
    out.k.resize(nn);  // eigenvectors() writes every entry of these four
    out.exp_k.resize(nn);
    out.gp.resize(nn * nn);
    out.gm.resize(nn * nn);
    homogeneous(q, m, optics, lam, out, scratch);
    // Scattering moments of every decaying solution (scatter_moments for each), folded
    // with Lambda_l(-mu) = (-1)^(l+m) Lambda_l(mu): w (G+ + G-) serves even l + m, w (G+ - G-)
    // odd; hmom[l][j] = (omega/2)(2l+1) g_l sum_a Lambda_l(mu_a) w_a (G+ +- G-)_a.
    out.hmom.assign(nn * nl, 0.0);
    scratch.fold.resize(2 * nn * nn);
    double* sp = scratch.fold.data();
    double* sm = sp + nn * nn;
    for (int a = 0; a < nn; ++a)
        for (int j = 0; j < nn; ++j) {
            const double gp = out.gp[j * nn + a], gm = out.gm[j * nn + a];
            sp[a * nn + j] = q.weight[a] * (gp + gm);
            sm[a * nn + j] = q.weight[a] * (gp - gm);
        }
    for (int l = m; l < nl; ++l) {
        const double c = 0.5 * optics.ssa * (2 * l + 1) * optics.g[l];
        if (c == 0) continue;
        const double* fold = (l + m) % 2 == 0 ? sp : sm;
        const double* lm = lam + l * n2;
        double* h = &out.hmom[l * nn];
        for (int a = 0; a < nn; ++a) {
            const double la = c * lm[a];
            for (int j = 0; j < nn; ++j) h[j] += la * fold[a * nn + j];
        }
    }
    out.beam.assign(n2, 0.0);
    out.bmom.assign(nl, 0.0);
    out.inv_mu0 = mu0 > 0 ? 1 / mu0 : 0;
    if (optics.beam_top > 0) beam_particular(q, m, optics, lam, mu0, lam0, out, scratch);
    out.exp_beam = std::exp(-optics.dtau * out.inv_mu0);
    out.thermal0.assign(n2, 0.0);
    out.tmom.assign(nl, 0.0);
    if (thermal && m == 0) thermal_particular(q, optics, lam, out, scratch);
}

}  // namespace sigchain::rt::detail
