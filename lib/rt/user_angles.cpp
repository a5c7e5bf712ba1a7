// Intensities at user angles by analytic integration of the source function (part of
// the discrete-ordinate solver; the intensity correction is intensity_correction.cpp).
#include <algorithm>
#include <cmath>

#include "rt/quadrature.hpp"
#include "rt/solver.hpp"

namespace sigchain::rt::detail {

// Sources at +|mu| (up) and -|mu| (down) from Lambda_l^m(|mu|): Lambda_l(-mu) =
// (-1)^(l+m) Lambda_l(mu), so the even and odd (l + m) parts of each sum serve both.
void Solver::user_source(int n, int m, const double* lam_mu, UserSource& up,
                         UserSource& down) const {
    const LayerSolution& s = m_sol[n];
    const LayerOptics& o = m_s.optics[n];
    const int nn = m_q.nn, nl = s.nl;
    double even[64], odd[64];
    for (int j = 0; j < nn; ++j) even[j] = odd[j] = 0;
    for (int l = m; l < nl; l += 2) {
        const double* h = &s.hmom[l * nn];
        for (int j = 0; j < nn; ++j) even[j] += lam_mu[l] * h[j];
    }
    for (int l = m + 1; l < nl; l += 2) {
        const double* h = &s.hmom[l * nn];
        for (int j = 0; j < nn; ++j) odd[j] += lam_mu[l] * h[j];
    }
    up.hd.resize(nn);
    up.hg.resize(nn);
    down.hd.resize(nn);
    down.hg.resize(nn);
    for (int j = 0; j < nn; ++j) {
        up.hd[j] = down.hg[j] = even[j] + odd[j];
        up.hg[j] = down.hd[j] = even[j] - odd[j];
    }
    double be = 0, bo = 0, te = 0, to = 0;
    for (int l = m; l < nl; l += 2) be += lam_mu[l] * s.bmom[l], te += lam_mu[l] * s.tmom[l];
    for (int l = m + 1; l < nl; l += 2) bo += lam_mu[l] * s.bmom[l], to += lam_mu[l] * s.tmom[l];
    up.hb = be + bo;
    down.hb = be - bo;
    up.a0 = te + to;
    down.a0 = te - to;
    up.a1 = down.a1 = 0;
    if (m == 0 && m_thermal) {
        up.a0 += (1 - o.ssa) * o.planck_top;
        down.a0 += (1 - o.ssa) * o.planck_top;
        up.a1 = down.a1 = o.planck_slope;
    }
}

// Integral of the source function along direction mu across [ta, tb] of layer n,
// attenuated to the end the radiation leaves from (ta for mu > 0, tb for mu < 0):
// DISORT's analytic user-angle integration (Stamnes et al. 1988, eqs. 24-26).
double Solver::segment(int n, double mu, const UserSource& us, double ta, double tb) const {
    const LayerSolution& s = m_sol[n];
    const double dt = m_s.optics[n].dtau;
    const int nn = m_q.nn;
    const double* c = &m_x[n * 2 * nn];
    const double len = tb - ta;
    if (len <= 0) return 0;
    double v = 0;
    if (mu > 0) {
        const double im = 1 / mu;
        for (int j = 0; j < nn; ++j) {
            const double k = s.k[j];
            v += c[j] * us.hd[j] * exp_integral(-k * ta, -(k + im), len);
            v += c[nn + j] * us.hg[j] * exp_integral(-k * (dt - ta), k - im, len);
        }
        if (us.hb != 0) v += us.hb * exp_integral(-ta * s.inv_mu0, -(s.inv_mu0 + im), len);
        v *= im;
        const double e = std::exp(-len * im);
        v += us.a0 * (1 - e) + us.a1 * (ta * (1 - e) + mu * (1 - e) - len * e);
    } else {
        const double nu = -mu, im = 1 / nu;
        for (int j = 0; j < nn; ++j) {
            const double k = s.k[j];
            v += c[j] * us.hd[j] * exp_integral(-k * ta - len * im, im - k, len);
            v += c[nn + j] * us.hg[j] * exp_integral(-k * (dt - ta) - len * im, k + im, len);
        }
        if (us.hb != 0) v += us.hb * exp_integral(-ta * s.inv_mu0 - len * im, im - s.inv_mu0, len);
        v *= im;
        const double e = std::exp(-len * im);
        v += us.a0 * (1 - e) + us.a1 * (ta * (1 - e) + len - nu * (1 - e));
    }
    return v;
}

namespace {

struct HomogeneousPair {
    int m, nl;
    const double *lam_mu, *hmom, *k, *exp_k, *c;
    double amu, et, dt;
};

// The homogeneous-solution part of full_layer_pair (see there); kNn > 0 fixes nn at
// compile time, 0 takes it from nn_dynamic.
template <int kNn>
void homogeneous_pair(const HomogeneousPair& a, int nn_dynamic, double& vu, double& vd) {
    const int nn = kNn > 0 ? kNn : nn_dynamic;
    const double im = 1 / a.amu;
    // Source moments: Lambda_l(-mu) = (-1)^(l+m) Lambda_l(mu) splits each sum into even
    // and odd (l + m) parts shared by both directions.
    double even[64], odd[64];
    for (int j = 0; j < nn; ++j) even[j] = odd[j] = 0;
    for (int l = a.m; l < a.nl; l += 2) {
        const double* h = &a.hmom[l * nn];
        const double lm = a.lam_mu[l];
        for (int j = 0; j < nn; ++j) even[j] += lm * h[j];
    }
    for (int l = a.m + 1; l < a.nl; l += 2) {
        const double* h = &a.hmom[l * nn];
        const double lm = a.lam_mu[l];
        for (int j = 0; j < nn; ++j) odd[j] += lm * h[j];
    }
    double same[64], other[64];
    bool resonance = false;
    // One division for both: 1 / ((1 + x)(x - 1)); x - 1 is exact near 1 (Sterbenz).
    for (int j = 0; j < nn; ++j) {
        const double x = a.k[j] * a.amu, ek = a.exp_k[j];
        const double xm = x - 1, xp = 1 + x, r = 1 / (xp * xm);
        same[j] = (1 - ek * a.et) * xm * r;
        other[j] = (a.et - ek) * xp * r;
        resonance |= std::abs(xm) * a.dt * im < 1e-3;
    }
    if (resonance)
        for (int j = 0; j < nn; ++j) {
            const double x = a.k[j] * a.amu;
            if (std::abs(x - 1) * a.dt * im < 1e-3) {
                same[j] = (1 - a.exp_k[j] * a.et) / (1 + x);
                other[j] = two_exp(a.et, a.exp_k[j], im, a.k[j], a.dt) * im;
            }
        }
    // Per-solution terms summed afterwards: local arrays keep the loop free of stores
    // through vu/vd (which the compiler cannot prove unaliased) and let it vectorise.
    double tu[64], td[64];
    for (int j = 0; j < nn; ++j) {
        const double plus = even[j] + odd[j], minus = even[j] - odd[j];
        const double cd = a.c[j], cg = a.c[nn + j];
        tu[j] = cd * plus * same[j] + cg * minus * other[j];
        td[j] = cd * minus * other[j] + cg * plus * same[j];
    }
    double su = 0, sd = 0;
    for (int j = 0; j < nn; ++j) su += tu[j], sd += td[j];
    vu += su;
    vd += sd;
}

}  // namespace

// segment(n, +-|mu|, us, 0, dtau) for both directions of one |mu| at once, without
// exponentials (e^{-k dtau}, e^{-dtau/|mu|} = et and e^{-dtau/mu0'} are precomputed).
// With x = k |mu|, the term decaying along the direction of travel integrates to
// same = (1 - e^{-k dt} et) / (1 + x), the other to other = (et - e^{-k dt}) / (x - 1)
// (two_exp with a = k + 1/|mu|, b = 0 and with a = 1/|mu|, b = k, divided by |mu|);
// upward radiation sees the decaying solution as "same", downward the growing one.
void Solver::full_layer_pair(int n, int m, const double* lam_mu, double amu, double et, double& up,
                             double& down) const {
    const LayerSolution& s = m_sol[n];
    const LayerOptics& o = m_s.optics[n];
    const double dt = o.dtau, im = 1 / amu;
    const int nn = m_q.nn, nl = s.nl;
    const double* c = &m_x[n * 2 * nn];
    double vu = 0, vd = 0;
    const HomogeneousPair args{m,   nl, lam_mu, s.hmom.data(), s.k.data(), s.exp_k.data(), c,
                               amu, et, dt};
    // Fixed sizes for the usual stream counts let the compiler unroll and vectorise.
    switch (nn) {
        case 4:
            homogeneous_pair<4>(args, nn, vu, vd);
            break;
        case 8:
            homogeneous_pair<8>(args, nn, vu, vd);
            break;
        case 16:
            homogeneous_pair<16>(args, nn, vu, vd);
            break;
        default:
            homogeneous_pair<0>(args, nn, vu, vd);
            break;
    }
    // Beam moments, and thermal ones where they exist (m = 0 with emission; zero otherwise).
    double be = 0, bo = 0, te = 0, to = 0;
    for (int l = m; l < nl; l += 2) be += lam_mu[l] * s.bmom[l];
    for (int l = m + 1; l < nl; l += 2) bo += lam_mu[l] * s.bmom[l];
    if (m == 0 && m_thermal) {
        for (int l = m; l < nl; l += 2) te += lam_mu[l] * s.tmom[l];
        for (int l = m + 1; l < nl; l += 2) to += lam_mu[l] * s.tmom[l];
    }
    if (be != 0 || bo != 0) {
        const double eb = s.exp_beam;
        vu += im * (be + bo) * two_exp(eb * et, 1.0, s.inv_mu0 + im, 0.0, dt);
        vd += im * (be - bo) * two_exp(eb, et, s.inv_mu0, im, dt);
    }
    double a0u = te + to, a0d = te - to, a1 = 0;
    if (m == 0 && m_thermal) {
        a0u += (1 - o.ssa) * o.planck_top;
        a0d += (1 - o.ssa) * o.planck_top;
        a1 = o.planck_slope;
    }
    up = vu + a0u * (1 - et) + a1 * (amu * (1 - et) - dt * et);
    down = vd + a0d * (1 - et) + a1 * (dt - amu * (1 - et));
}

bool Solver::interior(const Position& ps) const {
    return ps.t > 0 && ps.t < m_s.optics[ps.layer].dtau;
}

// Lambertian surface: upward intensity of mode m at the bottom (zero for m > 0).
double Solver::bottom_intensity(int m) const {
    if (m != 0) return 0;
    const int nn = m_q.nn;
    double down = 0;
    for (int k = 0; k < nn; ++k)
        down += m_q.weight[k] * m_q.mu[k] *
                quad_intensity(m_L - 1, nn + k, m_s.optics[m_L - 1].dtau);
    const double beam_bottom = m_p.beam_flux * std::exp(-m_slant_s[m_L]);
    return m_p.albedo * (2 * down + m_p.beam_mu0 * beam_bottom / kPi) +
           (1 - m_p.albedo) * m_p.planck_surface;
}

// The cosines computed (a downward cosine whose upward mirror is also wanted is done
// with the mirror), their Legendre functions, and the full-layer integrals of every
// layer a wanted intensity depends on, layer by layer so that a layer's solution stays
// in cache; the others are 0. The sweeps below read level n from the layers below it
// (upward) or above it (downward), so upward intensities need layers from up_lo down,
// downward ones layers down to down_hi.
std::vector<std::size_t> Solver::prepare_user_cosines(int m) {
    const std::size_t nu = m_p.umu.size();
    int up_lo = m_L, down_hi = -1;
    for (const Position& ps : m_pos) {
        if (ps.up) up_lo = std::min(up_lo, ps.t == 0 ? ps.layer : ps.layer + 1);
        if (ps.down) down_hi = std::max(down_hi, ps.t == m_s.optics[ps.layer].dtau ? ps.layer
                                                                                  : ps.layer - 1);
    }
    std::vector<std::size_t> primary;
    for (std::size_t u = 0; u < nu; ++u)
        if (!(m_p.umu[u] < 0 && m_mirror[u] >= 0)) primary.push_back(u);
    const std::size_t np = primary.size();
    m_lam_user.resize(np * m_N);
    std::vector<char> need_up(np), need_down(np);
    for (std::size_t k = 0; k < np; ++k) {
        const std::size_t u = primary[k];
        normalized_legendre(m, m_N - 1, std::abs(m_p.umu[u]), &m_lam_user[k * m_N]);
        need_up[k] = m_p.umu[u] > 0;
        need_down[k] = m_p.umu[u] < 0 || m_mirror[u] >= 0;
    }
    m_full_up.assign(np * m_L, 0.0);
    m_full_down.assign(np * m_L, 0.0);
    for (int n = 0; n < m_L; ++n)
        for (std::size_t k = 0; k < np; ++k) {
            if (!((need_up[k] && n >= up_lo) || (need_down[k] && n <= down_hi))) continue;
            const std::size_t u = primary[k];
            full_layer_pair(n, m, &m_lam_user[k * m_N], std::abs(m_p.umu[u]), m_trans[n * nu + u],
                            m_full_up[k * m_L + n], m_full_down[k * m_L + n]);
        }
    return primary;
}

// Upward cosine u (k-th computed): sweep from the bottom up, then read every depth.
void Solver::sweep_up(std::size_t u, std::size_t k, double bottom, std::vector<double>& im) {
    const std::size_t nu = m_p.umu.size();
    const double mu = m_p.umu[u];
    const double* full_up = &m_full_up[k * m_L];
    m_level_int[m_L] = bottom;
    for (int n = m_L - 1; n >= 0; --n)
        m_level_int[n] = m_level_int[n + 1] * m_trans[n * nu + u] + full_up[n];
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        const Position& ps = m_pos[i];
        if (!ps.up) continue;
        const double dt = m_s.optics[ps.layer].dtau;
        if (ps.t == 0)
            im[i * nu + u] = m_level_int[ps.layer];
        else if (ps.t == dt)
            im[i * nu + u] = m_level_int[ps.layer + 1];
        else
            im[i * nu + u] = m_level_int[ps.layer + 1] * std::exp(-(dt - ps.t) / mu) +
                             segment(ps.layer, mu, m_us[ps.layer], ps.t, dt);
    }
}

