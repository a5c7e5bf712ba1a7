// The street canyon at --bounces 0 to 3 against a radiosity reference computed
// without rays. Two parallel vertical walls of height H over a floor of width W, all
// grey Lambertian of reflectance a, long enough along y to be two-dimensional, under
// a uniform sky of radiance L and a sun at 30 deg zenith across the canyon (from the
// east). The floor's centre line lies in the shadow of the east wall, so it is lit by
// the sky and the walls only.
//
// The reference cuts the cross-section into strips and takes the exact view factors of
// infinitely long strips from Hottel's crossed-strings rule (Hottel & Sarofim 1967,
// Radiative Transfer, ch. 2; Modest, Radiative Heat Transfer, ch. 4): between strips
// of ends (a, b) and (c, d), F = (|ad| + |bc| - |ac| - |bd|) / (2 |ab|); from a line
// element to a strip, F = (sin phi_2 - sin phi_1) / 2, phi from the element's normal.
// Each strip's sunlit fraction comes from the east wall's top edge, analytically.
//
// --bounces N means (trace(1), --bounces): a hit at depth d < N is lit by the sun,
// the sky it sees and the hits one deeper; the hit at depth N is closed with the sun
// and an unobstructed sky, L (1 + n_z) / 2 (White (1996), section 5.2.3 step 4). So
// the strips' radiance at depth N is C_i = a/pi (E_i + pi L (1 + n_z,i)/2), at depth d
// R_d,i = a/pi (E_i + pi L F_i,sky + pi sum_j F_ij R_d+1,j), and the floor centre's
// (depth 0) a/pi (E_c + pi L F_c,sky + pi sum_j F_c,j R_1,j): a radiosity series cut
// after N reflections off the walls, with the closing term of the tracer's definition.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using test::Mesh;
using test::Ortho;

constexpr double kPi = std::numbers::pi;
constexpr double kW = 10, kH = 10;    // floor width and wall height, m
constexpr double kA = 0.6;            // reflectance of floor and walls
constexpr double kSunE = 100;         // sun irradiance normal to the beam, W cm-2 um-1
constexpr double kSkyL = 3;           // sky radiance, W cm-2 sr-1 um-1
constexpr double kSunZenithDeg = 30;  // sun in the east (azimuth 90): toward +x
// Half the canyon's length, m. A hemisphere ray that would meet a wall in the
// two-dimensional canyon but leaves through an open end instead must climb less than
// H over 1000 m, at most 0.57 deg above the floor: a cosine-weighted share under
// sin^2(0.57 deg) = 1e-4 of the floor's rays.
constexpr double kHalfLength = 1000;
const std::vector<double> kWl = {0.55};

// --- The reference: strips of the cross-section (x across, z up) -----------------

struct Strip {
    double ax, az, bx, bz;  // ends, m
    double nx, nz;          // unit normal into the canyon
    int surface;            // 0 floor, 1 west wall, 2 east wall
};

double dist(double x0, double z0, double x1, double z1) { return std::hypot(x1 - x0, z1 - z0); }

// The floor and the two walls, n strips each.
std::vector<Strip> strips(int n) {
    std::vector<Strip> s;
    for (int i = 0; i < n; ++i) {
        const double u0 = static_cast<double>(i) / n, u1 = static_cast<double>(i + 1) / n;
        s.push_back({-kW / 2 + kW * u0, 0, -kW / 2 + kW * u1, 0, 0, 1, 0});
        s.push_back({-kW / 2, kH * u0, -kW / 2, kH * u1, 1, 0, 1});
        s.push_back({kW / 2, kH * u0, kW / 2, kH * u1, -1, 0, 2});
    }
    return s;
}

// Crossed strings between strips of different surfaces (the canyon's cross-section
// is a convex rectangle with the opening: no strip hides another); 0 on one surface.
double crossed_strings(const Strip& i, const Strip& j) {
    if (i.surface == j.surface) return 0;
    const double crossed = dist(i.ax, i.az, j.bx, j.bz) + dist(i.bx, i.bz, j.ax, j.az);
    const double uncrossed = dist(i.ax, i.az, j.ax, j.az) + dist(i.bx, i.bz, j.bx, j.bz);
    return std::abs(crossed - uncrossed) / (2 * dist(i.ax, i.az, i.bx, i.bz));
}

// From the floor's line element at x (normal +z) to a wall strip: (sin phi_2 - sin
// phi_1) / 2, sin phi the x-component of the unit vector toward each end.
double floor_point_to_strip(double x, const Strip& j) {
    if (j.surface == 0) return 0;
    const double s1 = (j.ax - x) / dist(x, 0, j.ax, j.az);
    const double s2 = (j.bx - x) / dist(x, 0, j.bx, j.bz);
    return std::abs(s2 - s1) / 2;
}

