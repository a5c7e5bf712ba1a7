// Tests for LOWTRAN 7 rain (lib/atmos/rain) and cirrus (lib/atmos/cirrus), and their place
// in the column (lib/atmos/column_model).
#include "atmos/rain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "../record_property.hpp"
#include "atmos/cirrus.hpp"
#include "atmos/column_model.hpp"
#include "io/cdk.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

const std::string kSource = SIGCHAIN_SOURCE_DIR;
const std::string kData = kSource + "/data";

// Pure arithmetic on the model's constants: double rounding only.
constexpr double kArith = 1e-12;

RainModel rain(int icld, double rainrt, double ground_km = 0) {
    io::CdkCard2 c;
    c.icld = icld;
    c.rain_rate_mm_h = rainrt;
    return *RainModel::from_deck(c, ground_km, kData);
}

// Composite Simpson's rule of f over [a, b] in n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
    const double h = (b - a) / n;
    double s = f(a) + f(b);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
    return s * h / 3;
}

}  // namespace

// Geometric-optics extinction of the Marshall & Palmer (1948) distribution: the integral
// of Q_ext (pi D^2 / 4) N(D) over D, Q_ext = 2, done numerically here, against the closed
// form pi N0 / Lambda^3. D in mm up to 60 / Lambda (the integrand is down by e^-60 there);
// 20000 Simpson intervals leave ~1e-14 relative. mm2 m-3 -> km-1: 1e-6 m-1 = 1e-3 km-1.
TEST(AtmosRain, MarshallPalmerClosedFormMatchesTheIntegral) {
    double worst = 0, worst_law = 0;
    for (double r : {0.5, 2.0, 5.0, 12.5, 25.0, 75.0}) {
        const double lambda = 4.1 * std::pow(r, -0.21);
        EXPECT_NEAR(marshall_palmer_slope_mm1(r), lambda, kArith * lambda);
        auto integrand = [&](double d_mm) {
            return 2 * std::numbers::pi / 4 * d_mm * d_mm * 8000 * std::exp(-lambda * d_mm);
        };
        const double numeric_km1 = simpson(integrand, 0, 60 / lambda, 20000) * 1e-3;
        EXPECT_NEAR(rain_extinction_km1(r), numeric_km1, 1e-10 * numeric_km1) << r;
        // The rounded law the LOWTRAN 7 user's guide quotes: 0.365 R^0.63 km-1 (0.3647).
        EXPECT_NEAR(rain_extinction_km1(r), 0.3647 * std::pow(r, 0.63),
                    2e-4 * rain_extinction_km1(r))
            << r;
        worst = std::max(worst, std::abs(rain_extinction_km1(r) / numeric_km1 - 1));
        worst_law = std::max(worst_law,
                             std::abs(rain_extinction_km1(r) / (0.3647 * std::pow(r, 0.63)) - 1));
    }
    EXPECT_EQ(rain_extinction_km1(0), 0.0);
    unit::record("relative_difference", worst);
    unit::record("limit", 1e-10);
    unit::record("law_relative_difference", worst_law);
    unit::record("law_limit", 2e-4);
    unit::record("extinction_5mm_h_km1", rain_extinction_km1(5));
}

// RAINRT without a cloud: the rate on the aerosol grid (0, 1, .. 6 km) and zero at 7 km,
// so the column is beta (6 + 1/2) km (linear taper between 6 and 7 km).
TEST(AtmosRain, RainRateWithoutCloudReachesSixKilometres) {
    const RainModel r = rain(0, 5);
    EXPECT_EQ(r.levels_km(), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
    const double beta = rain_extinction_km1(5);
    EXPECT_NEAR(r.extinction_km1(3.3), beta, kArith * beta);
    EXPECT_NEAR(r.extinction_km1(6.5), beta / 2, kArith * beta);
    EXPECT_EQ(r.extinction_km1(7.5), 0.0);
    EXPECT_NEAR(r.layer(0, 20).tau_ext, 6.5 * beta, kArith * beta);
    EXPECT_EQ(r.layer(0, 1).ssa, RainModel::kSingleScatteringAlbedo);
    EXPECT_EQ(r.layer(0, 1).g, RainModel::kAsymmetry);
    // GNDALT 1.2: six levels evenly from 1.2 km below 6 km (FLAYZ), then 6 and 7 km.
    const RainModel g = rain(0, 5, 1.2);
    EXPECT_EQ(g.levels_km().size(), 8u);
    EXPECT_NEAR(g.levels_km()[1], 1.2 + 0.8, kArith);
    EXPECT_NEAR(g.layer(0, 20).tau_ext, (6 - 1.2 + 0.5) * beta, kArith * beta);
}

// ICLD 6 (drizzle): RR1 of cloud_rain_profiles.txt on the cloud levels, 2, 1.78, 1.43,
// 1.22, 0.86 mm/h at 0, .16, .33, .66, 1.0 km, zero from 1.5 km (above the stratus top,
// 1 km); between levels the extinction is exponential (both positive) or linear.
TEST(AtmosRain, DrizzleProfileStopsAtItsCloudTop) {
    const RainModel r = rain(6, 0, 0.3);
    const std::vector<double> h{0, 0.16, 0.33, 0.66, 1.0, 1.5};
    const std::vector<double> rate{2, 1.78, 1.43, 1.22, 0.86, 0};
    ASSERT_EQ(r.levels_km().size(), h.size());
    double column = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        EXPECT_NEAR(r.levels_km()[i], 0.3 + h[i], kArith);
        EXPECT_NEAR(r.rates_mm_h()[i], rate[i], 1e-6);  // single-precision table values
        if (i == 0) continue;
        const double a = rain_extinction_km1(rate[i - 1]), b = rain_extinction_km1(rate[i]);
        column += b > 0 ? (h[i] - h[i - 1]) * (b - a) / std::log(b / a) : (h[i] - h[i - 1]) * a / 2;
    }
    EXPECT_NEAR(r.layer(0, 10).tau_ext, column, 1e-6 * column);
    // RAINRT replaces the profile by a constant rate up to the cloud top.
    const RainModel c = rain(3, 2);  // stratus, top 1 km
    EXPECT_NEAR(c.layer(0, 10).tau_ext, rain_extinction_km1(2) * (1 + 0.25), kArith);
    io::CdkCard2 clear;
    EXPECT_FALSE(RainModel::from_deck(clear, 0, kData).has_value());
}

