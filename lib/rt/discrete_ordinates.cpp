// Discrete-ordinate radiative transfer solver (DISORT method, Stamnes et al. 1988).
#include "rt/discrete_ordinates.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "rt/quadrature.hpp"
#include "rt/solver.hpp"

namespace sigchain::rt {
namespace detail {
namespace {
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
    if (!p.beam_airmass.empty()) {
        if (p.beam_airmass.size() != p.layers.size()) bad("beam_airmass: not one per layer");
        for (double a : p.beam_airmass)
            if (!(a > 0 && std::isfinite(a))) bad("beam_airmass: not positive and finite");
    }
    if (p.top_isotropic < 0 || !(p.albedo >= 0 && p.albedo <= 1)) bad("bad top or albedo");
    if (!p.planck_levels.empty() && p.planck_levels.size() != p.layers.size() + 1)
        bad("planck_levels must have layers.size() + 1 values");
    double total = 0;
    for (const Layer& l : p.layers) total += l.tau;
    for (std::size_t i = 0; i < p.utau.size(); ++i)
        if (p.utau[i] < 0 || (i > 0 && p.utau[i] < p.utau[i - 1]) ||
            p.utau[i] > total * (1 + 1e-9) + 1e-12)
            bad("utau must ascend within [0, total optical depth]");
    for (double mu : p.umu)
        if (mu == 0 || std::abs(mu) > 1) bad("umu must be nonzero cosines");
    const ExactPhase& x = p.exact_phase;
    if (x.components > 0 && (!x.evaluate || x.weights.size() != x.components * p.layers.size()))
        bad("exact_phase: one weight per component and layer, and a function");
    if (!p.want.empty() && p.want.size() != p.utau.size()) bad("want: not one per utau");
    for (unsigned char w : p.want)
        if (w > Problem::kWantBoth) bad("want: not 0-3");
}

// Into s, whose storage is reused: each layer's optics are reset to their defaults (its
// moments' capacity kept) before they are set, so s holds what a new Scaled would.
void scale_layers(const Problem& p, Scaled& s) {
    const int N = p.streams;
    const std::size_t L = p.layers.size();
    s.optics.resize(L);
    s.f.assign(L, 0.0);
    s.tau_level.assign(L + 1, 0.0);
    s.tau_s_level.assign(L + 1, 0.0);
    for (std::size_t n = 0; n < L; ++n) {
        const Layer& l = p.layers[n];
        LayerOptics& o = s.optics[n];
        std::vector<double> g = std::move(o.g);
        o = LayerOptics{};
        o.g = std::move(g);
        auto mom = [&](int k) { return k < static_cast<int>(l.pmom.size()) ? l.pmom[k] : 0.0; };
        // f -> 1 (all scattering in the truncated peak) would divide by zero; such a
        // layer is kept just short of it (g* then carries no information anyway).
        const double f = p.delta_m ? std::min(mom(N), 1 - 1e-9) : 0.0;
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
            o.planck_slope =
                o.dtau > 0 ? (p.planck_levels[n + 1] - p.planck_levels[n]) / o.dtau : 0;
        }
    }
}

std::vector<Position> locate(const Problem& p, const Scaled& s) {
    std::vector<Position> out;
    const std::size_t L = p.layers.size();
    for (double ut : p.utau) {
        std::size_t n = 0;
        while (n + 1 < L && ut > s.tau_level[n + 1] * (1 + 1e-12)) ++n;
        const double ratio = s.optics[n].dtau / std::max(p.layers[n].tau, 1e-300);
        double t = std::clamp((ut - s.tau_level[n]) * (p.layers[n].tau > 0 ? ratio : 0), 0.0,
                              s.optics[n].dtau);
        // A depth within rounding of the layer's bottom is the bottom exactly, so that the
        // user-angle sweep can take the level's value instead of a partial-layer integral.
        if (s.optics[n].dtau - t <= 1e-12 * s.optics[n].dtau) t = s.optics[n].dtau;
        out.push_back({static_cast<int>(n), t});
    }
    return out;
}

// The particular solution (beam and thermal) of mode m: its intensity in stream a at
// scaled depth t of layer n.
struct Particular {
    const std::vector<LayerOptics>& opt;
    const std::vector<LayerSolution>& sol;
    int m;
    double operator()(int n, int a, double t) const {
        const LayerSolution& s = sol[n];
        return s.beam[a] * std::exp(-t * s.inv_mu0) + s.thermal0[a] +
               opt[n].planck_slope * t * (m == 0 ? 1 : 0);
    }
};

// Top: downward intensities at t = 0 of layer 0 (rows 0 to nn - 1).
void top_rows(const Problem& p, const Quadrature& q, const Particular& part, bool assemble,
              linalg::BandMatrix& band, std::vector<double>& x) {
    const int nn = q.nn;
    const std::vector<LayerSolution>& sol = part.sol;
    const double top = part.m == 0 ? p.top_isotropic + p.top_emission : 0.0;
    for (int i = 0; i < nn; ++i) {
        const int a = nn + i;
        for (int j = 0; j < nn && assemble; ++j) {
            band.at(i, j) = sol[0].dec(j, a);
            band.at(i, nn + j) = sol[0].grow(j, a) * sol[0].exp_k[j];
        }
        x[i] = top - part(0, a, 0);
    }
}

// Interfaces: every stream's intensity continuous from layer n's bottom to n + 1's top.
void interface_rows(const Quadrature& q, const Particular& part, bool assemble,
                    linalg::BandMatrix& band, std::vector<double>& x) {
    const int nn = q.nn, n2 = 2 * nn, L = static_cast<int>(part.sol.size());
    for (int n = 0; n + 1 < L; ++n) {
        const LayerSolution &u = part.sol[n], &d = part.sol[n + 1];
        for (int a = 0; a < n2; ++a) {
            const int r = nn + n * n2 + a;
            for (int j = 0; j < nn && assemble; ++j) {
                band.at(r, n * n2 + j) = u.dec(j, a) * u.exp_k[j];
                band.at(r, n * n2 + nn + j) = u.grow(j, a);
                band.at(r, (n + 1) * n2 + j) = -d.dec(j, a);
                band.at(r, (n + 1) * n2 + nn + j) = -d.grow(j, a) * d.exp_k[j];
            }
            x[r] = part(n + 1, a, 0) - part(n, a, part.opt[n].dtau);
        }
    }
}

// Bottom: I(+mu_i) - 2 albedo sum_k w_k mu_k I(-mu_k) = surface sources.
void bottom_rows(const Problem& p, const Quadrature& q, const Particular& part,
                 double beam_bottom, bool assemble, linalg::BandMatrix& band,
                 std::vector<double>& x) {
    const int nn = q.nn, n2 = 2 * nn, L = static_cast<int>(part.sol.size());
    const int nb = L - 1;
    const LayerSolution& b = part.sol[nb];
    const double dt = part.opt[nb].dtau;
    const double alb = part.m == 0 ? p.albedo : 0.0;
    double src = 0;
    if (part.m == 0)
        src = alb * p.beam_mu0 * beam_bottom / kPi + (1 - p.albedo) * p.planck_surface;
    double part_refl = 0;
    for (int k = 0; k < nn; ++k) part_refl += q.weight[k] * q.mu[k] * part(nb, nn + k, dt);
    for (int i = 0; i < nn; ++i) {
        const int r = nn + nb * n2 + i;
        for (int j = 0; j < nn && assemble; ++j) {
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
}

// Assembles and solves the boundary-value problem for one mode: top boundary, continuity
// at every interface, Lambertian bottom (Stamnes et al. 1988, eqs. 16-20), as a banded
// system with kl = ku = 3 nn - 1 (unknowns ordered layer by layer, decaying then growing).
// With `factored`, band already holds this system's factors: only the right-hand side
// is formed.
void solve_boundary(const Problem& p, const Quadrature& q, int m,
                    const std::vector<LayerOptics>& opt, const std::vector<LayerSolution>& sol,
                    double beam_bottom, bool factored, linalg::BandMatrix& band,
                    std::vector<double>& x) {
    const int nn = q.nn, n2 = 2 * nn, L = static_cast<int>(sol.size());
    const bool assemble = !factored;
    if (assemble) band.reset(L * n2, 3 * nn - 1, 3 * nn - 1);
    x.assign(L * n2, 0.0);
    const Particular part{opt, sol, m};
    top_rows(p, q, part, assemble, band, x);
    interface_rows(q, part, assemble, band, x);
    bottom_rows(p, q, part, beam_bottom, assemble, band, x);
    if (assemble && !band.factor())
        throw Error("discrete-ordinate solver: singular boundary-value system");
    band.solve(x.data());
}

// Mode 0 of the last solve on this thread: its layers' homogeneous solutions and the
// factors of its boundary-value system, with what they depend on (the key: streams,
// surface albedo and every scaled layer's optical depth, albedo and moments).
// build_radiance's coupling solve follows its solar solve on the same layers: it takes
// them instead of solving them again, bit for bit the same numbers. A solve of mode 0
// alone hands its own over (moved); one of several modes leaves a copy.
struct ModeZero {
    std::vector<double> key;
    std::vector<LayerSolution> sol;
    linalg::BandMatrix band;
};
thread_local ModeZero t_mode_zero;

// The storage (not the values) of the last solve on this thread, lent to the next one:
// its layer solutions, band matrix and scratch keep their capacity, so a solve of the
// same size allocates nothing for them. Every value is written again before it is read
// (solve_layer assigns each field of a layer's solution, BandMatrix::reset zeroes it).
struct Spare {
    std::vector<LayerSolution> sol;
    linalg::BandMatrix band;
    Scratch scratch;
    Scaled scaled;  // scale_layers sets every value
};
thread_local Spare t_spare;

std::vector<double> mode_zero_key(const Problem& p, const Scaled& s) {
    std::vector<double> key{static_cast<double>(p.streams), p.albedo};
    key.reserve(2 + s.optics.size() * (2 + static_cast<std::size_t>(p.streams)));
    for (const LayerOptics& o : s.optics) {
        key.push_back(o.dtau);
        key.push_back(o.ssa);
        key.insert(key.end(), o.g.begin(), o.g.end());
    }
    return key;
}

}  // namespace

void Solver::setup() {
    std::swap(m_sol, t_spare.sol);
    std::swap(m_band, t_spare.band);
    std::swap(m_scratch, t_spare.scratch);
    std::swap(m_s, t_spare.scaled);
    m_N = m_p.streams;
    m_L = static_cast<int>(m_p.layers.size());
    m_q.nn = m_N / 2;
    gauss_half_range(m_q.nn, m_q.mu, m_q.weight);
    scale_layers(m_p, m_s);
    m_pos = locate(m_p, m_s);
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        const unsigned char w = m_p.want.empty() ? static_cast<unsigned char>(Problem::kWantBoth)
                                                  : m_p.want[i];
        m_pos[i].up = (w & Problem::kWantUp) != 0;
        m_pos[i].down = (w & Problem::kWantDown) != 0;
    }
    m_sol.resize(m_L);
    m_us.resize(m_L);
    m_us_down.resize(m_L);
    m_mirror.assign(m_p.umu.size(), -1);
    for (std::size_t u = 0; u < m_p.umu.size(); ++u)
        for (std::size_t v = 0; v < m_p.umu.size(); ++v)
            if (m_p.umu[v] == -m_p.umu[u]) m_mirror[u] = static_cast<std::ptrdiff_t>(v);
    m_thermal = !m_p.planck_levels.empty();
    // The beam's path: plane-parallel tau / mu0 (kept to the bit), or pseudo-spherical.
    const bool sph = !m_p.beam_airmass.empty();
    m_beam_mu0.assign(m_L, m_p.beam_mu0);
    m_slant_s.assign(m_L + 1, 0.0);
    for (int n = 0; n <= m_L; ++n) {
        if (sph && n < m_L) m_beam_mu0[n] = 1 / m_p.beam_airmass[n];
        m_slant_s[n] = !sph ? m_s.tau_s_level[n] / m_p.beam_mu0
                       : n == 0
                           ? 0.0
                           : m_slant_s[n - 1] + m_p.beam_airmass[n - 1] * m_s.optics[n - 1].dtau;
    }
    for (int n = 0; n < m_L; ++n) m_s.optics[n].beam_top = m_p.beam_flux * std::exp(-m_slant_s[n]);
    const std::size_t nu = m_p.umu.size();
    m_trans.assign(m_L * nu, 0.0);
    for (int n = 0; n < m_L; ++n)
        for (std::size_t u = 0; u < nu; ++u)
            m_trans[n * nu + u] = std::exp(-m_s.optics[n].dtau / std::abs(m_p.umu[u]));
    m_result.levels.assign(m_p.utau.size(), LevelResult{});
    for (auto& lev : m_result.levels)
        lev.intensity.assign(m_p.umu.size() * m_p.phi_deg.size(), 0.0);
}

void Solver::solve_mode(int m) {
    detail::quadrature_legendre(m_q, m, m_N, m_lam);
    m_lam0.assign(m_N, 0.0);
    normalized_legendre(m, m_N - 1, -m_p.beam_mu0, m_lam0.data());
    // Without sources inside the layers, mode 0 of a system solved just before is reused
    // (ModeZero): its layers need no particular solutions, which would need the
    // eigen-decomposition's work arrays.
    const bool reuse = m == 0 && !(m_p.beam_flux > 0) && !m_thermal &&
                       t_mode_zero.key == m_mode_zero_key;
    if (reuse) {
        std::swap(m_sol, t_mode_zero.sol);
        std::swap(m_band, t_mode_zero.band);
        t_mode_zero.key.clear();
        for (int n = 0; n < m_L; ++n) {  // as solve_layer leaves a layer without sources
            LayerSolution& s = m_sol[n];
            s.beam.assign(2 * m_q.nn, 0.0);
            s.bmom.assign(s.nl, 0.0);
            s.inv_mu0 = m_beam_mu0[n] > 0 ? 1 / m_beam_mu0[n] : 0;
            s.exp_beam = std::exp(-m_s.optics[n].dtau * s.inv_mu0);
            s.thermal0.assign(2 * m_q.nn, 0.0);
            s.tmom.assign(s.nl, 0.0);
        }
    } else {
        for (int n = 0; n < m_L; ++n)
            detail::solve_layer(m_q, m, m_s.optics[n], m_lam.data(), m_beam_mu0[n],
                                m_lam0.data(), m_thermal, m_sol[n], m_scratch);
    }
    const double beam_bottom = m_p.beam_flux * std::exp(-m_slant_s[m_L]);
    solve_boundary(m_p, m_q, m, m_s.optics, m_sol, beam_bottom, reuse, m_band, m_x);
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
        if (m_p.beam_flux > 0 && m_p.beam_airmass.empty()) {
            direct = m_p.beam_flux * std::exp(-m_p.utau[i] / m_p.beam_mu0);
            direct_s = m_p.beam_flux * std::exp(-tau_s / m_p.beam_mu0);
        } else if (m_p.beam_flux > 0) {  // pseudo-spherical: along the layers' air masses
            const int n = ps.layer;
            const double a = m_p.beam_airmass[n];
            double slant = 0;
            for (int k = 0; k < n; ++k) slant += m_p.beam_airmass[k] * m_p.layers[k].tau;
            direct = m_p.beam_flux * std::exp(-(slant + a * (m_p.utau[i] - m_s.tau_level[n])));
            direct_s = m_p.beam_flux * std::exp(-(m_slant_s[n] + a * ps.t));
        }
        lev.direct_down = m_p.beam_mu0 * direct;
        lev.diffuse_down = 2 * kPi * down + m_p.beam_mu0 * (direct_s - direct);
        lev.diffuse_up = 2 * kPi * up;
        lev.mean_intensity = mean + (direct_s - direct) / (4 * kPi);
        const LayerOptics& o = m_s.optics[ps.layer];
        const double planck = m_thermal ? o.planck_top + o.planck_slope * ps.t : 0.0;
        // d(F_up - F_down)/d tau = (1 - omega) 4 pi (mean intensity incl. beam - B).
        lev.dfdt =
            (1 - m_p.layers[ps.layer].ssa) * 4 * kPi * (mean + direct_s / (4 * kPi) - planck);
    }
}

