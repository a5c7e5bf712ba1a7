// Brdf: energy conservation of every lobe by brute-force quadrature, lobe normalisation
// over the sphere, and importance sampling (Monte Carlo mean of w/pdf, alpha histogram).
#include "radiometry/brdf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

namespace sigchain::radiometry {
namespace {

using geo::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

struct Case {
    std::string name;
    Brdf brdf;
    double support_deg;  // the lobe is 0 beyond this angle from the mirror direction
    double width_deg;    // its angular scale (quadrature breakpoints); for the linear
                         // cone, the radius at normal incidence
};

std::vector<Case> lobes() {
    return {
        {"cone 5", Brdf::cone(5), 5, 5},
        {"cone 40", Brdf::cone(40), 40, 40},
        {"linear cone", Brdf::linear_cone({4, 6, 8, 12, 20, 30, 45}), 45, 4},
        {"phong 2", Brdf::phong(2), 90, 40},
        {"phong 50", Brdf::phong(50), 90, 8},
        {"phong 1000", Brdf::phong(1000), 90, 1.8},
        {"exponential 3", Brdf::exponential(3), 180, 3},
        {"exponential 30", Brdf::exponential(30), 180, 30},
    };
}

Vec3 viewer(double theta_o_deg) {
    return {std::sin(theta_o_deg * kDeg), 0, std::cos(theta_o_deg * kDeg)};
}

// Unit vector at angle alpha from unit axis a (in the plane of a and a fixed
// perpendicular rotated by phi).
Vec3 about(const Vec3& a, double alpha, double phi) {
    // Perpendiculars of a = (sin t, 0, cos t): (cos t, 0, -sin t) and (0, 1, 0).
    Vec3 t{a[2], 0, -a[0]}, b{0, 1, 0};
    double n = std::hypot(t[0], t[2]);
    t = {t[0] / n, 0, t[2] / n};
    Vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = std::sin(alpha) * (std::cos(phi) * t[i] + std::sin(phi) * b[i]) +
               std::cos(alpha) * a[i];
    return v;
}

// Midpoint quadrature over the whole sphere in coordinates (alpha, phi) about the
// mirror direction, alpha split at 1, 3, 10 and 30 lobe widths and at the lobe's
// support (so its edge is a cell edge and narrow lobes get dense nodes), n_alpha nodes
// per piece. f takes a direction.
template <class F>
double sphere_integral(const Vec3& axis, const Case& c, F f, int n_alpha = 300, int n_phi = 2000) {
    double sum = 0, dphi = 2 * kPi / n_phi;
    std::vector<double> edges{0};
    for (double k : {1.0, 3.0, 10.0, 30.0})
        if (k * c.width_deg < c.support_deg) edges.push_back(k * c.width_deg * kDeg);
    edges.push_back(c.support_deg * kDeg);
    if (c.support_deg < 180) edges.push_back(kPi);
    for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
        double lo = edges[e], hi = edges[e + 1];
        double da = (hi - lo) / n_alpha;
        for (int i = 0; i < n_alpha; ++i) {
            double alpha = lo + (i + 0.5) * da, ring = 0;
            for (int j = 0; j < n_phi; ++j) ring += f(about(axis, alpha, (j + 0.5) * dphi));
            sum += ring * dphi * std::sin(alpha) * da;
        }
    }
    return sum;
}

TEST(Brdf, EveryLobeConservesEnergyOverTheHemisphere) {
    // Int_hemisphere w(wi, wo) d(omega_i) = 1 for any s: the reference is the conservation
    // law itself. Tolerance: the facet horizon cuts the rings of the quadrature, and the
    // midpoint rule misclassifies at most one phi cell at each end of a ring, i.e. at
    // most 2 / n_phi = 1e-3 of the lobe's mass (n_phi = 2000) in the worst case; the
    // alpha rule on the smooth pieces is far more accurate. The 0.5 deg viewer puts a
    // narrow lobe's peak on the horizon, the hardest case for m(theta_o). s = 0 and
    // s = 1 bound every s (w is linear in s; one mixed s is checked too).
    double worst = 0;
    for (const auto& c : lobes()) {
        for (double theta_o : {0.0, 45.0, 80.0, 89.5}) {
            Vec3 wo = viewer(theta_o);
            for (double s : {0.0, 1.0, 0.4}) {
                if (s == 0.4 && theta_o != 80.0) continue;
                double w = sphere_integral(
                    mirror(wo), c, [&](const Vec3& wi) { return c.brdf.weight(wi, wo, s); }, 150);
                EXPECT_NEAR(w, 1.0, 1e-3) << c.name << " theta_o " << theta_o << " s " << s;
                worst = std::max(worst, std::abs(w - 1));
            }
        }
    }
    std::printf("largest |Int w - 1| over the hemisphere: %.2e\n", worst);
}

// m(theta_o) by a fine 1-D quadrature: the lobe density (pdf() with s = 1) on rings
// about the mirror direction at zenith theta_r, each ring above the horizon for the
// fraction acos(-cot(theta_r) cot(alpha)) / pi of its azimuths (spherical geometry:
// z = cos(theta_r) cos(alpha) + sin(theta_r) sin(alpha) cos(phi) > 0). Midpoint rule
// with 4000 nodes per piece in t, alpha = lo + (hi - lo)(1 - cos t)/2, pieces split
// where the fraction or the lobe has a kink.
double reference_mass(const Case& c, double theta_r) {
    Vec3 wo = viewer(theta_r / kDeg), m = mirror(wo);
    std::vector<double> edges{0, std::max(0.0, kPi / 2 - theta_r), std::min(kPi, kPi / 2 + theta_r),
                              c.support_deg * kDeg, kPi};
    std::sort(edges.begin(), edges.end());
    double sum = 0;
    const int n = 4000;
    for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
        double lo = edges[e], hi = edges[e + 1];
        for (int i = 0; i < n && hi > lo; ++i) {
            double t = (i + 0.5) * kPi / n;
            double alpha = lo + (hi - lo) * 0.5 * (1 - std::cos(t));
            double dalpha = (hi - lo) * 0.5 * std::sin(t) * kPi / n;
            double f = alpha <= kPi / 2 - theta_r ? 1
                       : alpha >= kPi / 2 + theta_r
                           ? 0
                           : std::acos(std::clamp(-std::cos(theta_r) * std::cos(alpha) /
                                                      (std::sin(theta_r) * std::sin(alpha)),
                                                  -1.0, 1.0)) /
                                 kPi;
            sum += c.brdf.pdf(about(m, alpha, 0), wo, 1.0) * f * 2 * kPi * std::sin(alpha) * dalpha;
        }
    }
    return sum;
}

