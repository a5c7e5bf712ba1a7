// The Nakajima-Tanaka intensity correction of the discrete-ordinate solver: TMS (the
// beam's single scattering with the exact phase function) and IMS (secondary scattering
// within the forward peak).
#include <algorithm>
#include <array>
#include <cmath>

#include "rt/quadrature.hpp"
#include "rt/solver.hpp"

namespace sigchain::rt::detail {

// Nakajima & Tanaka (1988, JQSRT 40, 51) TMS correction: the single-scattered beam
// computed with the truncated delta-M phase function is replaced by the one with the
// exact phase function, P(cos) omega / (1 - omega f) in the scaled medium (their eq. 13).
// The correction is sum_l P_l(cos scattering angle) e_l(level, mu), with
// e_l = sum_n d_nl T_n: d_nl the layer's moment difference, T_n the beam's path integral
// through layer n seen from the output level.
// d_nl of every layer: the beam's single-scattering source with the exact moments
// less the one with the truncated (delta-M) moments, [layer * nmom + l].
std::vector<double> Solver::moment_differences(std::size_t nmom) const {
    std::vector<double> d(m_L * nmom, 0.0);
    for (int n = 0; n < m_L; ++n) {
        const Layer& layer = m_p.layers[n];
        const LayerOptics& o = m_s.optics[n];
        for (std::size_t l = 0; l < nmom; ++l) {
            // With exact_phase, its part is added by add_exact_correction.
            const bool moments = m_p.exact_phase.components == 0;
            const double exact = moments && l < layer.pmom.size() ? layer.pmom[l] : 0.0;
            const double trunc = l < static_cast<std::size_t>(m_N) ? o.g[l] : 0.0;
            d[n * nmom + l] = m_p.beam_flux / (4 * kPi) * (2.0 * l + 1) *
                              (layer.ssa * exact / (1 - layer.ssa * m_s.f[n]) - o.ssa * trunc);
        }
    }
    return d;
}

// T_n for user cosine u seen from output depth ps: the beam path integral of layer n,
// attenuated to the output level (zero for layers on the far side).
void Solver::beam_path_integrals(std::size_t u, const Position& ps, std::vector<double>& tn) const {
    const std::size_t nu = m_p.umu.size();
    const double mu = m_p.umu[u];
    const int np = ps.layer;
    double mu0 = m_beam_mu0[np];  // the beam's decay cosine in the layer at hand
    std::fill(tn.begin(), tn.end(), 0.0);
    double atten = 1;
    const double dtp = m_s.optics[np].dtau;
    const double e0 = std::exp(-m_slant_s[np]);
    if (mu > 0) {
        tn[np] = e0 * exp_integral(-ps.t / mu0, -(1 / mu0 + 1 / mu), dtp - ps.t) / mu;
        atten = std::exp(-(dtp - ps.t) / mu);
        for (int n = np + 1; n < m_L; ++n) {
            const double dt = m_s.optics[n].dtau;
            mu0 = m_beam_mu0[n];
            tn[n] = atten * std::exp(-m_slant_s[n]) * exp_integral(0, -(1 / mu0 + 1 / mu), dt) / mu;
            atten *= m_trans[n * nu + u];
        }
    } else {
        tn[np] = e0 * exp_integral(ps.t / mu, -1 / mu - 1 / mu0, ps.t) / -mu;
        atten = std::exp(ps.t / mu);
        for (int n = np - 1; n >= 0; --n) {
            const double dt = m_s.optics[n].dtau;
            mu0 = m_beam_mu0[n];
            tn[n] = atten * std::exp(-m_slant_s[n]) * exp_integral(dt / mu, -1 / mu - 1 / mu0, dt) /
                    -mu;
            atten *= m_trans[n * nu + u];
        }
    }
}

// Adds sum_l P_l(cos scattering angle) e_l to user cosine u's intensities at every
// depth and azimuth. The Legendre recursion runs for all azimuths at once (the inner
// loops run over azimuth and vectorise); the sums accumulate in the same order as a
// per-azimuth loop would.
void Solver::add_correction(std::size_t u, const std::vector<double>& e, std::size_t nmom,
                            CorrectionScratch& w) {
    const std::size_t nphi = m_p.phi_deg.size(), npos = m_pos.size();
    const double mu = m_p.umu[u], mu0 = m_p.beam_mu0;
    for (std::size_t f = 0; f < nphi; ++f) {
        w.cs[f] = -mu * mu0 + std::sqrt((1 - mu * mu) * (1 - mu0 * mu0)) * w.cos_dphi[f];
        w.p0[f] = 1;
        w.p1[f] = w.cs[f];
    }
    for (std::size_t i = 0; i < npos; ++i)
        for (std::size_t f = 0; f < nphi; ++f)
            w.corr[i * nphi + f] = e[i * nmom] + w.cs[f] * e[i * nmom + 1];
    for (std::size_t l = 2; l < nmom; ++l) {
        const double ra = w.rec_a[l], rb = w.rec_b[l];
        for (std::size_t f = 0; f < nphi; ++f) {
            const double p2 = ra * w.cs[f] * w.p1[f] - rb * w.p0[f];
            w.p0[f] = w.p1[f];
            w.p1[f] = p2;
        }
        for (std::size_t i = 0; i < npos; ++i) {
            const double el = e[i * nmom + l];
            double* ci = &w.corr[i * nphi];
            for (std::size_t f = 0; f < nphi; ++f) ci[f] += w.p1[f] * el;
        }
    }
    for (std::size_t i = 0; i < npos; ++i)
        for (std::size_t f = 0; f < nphi; ++f)
            m_result.levels[i].intensity[u * nphi + f] += w.corr[i * nphi + f];
}

// With exact_phase: the factor of component c in layer n's TMS source,
// F / (4 pi) omega w_nc / (1 - omega f) (their eq. 13), [layer * components + c].
std::vector<double> Solver::exact_weights() const {
    const ExactPhase& x = m_p.exact_phase;
    std::vector<double> a(x.weights.size());
    for (int n = 0; n < m_L; ++n) {
        const double ssa = m_p.layers[n].ssa;
        const double k = m_p.beam_flux / (4 * kPi) * ssa / (1 - ssa * m_s.f[n]);
        for (std::size_t c = 0; c < x.components; ++c)
            a[n * x.components + c] = k * x.weights[n * x.components + c];
    }
    return a;
}

// Adds sum_c P_c(cos scattering angle) e_c (e: [level * components + c]) to user cosine
// u's intensities: the exact phase functions' part of the TMS correction.
void Solver::add_exact_correction(std::size_t u, const std::vector<double>& e,
                                  CorrectionScratch& w) {
    const ExactPhase& x = m_p.exact_phase;
    const std::size_t nphi = m_p.phi_deg.size(), nc = x.components;
    const double mu = m_p.umu[u], mu0 = m_p.beam_mu0;
    w.p0.resize(nc);
    const double sines = std::sqrt((1 - mu * mu) * (1 - mu0 * mu0));
    for (std::size_t f = 0; f < nphi; ++f) {
        const double cs = -mu * mu0 + sines * w.cos_dphi[f];
        x.evaluate(std::clamp(cs, -1.0, 1.0), w.p0.data());
        for (std::size_t i = 0; i < m_pos.size(); ++i) {
            double sum = 0;
            for (std::size_t c = 0; c < nc; ++c) sum += w.p0[c] * e[i * nc + c];
            m_result.levels[i].intensity[u * nphi + f] += sum;
        }
    }
}

namespace {

// Nodes of the midpoint rule in azimuth over [0, pi] for an exact phase function's
// azimuthal mean (Gauss-Chebyshev in the cosine of the scattering angle), 1 deg apart.
// On LOWTRAN 7's Mie functions (ln P piecewise linear in angle) the Hawkeye tables change
// by at most 1.4e-5 from 180 to 1440 nodes (9e-5 with 90, 2e-7 with 360), a
// seven-hundredth of --streams auto's default 1 %; tests/unit/rt/azimuth_mean_test.cpp.
constexpr int kMeanAzimuths = 180;

// cos((k + 1/2) pi / kMeanAzimuths), k < kMeanAzimuths: the nodes' cosines, made once.
const std::array<double, kMeanAzimuths>& mean_azimuth_cosines() {
    static const std::array<double, kMeanAzimuths> c = [] {
        std::array<double, kMeanAzimuths> v{};
        for (int k = 0; k < kMeanAzimuths; ++k) v[k] = std::cos((k + 0.5) * kPi / kMeanAzimuths);
        return v;
    }();
    return c;
}

// Legendre polynomials P_0 .. P_{n-1} at x: the solver's normalised functions of mode 0.
std::vector<double> legendre(double x, std::size_t n) {
    std::vector<double> p(n);
    if (n > 0) normalized_legendre(0, static_cast<int>(n) - 1, x, p.data());
    return p;
}

}  // namespace

// Problem::azimuth_mean: adds the mean over azimuth of user cosine u's TMS correction to
// its intensities at every azimuth. The moments' part by the addition theorem,
// mean P_l(cos Theta) = P_l(mu) P_l(-mu0) (cos Theta = -mu mu0 + sin sin0 cos phi); the
// exact phase functions' part (ex) by the midpoint rule in azimuth. p0: P_l(-mu0).
void Solver::add_mean_correction(std::size_t u, const std::vector<double>& e, std::size_t nmom,
                                 const std::vector<double>& ex, const std::vector<double>& p0) {
    const std::size_t nphi = m_p.phi_deg.size(), nc = m_p.exact_phase.components;
    const double mu = m_p.umu[u], mu0 = m_p.beam_mu0;
    const std::vector<double> pu = legendre(mu, nmom);
    std::vector<double> mean(nc, 0.0), v(nc);
    const double sines = std::sqrt((1 - mu * mu) * (1 - mu0 * mu0));
    // At mu = +-1 (or the beam at the zenith) the scattering angle is one for every azimuth.
    const int nodes = sines > 0 ? kMeanAzimuths : 1;
    const std::array<double, kMeanAzimuths>& cosines = mean_azimuth_cosines();
    std::array<double, kMeanAzimuths> xs{};  // the scattering angles' cosines
    for (int k = 0; k < nodes; ++k)
        xs[k] = std::clamp(-mu * mu0 + sines * (sines > 0 ? cosines[k] : 0.0), -1.0, 1.0);
    if (nc > 0 && m_p.exact_phase.mean) {
        m_p.exact_phase.mean(xs.data(), nodes, mean.data());
    } else if (nc > 0) {
        for (int k = 0; k < nodes; ++k) {
            m_p.exact_phase.evaluate(xs[k], v.data());
            for (std::size_t c = 0; c < nc; ++c) mean[c] += v[c] / nodes;
        }
    }
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        double add = 0;
        for (std::size_t l = 0; l < nmom; ++l) add += e[i * nmom + l] * pu[l] * p0[l];
        for (std::size_t c = 0; c < nc; ++c) add += ex[i * nc + c] * mean[c];
        for (std::size_t f = 0; f < nphi; ++f) m_result.levels[i].intensity[u * nphi + f] += add;
    }
}