// Sun direction (x, z) in the cross-section.
double sun_x() { return std::sin(kSunZenithDeg * kPi / 180); }
double sun_z() { return std::cos(kSunZenithDeg * kPi / 180); }

// Part of a strip the sun reaches: point p is lit when its ray toward the sun crosses
// the top (z = H) at x <= W/2, i.e. g(p) = p_x + (H - p_z) tan(zenith) - W/2 <= 0, a
// linear function along the strip.
double sunlit_fraction(const Strip& s) {
    const double t = sun_x() / sun_z();
    const double g0 = s.ax + (kH - s.az) * t - kW / 2, g1 = s.bx + (kH - s.bz) * t - kW / 2;
    if (g0 <= 0 && g1 <= 0) return 1;
    if (g0 > 0 && g1 > 0) return 0;
    const double cut = g0 / (g0 - g1);  // where g = 0, 0..1 from a
    return g0 <= 0 ? cut : 1 - cut;
}

double direct_sun(const Strip& s) {
    const double cos_i = s.nx * sun_x() + s.nz * sun_z();
    return cos_i > 0 ? kSunE * cos_i * sunlit_fraction(s) : 0.0;
}

struct Reference {
    std::vector<Strip> s;
    std::vector<std::vector<double>> f;  // f[i][j], strip to strip
    std::vector<double> f_sky;           // strip to the opening, 1 - sum_j f[i][j]
    explicit Reference(int n) : s(strips(n)), f(s.size(), std::vector<double>(s.size())) {
        for (std::size_t i = 0; i < s.size(); ++i) {
            double sum = 0;
            for (std::size_t j = 0; j < s.size(); ++j) sum += f[i][j] = crossed_strings(s[i], s[j]);
            f_sky.push_back(1 - sum);
        }
    }

    // The floor radiance at x (a shadowed or lit point) with `bounces` (header).
    double floor_radiance(double x, int bounces) const {
        std::vector<double> r(s.size()), next(s.size());
        for (std::size_t i = 0; i < s.size(); ++i)
            r[i] = kA / kPi * (direct_sun(s[i]) + kPi * kSkyL * (1 + s[i].nz) / 2);
        for (int d = bounces - 1; d >= 1; --d) {
            for (std::size_t i = 0; i < s.size(); ++i) {
                double e = direct_sun(s[i]) + kPi * kSkyL * f_sky[i];
                for (std::size_t j = 0; j < s.size(); ++j) e += kPi * f[i][j] * r[j];
                next[i] = kA / kPi * e;
            }
            r.swap(next);
        }
        const bool lit = x + kH * sun_x() / sun_z() <= kW / 2;
        double e = lit ? kSunE * sun_z() : 0.0, f_sky_c = 1;
        for (std::size_t j = 0; j < s.size(); ++j) {
            const double fj = floor_point_to_strip(x, s[j]);
            if (bounces > 0) e += kPi * fj * r[j];  // 0 bounces: the walls are black
            f_sky_c -= fj;
        }
        return kA / kPi * (e + kPi * kSkyL * f_sky_c);
    }
};

// 200 strips per surface: the floor centre's radiance changes by < 1e-5 (relative)
// from 100 to 200 strips (ReferenceIsConverged).
const Reference& reference() {
    static const Reference r(200);
    return r;
}

// --- The render ----------------------------------------------------------------

struct CanyonScene {
    scene::Scene scene;
    radiometry::MaterialLibrary materials;
    radiometry::Atmosphere atmosphere;
};

// Floor and walls as long quads. The floor reaches 0.05 m past the walls and the walls
// 0.05 m below the floor, so no ray slips through a crack along the corners (the
// overlaps lie outside the canyon, where no ray from inside goes).
const CanyonScene& canyon() {
    static const CanyonScene c = [] {
        Mesh m;
        const double e = 0.05, y = kHalfLength, x = kW / 2;
        m.quad({{{-x - e, -y, 0}, {x + e, -y, 0}, {x + e, y, 0}, {-x - e, y, 0}}}, 1);
        m.quad({{{-x, y, -e}, {-x, -y, -e}, {-x, -y, kH}, {-x, y, kH}}}, 1);
        m.quad({{{x, -y, -e}, {x, y, -e}, {x, y, kH}, {x, -y, kH}}}, 1);
        return CanyonScene{
            test::single(m.data),
            radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, kA, 1)}),
            radiometry::Atmosphere::from_rads(
                {radiometry::uniform_rad(kWl, kSunZenithDeg, 90, kSunE, kSkyL, 1, 0)},
                {"canyon.rad"})};
    }();
    return c;
}

