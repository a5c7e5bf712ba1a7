// Discrete-ordinate radiative transfer solver (DISORT method, Stamnes et al. 1988).
#include "rt/discrete_ordinates.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "rt/layer_solution.hpp"
#include "rt/linalg.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::rt {
namespace {

using detail::LayerOptics;
using detail::LayerSolution;
using detail::Quadrature;

constexpr double kPi = std::numbers::pi;
// Conservative scattering: DISORT dithers omega = 1 to 1 - dither; here 1e-9, which
// keeps the k -> 0 eigenvalue resolvable in double precision while absorbing a fraction
// ~1e-9 per unit optical path (energy conserved to ~1e-6 even for tau ~ 100 clouds).
constexpr double kDither = 1e-9;

void validate(const Problem& p) {
    auto bad = [](const std::string& what) { throw Error("discrete-ordinate solver: " + what); };
    if (p.layers.empty()) bad("no layers");
    if (p.streams < 4 || p.streams > 128 || p.streams % 2 != 0)
        bad("streams must be even, 4 .. 128");
    for (std::size_t n = 0; n < p.layers.size(); ++n) {
        const Layer& l = p.layers[n];
        if (!(l.tau >= 0) || !(l.ssa >= 0 && l.ssa <= 1))
            bad("layer " + std::to_string(n) + ": tau < 0 or ssa outside [0, 1]");
        if (l.ssa > 0 && (l.pmom.empty() || std::abs(l.pmom[0] - 1) > 1e-6))
            bad("layer " + std::to_string(n) + ": pmom[0] must be 1");
    }
    if (p.beam_flux < 0 || (p.beam_flux > 0 && !(p.beam_mu0 > 0 && p.beam_mu0 <= 1)))
        bad("beam_flux < 0 or beam_mu0 outside (0, 1]");
    if (p.top_isotropic < 0 || !(p.albedo >= 0 && p.albedo <= 1)) bad("bad top or albedo");
    if (!p.planck_levels.empty() && p.planck_levels.size() != p.layers.size() + 1)
        bad("planck_levels must have layers.size() + 1 values");
    for (std::size_t i = 0; i < p.utau.size(); ++i)
        if (p.utau[i] < 0 || (i > 0 && p.utau[i] < p.utau[i - 1])) bad("utau not ascending >= 0");
    for (double mu : p.umu)
        if (mu == 0 || std::abs(mu) > 1) bad("umu must be nonzero cosines");
}

// Delta-M scaling (Wiscombe 1977, J. Atmos. Sci. 34, 1408, eqs. 13-15): f = pmom[N],
// tau* = (1 - omega f) tau, omega* = omega (1 - f)/(1 - omega f), g*_l = (g_l - f)/(1 - f).
struct Scaled {
    std::vector<LayerOptics> optics;
    std::vector<double> f;            // truncation fraction per layer
    std::vector<double> tau_level;    // unscaled optical depth of each level
    std::vector<double> tau_s_level;  // scaled optical depth of each level
};

Scaled scale_layers(const Problem& p) {
    const int N = p.streams;
    const std::size_t L = p.layers.size();
    Scaled s;
    s.optics.resize(L);
    s.f.assign(L, 0.0);
    s.tau_level.assign(L + 1, 0.0);
    s.tau_s_level.assign(L + 1, 0.0);
    for (std::size_t n = 0; n < L; ++n) {
        const Layer& l = p.layers[n];
        LayerOptics& o = s.optics[n];
        auto mom = [&](int k) { return k < static_cast<int>(l.pmom.size()) ? l.pmom[k] : 0.0; };
        const double f = p.delta_m ? mom(N) : 0.0;
        s.f[n] = f;
        o.g.assign(N, 0.0);
        o.g[0] = 1;
        for (int k = 1; k < N; ++k) o.g[k] = (mom(k) - f) / (1 - f);
        o.dtau = (1 - l.ssa * f) * l.tau;
        o.ssa = std::min(l.ssa * (1 - f) / (1 - l.ssa * f), 1 - kDither);
        s.tau_level[n + 1] = s.tau_level[n] + l.tau;
        s.tau_s_level[n + 1] = s.tau_s_level[n] + o.dtau;
        if (!p.planck_levels.empty()) {
            o.planck_top = p.planck_levels[n];
            o.planck_slope = o.dtau > 0 ? (p.planck_levels[n + 1] - p.planck_levels[n]) / o.dtau : 0;
        }
    }
    return s;
}

// Where each output depth lies: layer index (the upper one at an interface) and the
// scaled depth below that layer's top.
struct Position {
    int layer = 0;
    double t = 0;  // scaled depth below the layer top
};

std::vector<Position> locate(const Problem& p, const Scaled& s) {
    std::vector<Position> out;
    const std::size_t L = p.layers.size();
    for (double ut : p.utau) {
        std::size_t n = 0;
        while (n + 1 < L && ut > s.tau_level[n + 1] * (1 + 1e-12)) ++n;
        const double ratio = s.optics[n].dtau / std::max(p.layers[n].tau, 1e-300);
        const double t = std::clamp((ut - s.tau_level[n]) * (p.layers[n].tau > 0 ? ratio : 0), 0.0,
                                    s.optics[n].dtau);
        out.push_back({static_cast<int>(n), t});
    }
    return out;
}

// Assembles and solves the boundary-value problem for one mode: top boundary, continuity
// at every interface, Lambertian bottom (Stamnes et al. 1988, eqs. 16-20), as a banded
// system with kl = ku = 3 nn - 1 (unknowns ordered layer by layer, decaying then growing).
void solve_boundary(const Problem& p, const Quadrature& q, int m,
                    const std::vector<LayerOptics>& opt, const std::vector<LayerSolution>& sol,
                    double beam_bottom, linalg::BandMatrix& band, std::vector<double>& x) {
    const int nn = q.nn, n2 = 2 * nn, L = static_cast<int>(sol.size());
    band.reset(L * n2, 3 * nn - 1, 3 * nn - 1);
    x.assign(L * n2, 0.0);
    auto part = [&](int n, int a, double t) {
        const LayerSolution& s = sol[n];
        return s.beam[a] * std::exp(-t * s.inv_mu0) + s.thermal0[a] + opt[n].planck_slope * t *
                                                                          (m == 0 ? 1 : 0);
    };
    const bool thermal = !p.planck_levels.empty() && m == 0;
    (void)thermal;
    // Top: downward intensities at t = 0 of layer 0.
    const double top = m == 0 ? p.top_isotropic + p.top_emission : 0.0;
    for (int i = 0; i < nn; ++i) {
        const int a = nn + i;
        for (int j = 0; j < nn; ++j) {
            band.at(i, j) = sol[0].dec(j, a);
            band.at(i, nn + j) = sol[0].grow(j, a) * sol[0].exp_k[j];
        }
        x[i] = top - part(0, a, 0);
    }
    // Interfaces.
    for (int n = 0; n + 1 < L; ++n) {
        const LayerSolution &u = sol[n], &d = sol[n + 1];
        for (int a = 0; a < n2; ++a) {
            const int r = nn + n * n2 + a;
            for (int j = 0; j < nn; ++j) {
                band.at(r, n * n2 + j) = u.dec(j, a) * u.exp_k[j];
                band.at(r, n * n2 + nn + j) = u.grow(j, a);
                band.at(r, (n + 1) * n2 + j) = -d.dec(j, a);
                band.at(r, (n + 1) * n2 + nn + j) = -d.grow(j, a) * d.exp_k[j];
            }
            x[r] = part(n + 1, a, 0) - part(n, a, opt[n].dtau);
        }
    }
    // Bottom: I(+mu_i) - 2 albedo sum_k w_k mu_k I(-mu_k) = surface sources.
    const int nb = L - 1;
    const LayerSolution& b = sol[nb];
    const double dt = opt[nb].dtau;
    const double alb = m == 0 ? p.albedo : 0.0;
    double src = 0;
    if (m == 0)
        src = alb * p.beam_mu0 * beam_bottom / kPi + (1 - p.albedo) * p.planck_surface;
    double part_refl = 0;
    for (int k = 0; k < nn; ++k) part_refl += q.weight[k] * q.mu[k] * part(nb, nn + k, dt);
    for (int i = 0; i < nn; ++i) {
        const int r = nn + nb * n2 + i;
        for (int j = 0; j < nn; ++j) {
            double rd = 0, rg = 0;
            if (alb > 0)
                for (int k = 0; k < nn; ++k) {
                    rd += q.weight[k] * q.mu[k] * b.dec(j, nn + k);
                    rg += q.weight[k] * q.mu[k] * b.grow(j, nn + k);
                }
            band.at(r, nb * n2 + j) = (b.dec(j, i) - 2 * alb * rd) * b.exp_k[j];
            band.at(r, nb * n2 + nn + j) = b.grow(j, i) - 2 * alb * rg;
        }
        x[r] = src - part(nb, i, dt) + 2 * alb * part_refl;
    }
    if (!band.factor()) throw Error("discrete-ordinate solver: singular boundary-value system");
    band.solve(x.data());
}

// Stable integral int_0^L exp(base + c s) ds, for base <= 0 and base + c L <= 0
// (both ends bounded by 1); a series near c L = 0 covers the resonances of user angles
// with eigenvalues or the beam.
double exp_integral(double base, double c, double len) {
    const double z = c * len;
    if (std::abs(z) < 1e-3) return std::exp(base) * len * (1 + z * (0.5 + z * (1.0 / 6 + z / 24)));
    if (c > 0) return std::exp(base + z) * -std::expm1(-z) / c;
    return std::exp(base) * -std::expm1(z) / -c;
}

// Source function of one layer at one user direction mu for one mode:
//   J(t) = sum_j C+_j hd_j e^{-k_j t} + C-_j hg_j e^{-k_j (dtau - t)} + hb e^{-t/mu0'}
//          + a0 + a1 t.
struct UserSource {
    std::vector<double> hd, hg;
    double hb = 0, a0 = 0, a1 = 0;
};

class Solver {
public:
    explicit Solver(const Problem& p) : m_p(p) {}
    Result run();

private:
    void setup();
    void solve_mode(int m);
    void fluxes();
    void user_intensities(int m, std::vector<double>& im);
    void user_source(int n, int m, const double* lam_mu, UserSource& up, UserSource& down) const;
    double segment(int n, double mu, const UserSource& us, double ta, double tb) const;
    void full_layer_pair(int n, int m, const double* lam_mu, double amu, double et, double& up,
                         double& down) const;
    double quad_intensity(int n, int a, double t) const;
    void intensity_correction();

