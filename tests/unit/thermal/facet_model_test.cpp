// Tests of a facet's surface energy balance: conservation over a day, shadow, and
// response times of thin and thick facets.
#include "thermal/facet_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../record_property.hpp"
#include "io/snd.hpp"
#include "io/wth.hpp"

namespace th = sigchain::thermal;
namespace io = sigchain::io;

namespace {

// Concrete 20 cm (Incropera table A.3: 2300 kg/m3, 880 J/kg/K, 1.4 W/m/K).
th::FacetThermal concrete() {
    th::FacetThermal f;
    f.slab = {0.20, 2300, 880, 1.4, 0};
    f.solar_absorptivity = 0.6;
    f.thermal_emissivity = 0.9;
    f.back_exposure = 0;
    f.normal = {0, 0, 1};
    f.sky_view_factor = 1;
    return f;
}

// Aluminium 2 mm, both faces to the air (2702 kg/m3, 903 J/kg/K, 237 W/m/K).
th::FacetThermal aluminium_plate() {
    th::FacetThermal f = concrete();
    f.slab = {0.002, 2702, 903, 237, 0};
    f.back_exposure = 1;
    return f;
}

// The Rochester day of White (1996) (weather_30_Sep_95.wth, hawkeye.snd), sampled every minute.
std::vector<th::EnvironmentStep> seed_day(double start_h, double end_h) {
    const std::string wth_path = SIGCHAIN_TEST_DATA "/white1996/weather_30_Sep_95.wth";
    io::Wth wth = io::read_wth_file(wth_path);
    io::Snd snd = io::read_snd_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd");
    return th::sample_environment(wth, wth_path, snd, start_h, end_h, 60, nullptr);
}

// Still surroundings at a fixed air temperature, no sun, a black sky at the air's
// temperature: the facet relaxes toward the air.
std::vector<th::EnvironmentStep> still_air(double air_k, double hours, double h_conv) {
    std::vector<th::EnvironmentStep> env;
    for (int i = 0; i <= static_cast<int>(hours * 60); ++i) {
        th::EnvironmentStep e;
        e.time_h = i / 60.0;
        e.air_k = air_k;
        e.convection_w_m2_k = h_conv;
        e.sky_longwave_w_m2 = th::kStefanBoltzmann * std::pow(air_k, 4);
        e.sun_up = false;
        env.push_back(e);
    }
    return env;
}

}  // namespace

// Energy balance over the second day of White's (1996) weather (24 h to 48 h): absorbed - emitted -
// convected - stored = 0 up to the linearisation of T^4 inside each 60 s step. That
// error is about 6 eps sigma T^2 dT^2 per step with dT < 0.1 K: < 3e-4 W/m2, i.e.
// < 30 J/m2 over the day, against ~3e7 J/m2 absorbed (sun and long-wave); the bound
// 1e-5 x absorbed (~300 J/m2) leaves a margin of 10.
TEST(FacetModel, EnergyBalanceClosesOverADay) {
    auto env = seed_day(24, 48);
    th::FacetThermal f = concrete();
    std::vector<double> sun(env.size(), 1.0);
    th::Slab slab(f.slab, th::slab_nodes(f.slab.thickness_m, th::kSlabCells, th::kSlabGrowth),
                  env.front().air_k);
    th::EnergyBudget b;
    th::run_facet(f, env, sun, 0, env.size() - 1, slab, &b);
    const double absorbed = b.absorbed_solar + b.absorbed_longwave;
    EXPECT_GT(b.absorbed_solar, 5e6);  // a sunny autumn day: ~ 0.6 x 15 MJ/m2
    EXPECT_LT(std::abs(b.residual()), 1e-5 * absorbed)
        << "residual " << b.residual() << " J/m2 of " << absorbed;
    sigchain::unit::record("residual_over_absorbed", b.residual() / absorbed);
    sigchain::unit::record("limit", 1e-5);
    std::printf(
        "energy budget over the day (J/m2): solar %.4g, long-wave %.4g, emitted %.4g, "
        "convected %.4g, stored %.4g, residual %.3g (%.2e of absorbed)\n",
        b.absorbed_solar, b.absorbed_longwave, b.emitted, b.convected, b.stored_change,
        b.residual(), b.residual() / absorbed);
}