TEST(Brdf, MassAboveTheHorizonMatchesAFineQuadrature) {
    // The Brdf's m(theta_o) is pdf / lobe_weight at the mirror direction (lobe_weight =
    // lobe / m). Tolerance 5e-5 relative: the table is linear in cos(theta_o) with step
    // 1/2048, and a 5 deg lobe near grazing bends m on a scale of its width (error ~
    // step^2 / 8 / width^2 ~ 1e-5); the reference's own error is < 1e-6. Lobes whose
    // support varies with theta_o (linear cone) are skipped: the reference splits at a
    // fixed support.
    for (const auto& c : lobes()) {
        if (c.name == "linear cone") continue;
        for (int i = 0; i < 60; ++i) {
            double u = i < 30 ? (i + 0.37) / 30 * 0.05 : (i - 30 + 0.37) / 30;
            Vec3 wo{std::sqrt(1 - u * u), 0, u}, m = mirror(wo);
            double mass = c.brdf.pdf(m, wo, 1.0) / c.brdf.lobe_weight(m, wo);
            EXPECT_NEAR(mass / reference_mass(c, std::acos(u)), 1.0, 5e-5) << c.name << " u " << u;
        }
    }
}

TEST(Brdf, EveryLobeHasUnitIntegralOverTheSphere) {
    // pdf() with s = 1 is the untruncated lobe: Int over the sphere = 1. No horizon
    // cut here, so the alpha midpoint rule alone sets the error (< 1e-5 at 300 nodes
    // per piece for these profiles, smooth between the breakpoints).
    for (const auto& c : lobes()) {
        for (double theta_o : {0.0, 60.0}) {
            Vec3 wo = viewer(theta_o);
            double total = sphere_integral(
                mirror(wo), c, [&](const Vec3& wi) { return c.brdf.pdf(wi, wo, 1.0); }, 300, 64);
            EXPECT_NEAR(total, 1.0, 1e-5) << c.name << " theta_o " << theta_o;
        }
    }
}

TEST(Brdf, SamplingIsUnbiased) {
    // E[w / pdf] = Int_hemisphere w = 1. Tolerance: 4 standard errors of the mean,
    // estimated from the same samples, plus 1e-9 for rounding when w / pdf is constant
    // (a lobe wholly above the horizon with s = 1: the variance is then 0).
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto& c : lobes()) {
        for (double theta_o : {10.0, 70.0, 88.0}) {
            for (double s : {0.5, 1.0}) {
                Vec3 wo = viewer(theta_o);
                const int n = 100000;
                double sum = 0, sum2 = 0;
                for (int i = 0; i < n; ++i) {
                    BrdfSample smp = c.brdf.sample(wo, s, u(rng), u(rng), u(rng));
                    ASSERT_GT(smp.pdf, 0) << c.name;
                    double x = c.brdf.weight(smp.wi, wo, s) / smp.pdf;
                    sum += x, sum2 += x * x;
                }
                double mean = sum / n, var = sum2 / n - mean * mean;
                double sigma = std::sqrt(std::max(var, 0.0) / n);
                EXPECT_NEAR(mean, 1.0, 4 * sigma + 1e-9)
                    << c.name << " theta_o " << theta_o << " s " << s;
            }
        }
    }
}

