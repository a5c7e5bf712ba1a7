// First-order scattering of the beam (see single_scatter.hpp).
#include "atmos/single_scatter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/numeric.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kPi = std::numbers::pi;

// Legendre polynomials P_0..P_n at x, into out (size n + 1).
void legendre(double x, std::vector<double>& out) {
    out[0] = 1;
    if (out.size() > 1) out[1] = x;
    for (std::size_t k = 2; k < out.size(); ++k)
        out[k] = ((2 * k - 1) * x * out[k - 1] - (k - 1) * out[k - 2]) / k;
}

// Phase function sum (2k+1) pmom[k] P_k, normalised to 1 over 4 pi / (4 pi).
double phase(const std::vector<double>& pmom, const std::vector<double>& pk) {
    double s = 0;
    for (std::size_t k = 0; k < pmom.size(); ++k) s += (2 * k + 1) * pmom[k] * pk[k];
    return s;
}

// int_0^L exp(base + c s) ds, stable for base <= 0 and base + c L <= 0 (a series when
// c L is near 0: the resonance of a downward direction with the beam).
double exp_integral(double base, double c, double len) {
    const double z = c * len;
    if (std::abs(z) < 1e-3) return std::exp(base) * len * (1 + z * (0.5 + z * (1.0 / 6 + z / 24)));
    if (c > 0) return std::exp(base + z) * -std::expm1(-z) / c;
    return std::exp(base) * -std::expm1(z) / -c;
}

struct Column {
    std::vector<double> top;    // optical depth of each layer's top (from the top of the column)
    std::vector<double> slant;  // the beam's slant optical depth there (pseudo-spherical only)
    double total = 0;
};

Column column_of(const rt::Problem& p) {
    Column c;
    double slant = 0;
    for (std::size_t n = 0; n < p.layers.size(); ++n) {
        c.top.push_back(c.total);
        c.slant.push_back(slant);
        c.total += p.layers[n].tau;
        if (!p.beam_airmass.empty()) slant += p.beam_airmass[n] * p.layers[n].tau;
    }
    return c;
}

// The beam's slant optical depth at depth t in layer n: t / mu0 plane-parallel, else
// along the layers' air masses (rt::Problem::beam_airmass, pseudo-spherical).
double beam_slant(const rt::Problem& p, const Column& c, std::size_t n, double t) {
    if (p.beam_airmass.empty()) return t / p.beam_mu0;
    return c.slant[n] + p.beam_airmass[n] * (t - c.top[n]);
}

// Single-scattered intensity at depth t in direction cosine mu (> 0 up, < 0 down)
// per unit of omega F0 / (4 pi), with phase[n] the layer's phase function value at the
// direction's scattering angle.
double path_integral(const rt::Problem& p, const Column& c, double t, double mu,
                     const std::vector<double>& phase_n) {
    const double mu0 = p.beam_mu0, m = std::abs(mu);
    double sum = 0;
    for (std::size_t n = 0; n < p.layers.size(); ++n) {
        const rt::Layer& l = p.layers[n];
        if (!(l.tau > 0) || !(l.ssa > 0)) continue;
        double a = c.top[n], b = a + l.tau;
        // Up: the layers below t contribute; down: those above t.
        if (mu > 0)
            a = std::max(a, t);
        else
            b = std::min(b, t);
        if (!(b > a)) continue;
        // exp(-beam slant) along the beam, exp(-|s - t| / m) toward t, over s in [a, b].
        const double sa = beam_slant(p, c, n, a);
        const double inv = p.beam_airmass.empty() ? 1 / mu0 : p.beam_airmass[n];
        const double base = mu > 0 ? -sa - (a - t) / m : -sa - (t - a) / m;
        const double slope = mu > 0 ? -inv - 1 / m : -inv + 1 / m;
        sum += l.ssa * phase_n[n] * exp_integral(base, slope, b - a) / m;
    }
    return sum;
}

}  // namespace

rt::Result single_scattering(const rt::Problem& p) {
    const Column col = column_of(p);
    const double mu0 = p.beam_mu0, f0 = p.beam_flux;
    const double scale = f0 / (4 * kPi);
    std::size_t nmom = 1;
    for (const rt::Layer& l : p.layers) nmom = std::max(nmom, l.pmom.size());
    std::vector<double> pk(nmom), phase_n(p.layers.size());
    const rt::ExactPhase& x = p.exact_phase;
    std::vector<double> comp(x.components);
    auto phases = [&](double cos_theta) {
        const double c = std::clamp(cos_theta, -1.0, 1.0);
        if (x.components > 0) {  // the exact mixtures (IPH 2's Mie functions)
            x.evaluate(c, comp.data());
            for (std::size_t n = 0; n < p.layers.size(); ++n) {
                phase_n[n] = 0;
                for (std::size_t k = 0; k < comp.size(); ++k)
                    phase_n[n] += x.weights[n * comp.size() + k] * comp[k];
            }
            return;
        }
        legendre(c, pk);
        for (std::size_t n = 0; n < p.layers.size(); ++n) phase_n[n] = phase(p.layers[n].pmom, pk);
    };
    rt::Result r;
    const double s0 = std::sqrt(std::max(0.0, 1 - mu0 * mu0));
    for (double t : p.utau) {
        rt::LevelResult lv;
        std::size_t layer = 0;
        while (layer + 1 < p.layers.size() && t > col.top[layer + 1]) ++layer;
        lv.direct_down = f0 * mu0 * std::exp(-beam_slant(p, col, layer, t));
        for (double mu : p.umu) {
            const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
            for (double phi : p.phi_deg) {
                // Propagation (mu, phi) against the beam's (-mu0, phi0).
                phases(-mu * mu0 + s * s0 * std::cos((phi - p.beam_phi0_deg) * kRadPerDeg));
                lv.intensity.push_back(scale * path_integral(p, col, t, mu, phase_n));
            }
        }
        // Downward flux: 2 pi int_0^1 I(-m) m dm with the azimuth-averaged phase
        // function sum (2k+1) pmom_k P_k(m) P_k(mu0).
        std::vector<double> nodes, weights;
        rt::gauss_half_range(64, nodes, weights);
        std::vector<double> p0(nmom), pm(nmom);
        legendre(mu0, p0);
        for (std::size_t q = 0; q < nodes.size(); ++q) {
            legendre(nodes[q], pm);
            for (std::size_t k = 0; k < nmom; ++k) pk[k] = p0[k] * pm[k];
            for (std::size_t n = 0; n < p.layers.size(); ++n)
                phase_n[n] = phase(p.layers[n].pmom, pk);
            lv.diffuse_down += 2 * kPi * weights[q] * nodes[q] * scale *
                               path_integral(p, col, t, -nodes[q], phase_n);
        }
        r.levels.push_back(std::move(lv));
    }
    return r;
}

}  // namespace sigchain::atmos