constexpr long kPixels = 1024;      // along the floor's centre line x = 0, 0.05 m apart
constexpr long kHemisphere = 1024;  // montecarlo rays per primary hit

// The floor centre line's radiance per pixel (tau2 = 1 and no path radiance: the
// pixel is the floor's leaving radiance).
std::vector<double> render_floor(int bounces, bool open_sky_integrated = false) {
    const CanyonScene& c = canyon();
    Ortho cam(kPixels, 1, 0.05, -0.025, 6.4, {0, 0, -1});
    RenderInputs in = test::inputs(&c.scene, &c.materials, &c.atmosphere, &cam);
    RenderOptions o;
    o.sampling = Sampling::MonteCarlo;
    o.bounces = bounces;
    o.hemisphere_samples = kHemisphere;
    o.open_sky_integrated = open_sky_integrated;
    o.background = BackgroundChoice::None;  // nothing below the horizon: the canyon is closed
    o.threads = 2;
    RenderResult res = render(in, o);
    std::vector<double> l(kPixels);
    for (long r = 0; r < kPixels; ++r) l[static_cast<std::size_t>(r)] = res.radiance.at(0, r, 0);
    return l;
}

// The renders at 0 to 3 bounces (index = bounces), made once for every test.
const std::array<std::vector<double>, 4>& renders() {
    static const std::array<std::vector<double>, 4> r = {render_floor(0), render_floor(1),
                                                         render_floor(2), render_floor(3)};
    return r;
}

struct MeanError {
    double mean = 0, standard_error = 0;
};
// Mean of the pixels and its standard error, from their scatter (the pixels are
// independent estimates: each hashes its own row into its random numbers).
MeanError mean_error(const std::vector<double>& v) {
    MeanError m;
    const double n = static_cast<double>(v.size());
    for (double x : v) m.mean += x / n;
    double var = 0;
    for (double x : v) var += (x - m.mean) * (x - m.mean) / (n - 1);
    m.standard_error = std::sqrt(var / n);
    return m;
}

// Allowance besides the noise, relative: the ray offset eps = 2e-3 m (1e-6 of the
// 2 km scene) lifts the floor point and its sky view factor by 1.6e-4; the open ends
// hide at most 1e-4 of the floor's rays (kHalfLength); the strips err by < 1e-5.
constexpr double kBias = 3e-4;

TEST(Canyon, ReferenceViewFactorsAreHottelsClosedForms) {
    // The strips summed give the closed forms of whole surfaces (crossed strings on
    // the surfaces themselves): floor to opening sqrt(1 + (H/W)^2) - H/W, a wall to
    // the opening (H + W - sqrt(H^2 + W^2)) / (2H); the floor's centre sees the sky
    // through sin(atan(W / 2H)) (Modest, appendix D, config. 12). And reciprocity.
    const Reference& ref = reference();
    double floor_sky = 0, wall_sky = 0;
    int floors = 0, walls = 0;
    for (std::size_t i = 0; i < ref.s.size(); ++i) {
        if (ref.s[i].surface == 0) floor_sky += ref.f_sky[i], ++floors;
        if (ref.s[i].surface == 1) wall_sky += ref.f_sky[i], ++walls;
    }
    const double r = kH / kW;
    EXPECT_NEAR(floor_sky / floors, std::sqrt(1 + r * r) - r, 1e-12);
    EXPECT_NEAR(wall_sky / walls, (kH + kW - std::hypot(kH, kW)) / (2 * kH), 1e-12);
    double centre_sky = 1;
    for (const Strip& j : ref.s) centre_sky -= floor_point_to_strip(0, j);
    EXPECT_NEAR(centre_sky, std::sin(std::atan(kW / (2 * kH))), 1e-12);
    for (std::size_t i = 0; i < ref.s.size(); i += 37)
        for (std::size_t j = 0; j < ref.s.size(); j += 11)
            EXPECT_NEAR(ref.f[i][j] * dist(ref.s[i].ax, ref.s[i].az, ref.s[i].bx, ref.s[i].bz),
                        ref.f[j][i] * dist(ref.s[j].ax, ref.s[j].az, ref.s[j].bx, ref.s[j].bz),
                        1e-12);
}