TEST(Brdf, SampledLobeAnglesFollowThePdf) {
    // Histogram of alpha (angle to the mirror direction) of lobe samples (s = 1) in 20
    // bins over the support, against the pdf integrated over each bin (midpoint rule,
    // 200 nodes per bin). Tolerance: 5 binomial standard deviations per bin.
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto& c : lobes()) {
        Vec3 wo = viewer(30);
        Vec3 m = mirror(wo);
        double support = std::min(c.support_deg, 90.0) * kDeg;
        const int bins = 20, n = 200000;
        std::vector<int> count(bins, 0);
        for (int i = 0; i < n; ++i) {
            Vec3 wi = c.brdf.sample(wo, 1.0, 0.0, u(rng), u(rng)).wi;
            double dot = wi[0] * m[0] + wi[1] * m[1] + wi[2] * m[2];
            double alpha = std::acos(std::clamp(dot, -1.0, 1.0));
            int b = static_cast<int>(alpha / support * bins);
            if (b < bins) ++count[b];
        }
        for (int b = 0; b < bins; ++b) {
            double lo = b * support / bins, hi = (b + 1) * support / bins, p = 0;
            for (int i = 0; i < 200; ++i) {
                double a = lo + (i + 0.5) * (hi - lo) / 200;
                p +=
                    c.brdf.pdf(about(m, a, 0.3), wo, 1.0) * 2 * kPi * std::sin(a) * (hi - lo) / 200;
            }
            double expected = p * n, sd = std::sqrt(n * p * (1 - p));
            EXPECT_NEAR(count[b], expected, 5 * sd + 1) << c.name << " bin " << b;
        }
    }
}

TEST(Brdf, LambertianAndDelta) {
    // Lambertian: w = cos/pi whatever s; Delta: w = (1 - s) cos/pi (the mirror term is
    // the caller's), lobe_weight 0, cosine sampling with pdf cos/pi.
    Brdf lam = Brdf::lambertian(), del = Brdf::delta();
    EXPECT_EQ(lam.shape(), LobeShape::None);
    EXPECT_TRUE(del.is_delta());
    Vec3 wo = viewer(20), wi = viewer(-50);
    double c = std::cos(50 * kDeg);
    EXPECT_DOUBLE_EQ(lam.weight(wi, wo, 0.0), c / kPi);
    EXPECT_DOUBLE_EQ(del.weight(wi, wo, 0.3), 0.7 * c / kPi);
    EXPECT_EQ(del.lobe_weight(mirror(wo), wo), 0.0);
    BrdfSample s = del.sample(wo, 0.3, 0.1, 0.25, 0.5);
    EXPECT_NEAR(s.wi[2], std::sqrt(0.75), 1e-15);
    EXPECT_DOUBLE_EQ(s.pdf, s.wi[2] / kPi);
    EXPECT_EQ(lam.weight({0, 0.5, -0.5}, wo, 0.0), 0.0);  // below the horizon
    // A default-constructed Brdf (MaterialOptics' member) is Lambertian.
    EXPECT_EQ(Brdf().shape(), LobeShape::None);
    EXPECT_DOUBLE_EQ(Brdf().weight(wi, wo, 0.0), c / kPi);
}

TEST(Brdf, NarrowLobeAtNormalIncidenceIsItsDensity) {
    // theta_o = 0 and a lobe inside the hemisphere: m = 1, so lobe_weight at the mirror
    // direction is the density's peak: (n + 1) / (2 pi) for phong, 1 / (2 pi (1 - cos h))
    // for a cone (closed forms of the normalisation). Tolerance: the m table is
    // exact at u = 1 up to its quadrature (1e-12).
    Vec3 up{0, 0, 1};
    EXPECT_NEAR(Brdf::phong(50).lobe_weight(up, up), 51 / (2 * kPi), 1e-12 * 51);
    EXPECT_NEAR(Brdf::cone(10).lobe_weight(up, up), 1 / (2 * kPi * (1 - std::cos(10 * kDeg))),
                1e-9);
}

TEST(Brdf, RejectsBadParameters) {
    EXPECT_THROW(Brdf::cone(0), std::invalid_argument);
    EXPECT_THROW(Brdf::phong(-1), std::invalid_argument);
    EXPECT_THROW(Brdf::exponential(0), std::invalid_argument);
}

}  // namespace
}  // namespace sigchain::radiometry