// A facet in shadow all day is cooler at 14:00 than its sunlit twin; at the night's
// end (06:00, before sunrise) their difference has mostly decayed.
TEST(FacetModel, ShadowedFacetIsCoolerThanSunlitTwinByDay) {
    auto env = seed_day(0, 38);
    th::FacetThermal f = concrete();
    f.slab.thickness_m = 0.05;
    auto nodes = th::slab_nodes(f.slab.thickness_m, th::kSlabCells, th::kSlabGrowth);
    th::Slab lit(f.slab, nodes, env.front().air_k), dark(f.slab, nodes, env.front().air_k);
    th::run_facet(f, env, std::vector<double>(env.size(), 1.0), 0, env.size() - 1, lit, nullptr);
    th::run_facet(f, env, std::vector<double>(env.size(), 0.0), 0, env.size() - 1, dark, nullptr);
    // Clear-sky noon sun (~650 W/m2 at 46 deg, 60 % absorbed) over h ~ 20 W/m2/K:
    // a difference of order 10 K; 5 K is a safe floor for "cooler by day".
    EXPECT_GT(lit.front_k() - dark.front_k(), 5.0);
    sigchain::unit::record("sunlit_minus_shadowed_K", lit.front_k() - dark.front_k());
    sigchain::unit::record("limit_K", 5.0);
    std::printf("14:00: sunlit %.2f K, shadowed %.2f K, air %.2f K\n", lit.front_k(),
                dark.front_k(), env.back().air_k);
}

// After a 10 K step in air temperature, a thin aluminium plate (lumped time constant
// rho c L / (2 (h + 4 eps sigma T^3)) ~ 130 s) is within 0.5 K of the air after 10
// minutes, while 20 cm of concrete follows the semi-infinite solid with a convective
// surface (Carslaw & Jaeger sec. 2.7; Incropera eq. 5.60): after 1 h, the surface has
// covered 1 - exp(b^2) erfc(b) = 0.41 of the step, b = h sqrt(alpha t) / k.
TEST(FacetModel, ThinMetalFollowsAirFasterThanThickConcrete) {
    const double h_conv = 10, t0 = 290, t_air = 300;
    auto env = still_air(t_air, 1.0, h_conv);
    th::FacetThermal metal = aluminium_plate(), slab_c = concrete();
    th::Slab plate(metal.slab, th::slab_nodes(0.002, th::kSlabCells, th::kSlabGrowth), t0);
    th::Slab thick(slab_c.slab, th::slab_nodes(0.20, th::kSlabCells, th::kSlabGrowth), t0);
    std::vector<double> sun(env.size(), 0.0);
    th::run_facet(metal, env, sun, 0, 10, plate, nullptr);
    EXPECT_LT(t_air - plate.front_k(), 0.5);
    th::run_facet(slab_c, env, sun, 0, env.size() - 1, thick, nullptr);
    // Effective h: convection plus linearised radiation at the mean 295 K.
    const double h = h_conv + 4 * 0.9 * th::kStefanBoltzmann * std::pow(295.0, 3);
    const double alpha = 1.4 / (2300 * 880);
    const double b = h * std::sqrt(alpha * 3600) / 1.4;
    const double covered = 1 - std::exp(b * b) * std::erfc(b);
    // 3 %: the radiative h varies by +-5 % over 290..300 K (+-1.5 % of h, +-1 % of the
    // answer), the first cell (8.7 mm) against a 5 cm penetration depth adds ~1 %.
    EXPECT_NEAR((thick.front_k() - t0) / (t_air - t0), covered, 0.03 * covered);
    EXPECT_GT(t_air - thick.front_k(), 4.0);
    std::printf(
        "after the step: plate %.3f K from the air at 10 min; concrete covered %.4f of "
        "the step at 1 h (semi-infinite %.4f)\n",
        t_air - plate.front_k(), (thick.front_k() - t0) / (t_air - t0), covered);
}