    const Problem& m_p;
    int m_N = 0, m_L = 0;
    Quadrature m_q;
    Scaled m_s;
    std::vector<Position> m_pos;
    std::vector<LayerSolution> m_sol;
    detail::Scratch m_scratch;
    linalg::BandMatrix m_band;
    std::vector<double> m_x;  // boundary-value solution of the current mode
    std::vector<double> m_lam, m_lam0;
    std::vector<UserSource> m_us, m_us_down;  // per layer, for +|mu| and -|mu|
    std::vector<std::ptrdiff_t> m_mirror;     // index of -umu[u] in umu, or -1
    std::vector<double> m_level_int, m_full_up, m_full_down;
    std::vector<double> m_trans;  // m_trans[n * umu.size() + u] = exp(-dtau_n / |umu_u|)
    Result m_result;
    bool m_thermal = false;
};

void Solver::setup() {
    m_N = m_p.streams;
    m_L = static_cast<int>(m_p.layers.size());
    m_q.nn = m_N / 2;
    gauss_half_range(m_q.nn, m_q.mu, m_q.weight);
    m_s = scale_layers(m_p);
    m_pos = locate(m_p, m_s);
    m_sol.resize(m_L);
    m_us.resize(m_L);
    m_us_down.resize(m_L);
    m_mirror.assign(m_p.umu.size(), -1);
    for (std::size_t u = 0; u < m_p.umu.size(); ++u)
        for (std::size_t v = 0; v < m_p.umu.size(); ++v)
            if (m_p.umu[v] == -m_p.umu[u]) m_mirror[u] = static_cast<std::ptrdiff_t>(v);
    m_thermal = !m_p.planck_levels.empty();
    for (int n = 0; n < m_L; ++n)
        m_s.optics[n].beam_top = m_p.beam_flux * std::exp(-m_s.tau_s_level[n] / m_p.beam_mu0);
    const std::size_t nu = m_p.umu.size();
    m_trans.assign(m_L * nu, 0.0);
    for (int n = 0; n < m_L; ++n)
        for (std::size_t u = 0; u < nu; ++u)
            m_trans[n * nu + u] = std::exp(-m_s.optics[n].dtau / std::abs(m_p.umu[u]));
    m_result.levels.assign(m_p.utau.size(), LevelResult{});
    for (auto& lev : m_result.levels) lev.intensity.assign(m_p.umu.size() * m_p.phi_deg.size(), 0.0);
}

void Solver::solve_mode(int m) {
    detail::quadrature_legendre(m_q, m, m_N, m_lam);
    m_lam0.assign(m_N, 0.0);
    normalized_legendre(m, m_N - 1, -m_p.beam_mu0, m_lam0.data());
    for (int n = 0; n < m_L; ++n)
        detail::solve_layer(m_q, m, m_s.optics[n], m_lam.data(), m_p.beam_mu0, m_lam0.data(),
                            m_thermal, m_sol[n], m_scratch);
    const double beam_bottom = m_p.beam_flux * std::exp(-m_s.tau_s_level[m_L] / m_p.beam_mu0);
    solve_boundary(m_p, m_q, m, m_s.optics, m_sol, beam_bottom, m_band, m_x);
}

// Intensity at quadrature direction a, scaled depth t in layer n, current mode.
double Solver::quad_intensity(int n, int a, double t) const {
    const LayerSolution& s = m_sol[n];
    const LayerOptics& o = m_s.optics[n];
    const int nn = m_q.nn;
    const double* c = &m_x[n * 2 * nn];
    double v = s.beam[a] * std::exp(-t * s.inv_mu0) + s.thermal0[a] + o.planck_slope * t;
    for (int j = 0; j < nn; ++j)
        v += c[j] * s.dec(j, a) * std::exp(-s.k[j] * t) +
             c[nn + j] * s.grow(j, a) * std::exp(-s.k[j] * (o.dtau - t));
    return v;
}

// Fluxes, mean intensity and flux divergence from the m = 0 quadrature intensities
// (Stamnes et al. 1988, eqs. 21-23); with delta-M the diffuse fluxes add back the
// scaled-minus-true direct beam (the forward peak counted as diffuse).
void Solver::fluxes() {
    const int nn = m_q.nn;
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        const Position& ps = m_pos[i];
        LevelResult& lev = m_result.levels[i];
        double up = 0, down = 0, mean = 0;
        for (int k = 0; k < nn; ++k) {
            const double iu = quad_intensity(ps.layer, k, ps.t);
            const double id = quad_intensity(ps.layer, nn + k, ps.t);
            up += m_q.weight[k] * m_q.mu[k] * iu;
            down += m_q.weight[k] * m_q.mu[k] * id;
            mean += 0.5 * m_q.weight[k] * (iu + id);
        }
        const double tau_s = m_s.tau_s_level[ps.layer] + ps.t;
        double direct = 0, direct_s = 0;
        if (m_p.beam_flux > 0) {
            direct = m_p.beam_flux * std::exp(-m_p.utau[i] / m_p.beam_mu0);
            direct_s = m_p.beam_flux * std::exp(-tau_s / m_p.beam_mu0);
        }
        lev.direct_down = m_p.beam_mu0 * direct;
        lev.diffuse_down = 2 * kPi * down + m_p.beam_mu0 * (direct_s - direct);
        lev.diffuse_up = 2 * kPi * up;
        lev.mean_intensity = mean + (direct_s - direct) / (4 * kPi);
        const LayerOptics& o = m_s.optics[ps.layer];
        const double planck = m_thermal ? o.planck_top + o.planck_slope * ps.t : 0.0;
        // d(F_up - F_down)/d tau = (1 - omega) 4 pi (mean intensity incl. beam - B).
        lev.dfdt = (1 - m_p.layers[ps.layer].ssa) * 4 * kPi *
                   (mean + direct_s / (4 * kPi) - planck);
    }
}

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
        if (us.hb != 0)
            v += us.hb * exp_integral(-ta * s.inv_mu0 - len * im, im - s.inv_mu0, len);
        v *= im;
        const double e = std::exp(-len * im);
        v += us.a0 * (1 - e) + us.a1 * (ta * (1 - e) + len - nu * (1 - e));
    }
    return v;
}

