// The angular shape of reflection: a cosine (diffuse) part plus a specular lobe about
// the mirror direction, normalised over the facet's hemisphere (brdf.hpp; mat(5),
// REFLECTANCE MODELS; White (1996), section 3.6.5 and 5.2.1-5.2.3).
#include "radiometry/brdf.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "core/numeric.hpp"
#include "radiometry/brdf_table.hpp"

namespace sigchain::radiometry {

namespace {

constexpr double kPi = std::numbers::pi;
// m(theta_o) is tabulated on a uniform grid of u = cos(theta_o) in [0, 1]: m is an even
// function of theta_o, hence smooth in u at normal incidence, and the grid is densest
// in angle near grazing, where narrow lobes cross the horizon (step 1/2048 in u is
// 0.028 deg in angle at grazing).
constexpr int kTableSteps = 2048;
// Gauss-Legendre nodes per piece of the quadrature of the part of the lobe that
// straddles the horizon (m()).
constexpr int kQuadratureNodes = 20;
// A LinearCone row radius below this (deg) is raised to it: a zero radius would be a
// delta lobe, which the `dirsig` model (Delta) represents instead.
constexpr double kMinConeRadiusDeg = 0.05;

// 1 - sin(r) / r without cancellation for small r (series r^2/6 - r^4/120 + r^6/5040).
double one_minus_sinc(double r) {
    if (r < 1e-2) {
        double r2 = r * r;
        return r2 / 6 - r2 * r2 / 120 + r2 * r2 * r2 / 5040;
    }
    return 1 - std::sin(r) / r;
}

double clamp_unit(double x) { return std::clamp(x, -1.0, 1.0); }

// Gauss-Legendre nodes and weights on [-1, 1]: roots of P_n by Newton's method from
// the Chebyshev-like guesses cos(pi (i + 0.75) / (n + 0.5)) (Abramowitz & Stegun 25.4.29).
struct GaussLegendre {
    std::array<double, kQuadratureNodes> x{}, w{};
    GaussLegendre() {
        const int n = kQuadratureNodes;
        for (int i = 0; i < n; ++i) {
            double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = z;  // P_0, P_1, then the three-term recurrence
                for (int k = 2; k <= n; ++k) {
                    double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                    p0 = p1, p1 = p2;
                }
                dp = n * (z * p1 - p0) / (z * z - 1);  // P_n'
                double dz = p1 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-15) break;
            }
            x[i] = z;
            w[i] = 2 / ((1 - z * z) * dp * dp);
        }
    }
};

const GaussLegendre& gauss_legendre() {
    static const GaussLegendre g;
    return g;
}

}  // namespace

// Lobe parameters and tables. A lobe is a density p(alpha) per steradian about the
// mirror direction with Int p d(omega) = 1 over the sphere; `cdf(alpha)` is the
// fraction of it within alpha of the mirror direction.
struct Brdf::Impl {
    LobeShape shape = LobeShape::None;
    double half_angle_rad = 0;           // Uniform
    double cos_half_angle = 1;           // Uniform
    double uniform_density = 0;          // Uniform: 1 / (2 pi (1 - cos h))
    std::array<double, 7> radius_rad{};  // LinearCone rows at 0, 15, ..., 90 deg
    double exponent = 0;                 // CosinePower: n
    double k_per_rad = 0;                // Exponential: 1 / width
    double exp_norm = 0;                 // Exponential: (1 + k^2) / (2 pi (1 + exp(-k pi)))
    // table[i] for u = i / kTableSteps: 1 / m(theta_o) (LinearCone: with its radius
    // r(theta_o) at that u).
    std::vector<double> table;
    std::shared_ptr<const TableLobe> tabulated;  // Table

