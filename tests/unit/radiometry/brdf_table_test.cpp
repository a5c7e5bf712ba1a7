// The table model (brdf_table.hpp): a Lambertian table is Brdf::lambertian(), a table
// sampled from the Phong lobe reproduces it within the interpolation error, the weight
// integrates to 1, and sample()/pdf() agree (unbiased w/pdf, histogram).
#include "radiometry/brdf_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "radiometry/brdf.hpp"

namespace sigchain::radiometry {
namespace {

using geo::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

Vec3 direction(double theta_deg, double phi_deg) {
    double t = theta_deg * kDeg, p = phi_deg * kDeg;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

std::vector<double> steps(double lo, double hi, double step) {
    std::vector<double> out;
    for (double x = lo; x <= hi + 1e-9; x += step) out.push_back(x);
    return out;
}

// A table on the given grids with f(theta_i, theta_o, phi) from `f` (degrees).
template <class F>
io::BrdfTable make_table(const std::vector<double>& ti, const std::vector<double>& to,
                         const std::vector<double>& phi, F f) {
    io::BrdfTable t;
    t.theta_i_deg = ti, t.theta_o_deg = to, t.phi_deg = phi;
    for (double i : ti)
        for (double o : to)
            for (double p : phi) t.values.push_back(f(i, o, p));
    return t;
}

// The Phong lobe (exponent n) as a BRDF: lobe/m divided by cos(theta_i), the relative
// azimuth phi measured from the viewer's azimuth (mirror direction at phi = 180).
io::BrdfTable phong_table(const Brdf& phong, double step_deg) {
    auto f = [&](double ti, double to, double p) {
        Vec3 wi = direction(ti, p), wo = direction(to, 0);
        return phong.lobe_weight(wi, wo) / std::cos(ti * kDeg);
    };
    return make_table(steps(0, 88, step_deg), steps(0, 88, step_deg), steps(0, 180, step_deg), f);
}

// Int w(wi, wo) over the hemisphere by the midpoint rule in (theta, phi), 400 x 400.
double hemisphere_integral(const TableLobe& t, const Vec3& wo) {
    const int n = 400;
    double sum = 0, dt = kPi / 2 / n, dp = 2 * kPi / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double th = (i + 0.5) * dt, ph = (j + 0.5) * dp;
            sum += t.weight(direction(th / kDeg, ph / kDeg), wo) * std::sin(th) * dt * dp;
        }
    return sum;
}

TEST(TableLobe, LambertianTableIsLambertian) {
    // A constant table, whatever its constant, normalises to cos/pi: A = pi c exactly
    // (closed-form integral), so the weights agree to rounding.
    io::BrdfTable t = make_table({0, 30, 90}, {0, 45, 80}, {0, 90, 180},
                                 [](double, double, double) { return 0.2; });
    Brdf table = Brdf::table(t), lam = Brdf::lambertian();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 1000; ++k) {
        Vec3 wi = direction(90 * u(rng), 360 * u(rng)), wo = direction(89 * u(rng), 360 * u(rng));
        EXPECT_NEAR(table.weight(wi, wo, 1.0), lam.weight(wi, wo, 0.0), 1e-15);
        EXPECT_NEAR(table.weight(wi, wo, 0.4), lam.weight(wi, wo, 0.0), 1e-15);
    }
    EXPECT_NEAR(TableLobe(t).albedo(0.3), 0.2 * kPi, 1e-15);
}

TEST(TableLobe, PhongTableReproducesPhong) {
    // Linear interpolation of a smooth function errs by at most h^2/8 |f''| per angle.
    // The table holds f = w / cos(theta_i): near its peak cos^n(alpha) has |f''|/f ~ n + 1
    // per rad^2 and 1/cos(theta) adds 1 + 2 tan^2(theta), so over three angles the
    // error is at most 3 h^2/8 (n + 1 + 2 tan^2(theta_max)) of the peak: with h = 2 deg
    // and n = 10, 0.78% up to 60 deg and 3.4% up to 80 deg (the grazing 1/cos growth
    // dominates there). Measured: 0.35% and 2.38%.
    Brdf phong = Brdf::phong(10);
    Brdf table = Brdf::table(phong_table(phong, 2));
    const double h = 2 * kDeg;
    for (double theta_max : {60.0, 80.0}) {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double worst = 0, peak = 0;
        for (int k = 0; k < 20000; ++k) {
            Vec3 wi = direction(theta_max * u(rng), 360 * u(rng));
            Vec3 wo = direction(theta_max * u(rng), 360 * u(rng));
            double want = phong.lobe_weight(wi, wo), got = table.lobe_weight(wi, wo);
            worst = std::max(worst, std::abs(got - want));
            peak = std::max(peak, want);
        }
        double t = std::tan(theta_max * kDeg);
        double bound = 3 * h * h / 8 * (10 + 1 + 2 * t * t);
        std::printf(
            "phong 10 as a 2-deg table, angles <= %g deg: max |w error| %.3g%% of the "
            "peak (bound %.3g%%)\n",
            theta_max, 100 * worst / peak, 100 * bound);
        EXPECT_LT(worst, bound * peak) << theta_max;
    }
}

TEST(TableLobe, WeightIntegratesToOne) {
    // Quadrature error of the 400 x 400 midpoint rule on these smooth tables: < 1e-3.
    io::BrdfTable rpv = io::read_brdf_file(SIGCHAIN_SOURCE_DIR "/data/brdf/rpv_grassland.brdf");
    TableLobe rpv_lobe(rpv), phong_lobe(phong_table(Brdf::phong(10), 5));
    for (double theta_o : {0.0, 30.0, 62.5, 85.0, 89.0}) {
        EXPECT_NEAR(hemisphere_integral(rpv_lobe, direction(theta_o, 20)), 1, 1e-3) << theta_o;
        EXPECT_NEAR(hemisphere_integral(phong_lobe, direction(theta_o, 20)), 1, 1e-3) << theta_o;
    }
}

TEST(TableLobe, SamplingIsUnbiased) {
    // E[w / pdf] = Int w = 1 for the mixture of Brdf::sample (s = 1 and 0.5).
    // Tolerance: 4 standard errors of the mean, estimated from the same samples.
    io::BrdfTable rpv = io::read_brdf_file(SIGCHAIN_SOURCE_DIR "/data/brdf/rpv_grassland.brdf");
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const Brdf& b : {Brdf::table(rpv), Brdf::table(phong_table(Brdf::phong(20), 3))}) {
        for (double theta_o : {0.0, 35.0, 80.0}) {
            for (double s : {0.5, 1.0}) {
                Vec3 wo = direction(theta_o, 40);
                const int n = 100000;
                double sum = 0, sum2 = 0;
                for (int i = 0; i < n; ++i) {
                    BrdfSample smp = b.sample(wo, s, u(rng), u(rng), u(rng));
                    ASSERT_GT(smp.pdf, 0);
                    double x = b.weight(smp.wi, wo, s) / smp.pdf;
                    sum += x, sum2 += x * x;
                }
                double mean = sum / n, sigma = std::sqrt((sum2 / n - mean * mean) / n);
                EXPECT_NEAR(mean, 1.0, 4 * sigma) << "theta_o " << theta_o << " s " << s;
            }
        }
    }
}