void Solver::intensity_correction() {
    const std::size_t nu = m_p.umu.size(), nphi = m_p.phi_deg.size(), npos = m_pos.size();
    const std::size_t nc = m_p.exact_phase.components;
    std::size_t nmom = m_N;
    if (nc == 0)
        for (const Layer& l : m_p.layers) nmom = std::max(nmom, l.pmom.size());
    const std::vector<double> d = moment_differences(nmom);
    const std::vector<double> a = exact_weights();
    std::vector<double> tn(m_L), e(npos * nmom), ex(npos * nc);
    CorrectionScratch wx;
    if (!m_p.azimuth_mean) wx.cos_dphi = cos_dphi();  // azimuth means need no azimuths
    const std::vector<double> p0_mean =
        m_p.azimuth_mean ? legendre(-m_p.beam_mu0, nmom) : std::vector<double>{};
    CorrectionScratch w;
    w.cos_dphi = wx.cos_dphi;
    w.cs.resize(nphi), w.p0.resize(nphi), w.p1.resize(nphi), w.corr.resize(npos * nphi);
    w.rec_a.resize(nmom), w.rec_b.resize(nmom);  // P_l = ((2l-1) x P_{l-1} - (l-1) P_{l-2}) / l
    for (std::size_t l = 2; l < nmom; ++l)
        w.rec_a[l] = (2.0 * l - 1) / l, w.rec_b[l] = (l - 1.0) / l;
    for (std::size_t u = 0; u < nu; ++u) {
        const double mu = m_p.umu[u];
        if (std::none_of(m_pos.begin(), m_pos.end(), [&](const Position& p) { return p.wants(mu); }))
            continue;
        std::fill(e.begin(), e.end(), 0.0);
        for (std::size_t i = 0; i < npos; ++i) {
            if (!m_pos[i].wants(mu)) continue;
            beam_path_integrals(u, m_pos[i], tn);
            for (int n = 0; n < m_L; ++n) {
                if (tn[n] == 0) continue;
                for (std::size_t l = 0; l < nmom; ++l) e[i * nmom + l] += d[n * nmom + l] * tn[n];
            }
        }
        if (!m_p.azimuth_mean) add_correction(u, e, nmom, w);
        if (nc == 0) {
            if (m_p.azimuth_mean) add_mean_correction(u, e, nmom, ex, p0_mean);
            continue;
        }
        std::fill(ex.begin(), ex.end(), 0.0);
        for (std::size_t i = 0; i < npos; ++i) {
            if (!m_pos[i].wants(mu)) continue;
            beam_path_integrals(u, m_pos[i], tn);
            for (int n = 0; n < m_L; ++n)
                for (std::size_t c = 0; c < nc && tn[n] != 0; ++c)
                    ex[i * nc + c] += a[n * nc + c] * tn[n];
        }
        if (m_p.azimuth_mean)
            add_mean_correction(u, e, nmom, ex, p0_mean);
        else
            add_exact_correction(u, ex, wx);
    }
}