    // Cone radius (rad) for a viewer at theta_o (rad): linear between the rows.
    double cone_radius(double theta_o_rad) const {
        double x = std::clamp(theta_o_rad / (15 * kRadPerDeg), 0.0, 6.0);
        int i = std::min(static_cast<int>(x), 5);
        double f = x - i;
        return radius_rad[i] + f * (radius_rad[i + 1] - radius_rad[i]);
    }
    // Support of the lobe: p(alpha) = 0 beyond (rad).
    double alpha_max(double radius) const {
        switch (shape) {
            case LobeShape::Uniform:
                return half_angle_rad;
            case LobeShape::LinearCone:
                return radius;
            case LobeShape::CosinePower:
                return kPi / 2;
            default:
                return kPi;
        }
    }
    // Normalised density per sr at alpha (rad); `radius` for LinearCone.
    double density(double alpha, double radius) const {
        switch (shape) {
            case LobeShape::Uniform:
                return alpha < half_angle_rad ? uniform_density : 0;
            case LobeShape::LinearCone:
                return alpha < radius ? (1 - alpha / radius) / (2 * kPi * one_minus_sinc(radius))
                                      : 0;
            case LobeShape::CosinePower:
                return alpha < kPi / 2
                           ? (exponent + 1) / (2 * kPi) * std::pow(std::cos(alpha), exponent)
                           : 0;
            case LobeShape::Exponential:
                return exp_norm * std::exp(-k_per_rad * alpha);
            default:
                return 0;
        }
    }
    // Fraction of the lobe within alpha (rad) of its axis (closed forms of
    // Int_0^alpha p 2 pi sin a da).
    double cdf(double alpha, double radius) const {
        alpha = std::clamp(alpha, 0.0, alpha_max(radius));
        switch (shape) {
            case LobeShape::Uniform:
                return (1 - std::cos(alpha)) / (1 - cos_half_angle);
            case LobeShape::LinearCone:
                // Int_0^a (1 - x/r) sin x dx = 1 - cos a - (sin a - a cos a) / r.
                return (1 - std::cos(alpha) -
                        (std::sin(alpha) - alpha * std::cos(alpha)) / radius) /
                       one_minus_sinc(radius);
            case LobeShape::CosinePower:
                return 1 - std::pow(std::cos(alpha), exponent + 1);
            case LobeShape::Exponential: {
                // Int_0^a e^(-k x) sin x dx = (1 - e^(-k a) (k sin a + cos a)) / (1 + k^2).
                double k = k_per_rad;
                return (1 - std::exp(-k * alpha) * (k * std::sin(alpha) + std::cos(alpha))) /
                       (1 + std::exp(-k * kPi));
            }
            default:
                return 0;
        }
    }
    // alpha (rad) with cdf(alpha) = u: closed form or safeguarded Newton.
    double inverse_cdf(double u, double radius) const {
        if (shape == LobeShape::Uniform) return std::acos(1 - u * (1 - cos_half_angle));
        if (shape == LobeShape::CosinePower) return std::acos(std::pow(u, 1 / (exponent + 1)));
        double lo = 0, hi = alpha_max(radius), a = 0.5 * (lo + hi);
        for (int it = 0; it < 60; ++it) {
            double f = cdf(a, radius) - u;
            if (f > 0)
                hi = a;
            else
                lo = a;
            double d = density(a, radius) * 2 * kPi * std::sin(a);
            double next = d > 0 ? a - f / d : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::abs(next - a) < 1e-13) return next;
            a = next;
        }
        return a;
    }
    // m(theta_o): the part of the lobe above the horizon, its axis at zenith theta_r.
    // A ring at alpha about the axis lies above the horizon for the fraction
    // acos(-cot(theta_r) cot(alpha)) / pi of its azimuths when |90 - theta_r| < alpha
    // < 90 + theta_r, all of it below that range, none above. The straddling range is
    // cut at the lobe's quantiles `quantile_alpha` (so a narrow lobe gets its own
    // pieces) and geometrically near its start, and each piece integrated with the substitution
    // alpha = lo + (hi - lo) (1 - cos t)/2 and Gauss-Legendre in t, which removes the square-root
    // behaviour of the fraction at the ends of the range.
    double mass_above_horizon(double theta_r, double radius,
                              const std::vector<double>& quantile_alpha) const {
        double amax = alpha_max(radius);
        double a1 = kPi / 2 - theta_r, a2 = std::min(kPi / 2 + theta_r, amax);
        double mass = cdf(std::min(a1, amax), radius);
        if (a2 <= a1) return mass;
        double ct = std::cos(theta_r), st = std::sin(theta_r);
        std::vector<double> edges{a1};
        for (double a : quantile_alpha)
            if (a > a1 && a < a2) edges.push_back(a);
        // Near grazing (a1 small) the fraction falls from 1 to about 1/2 within a few
        // a1 of a1: pieces at 2, 8, 32, ... a1 resolve that.
        for (double a = 2 * a1; a1 > 0 && a < a2; a *= 4) edges.push_back(a);
        edges.push_back(a2);
        std::sort(edges.begin(), edges.end());
        const GaussLegendre& gl = gauss_legendre();
        double sum = 0;
        for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
            double lo = edges[p], hi = edges[p + 1];
            for (int i = 0; i < kQuadratureNodes; ++i) {
                double t = 0.5 * kPi * (gl.x[i] + 1), dt = 0.5 * kPi * gl.w[i];
                double alpha = lo + (hi - lo) * 0.5 * (1 - std::cos(t));
                double dalpha = (hi - lo) * 0.5 * std::sin(t) * dt;
                double c = -ct * std::cos(alpha) / (st * std::sin(alpha));
                double fraction = std::acos(clamp_unit(c)) / kPi;
                sum += density(alpha, radius) * fraction * 2 * kPi * std::sin(alpha) * dalpha;
            }
        }
        return mass + sum;
    }
    std::vector<double> quantiles(double radius) const {
        std::vector<double> out;
        for (double q : {0.3, 0.6, 0.85, 0.95, 0.99, 0.999}) out.push_back(inverse_cdf(q, radius));
        return out;
    }
    void build_table() {
        table.resize(kTableSteps + 1);
        std::vector<double> q;
        for (int i = 0; i <= kTableSteps; ++i) {
            double theta = std::acos(static_cast<double>(i) / kTableSteps);
            double radius = shape == LobeShape::LinearCone ? cone_radius(theta) : 0;
            if (i == 0 || shape == LobeShape::LinearCone) q = quantiles(radius);
            double m = mass_above_horizon(theta, radius, q);
            table[i] = 1 / m;
        }
    }
    double table_at(double u) const {
        double x = std::clamp(u, 0.0, 1.0) * kTableSteps;
        int i = std::min(static_cast<int>(x), kTableSteps - 1);
        double f = x - i;
        return table[i] + f * (table[i + 1] - table[i]);
    }
    bool lobed() const { return shape != LobeShape::None && shape != LobeShape::Delta; }
    // lobe(alpha) / m(theta_o) for wi, wo in the facet frame (wi above the horizon).
    double lobe_over_mass(const geo::Vec3& wi, const geo::Vec3& wo) const {
        double c = clamp_unit(-wi[0] * wo[0] - wi[1] * wo[1] + wi[2] * wo[2]);  // cos alpha
        double u = wo[2];
        switch (shape) {
            case LobeShape::Uniform:
                return c > cos_half_angle ? uniform_density * table_at(u) : 0;
            case LobeShape::CosinePower:
                return c > 0 ? (exponent + 1) / (2 * kPi) * std::pow(c, exponent) * table_at(u) : 0;
            case LobeShape::Exponential:
                return exp_norm * std::exp(-k_per_rad * std::acos(c)) * table_at(u);
            case LobeShape::LinearCone: {
                double radius = cone_radius(std::acos(std::clamp(u, 0.0, 1.0)));
                double alpha = std::acos(c);
                return alpha < radius ? density(alpha, radius) * table_at(u) : 0;
            }
            case LobeShape::Table:
                return tabulated->weight(wi, wo);
            default:
                return 0;
        }
    }
};