TEST(TableLobe, SampledDirectionsFollowThePdf) {
    // Histogram of (theta_i, relative azimuth) of 400000 draws in 9 x 6 bins against
    // pdf() integrated over each bin (midpoint rule, 40 x 40 nodes per bin, error well
    // under the tolerance): 5 binomial standard deviations per bin.
    io::BrdfTable rpv = io::read_brdf_file(SIGCHAIN_SOURCE_DIR "/data/brdf/rpv_grassland.brdf");
    TableLobe lobe(rpv);
    Vec3 wo = direction(50, 0);
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int nt = 9, np = 6, n = 400000, q = 40;
    std::vector<int> count(nt * np, 0);
    for (int i = 0; i < n; ++i) {
        Vec3 wi = lobe.sample(wo, u(rng), u(rng), u(rng));
        double th = std::acos(wi[2]) / (kPi / 2), ph = std::abs(std::atan2(wi[1], wi[0])) / kPi;
        ++count[std::min(static_cast<int>(th * nt), nt - 1) * np +
                std::min(static_cast<int>(ph * np), np - 1)];
    }
    for (int a = 0; a < nt; ++a)
        for (int b = 0; b < np; ++b) {
            double p = 0, dt = kPi / 2 / nt / q, dp = kPi / np / q;
            for (int i = 0; i < q; ++i)
                for (int j = 0; j < q; ++j) {
                    double th = a * kPi / 2 / nt + (i + 0.5) * dt,
                           ph = b * kPi / np + (j + 0.5) * dp;
                    p += 2 * lobe.pdf(direction(th / kDeg, ph / kDeg), wo) * std::sin(th) * dt * dp;
                }
            double sd = std::sqrt(n * p * (1 - p));
            EXPECT_NEAR(count[a * np + b], n * p, 5 * sd + 1) << "bin " << a << ", " << b;
        }
}

TEST(TableLobe, RejectsAnAllZeroTable) {
    io::BrdfTable t =
        make_table({0, 90}, {0, 90}, {0, 180}, [](double, double, double) { return 0.0; });
    EXPECT_THROW(TableLobe{t}, std::invalid_argument);
}

}  // namespace
}  // namespace sigchain::radiometry
