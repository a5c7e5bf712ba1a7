// The coupling of the scene with the atmosphere (trace/adjacency.hpp): the model
// against the solver's own Lambertian ground, and the render's use of it.
#include "trace/adjacency.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "rt/coupling.hpp"
#include "rt/discrete_ordinates.hpp"
#include "test_scene.hpp"

namespace sigchain::trace {
namespace {

constexpr double kPi = std::numbers::pi;
const std::vector<double> kWl{0.5, 0.6, 0.7};
using test::Mesh;
using test::Ortho;
using test::single;

// Rayleigh (moment 2 = 1/10) plus Henyey-Greenstein aerosol mixed by scattering
// depth, as build_radiance hands layers to the solver (32 moments).
rt::Layer mixed_layer(double tau_rayleigh, double tau_aerosol, double ssa_aerosol, double g) {
    rt::Layer l;
    const double scat_aer = tau_aerosol * ssa_aerosol, scat = tau_rayleigh + scat_aer;
    l.tau = tau_rayleigh + tau_aerosol;
    l.ssa = scat / l.tau;
    l.pmom.assign(33, 0.0);
    double gk = 1;
    for (int k = 0; k <= 32; ++k, gk *= g)
        l.pmom[k] = ((k == 0 ? 1.0 : k == 2 ? 0.1 : 0.0) * tau_rayleigh + scat_aer * gk) / scat;
    return l;
}

// The largest relative difference, over views and azimuths, between the
// ground-reflected radiance at the sensor of trace's model (black-ground tables plus
// the coupling terms) and of the solver run with a Lambertian ground of albedo rho.
double plain_error(const rt::Problem& column, double sensor_tau, double rho) {
    rt::Problem black = column;
    black.beam_flux = 1;
    black.beam_mu0 = std::cos(35 * kPi / 180);
    black.utau = {sensor_tau, 0};
    for (const auto& l : column.layers) black.utau[1] += l.tau;
    black.umu = {std::cos(50 * kPi / 180), std::cos(20 * kPi / 180), 1.0};
    black.phi_deg = {0, 60, 180};
    const rt::Result r0 = rt::solve(black);
    rt::Problem lambert = black;
    lambert.albedo = rho;
    const rt::Result r = rt::solve(lambert);
    // What build_radiance tabulates: direct and diffuse at the ground (E_sky), L_us,
    // and the coupling terms.
    const double e_dir = r0.levels[1].direct_down, e_sky = r0.levels[1].diffuse_down;
    const double e_tot = e_dir + e_sky;
    const rt::SurfaceCoupling c = rt::surface_coupling(black, sensor_tau, black.umu);
    const double s = c.spherical_albedo;
    double worst = 0;
    for (std::size_t i = 0; i < black.umu.size(); ++i)
        for (std::size_t j = 0; j < black.phi_deg.size(); ++j) {
            const std::size_t at = i * black.phi_deg.size() + j;
            const double l_us = r0.levels[0].intensity[at];
            const double tau2 = std::exp(-c.direct_tau / black.umu[i]);
            // trace: the target's leaving radiance under the coupled sky, times tau2,
            // plus the adjacency radiance (the target is its own environment here).
            const double leave = rho / kPi * (e_dir + e_sky + coupled_sky_increment(e_tot, rho, s));
            const double model =
                tau2 * leave + c.diffuse_up[i] * adjacency_radiance_per_td(e_tot, rho, s);
            const double solver = r.levels[0].intensity[at] - l_us;
            worst = std::max(worst, std::abs(model - solver) / solver);
        }
    return worst;
}

// The key check of the model: over a uniform Lambertian plain, the black-ground tables
// plus the coupling terms give the solver's own answer for that ground. For a
// plane-parallel atmosphere the decomposition is exact (the transfer is linear in the
// ground's isotropic radiance), so what is left is the solver's numerics; the bound
// is 1e-5 relative, well inside the 0.5 % asked of the model and still 70 times the
// largest residual measured (1.4e-7; printed below).
TEST(Adjacency, UniformLambertianPlainMatchesTheSolversLambertianGround) {
    rt::Problem column;
    column.layers = {mixed_layer(0.05, 0, 0, 0), mixed_layer(0.05, 0, 0, 0),
                     mixed_layer(0.04, 0.06, 0.9, 0.7), mixed_layer(0.03, 0.17, 0.9, 0.7)};
    for (double sensor_tau : {0.0, 0.1})  // above the atmosphere; an aircraft
        for (double rho : {0.05, 0.3, 0.8}) {
            const double e = plain_error(column, sensor_tau, rho);
            std::printf("uniform plain: sensor tau %.2f, rho %.2f: largest relative error %.2e\n",
                        sensor_tau, rho, e);
            EXPECT_LT(e, 1e-5) << "sensor tau " << sensor_tau << ", rho " << rho;
        }
}

// A synthetic .rad (uniform sky) with coupling terms S, t_d_down and t_d_up.
io::Rad coupled_rad(double s, double td_down, double td_up, double sun_zenith = 30) {
    io::Rad rad = radiometry::uniform_rad(kWl, sun_zenith, 120, 0.2, 0.004, 0.9, 0.001);
    rad.sky->version_minor = 2;
    io::RadCoupling c;
    c.spherical_albedo.assign(kWl.size(), s);
    c.diffuse_down.assign(kWl.size(), td_down);
    c.diffuse_up.assign(rad.views.size(), std::vector<double>(kWl.size(), td_up));
    rad.sky->coupling = c;
    return rad;
}

RenderResult render_plate(double rho, const radiometry::Atmosphere& atm, RenderOptions o) {
    Mesh m;
    m.quad({{{-500, -500, 0}, {500, -500, 0}, {500, 500, 0}, {-500, 500, 0}}}, 1);
    const scene::Scene s = single(m.data);
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, rho, kWl.size())});
    const Ortho cam(3, 3, 1, -1.5, 1.5, {0, 0, -1});
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    o.threads = 1;
    return render(in, o);
}