namespace {

// Lobes already built, by shape and parameters: building one costs some ms (its m
// table), and a scene's materials often share a lobe. Built under the lock, so
// concurrent loads are safe. Stored type-erased (Brdf::Impl is private).
using LobeKey = std::tuple<LobeShape, std::array<double, 7>>;

template <class Build>
std::shared_ptr<const void> cached_lobe(const LobeKey& key, Build build) {
    static std::mutex mutex;
    static std::map<LobeKey, std::shared_ptr<const void>> cache;
    std::lock_guard lock(mutex);
    auto& slot = cache[key];
    if (!slot) slot = build();
    return slot;
}

}  // namespace

Brdf Brdf::lambertian() { return Brdf(); }

Brdf Brdf::delta() {
    Brdf b;
    auto impl = std::make_shared<Impl>();
    impl->shape = LobeShape::Delta;
    b.m_impl = impl;
    return b;
}

Brdf Brdf::cone(double half_angle_deg) {
    if (!(half_angle_deg > 0 && half_angle_deg <= 180))
        throw std::invalid_argument("Brdf::cone: half angle must be in (0, 180] deg");
    Brdf b;
    b.m_impl = std::static_pointer_cast<const Impl>(
        cached_lobe({LobeShape::Uniform, {half_angle_deg}}, [&] {
            auto impl = std::make_shared<Impl>();
            impl->shape = LobeShape::Uniform;
            impl->half_angle_rad = half_angle_deg * kRadPerDeg;
            impl->cos_half_angle = std::cos(impl->half_angle_rad);
            impl->uniform_density = 1 / (2 * kPi * (1 - impl->cos_half_angle));
            impl->build_table();
            return std::shared_ptr<const void>(impl);
        }));
    return b;
}