// A rain deck's vertical transmittance from the ground to the sensor (1 km, inside the
// rain) is the clear deck's times exp(-beta x 1 km): every rain-free term is the same.
// 1e-7 relative in the optical depth: the rain levels re-layer the gas path (the cloud
// levels' re-layering moves it by 1.3e-8, cloud_test.cpp).
TEST(AtmosRain, VerticalTransmittanceIsBeerOfTheRainExtinction) {
    auto deck = io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk");
    ColumnOptions o;
    o.data_dir = kData;
    const io::CdkRun clear = deck.runs[0];
    io::CdkRun wet = clear;
    wet.card2.rain_rate_mm_h = 5;
    const ColumnModel a(clear, 1.0, o), b(wet, 1.0, o);
    const double tau = rain_extinction_km1(5) * 1.0;
    double worst = 0;
    for (double nu : {1e4 / 0.55, 1e4 / 2.2}) {
        const double ta = a.direct_transmittance(nu, a.layers(nu), 0, a.sensor_level(), 1.0);
        const double tb = b.direct_transmittance(nu, b.layers(nu), 0, b.sensor_level(), 1.0);
        EXPECT_NEAR(-std::log(tb / ta), tau, 1e-7 * tau) << nu;
        worst = std::max(worst, std::abs(-std::log(tb / ta) / tau - 1));
    }
    unit::record("relative_difference", worst);
    unit::record("limit", 1e-7);
}

// Cirrus defaults (CIRR18): standard 1 km thick, sub-visual 0.2 km; CEXT 0.14 CTHIK;
// the base the MODEL's mean (MODEL 2 midlatitude summer: 10 km; MODEL 6: 10 km too).
TEST(AtmosCirrus, DefaultsAndCard2aOverrides) {
    io::CdkRun run;
    run.card1.model = 5;
    run.card2.icld = 18;
    run.cirrus = io::CdkCirrus{};
    const CirrusModel s = *CirrusModel::from_deck(run, kData);
    EXPECT_EQ(s.thickness_km(), 1.0);
    EXPECT_NEAR(s.extinction055_km1(), 0.14, kArith);
    EXPECT_EQ(s.base_km(), 5.0);
    run.card1.model = 6;
    run.card2.icld = 19;
    const CirrusModel v = *CirrusModel::from_deck(run, kData);
    EXPECT_EQ(v.thickness_km(), 0.2);
    EXPECT_NEAR(v.extinction055_km1(), 0.028, kArith);
    EXPECT_EQ(v.base_km(), 10.0);
    run.cirrus = io::CdkCirrus{2.0, 8.5, 0.3, 0};
    const CirrusModel u = *CirrusModel::from_deck(run, kData);
    EXPECT_EQ(u.thickness_km(), 2.0);
    EXPECT_EQ(u.base_km(), 8.5);
    EXPECT_EQ(u.extinction055_km1(), 0.3);
    // FLAYZ's levels: 8.4, 8.6, 10.4, 10.6 km; the column is CEXT x CTHIK at 0.55 um.
    const std::vector<double> want{8.4, 8.6, 10.4, 10.6};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(u.levels_km()[i], want[i], kArith);
    EXPECT_NEAR(u.layer(0, 30, 0.55).tau_ext, 0.6, kArith);
    EXPECT_NEAR(u.extinction_km1(8.5, 0.55), 0.15, kArith);
    run.card2.icld = 0;
    EXPECT_FALSE(CirrusModel::from_deck(run, kData).has_value());
}

// The cirrus optics are cloud_models.txt's cirrus columns: standard (64 um) ext 1.005,
// abs 0.001917, g 0.8913 at 1.06 um; sub-visual (4 um) ext 1.038, g 0.8447 there; the
// extinction within 2 % of its 0.55-um value from 0.3 to 3 um (18).
TEST(AtmosCirrus, TabulatedOptics) {
    io::CdkRun run;
    run.card2.icld = 18;
    run.cirrus = io::CdkCirrus{};
    const CirrusModel s = *CirrusModel::from_deck(run, kData);
    const auto o = s.optics(1.06);
    EXPECT_NEAR(o[0], 1.005, kArith);
    EXPECT_NEAR(o[1], 0.001917, kArith);
    EXPECT_NEAR(o[2], 0.8913, kArith);
    const auto l = s.layer(0, 30, 1.06);
    EXPECT_NEAR(l.tau_ext, 0.14 * 1.005, kArith);
    EXPECT_NEAR(l.ssa, 1 - 0.001917 / 1.005, kArith);
    for (double w = 0.3; w <= 3.0; w += 0.05) EXPECT_NEAR(s.optics(w)[0], 1.0, 0.02) << w;
    run.card2.icld = 19;
    const auto v = CirrusModel::from_deck(run, kData)->optics(1.06);
    EXPECT_NEAR(v[0], 1.038, kArith);
    EXPECT_NEAR(v[2], 0.8447, kArith);
}