// The render applies the model: a Lambertian plate under a uniform sky (golf-ball
// sampling integrates it exactly) gives the closed form, to float precision.
TEST(Adjacency, RenderedPlateFollowsTheClosedForm) {
    const double rho = 0.3, s = 0.2, td_down = 0.1, td_up = 0.05, es = 0.2, sky = 0.004;
    const auto atm = radiometry::Atmosphere::from_rads({coupled_rad(s, td_down, td_up)}, {"c.rad"});
    ASSERT_TRUE(atm.has_coupling());
    const RenderResult res = render_plate(rho, atm, {});
    const double mu_s = std::cos(30 * kPi / 180);
    const double e_tot = mu_s * es * (1 + td_down);  // uniform_rad: tau1 = 1
    const double g = rho * s / (1 - rho * s);
    const double want = 0.9 * rho / kPi * (mu_s * es + kPi * sky + e_tot * g) + 0.001 +
                        td_up * rho * e_tot / (kPi * (1 - rho * s));
    EXPECT_NEAR(res.radiance.at(1, 1, 1), want, 1e-6 * want);
    for (const auto& why : res.stats.skipped) EXPECT_EQ(why.find("adjacency"), std::string::npos);

    RenderOptions off;
    off.adjacency = false;
    const RenderResult plain = render_plate(rho, atm, off);
    const double black = 0.9 * rho / kPi * (mu_s * es + kPi * sky) + 0.001;
    EXPECT_NEAR(plain.radiance.at(1, 1, 1), black, 1e-6 * black);
    EXPECT_NE(std::find(plain.stats.skipped.begin(), plain.stats.skipped.end(),
                        "adjacency and ground-sky coupling (--no-adjacency)"),
              plain.stats.skipped.end());
}

TEST(Adjacency, SkippedWithoutTermsWithoutSunOrWhenNegligible) {
    auto skipped_with = [](const io::Rad& rad, const std::string& what) {
        const auto atm = radiometry::Atmosphere::from_rads({rad}, {"c.rad"});
        const RenderResult res = render_plate(0.3, atm, {});
        bool found = false;
        for (const auto& why : res.stats.skipped) found |= why.find(what) != std::string::npos;
        EXPECT_TRUE(found) << what;
    };
    skipped_with(radiometry::uniform_rad(kWl, 30, 120, 0.2, 0.004, 0.9, 0.001), "no COUPLING");
    skipped_with(coupled_rad(0.2, 0.1, 0.05, 120), "the sun is down");
    skipped_with(coupled_rad(1e-6, 0.1, 1e-6), "below 1e-5");
}

TEST(Adjacency, EnvironmentIsTheMeanReflectanceWithinTheRadius) {
    // Two halves, 0.1 (x < 0) and 0.5 (x > 0): the disc about the origin sees both
    // equally; a disc inside one half sees only it.
    Mesh m;
    m.quad({{{-100, -100, 0}, {0, -100, 0}, {0, 100, 0}, {-100, 100, 0}}}, 1);
    m.quad({{{0, -100, 0}, {100, -100, 0}, {100, 100, 0}, {0, 100, 0}}}, 2);
    const scene::Scene s = single(m.data);
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.1, kWl.size()),
                                                  radiometry::grey_material(2, 0.5, kWl.size())});
    const auto atm = radiometry::Atmosphere::from_rads({coupled_rad(0.2, 0.1, 0.05)}, {"c.rad"});
    Ortho cam(3, 3, 1, -1.5, 1.5, {0, 0, -1});
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    const auto both = environment_reflectance(in, {0, 0, 0}, 50, 128);
    ASSERT_EQ(both.size(), kWl.size());
    EXPECT_NEAR(both[0], 0.3, 1e-9);  // the grid is symmetric about x = 0
    const auto left = environment_reflectance(in, {-60, 0, 0}, 30, 64);
    EXPECT_NEAR(left[0], 0.1, 1e-12);
    EXPECT_TRUE(environment_reflectance(in, {1000, 0, 0}, 10, 16).empty());
}

}  // namespace
}  // namespace sigchain::trace