Brdf Brdf::linear_cone(const std::array<double, 7>& base_radius_deg) {
    for (double r : base_radius_deg)
        if (!(r >= 0 && r <= 180))
            throw std::invalid_argument("Brdf::linear_cone: radius must be in [0, 180] deg");
    Brdf b;
    b.m_impl = std::static_pointer_cast<const Impl>(
        cached_lobe({LobeShape::LinearCone, base_radius_deg}, [&] {
            auto impl = std::make_shared<Impl>();
            impl->shape = LobeShape::LinearCone;
            for (int i = 0; i < 7; ++i)
                impl->radius_rad[i] = std::max(base_radius_deg[i], kMinConeRadiusDeg) * kRadPerDeg;
            impl->build_table();
            return std::shared_ptr<const void>(impl);
        }));
    return b;
}

Brdf Brdf::linear_cone(const std::array<double, 7>& base_radius_deg,
                       const std::array<double, 7>& depth) {
    for (double d : depth)
        if (!(d >= 0 && d <= 1))
            throw std::invalid_argument("Brdf::linear_cone: depth must be in [0, 1]");
    Brdf b = linear_cone(base_radius_deg);
    b.m_depth = std::make_shared<const std::array<double, 7>>(depth);
    return b;
}

// a_s = 2 alpha (1 - sin(beta)/beta): Int_0^beta (alpha/pi)(1 - phi/beta) 2 pi sin(phi) d(phi)
// = 2 alpha [1 - cos(beta) - (sin(beta) - beta cos(beta))/beta] (White (1996), section 3's
// cone), with the lobe's own radius (cone_radius, so a_s and the shape agree).
double Brdf::depth_albedo(double cos_theta_o) const {
    if (!m_depth) return 0;
    const double theta = std::acos(std::clamp(cos_theta_o, 0.0, 1.0));
    const double x = std::clamp(theta / (15 * kRadPerDeg), 0.0, 6.0);
    const int i = std::min(static_cast<int>(x), 5);
    const double f = x - i;
    const double alpha = (*m_depth)[i] + f * ((*m_depth)[i + 1] - (*m_depth)[i]);
    return 2 * alpha * one_minus_sinc(m_impl->cone_radius(theta));
}

Brdf Brdf::phong(double exponent) {
    if (!(exponent >= 0)) throw std::invalid_argument("Brdf::phong: exponent must be >= 0");
    Brdf b;
    b.m_impl =
        std::static_pointer_cast<const Impl>(cached_lobe({LobeShape::CosinePower, {exponent}}, [&] {
            auto impl = std::make_shared<Impl>();
            impl->shape = LobeShape::CosinePower;
            impl->exponent = exponent;
            impl->build_table();
            return std::shared_ptr<const void>(impl);
        }));
    return b;
}

Brdf Brdf::exponential(double width_deg) {
    if (!(width_deg > 0)) throw std::invalid_argument("Brdf::exponential: width must be > 0");
    Brdf b;
    b.m_impl = std::static_pointer_cast<const Impl>(
        cached_lobe({LobeShape::Exponential, {width_deg}}, [&] {
            auto impl = std::make_shared<Impl>();
            impl->shape = LobeShape::Exponential;
            double k = 1 / (width_deg * kRadPerDeg);
            impl->k_per_rad = k;
            // Int_sphere e^(-k alpha) = 2 pi (1 + e^(-k pi)) / (1 + k^2).
            impl->exp_norm = (1 + k * k) / (2 * kPi * (1 + std::exp(-k * kPi)));
            impl->build_table();
            return std::shared_ptr<const void>(impl);
        }));
    return b;
}