// The direct sun only counts on the face that looks at it, scaled by the sunlit
// fraction; the diffuse sky by the sky-view factor.
TEST(FacetModel, AbsorbedSolarFollowsGeometry) {
    th::EnvironmentStep e;
    e.sun = {0, -std::sqrt(0.5), std::sqrt(0.5)};  // 45 deg up in the south
    e.sun_up = true;
    e.direct_normal_w_m2 = 800;
    e.diffuse_horizontal_w_m2 = 100;
    th::FacetThermal f = concrete();
    f.solar_absorptivity = 0.5;
    f.normal = {0, -1, 0};  // south wall
    f.sky_view_factor = 0.5;
    EXPECT_NEAR(th::absorbed_solar_w_m2(f, e, 1.0), 0.5 * (800 * std::sqrt(0.5) + 50), 1e-9);
    EXPECT_NEAR(th::absorbed_solar_w_m2(f, e, 0.25), 0.5 * (200 * std::sqrt(0.5) + 50), 1e-9);
    f.normal = {0, 1, 0};  // north wall: diffuse only
    EXPECT_NEAR(th::absorbed_solar_w_m2(f, e, 1.0), 25, 1e-9);
}

// Self-generated power P in still air (no sun, black sky at the air temperature)
// reaches the steady state of the surface balance P / faces = h (T - Ta) +
// eps sigma (T^4 - Ta^4), solved here by Newton's method: one face for concrete with
// an insulated back, two for a conductive plate exposed on both sides.
TEST(FacetModel, SelfGeneratedPowerReachesSteadyBalance) {
    const double t_air = 290, h_conv = 10, power = 200, eps = 0.9;
    auto steady = [&](double flux) {
        double t = t_air;
        for (int i = 0; i < 50; ++i) {
            double f = h_conv * (t - t_air) +
                       eps * th::kStefanBoltzmann * (std::pow(t, 4) - std::pow(t_air, 4)) - flux;
            t -= f / (h_conv + 4 * eps * th::kStefanBoltzmann * std::pow(t, 3));
        }
        return t;
    };
    auto env = still_air(t_air, 48, h_conv);
    std::vector<double> sun(env.size(), 0.0);
    th::FacetThermal c = concrete();
    c.slab.thickness_m = 0.01;
    c.slab.volumetric_power_w_m3 = power / 0.01;
    th::Slab cs(c.slab, th::slab_nodes(0.01, th::kSlabCells, th::kSlabGrowth), t_air);
    th::run_facet(c, env, sun, 0, env.size() - 1, cs, nullptr);
    // 48 h is > 100 time constants of 1 cm of concrete (rho c L / h_total ~ 1300 s), so
    // the transient is gone; the steady state of backward Euler is exact, leaving
    // rounding: 1e-6 K.
    EXPECT_NEAR(cs.front_k(), steady(power), 1e-6);
    th::FacetThermal a = aluminium_plate();
    a.slab.volumetric_power_w_m3 = power / a.slab.thickness_m;
    th::Slab as(a.slab, th::slab_nodes(0.002, th::kSlabCells, th::kSlabGrowth), t_air);
    th::run_facet(a, env, sun, 0, env.size() - 1, as, nullptr);
    // The plate conducts P/2 across 2 mm of aluminium: a drop of < 1e-6 K; the front
    // sits at the two-face balance to rounding.
    EXPECT_NEAR(as.front_k(), steady(power / 2), 1e-5);
    std::printf("steady with 200 W/m2: concrete %.6f K (balance %.6f), plate %.6f K (%.6f)\n",
                cs.front_k(), steady(power), as.front_k(), steady(power / 2));
}