Result Solver::run() {
    setup();
    const bool beam = m_p.beam_flux > 0;
    const int modes = beam && !m_p.umu.empty() && !m_p.azimuth_mean ? m_N : 1;
    m_mode_zero_key = mode_zero_key(m_p, m_s);
    const std::size_t nu = m_p.umu.size(), nphi = m_p.phi_deg.size();
    std::vector<double> im, cos_m(nphi);
    int converged = 0;
    for (int m = 0; m < modes; ++m) {
        solve_mode(m);
        if (m == 0 && modes > 1) {  // mode 0 kept for the next solve (ModeZero), copied
            t_mode_zero.key = m_mode_zero_key;
            t_mode_zero.sol = m_sol;
            t_mode_zero.band = m_band;
        }
        if (m == 0) fluxes();
        if (nu == 0) continue;
        user_intensities(m, im);
        // Converged mode: |added| <= accuracy |total| wherever the total is nonzero
        // (compared without a division per value).
        const double acc = m_p.azimuth_accuracy;
        bool small = true;
        for (std::size_t f = 0; f < nphi; ++f)  // cos(0) = 1 exactly
            cos_m[f] =
                m == 0 ? 1.0 : std::cos(m * (m_p.phi_deg[f] - m_p.beam_phi0_deg) * kPi / 180);
        for (std::size_t i = 0; i < m_pos.size(); ++i)
            for (std::size_t u = 0; u < nu; ++u) {
                if (!m_pos[i].wants(m_p.umu[u])) continue;  // 0, and adds nothing
                double* total = &m_result.levels[i].intensity[u * nphi];
                const double a = im[i * nu + u];
                for (std::size_t f = 0; f < nphi; ++f) {
                    const double add = a * cos_m[f];
                    total[f] += add;
                    small &= total[f] == 0 || std::abs(add) <= acc * std::abs(total[f]);
                }
            }
        if (m > 0 && acc > 0) {
            converged = small ? converged + 1 : 0;
            if (converged >= 2) break;
        }
    }
    bool peaked = false;
    for (double f : m_s.f) peaked = peaked || f != 0;
    if (beam && m_p.delta_m && m_p.intensity_correction && peaked && nu > 0) {
        intensity_correction();
        if (m_p.secondary_correction) secondary_correction();
    }
    if (modes == 1) {  // the solve's mode 0 stays for the next one (ModeZero)
        t_mode_zero.key = std::move(m_mode_zero_key);
        std::swap(t_mode_zero.sol, m_sol);
        std::swap(t_mode_zero.band, m_band);
    }
    std::swap(m_sol, t_spare.sol);  // lent to the next solve (Spare)
    std::swap(m_band, t_spare.band);
    std::swap(m_scratch, t_spare.scratch);
    std::swap(m_s, t_spare.scaled);
    return std::move(m_result);
}

}  // namespace detail

Result solve(const Problem& problem) {
    detail::validate(problem);
    detail::Solver solver(problem);
    return solver.run();
}

}  // namespace sigchain::rt