std::vector<double> Solver::cos_dphi() const {
    std::vector<double> c;
    for (double phi : m_p.phi_deg) c.push_back(std::cos((phi - m_p.beam_phi0_deg) * kPi / 180));
    return c;
}

namespace {

// Nakajima & Tanaka (1988) eq. 15's path factor (DISORT report's Xi, eq. A12): twice
// scattered light along a cosine mu2 (the beam's, in the scaled medium) seen at cosine
// mu1 below optical depth tau, int_0^tau e^{-(tau - s)/mu1} (s / mu2) e^{-s/mu2} ds / mu1.
double xi(double mu1, double mu2, double tau) {
    // int_0^tau s e^{-a s} ds = tau^2 (1/2 - z/3 + z^2/8 ...), z = a tau, near z = 0.
    const double a = 1 / mu2 - 1 / mu1;
    const double z = a * tau, e1 = std::exp(-tau / mu1);
    if (std::abs(z) < 1e-4) return e1 * tau * tau * (0.5 - z / 3 + z * z / 8) / (mu1 * mu2);
    return (e1 - (1 + z) * std::exp(-tau / mu2)) / (a * a * mu1 * mu2);
}

// P_spike = 2 P'' - P''*P'' at scattering cosine cs by its Legendre series,
// sum_k (2k + 1) g_k (2 - g_k) P_k(cs) over `terms` terms, g_k = 1 below the n_streams
// streams and g[k] beyond (the recurrence for P_k).
double spike_at(double cs, const std::vector<double>& g, std::size_t terms, int n_streams) {
    double p0 = 1, p1 = cs, spike = 1 + 3 * cs;
    for (std::size_t k = 2; k < terms; ++k) {
        const double p2 = ((2.0 * k - 1) * cs * p1 - (k - 1.0) * p0) / k;
        p0 = p1, p1 = p2;
        const double gk = k < static_cast<std::size_t>(n_streams) ? 1 : g[k];
        spike += gk * (2 - gk) * (2.0 * k + 1) * p2;
    }
    return spike;
}

// P_spike's mean over azimuth (the addition theorem): the same series with
// P_k(mu) P_k(-mu0) for P_k(cs); pu and p0 hold those P_k.
double spike_mean(const std::vector<double>& pu, const std::vector<double>& p0,
                  const std::vector<double>& g, std::size_t terms, int n_streams) {
    double spike = 1 + 3 * pu[1] * p0[1];
    for (std::size_t k = 2; k < terms; ++k) {
        const double gk = k < static_cast<std::size_t>(n_streams) ? 1 : g[k];
        spike += gk * (2 - gk) * (2.0 * k + 1) * pu[k] * p0[k];
    }
    return spike;
}

}  // namespace