TEST(Canyon, ReferenceIsConverged) {
    const Reference coarse(100);
    for (int n : {0, 1, 2, 3}) {
        const double fine = reference().floor_radiance(0, n);
        EXPECT_NEAR(coarse.floor_radiance(0, n), fine, 1e-5 * fine) << n << " bounces";
    }
}

TEST(Canyon, FloorCentreAtZeroToThreeBouncesMatchesTheRadiosityReference) {
    // Within 4 standard errors of the render's mean (1024 pixels of 1024 hemisphere
    // rays each, about 0.1 %) plus kBias. The standard error must stay under 0.2 % for
    // the check to mean something: the bounces add 234 %, 32 % and 8 %, and closing
    // the last bounce with each wall's true sky view factor instead of trace's
    // unobstructed sky (a plain truncated radiosity series) would give 4.7 %, 2.6 %
    // and 0.9 % less at 1, 2 and 3 bounces. (Untruncated, the series converges to
    // 4.018, 5 % above 3 bounces.)
    for (int n : {0, 1, 2, 3}) {
        const MeanError m = mean_error(renders()[static_cast<std::size_t>(n)]);
        const double want = reference().floor_radiance(0, n);
        std::printf(
            "canyon floor centre, %d bounce(s): render %.5f +- %.5f, reference %.5f "
            "(%+.2f standard errors)\n",
            n, m.mean, m.standard_error, want, (m.mean - want) / m.standard_error);
        EXPECT_LT(m.standard_error, 0.002 * want) << n << " bounces";
        EXPECT_NEAR(m.mean, want, 4 * m.standard_error + kBias * want) << n << " bounces";
    }
}

TEST(Canyon, EachBounceBrightensTheFloorByTheExpectedAmount) {
    // Pixel by pixel, N + 1 bounces less N: the mean of those differences and its own
    // standard error (the renders share their seed, so the differences are paired).
    // The mean must be within 4 standard errors (plus kBias of the radiance) of the
    // reference's increment, and that increment must be at least 10 standard errors,
    // so that a bounce that added nothing would fail.
    for (int n : {0, 1, 2}) {
        const auto& lo = renders()[static_cast<std::size_t>(n)];
        const auto& hi = renders()[static_cast<std::size_t>(n + 1)];
        std::vector<double> d(lo.size());
        for (std::size_t i = 0; i < lo.size(); ++i) d[i] = hi[i] - lo[i];
        const MeanError m = mean_error(d);
        const double want = reference().floor_radiance(0, n + 1) - reference().floor_radiance(0, n);
        std::printf(
            "canyon floor centre, bounce %d -> %d: render %+.5f +- %.5f, reference "
            "%+.5f\n",
            n, n + 1, m.mean, m.standard_error, want);
        EXPECT_GT(want, 10 * m.standard_error) << n << " -> " << n + 1;
        EXPECT_NEAR(m.mean, want,
                    4 * m.standard_error + kBias * reference().floor_radiance(0, n + 1))
            << n << " -> " << n + 1;
    }
}

TEST(Canyon, OpenSkyIntegratedMatchesTheRadiosityReference) {
    // --open-sky integrated: the floor's open-sky irradiance pi L from the table
    // (straight up: a node, 6e-6 of E), the rays only the walls' radiance less the sky
    // they hide. Same reference and tolerance as the sampled sky's.
    for (int n : {0, 1, 2}) {
        const MeanError m = mean_error(render_floor(n, true));
        const double want = reference().floor_radiance(0, n);
        std::printf("canyon floor centre, %d bounce(s), open sky integrated: render %.5f +- "
                    "%.5f, reference %.5f\n",
                    n, m.mean, m.standard_error, want);
        EXPECT_LT(m.standard_error, 0.002 * want) << n << " bounces";
        EXPECT_NEAR(m.mean, want, 4 * m.standard_error + kBias * want) << n << " bounces";
    }
}

TEST(Canyon, DeepPathsConvergeToTheFullRadiositySolution) {
    // At 40 bounces the closing term weighs (a F)^40 < 1e-8: the reference is the whole
    // radiosity series, whatever closes it. Russian roulette (from depth 2) cuts the
    // paths at random, unbiased; tolerance as at 1 to 3 bounces.
    const MeanError m = mean_error(render_floor(40));
    const double want = reference().floor_radiance(0, 40);
    std::printf("canyon floor centre, 40 bounces: render %.5f +- %.5f, reference %.5f\n", m.mean,
                m.standard_error, want);
    EXPECT_LT(m.standard_error, 0.002 * want);
    EXPECT_NEAR(m.mean, want, 4 * m.standard_error + kBias * want);
}

}  // namespace
}  // namespace sigchain::trace
