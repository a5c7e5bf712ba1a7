// Refracted ray paths through spherical shells (see spherical_path.hpp).
#include "atmos/spherical_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/numeric.hpp"

namespace sigchain::atmos {

namespace {

// 16-point Gauss-Legendre nodes and weights on [0, 1] (Abramowitz & Stegun, table 25.4).
struct Gauss16 {
    std::array<double, 16> x{}, w{};
    Gauss16() {
        constexpr std::array<double, 8> xs{
            0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
            0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
        constexpr std::array<double, 8> ws{
            0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
            0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
        for (std::size_t i = 0; i < 8; ++i) {
            x[i] = 0.5 * (1 - xs[i]);
            x[15 - i] = 0.5 * (1 + xs[i]);
            w[i] = w[15 - i] = 0.5 * ws[i];
        }
    }
};
const Gauss16 kGauss;

// Value at fraction f of a layer of a quantity exponential between a and b (linear
// where either end is not positive).
double exp_between(double a, double b, double f) {
    if (a > 0 && b > 0) return a * std::pow(b / a, f);
    return a + (b - a) * f;
}

}  // namespace

double air_refractivity(double p_mb, double t_k) {
    constexpr double nu = cm1_from_um(0.55);
    constexpr double a = nu / 1.14e5, b = nu / 6.24e4;
    return (83.42 + 185.08 / (1 - a * a) + 4.11 / (1 - b * b)) * (p_mb * 288.15) /
           (1013.25 * t_k) * 1e-6;
}

Shells shells_from(const Profile& p, double radius_km, bool refraction) {
    Shells s;
    s.radius_km = radius_km;
    s.z_km = p.z_km;
    for (std::size_t k = 0; k < p.size(); ++k) {
        s.refractivity.push_back(refraction ? air_refractivity(p.p_mb[k], p.t_k[k]) : 0.0);
        s.density.push_back(air_number_density_cm3(p.p_mb[k], p.t_k[k]));
    }
    return s;
}

// In each layer the altitude is z = z_k + dz t^2 (t in [0, 1]), which removes the
// 1 / sqrt singularity of ds/dr at a grazing start (the tangent point) and leaves
// smooth integrands for 16-point Gauss-Legendre. Along the ray, with C = n0 r0 sin z0:
// ds/dr = n r / w and dpsi/dr = -C n' / (n w), w = sqrt((n r)^2 - C^2) (Born & Wolf,
// Principles of Optics, section 3.2.1; Smart, Spherical Astronomy, section 58), w
// written through n r - n0 r0 so that a huge radius keeps full precision.
namespace {

// The parts of trace_up's integrands that do not depend on the zenith angle, node by
// node (layer k from `from` up, Gauss point q): trace_to_sun's bisection evaluates
// the ray ~40 times over the same nodes. The ray is formed from them by the same
// operations in the same order as from scratch, so its bits do not depend on this.
struct PathNodes {
    std::size_t from = 0, to = 0;
    double n0r0 = 0;
    std::vector<double> nr2, dsum, rho, nr, dzdt, ndlnn, one_n;  // per node
};

// Layer k's nodes q (from 16 k + q on) of `all`, and the terms that depend on the start
// level `from`: n0 r0 and (n r - n0 r0)(n r + n0 r0).
PathNodes path_nodes(const Shells& s, const ShellNodes& all, std::size_t from, std::size_t to) {
    PathNodes p;
    p.from = from;
    p.to = to;
    const double R = s.radius_km, z0 = s.z_km[from], N0 = s.refractivity[from];
    p.n0r0 = (1 + N0) * (R + z0);
    const auto first = static_cast<long>(16 * from), last = static_cast<long>(16 * to);
    auto slice = [&](const std::vector<double>& v) {
        return std::vector<double>(v.begin() + first, v.begin() + last);
    };
    p.nr2 = slice(all.nr2);
    p.rho = slice(all.rho);
    p.nr = slice(all.nr);
    p.dzdt = slice(all.dzdt);
    p.ndlnn = slice(all.ndlnn);
    p.one_n = slice(all.one_n);
    for (long i = first; i < last; ++i) {
        const double z = all.z[i], N = all.n[i], nr = all.nr[i];
        const double d = (z - z0) + (N - N0) * (R + z0) + N * (z - z0);  // n r - n0 r0
        p.dsum.push_back(d * (nr + p.n0r0));
    }
    return p;
}

Ray trace_nodes(const PathNodes& p, std::size_t levels, double zenith_rad) {
    Ray ray;
    ray.zenith_rad = zenith_rad;
    ray.air_mass.assign(levels - 1, 0.0);
    const double sin0 = std::sin(zenith_rad), cos0 = std::cos(zenith_rad);
    const double sin2 = sin0 * sin0, cos2 = cos0 * cos0;
    const double C = p.n0r0 * sin0;
    for (std::size_t k = p.from, i = 0; k < p.to; ++k) {
        double slant = 0, vertical = 0;
        for (std::size_t q = 0; q < 16; ++q, ++i) {
            const double w = std::sqrt(std::max(0.0, p.nr2[i] * cos2 + p.dsum[i] * sin2));
            if (!(w > 0)) continue;  // a trapped (ducted) ray: no path beyond
            slant += p.rho[i] * p.nr[i] / w * p.dzdt[i];
            vertical += p.rho[i] * p.dzdt[i];
            ray.refraction_rad += -C * p.ndlnn[i] / (p.one_n[i] * w) * p.dzdt[i];
        }
        ray.air_mass[k] = vertical > 0 ? slant / vertical : 0.0;
    }
    return ray;
}

}  // namespace

ShellNodes shell_nodes(const Shells& s) {
    ShellNodes p;
    const double R = s.radius_km;
    for (std::size_t k = 0; k + 1 < s.z_km.size(); ++k) {
        const double dz = s.z_km[k + 1] - s.z_km[k];
        const double Na = s.refractivity[k], Nb = s.refractivity[k + 1];
        const double dlnN = Na > 0 && Nb > 0 ? std::log(Nb / Na) / dz : 0.0;  // km-1
        for (std::size_t q = 0; q < 16; ++q) {
            const double t = kGauss.x[q], f = t * t;
            const double z = s.z_km[k] + dz * f, dzdt = 2 * dz * t * kGauss.w[q];
            const double N = exp_between(Na, Nb, f);
            const double rho = exp_between(s.density[k], s.density[k + 1], f);
            const double nr = (1 + N) * (R + z);
            p.z.push_back(z);
            p.n.push_back(N);
            p.nr.push_back(nr);
            p.nr2.push_back(nr * nr);
            p.rho.push_back(rho);
            p.dzdt.push_back(dzdt);
            p.ndlnn.push_back(N * dlnN);
            p.one_n.push_back(1 + N);
        }
    }
    return p;
}

Ray trace_up(const Shells& s, std::size_t from, std::size_t to, double zenith_rad) {
    return trace_up(s, shell_nodes(s), from, to, zenith_rad);
}

Ray trace_up(const Shells& s, const ShellNodes& nodes, std::size_t from, std::size_t to,
             double zenith_rad) {
    const std::size_t levels = s.z_km.size();
    if (!(to > from && to < levels) || !(zenith_rad >= 0 && zenith_rad <= std::numbers::pi / 2))
        throw std::invalid_argument("trace_up: levels or zenith angle out of range");
    return trace_nodes(path_nodes(s, nodes, from, to), levels, zenith_rad);
}

Ray trace_to_sun(const Shells& s, std::size_t to, double true_zenith_rad) {
    return trace_to_sun(s, shell_nodes(s), to, true_zenith_rad);
}

namespace {

// The refraction R(z) grows with z, from R(0) = 0 (C = 0) to R(pi/2): a midpoint m
// with m + R(p) above the true zenith for a traced p <= m, or m + R(q) below it for
// a traced q >= m, by more than kSure, falls the same way as a trace of m would, so
// only the midpoints near the root are traced. The same intervals as tracing every
// midpoint, bit for bit, with a few traces instead of 40.
constexpr double kSure = 1e-13;  // rad: 400 times the rounding of m + R (2.2e-16)

using Traced = std::vector<std::pair<double, double>>;  // (z, R(z)) of the traced rays

// Points bracketing the root first, by z_k+1 = t - R(z_k) from z_0 = t: the root z*
// (z* + R(z*) = t) lies above t - R(t) (R(z*) <= R(t)), below t - R(z1) for z1 below
// it, and so on, each pair closer by a factor dR/dz (~1e-4 away from the horizon):
// after four traces the bracket is within rounding, and the midpoints' bounds decide
// them all but the last few. `seen(z)` traces the ray of apparent zenith z; r_horizon
// is R(pi/2).
template <class Seen>
void trace_bracket(const Seen& seen, double t, double r_horizon, Traced& traced) {
    const double half_pi = std::numbers::pi / 2;
    auto refraction = [&](double z) {
        const double r = seen(z).refraction_rad;
        traced.emplace_back(z, r);
        return r;
    };
    double z = std::min(t, half_pi);
    double r = z == half_pi ? r_horizon : refraction(z);
    for (int k = 0; k < 4; ++k) {
        const double next = std::clamp(t - r, 0.0, half_pi);
        if (std::abs(next - z) < kSure) break;
        z = next;
        r = refraction(z);
    }
}

// z + R(z) increases with z: bisection on [0, pi/2] to 1e-12 rad for the apparent
// zenith of true zenith t, tracing only the midpoints the traced bounds leave open.
template <class Seen>
double bisect_zenith(const Seen& seen, double t, double r_horizon, Traced& traced) {
    double a = 0, b = std::numbers::pi / 2;
    for (int it = 0; it < 60 && b - a > 1e-12; ++it) {
        const double m = 0.5 * (a + b);
        double r_below = 0, r_above = r_horizon;  // R at traced points <= m, >= m
        for (const auto& [zp, rp] : traced) {
            if (zp <= m) r_below = std::max(r_below, rp);
            if (zp >= m) r_above = std::min(r_above, rp);
        }
        if (m + r_below > t + kSure) {
            b = m;
        } else if (m + r_above < t - kSure) {
            a = m;
        } else {
            const Ray rm = seen(m);
            traced.emplace_back(m, rm.refraction_rad);
            (rm.zenith_rad + rm.refraction_rad > t ? b : a) = m;
        }
    }
    return 0.5 * (a + b);
}

}  // namespace

Ray trace_to_sun(const Shells& s, const ShellNodes& shell, std::size_t to, double true_zenith_rad) {
    const std::size_t top = s.z_km.size() - 1;
    if (to >= top) {  // at the top: no atmosphere above
        Ray ray;
        ray.zenith_rad = true_zenith_rad;
        ray.air_mass.assign(top, 0.0);
        ray.reaches = true_zenith_rad <= std::numbers::pi / 2;
        return ray;
    }
    const PathNodes nodes = path_nodes(s, shell, to, top);
    auto seen = [&](double z) { return trace_nodes(nodes, s.z_km.size(), z); };
    Ray hi = seen(std::numbers::pi / 2);
    if (true_zenith_rad > hi.zenith_rad + hi.refraction_rad) {
        hi.reaches = false;
        return hi;
    }
    Traced traced{{0.0, 0.0}, {std::numbers::pi / 2, hi.refraction_rad}};
    trace_bracket(seen, true_zenith_rad, hi.refraction_rad, traced);
    return seen(bisect_zenith(seen, true_zenith_rad, hi.refraction_rad, traced));
}

}  // namespace sigchain::atmos