Brdf Brdf::table(const io::BrdfTable& table) {
    auto impl = std::make_shared<Impl>();
    impl->shape = LobeShape::Table;
    impl->tabulated = std::make_shared<const TableLobe>(table);
    Brdf b;
    b.m_impl = impl;
    return b;
}

LobeShape Brdf::shape() const { return m_impl ? m_impl->shape : LobeShape::None; }

bool Brdf::is_delta() const { return shape() == LobeShape::Delta; }

// w = (1 - s) cos(theta_i) / pi + s lobe(alpha) / m(theta_o) (brdf.hpp). Lambertian and
// Delta have no lobe here: Lambertian ignores s (its specularity is 0), Delta leaves
// the s part to the caller.
double Brdf::weight(const geo::Vec3& wi, const geo::Vec3& wo, double specularity) const {
    if (wi[2] <= 0) return 0;
    if (!m_impl || m_impl->shape == LobeShape::None) return wi[2] / kPi;
    double diffuse = (1 - specularity) * wi[2] / kPi;
    if (!m_impl->lobed() || specularity <= 0) return diffuse;
    return diffuse + specularity * m_impl->lobe_over_mass(wi, wo);
}

double Brdf::lobe_weight(const geo::Vec3& wi, const geo::Vec3& wo) const {
    if (wi[2] <= 0 || !m_impl || !m_impl->lobed()) return 0;
    return m_impl->lobe_over_mass(wi, wo);
}

namespace {

// Unit vector at (alpha, phi) about unit axis `a`, phi measured from any fixed
// perpendicular (Frisvad-style branchless basis; the sign avoids the singularity).
geo::Vec3 about_axis(const geo::Vec3& a, double alpha, double phi) {
    double sign = std::copysign(1.0, a[2]);
    double p = -1 / (sign + a[2]);
    double q = a[0] * a[1] * p;
    geo::Vec3 t{1 + sign * a[0] * a[0] * p, sign * q, -sign * a[0]};
    geo::Vec3 b{q, sign + a[1] * a[1] * p, -a[1]};
    double sa = std::sin(alpha), ca = std::cos(alpha);
    double cp = std::cos(phi), sp = std::sin(phi);
    geo::Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = sa * (cp * t[i] + sp * b[i]) + ca * a[i];
    return v;
}

}  // namespace

// Mixture sampling: a cosine direction (Malley's method) with probability 1 - s, a lobe
// direction (alpha by the lobe's inverse CDF, azimuth uniform) with probability s.
// Lambertian and Delta: cosine only (Delta's mirror term is the caller's).
BrdfSample Brdf::sample(const geo::Vec3& wo, double specularity, double u1, double u2,
                        double u3) const {
    BrdfSample out;
    bool lobe = m_impl && m_impl->lobed() && u1 < specularity;
    if (lobe && m_impl->shape == LobeShape::Table) {
        out.wi = m_impl->tabulated->sample(wo, u1 / specularity, u2, u3);
    } else if (lobe) {
        geo::Vec3 axis = mirror(wo);
        double radius = m_impl->shape == LobeShape::LinearCone
                            ? m_impl->cone_radius(std::acos(std::clamp(wo[2], 0.0, 1.0)))
                            : 0;
        double alpha = m_impl->inverse_cdf(u2, radius);
        out.wi = about_axis(axis, alpha, 2 * kPi * u3);
    } else {
        double r = std::sqrt(u2), phi = 2 * kPi * u3;
        out.wi = {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u2))};
    }
    out.pdf = pdf(out.wi, wo, specularity);
    return out;
}

double Brdf::pdf(const geo::Vec3& wi, const geo::Vec3& wo, double specularity) const {
    double cosine = std::max(0.0, wi[2]) / kPi;
    if (!m_impl || !m_impl->lobed()) return cosine;
    double s = std::clamp(specularity, 0.0, 1.0);
    double p = (1 - s) * cosine;
    if (s <= 0) return p;
    if (m_impl->shape == LobeShape::Table) return p + s * m_impl->tabulated->pdf(wi, wo);
    double c = clamp_unit(-wi[0] * wo[0] - wi[1] * wo[1] + wi[2] * wo[2]);
    double radius = m_impl->shape == LobeShape::LinearCone
                        ? m_impl->cone_radius(std::acos(std::clamp(wo[2], 0.0, 1.0)))
                        : 0;
    return p + s * m_impl->density(std::acos(c), radius);
}

}  // namespace sigchain::radiometry