// Integral of exp(-a s - b (L - s)) over [0, L] = (e_a - e_b) / (b - a), from the
// precomputed ends e_a = exp(-a L), e_b = exp(-b L); a series when a L and b L nearly
// coincide (resonance of a user angle with an eigenvalue or the beam).
inline double two_exp(double ea, double eb, double a, double b, double len) {
    const double d = (b - a) * len;
    if (std::abs(d) < 1e-3) return ea * len * (1 - d * (0.5 - d * (1.0 / 6 - d / 24)));
    return (ea - eb) / (b - a);
}

// segment(n, +-|mu|, us, 0, dtau) for both directions of one |mu| at once, without
// exponentials (e^{-k dtau}, e^{-dtau/|mu|} = et and e^{-dtau/mu0'} are precomputed).
// With x = k |mu|, the term decaying along the direction of travel integrates to
// same = (1 - e^{-k dt} et) / (1 + x), the other to other = (et - e^{-k dt}) / (x - 1)
// (two_exp with a = k + 1/|mu|, b = 0 and with a = 1/|mu|, b = k, divided by |mu|);
// upward radiation sees the decaying solution as "same", downward the growing one.
void Solver::full_layer_pair(int n, int m, const double* lam_mu, double amu, double et,
                             double& up, double& down) const {
    const LayerSolution& s = m_sol[n];
    const LayerOptics& o = m_s.optics[n];
    const double dt = o.dtau, im = 1 / amu;
    const int nn = m_q.nn, nl = s.nl;
    const double* c = &m_x[n * 2 * nn];
    // Source moments: Lambda_l(-mu) = (-1)^(l+m) Lambda_l(mu) splits each sum into even
    // and odd (l + m) parts shared by both directions.
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
    double same[64], other[64];
    bool resonance = false;
    for (int j = 0; j < nn; ++j) {
        const double x = s.k[j] * amu, ek = s.exp_k[j];
        same[j] = (1 - ek * et) / (1 + x);
        other[j] = (et - ek) / (x - 1);
        resonance |= std::abs(x - 1) * dt * im < 1e-3;
    }
    if (resonance)
        for (int j = 0; j < nn; ++j)
            if (std::abs(s.k[j] * amu - 1) * dt * im < 1e-3)
                other[j] = two_exp(et, s.exp_k[j], im, s.k[j], dt) * im;
    double vu = 0, vd = 0;
    for (int j = 0; j < nn; ++j) {
        const double plus = even[j] + odd[j], minus = even[j] - odd[j];
        vu += c[j] * plus * same[j] + c[nn + j] * minus * other[j];
        vd += c[j] * minus * other[j] + c[nn + j] * plus * same[j];
    }
    double be = 0, bo = 0, te = 0, to = 0;
    for (int l = m; l < nl; l += 2) be += lam_mu[l] * s.bmom[l], te += lam_mu[l] * s.tmom[l];
    for (int l = m + 1; l < nl; l += 2) bo += lam_mu[l] * s.bmom[l], to += lam_mu[l] * s.tmom[l];
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

// Intensities of mode m at every output depth and user direction: im[level * nu + u].
void Solver::user_intensities(int m, std::vector<double>& im) {
    const std::size_t nu = m_p.umu.size();
    im.assign(m_pos.size() * nu, 0.0);
    std::vector<double> lam_mu(m_N);
    m_level_int.assign(m_L + 1, 0.0);
    m_full_up.assign(m_L, 0.0);
    m_full_down.assign(m_L, 0.0);
    const int nn = m_q.nn;
    // Lambertian surface: upward intensity of mode 0 at the bottom.
    double bottom = 0;
    if (m == 0) {
        double down = 0;
        for (int k = 0; k < nn; ++k)
            down += m_q.weight[k] * m_q.mu[k] *
                    quad_intensity(m_L - 1, nn + k, m_s.optics[m_L - 1].dtau);
        const double beam_bottom = m_p.beam_flux * std::exp(-m_s.tau_s_level[m_L] / m_p.beam_mu0);
        bottom = m_p.albedo * (2 * down + m_p.beam_mu0 * beam_bottom / kPi) +
                 (1 - m_p.albedo) * m_p.planck_surface;
    }
    const double top = m == 0 ? m_p.top_isotropic + m_p.top_emission : 0.0;
    for (std::size_t u = 0; u < nu; ++u) {
        const double mu = m_p.umu[u];
        // A downward cosine whose upward mirror is also wanted is done with the mirror.
        if (mu < 0 && m_mirror[u] >= 0) continue;
        const double amu = std::abs(mu);
        normalized_legendre(m, m_N - 1, amu, lam_mu.data());
        for (int n = 0; n < m_L; ++n)
            full_layer_pair(n, m, lam_mu.data(), amu, m_trans[n * nu + u], m_full_up[n],
                            m_full_down[n]);
        for (const Position& ps : m_pos) user_source(ps.layer, m, lam_mu.data(), m_us[ps.layer],
                                                     m_us_down[ps.layer]);
        if (mu > 0) {
            m_level_int[m_L] = bottom;
            for (int n = m_L - 1; n >= 0; --n)
                m_level_int[n] = m_level_int[n + 1] * m_trans[n * nu + u] + m_full_up[n];
            for (std::size_t i = 0; i < m_pos.size(); ++i) {
                const Position& ps = m_pos[i];
                const double dt = m_s.optics[ps.layer].dtau;
                im[i * nu + u] = m_level_int[ps.layer + 1] * std::exp(-(dt - ps.t) / mu) +
                                 segment(ps.layer, mu, m_us[ps.layer], ps.t, dt);
            }
        }
        const std::ptrdiff_t d = mu < 0 ? static_cast<std::ptrdiff_t>(u) : m_mirror[u];
        if (d < 0) continue;
        const double mud = m_p.umu[d];
        m_level_int[0] = top;
        for (int n = 0; n < m_L; ++n)
            m_level_int[n + 1] = m_level_int[n] * m_trans[n * nu + d] + m_full_down[n];
        for (std::size_t i = 0; i < m_pos.size(); ++i) {
            const Position& ps = m_pos[i];
            im[i * nu + d] = m_level_int[ps.layer] * std::exp(ps.t / mud) +
                             segment(ps.layer, mud, m_us_down[ps.layer], 0, ps.t);
        }
    }
}

// Nakajima & Tanaka (1988, JQSRT 40, 51) TMS correction: the single-scattered beam
// computed with the truncated delta-M phase function is replaced by the one with the
// exact phase function, P(cos) omega / (1 - omega f) in the scaled medium (their eq. 13).
// The correction is sum_l P_l(cos scattering angle) e_l(level, mu), with
// e_l = sum_n d_nl T_n: d_nl the layer's moment difference, T_n the beam's path integral
// through layer n seen from the output level.
void Solver::intensity_correction() {
    const std::size_t nu = m_p.umu.size(), nphi = m_p.phi_deg.size(), npos = m_pos.size();
    const double mu0 = m_p.beam_mu0;
    std::size_t nmom = m_N;
    for (const Layer& l : m_p.layers) nmom = std::max(nmom, l.pmom.size());
    std::vector<double> d(m_L * nmom, 0.0);
    for (int n = 0; n < m_L; ++n) {
        const Layer& layer = m_p.layers[n];
        const LayerOptics& o = m_s.optics[n];
        for (std::size_t l = 0; l < nmom; ++l) {
            const double exact = l < layer.pmom.size() ? layer.pmom[l] : 0.0;
            const double trunc = l < static_cast<std::size_t>(m_N) ? o.g[l] : 0.0;
            d[n * nmom + l] = m_p.beam_flux / (4 * kPi) * (2.0 * l + 1) *
                              (layer.ssa * exact / (1 - layer.ssa * m_s.f[n]) - o.ssa * trunc);
        }
    }
    std::vector<double> tn(m_L), e(npos * nmom), pl(std::max<std::size_t>(nmom, 2));
    std::vector<double> rec_a(nmom), rec_b(nmom);  // P_l = ((2l-1) x P_{l-1} - (l-1) P_{l-2}) / l
    for (std::size_t l = 2; l < nmom; ++l) rec_a[l] = (2.0 * l - 1) / l, rec_b[l] = (l - 1.0) / l;
    for (std::size_t u = 0; u < nu; ++u) {
        const double mu = m_p.umu[u];
        std::fill(e.begin(), e.end(), 0.0);
        for (std::size_t i = 0; i < npos; ++i) {
            const Position& ps = m_pos[i];
            const int np = ps.layer;
            std::fill(tn.begin(), tn.end(), 0.0);
            // T_n: beam path integral of layer n, attenuated to the output level.
            double atten = 1;
            const double dtp = m_s.optics[np].dtau;
            const double e0 = std::exp(-m_s.tau_s_level[np] / mu0);
            if (mu > 0) {
                tn[np] = e0 * exp_integral(-ps.t / mu0, -(1 / mu0 + 1 / mu), dtp - ps.t) / mu;
                atten = std::exp(-(dtp - ps.t) / mu);
                for (int n = np + 1; n < m_L; ++n) {
                    const double dt = m_s.optics[n].dtau;
                    tn[n] = atten * std::exp(-m_s.tau_s_level[n] / mu0) *
                            exp_integral(0, -(1 / mu0 + 1 / mu), dt) / mu;
                    atten *= m_trans[n * nu + u];
                }
            } else {
                tn[np] = e0 * exp_integral(ps.t / mu, -1 / mu - 1 / mu0, ps.t) / -mu;
                atten = std::exp(ps.t / mu);
                for (int n = np - 1; n >= 0; --n) {
                    const double dt = m_s.optics[n].dtau;
                    tn[n] = atten * std::exp(-m_s.tau_s_level[n] / mu0) *
                            exp_integral(dt / mu, -1 / mu - 1 / mu0, dt) / -mu;
                    atten *= m_trans[n * nu + u];
                }
            }
            for (int n = 0; n < m_L; ++n) {
                if (tn[n] == 0) continue;
                for (std::size_t l = 0; l < nmom; ++l) e[i * nmom + l] += d[n * nmom + l] * tn[n];
            }
        }
        for (std::size_t f = 0; f < nphi; ++f) {
            const double dphi = (m_p.phi_deg[f] - m_p.beam_phi0_deg) * kPi / 180;
            const double cos_scat = -mu * mu0 + std::sqrt((1 - mu * mu) * (1 - mu0 * mu0)) *
                                                     std::cos(dphi);
            pl[0] = 1;
            pl[1] = cos_scat;
            for (std::size_t l = 2; l < nmom; ++l)
                pl[l] = rec_a[l] * cos_scat * pl[l - 1] - rec_b[l] * pl[l - 2];
            for (std::size_t i = 0; i < npos; ++i) {
                double corr = 0;
                for (std::size_t l = 0; l < nmom; ++l) corr += pl[l] * e[i * nmom + l];
                m_result.levels[i].intensity[u * nphi + f] += corr;
            }
        }
    }
}

Result Solver::run() {
    setup();
    const bool beam = m_p.beam_flux > 0;
    const int modes = beam && !m_p.umu.empty() ? m_N : 1;
    const std::size_t nu = m_p.umu.size(), nphi = m_p.phi_deg.size();
    std::vector<double> im, cos_m(nphi);
    int converged = 0;
    for (int m = 0; m < modes; ++m) {
        solve_mode(m);
        if (m == 0) fluxes();
        if (nu == 0) continue;
        user_intensities(m, im);
        double worst = 0;
        for (std::size_t f = 0; f < nphi; ++f)
            cos_m[f] = std::cos(m * (m_p.phi_deg[f] - m_p.beam_phi0_deg) * kPi / 180);
        for (std::size_t i = 0; i < m_pos.size(); ++i)
            for (std::size_t u = 0; u < nu; ++u)
                for (std::size_t f = 0; f < nphi; ++f) {
                    const double add = im[i * nu + u] * cos_m[f];
                    double& total = m_result.levels[i].intensity[u * nphi + f];
                    total += add;
                    if (total != 0) worst = std::max(worst, std::abs(add / total));
                }
        if (m > 0 && m_p.azimuth_accuracy > 0) {
            converged = worst <= m_p.azimuth_accuracy ? converged + 1 : 0;
            if (converged >= 2) break;
        }
    }
    bool peaked = false;
    for (double f : m_s.f) peaked = peaked || f != 0;
    if (beam && m_p.delta_m && m_p.intensity_correction && peaked && nu > 0) intensity_correction();
    return m_result;
}

}  // namespace

Result solve(const Problem& problem) {
    validate(problem);
    Solver solver(problem);
    return solver.run();
}

}  // namespace sigchain::rt