// Downward cosine d (its mirror the k-th computed): sweep from the top down.
void Solver::sweep_down(std::size_t d, std::size_t k, double top, std::vector<double>& im) {
    const std::size_t nu = m_p.umu.size();
    const double mud = m_p.umu[d];
    const double* full_down = &m_full_down[k * m_L];
    m_level_int[0] = top;
    for (int n = 0; n < m_L; ++n)
        m_level_int[n + 1] = m_level_int[n] * m_trans[n * nu + d] + full_down[n];
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        const Position& ps = m_pos[i];
        if (!ps.down) continue;
        const double dt = m_s.optics[ps.layer].dtau;
        if (ps.t == 0)
            im[i * nu + d] = m_level_int[ps.layer];
        else if (ps.t == dt)
            im[i * nu + d] = m_level_int[ps.layer + 1];
        else
            im[i * nu + d] = m_level_int[ps.layer] * std::exp(ps.t / mud) +
                             segment(ps.layer, mud, m_us_down[ps.layer], 0, ps.t);
    }
}

// Intensities of mode m at every output depth and user direction: im[level * nu + u].
void Solver::user_intensities(int m, std::vector<double>& im) {
    const std::size_t nu = m_p.umu.size();
    im.assign(m_pos.size() * nu, 0.0);
    m_level_int.assign(m_L + 1, 0.0);
    const double bottom = bottom_intensity(m);
    const double top = m == 0 ? m_p.top_isotropic + m_p.top_emission : 0.0;
    const std::vector<std::size_t> primary = prepare_user_cosines(m);
    for (std::size_t k = 0; k < primary.size(); ++k) {
        const std::size_t u = primary[k];
        const double mu = m_p.umu[u];
        // Partial-layer sources only for depths inside a layer; at a level the swept
        // level intensity is the answer.
        for (const Position& ps : m_pos)
            if (interior(ps))
                user_source(ps.layer, m, &m_lam_user[k * m_N], m_us[ps.layer],
                            m_us_down[ps.layer]);
        if (mu > 0) sweep_up(u, k, bottom, im);
        const std::ptrdiff_t d = mu < 0 ? static_cast<std::ptrdiff_t>(u) : m_mirror[u];
        if (d >= 0) sweep_down(static_cast<std::size_t>(d), k, top, im);
    }
}

}  // namespace sigchain::rt::detail