// Nakajima & Tanaka (1988, JQSRT 40, 51) IMS correction (eqs. 14-15; DISORT report v1.1,
// Stamnes et al. 2000, eqs. A7-A13): near the beam direction the delta-M solution misses
// the light scattered twice within the truncated forward peak. Over the medium above the
// output depth (averaged: omega-bar, f-bar, eq. A15), the correction subtracts
// F / (4 pi) (f w)^2 / (1 - f w) P_spike(cos) Xi(|mu|, mu0 / (1 - f w), tau), with
// P_spike = 2 P'' - P''*P'', P'' the normalised peak whose moments are 1 below the
// streams and g_k = mean(omega pmom_k) / (f w) beyond. Applied where DISORT applies it:
// downward cosines within 10 deg of the beam's zenith angle, every azimuth.
void Solver::secondary_correction() {
    constexpr double kTiny = 1e-4;   // DISORT's: below it the correction is negligible
    constexpr double kAureole = 10;  // deg
    const std::size_t nu = m_p.umu.size(), nphi = m_p.phi_deg.size();
    const double mu0 = m_p.beam_mu0, theta0 = std::acos(-mu0) * 180 / kPi;
    std::size_t nmom = 0;
    for (const Layer& l : m_p.layers) nmom = std::max(nmom, l.pmom.size());
    std::vector<double> g(nmom);
    const std::vector<double> cosd = m_p.azimuth_mean ? std::vector<double>{} : cos_dphi();
    const std::size_t n_spike = std::max<std::size_t>(nmom, m_N);  // the spike's series
    const std::vector<double> p0_spike =
        m_p.azimuth_mean ? legendre(-mu0, n_spike) : std::vector<double>{};
    std::vector<char> aureole(nu);
    for (std::size_t u = 0; u < nu; ++u)
        aureole[u] = m_p.umu[u] < 0 &&
                     std::abs(std::acos(m_p.umu[u]) * 180 / kPi - theta0) <= kAureole;
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        if (!m_pos[i].down) continue;
        const int np = m_pos[i].layer;
        const double utau = m_p.utau[i];
        double w = 0, fw = 0, stau = 0;
        std::fill(g.begin(), g.end(), 0.0);
        for (int n = 0; n <= np; ++n) {
            const Layer& l = m_p.layers[n];
            const double dt = n < np ? l.tau : utau - m_s.tau_level[np];
            w += l.ssa * dt;
            fw += l.ssa * dt * m_s.f[n];
            stau += dt;
            for (std::size_t k = m_N; k < l.pmom.size(); ++k) g[k] += l.pmom[k] * l.ssa * dt;
        }
        if (w <= kTiny || fw <= kTiny || stau <= kTiny) continue;
        for (std::size_t k = m_N; k < nmom; ++k) g[k] /= fw;
        const double fwbar = fw / stau;  // f-bar omega-bar
        const double amp = m_p.beam_flux / (4 * kPi) * fwbar * fwbar / (1 - fwbar);
        const double mu0p = mu0 / (1 - fwbar);
        for (std::size_t u = 0; u < nu; ++u) {
            const double mu = m_p.umu[u];
            if (!aureole[u]) continue;
            const double x = amp * xi(-mu, mu0p, utau);
            if (m_p.azimuth_mean) {  // the spike's mean over azimuth: addition theorem
                const double spike = spike_mean(legendre(mu, n_spike), p0_spike, g, n_spike, m_N);
                for (std::size_t f = 0; f < nphi; ++f)
                    m_result.levels[i].intensity[u * nphi + f] -= x * spike;
                continue;
            }
            const double sines = std::sqrt((1 - mu * mu) * (1 - mu0 * mu0));
            for (std::size_t f = 0; f < nphi; ++f) {
                const double cs = -mu * mu0 + sines * cosd[f];
                m_result.levels[i].intensity[u * nphi + f] -= x * spike_at(cs, g, n_spike, m_N);
            }
        }
    }
}

}  // namespace sigchain::rt::detail
