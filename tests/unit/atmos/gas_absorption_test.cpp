// Tests for LOWTRAN 7 gas absorption (lib/atmos/gas_absorption): the band model against
// its own formula with coefficients typed from the tables, its limits, Beer's law of the
// continua, and the column against independent references (WMO 1986 ozone cross
// sections, Bird & Riordan's SPCTRAL2 water vapour and mixed-gas transmittances).
#include "atmos/gas_absorption.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../record_property.hpp"
#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

const std::string kDataDir = SIGCHAIN_SOURCE_DIR "/data";
const std::string kTestData = SIGCHAIN_TEST_DATA "/atmos";

const GasTables& tables() {
    static const GasTables t = GasTables::load(kDataDir);
    return t;
}

// A profile with the given levels and no absorber at all.
Profile dry_profile(std::vector<double> z_km, std::vector<double> p_mb, std::vector<double> t_k) {
    Profile p;
    const std::size_t n = z_km.size();
    p.z_km = std::move(z_km);
    p.p_mb = std::move(p_mb);
    p.t_k = std::move(t_k);
    p.h2o_g_m3.assign(n, 0.0);
    p.rh_percent.assign(n, 0.0);
    for (auto& v : p.vmr_ppmv) v.assign(n, 0.0);
    return p;
}

// `levels` levels 1 km apart at one pressure and temperature.
Profile homogeneous(int levels, double p_mb, double t_k) {
    std::vector<double> z;
    for (int k = 0; k < levels; ++k) z.push_back(k);
    return dry_profile(z, std::vector<double>(levels, p_mb), std::vector<double>(levels, t_k));
}

void set_gas(Profile& p, Gas g, double ppmv) { p.vmr_ppmv[int(g)].assign(p.size(), ppmv); }

struct AfglColumns {
    Profile profile;
    std::vector<double> n_air_cm3;  // the table's own air density
};

// An AFGL model atmosphere (columns z p T n_air, then ppmv of H2O CO2 O3 N2O CO CH4 O2),
// read here so the test does not depend on lib/atmos/profile. H2O density from its
// mixing ratio with LOWTRAN's 3.3429e16 molecules cm-3 per g m-3.
AfglColumns afgl(const std::string& name) {
    std::ifstream in(kDataDir + "/atmosphere/" + name);
    EXPECT_TRUE(in) << name;
    AfglColumns out;
    Profile& p = out.profile;
    const Gas order[7] = {Gas::H2O, Gas::CO2, Gas::O3, Gas::N2O, Gas::CO, Gas::CH4, Gas::O2};
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        double z, pr, t, n, v[7];
        s >> z >> pr >> t >> n;
        for (double& x : v) s >> x;
        p.z_km.push_back(z);
        p.p_mb.push_back(pr);
        p.t_k.push_back(t);
        out.n_air_cm3.push_back(n);
        p.h2o_g_m3.push_back(v[0] * 1e-6 * n / 3.3429e16);
        p.rh_percent.push_back(0);
        for (int g = 0; g < 7; ++g) p.vmr_ppmv[int(order[g])].push_back(v[g]);
    }
    for (auto& col : p.vmr_ppmv) col.resize(p.size(), 0.0);
    return out;
}

// The profile with only gas `keep` left (the continua of the others vanish with them;
// the N2 continuum, which depends on pressure alone, stays).
Profile only(Profile p, Gas keep) {
    for (int g = 0; g < kGasCount; ++g)
        if (g != int(keep)) p.vmr_ppmv[g].assign(p.size(), 0.0);
    if (keep != Gas::H2O) p.h2o_g_m3.assign(p.size(), 0.0);
    return p;
}

// Vertical column of a density given on levels (per cm3), exponential between levels,
// per cm2.
double column_cm2(const std::vector<double>& z_km, const std::vector<double>& density) {
    double sum = 0;
    for (std::size_t k = 0; k + 1 < z_km.size(); ++k) {
        double a = density[k], b = density[k + 1], dz = (z_km[k + 1] - z_km[k]) * 1e5;
        sum += (a > 0 && b > 0 && a != b) ? (a - b) / std::log(a / b) * dz : 0.5 * (a + b) * dz;
    }
    return sum;
}

// Columns of a '#'-commented numeric table.
std::vector<std::vector<double>> read_table(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << path;
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        std::vector<double> row;
        for (double x; s >> x;) row.push_back(x);
        rows.push_back(row);
    }
    return rows;
}

// Linear interpolation in a table column (x ascending).
double interpolate(const std::vector<std::vector<double>>& t, double x, int col) {
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
        if (x >= t[i][0] && x <= t[i + 1][0]) {
            double f = (x - t[i][0]) / (t[i + 1][0] - t[i][0]);
            return t[i][col] * (1 - f) + t[i + 1][col] * f;
        }
    ADD_FAILURE() << x << " outside table";
    return 0;
}

// Mean over wavelength [lo_nm, hi_nm] (trapezoid on a 0.05 nm grid) of f(lambda_nm).
template <class F>
double wavelength_mean(double lo_nm, double hi_nm, F f) {
    const int n = static_cast<int>((hi_nm - lo_nm) / 0.05);
    double sum = 0;
    for (int i = 0; i <= n; ++i)
        sum += f(lo_nm + (hi_nm - lo_nm) * i / n) * (i == 0 || i == n ? 0.5 : 1);
    return sum / n;
}

constexpr double kP0 = 1013.25, kT0 = 273.15;

}  // namespace

// ---- The band model is its formula -----------------------------------------------------

// One absorber on a homogeneous 1 km path at 850 mb, 280 K. Expected values use only the
// numbers typed here from the tables (C' from band_model_GAS.txt at the grid point, a, n,
// m from band_model_constants.txt) and the units of the file headers. Tolerance 1e-12
// relative: the same arithmetic in another order, rounding only.
TEST(GasAbsorptionBandModel, SingleAbsorberEqualsDoubleExponentialFormula) {
    const double p = 850, t = 280, pr = p / kP0, tr = kT0 / t;
    const double n_air = 2.6868e19 * pr * tr;  // cm-3 (Loschmidt, ideal gas)
    struct Case {
        Gas gas;
        double ppmv, nu, cprime, a, n, m, amount;  // amount per 1 km: g cm-2 or atm-cm
    };
    const Case cases[] = {
        // band_model_H2O.txt 10600 -0.36117 band 26: a 0.5621 n 0.8874 m -0.2576; 5 g m-3
        {Gas::H2O, 0, 10600, -0.36117, 0.5621, 0.8874, -0.2576, 0.1 * 5.0},
        // band_model_O2.txt 13100 -5.2458 band 51: a 0.5641 n 0.9353 m 0.1936; 209000 ppmv
        {Gas::O2, 209000, 13100, -5.2458, 0.5641, 0.9353, 0.1936, n_air * 209000 * 3.7194e-21},
        // band_model_CO2.txt 2350 1.2255 band 38: a 0.6033 n 0.7258 m -1.6740; 330 ppmv
        {Gas::CO2, 330, 2350, 1.2255, 0.6033, 0.7258, -1.6740, n_air * 330 * 3.7194e-21},
        // band_model_CH4.txt 3020 -0.5049 band 46: a 0.5844 n 0.7139 m -0.4185; 1.7 ppmv
        {Gas::CH4, 1.7, 3020, -0.5049, 0.5844, 0.7139, -0.4185, n_air * 1.7 * 3.7194e-21},
    };
    for (const Case& c : cases) {
        Profile prof = homogeneous(2, p, t);
        if (c.gas == Gas::H2O)
            prof.h2o_g_m3.assign(2, 5.0);  // the band model reads water as a density
        else
            set_gas(prof, c.gas, c.ppmv);
        GasColumn col(tables(), prof);
        const double w = c.amount * std::pow(pr, c.n) * std::pow(tr, c.m);
        for (double mu : {1.0, 0.5, 0.2}) {
            const double want = std::exp(-std::pow(std::pow(10.0, c.cprime) * w / mu, c.a));
            const double got = col.band_transmittance(c.gas, c.nu, 0, 1, mu);
            EXPECT_NEAR(got, want, 1e-12 * want) << int(c.gas) << " nu " << c.nu << " mu " << mu;
            EXPECT_LT(got, 0.999) << "the case must absorb to test anything";
        }
    }
}

// CO2 at 670 cm-1 with nothing else in the air: transmittance() is the band model alone
// (no continuum there without water vapour), exp(-(C W)^a) with band_model_CO2.txt 670
// C' 0.1367, band 36: a 0.6176 n 0.6705 m -2.2560. Same tolerance.
TEST(GasAbsorptionBandModel, TransmittanceOfCo2AloneIsItsBandModel) {
    const double p = 500, t = 250, pr = p / kP0, tr = kT0 / t;
    Profile prof = homogeneous(2, p, t);
    set_gas(prof, Gas::CO2, 0.02);  // little enough not to saturate the band centre
    GasColumn col(tables(), prof);
    const double w =
        2.6868e19 * pr * tr * 0.02 * 3.7194e-21 * std::pow(pr, 0.6705) * std::pow(tr, -2.2560);
    const double want = std::exp(-std::pow(std::pow(10.0, 0.1367) * w, 0.6176));
    EXPECT_NEAR(col.transmittance(670, 0, 1, 1.0), want, 1e-12);
    EXPECT_GT(want, 0.01);
    EXPECT_LT(want, 0.99);
}

// The band model applies to the path's summed amount, not to a product of layer
// transmittances: two identical layers give exp(-(2 C W)^a), which exceeds
// T(layer)^2 because a < 1; a slant path at mu = 1/2 holds the amount of two layers.
TEST(GasAbsorptionBandModel, PathSumsAmountsNotTransmittances) {
    Profile prof = homogeneous(3, kP0, kT0);
    prof.h2o_g_m3.assign(3, 10.0);
    GasColumn col(tables(), prof);
    const double one = col.band_transmittance(Gas::H2O, 10600, 0, 1, 1.0);
    const double two = col.band_transmittance(Gas::H2O, 10600, 0, 2, 1.0);
    // At STP with 1 g cm-2 per layer, W = 1 and 2 (n, m scalings are 1).
    const double c = std::pow(10.0, -0.36117), a = 0.5621;
    EXPECT_NEAR(one, std::exp(-std::pow(c * 1.0, a)), 1e-12);
    EXPECT_NEAR(two, std::exp(-std::pow(c * 2.0, a)), 1e-12);
    EXPECT_GT(two, one * one + 0.01);  // not Beer's law
    EXPECT_NEAR(col.band_transmittance(Gas::H2O, 10600, 0, 1, 0.5), two, 1e-12);
    EXPECT_NEAR(col.band_transmittance(Gas::H2O, 10600, 1, 2, 1.0), one, 1e-12);
    EXPECT_EQ(col.band_transmittance(Gas::H2O, 10600, 2, 0, 1.0), two);  // order-free
}

// Densities vary exponentially between levels (as LOWTRAN interpolates them): water
// vapour halving over a 1 km layer at STP holds 0.1 * 10 g m-3 * (1 - 1/2) / ln 2 km =
// 0.72135 g cm-2 (a linear rule would give 0.75). Recovered from the band model at
// 10600 cm-1 (C' -0.36117, a 0.5621; n, m scalings are 1 at STP); 1e-9 relative
// (rounding of the inversion).
TEST(GasAbsorptionBandModel, LayerAmountIntegratesExponentialDensity) {
    Profile prof = homogeneous(2, kP0, kT0);
    prof.h2o_g_m3 = {10.0, 5.0};
    GasColumn col(tables(), prof);
    const double t = col.band_transmittance(Gas::H2O, 10600, 0, 1, 1.0);
    const double w = std::pow(-std::log(t), 1 / 0.5621) / std::pow(10.0, -0.36117);
    EXPECT_NEAR(w, 0.5 / std::log(2.0), 1e-9);
}

// Levels outside the profile and cosines outside (0, 1] are programming errors.
TEST(GasAbsorptionBandModel, RejectsBadArguments) {
    GasColumn col(tables(), homogeneous(3, kP0, kT0));
    EXPECT_THROW(col.transmittance(1000, 0, 3, 1.0), std::invalid_argument);
    EXPECT_THROW(col.transmittance(1000, 0, 2, 0.0), std::invalid_argument);
    EXPECT_THROW(col.transmittance(1000, 0, 2, 1.5), std::invalid_argument);
    EXPECT_EQ(col.transmittance(1000, 1, 1, 1.0), 1.0);
    EXPECT_THROW(GasColumn(tables(), homogeneous(1, kP0, kT0)), std::invalid_argument);
}

// ---- Limits ------------------------------------------------------------------------------

// A vanishing amount gives exactly 1 (LOWTRAN: a (log10 W + C') <= -6 or W < 1e-20).
TEST(GasAbsorptionLimits, VanishingAmountTransmitsEverything) {
    Profile prof = homogeneous(2, kP0, kT0);
    set_gas(prof, Gas::CO2, 1e-12);
    GasColumn col(tables(), prof);
    EXPECT_EQ(col.band_transmittance(Gas::CO2, 2350, 0, 1, 1.0), 1.0);
    Profile none = homogeneous(2, kP0, kT0);
    GasColumn empty(tables(), none);
    EXPECT_EQ(empty.transmittance(10600, 0, 1, 1.0), 1.0);
}

// Outside every band (16200 cm-1 lies in the H2O gap 16050-16335 and no other absorber
// has a band there) each band-model transmittance is exactly 1; between the Chappuis
// and Hartley-Huggins ranges (24370-27370 cm-1) above the H2O continuum (< 20000) the
// whole US standard atmosphere transmits exactly 1, as in LOWTRAN 7.
TEST(GasAbsorptionLimits, OutsideEveryBandOnlyContinuaRemain) {
    auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    GasColumn col(tables(), us);
    const std::size_t top = us.size() - 1;
    for (int g = 0; g < kGasCount; ++g)
        EXPECT_EQ(col.band_transmittance(Gas(g), 16200, 0, top, 1.0), 1.0) << g;
    EXPECT_EQ(col.transmittance(25000, 0, top, 1.0), 1.0);
    EXPECT_LT(col.transmittance(16200, 0, top, 1.0), 1.0);  // H2O continuum and ozone
}

// A continuum-only wavenumber follows Beer's law: doubling the path squares T.
// (1) 16200 cm-1, US standard water vapour only: H2O continuum.
// (2) 2400 cm-1, gas-free air at 900 mb 260 K over 1 km: the N2 continuum alone, equal
//     to exp(-C4 0.781 (P/P0)^2 (T0/T)^1.5 dz) with n2_continuum.txt 2400 C4 = 0.113
//     km-1. Tolerances 1e-12 relative (rounding).
TEST(GasAbsorptionLimits, ContinuumFollowsBeersLaw) {
    auto wet = only(afgl("afgl_atmosphere_6_us_standard_1976.txt").profile, Gas::H2O);
    GasColumn col(tables(), wet);
    const std::size_t top = wet.size() - 1;
    const double t1 = col.transmittance(16200, 0, top, 1.0);
    EXPECT_LT(t1, 1.0);
    EXPECT_NEAR(col.transmittance(16200, 0, top, 0.5), t1 * t1, 1e-12 * t1 * t1);

    Profile air = homogeneous(2, 900, 260);
    GasColumn n2(tables(), air);
    const double want =
        std::exp(-0.113 * 0.781 * std::pow(900 / kP0, 2) * std::pow(kT0 / 260, 1.5));
    const double got = n2.transmittance(2400, 0, 1, 1.0);
    EXPECT_NEAR(got, want, 1e-12 * want);
    EXPECT_NEAR(n2.transmittance(2400, 0, 1, 0.5), got * got, 1e-12 * got);
}

// ---- Equivalent Beer's law -----------------------------------------------------------------

// The layer depths sum to -ln of the vertical column transmittance (telescoping sum,
// exact to rounding: 1e-10 relative), and the depth from the top to any level gives
// that path's transmittance. US standard atmosphere with every gas.
TEST(GasAbsorptionLayers, DepthsReproduceVerticalTransmittance) {
    auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    set_gas(us, Gas::NO2, 2.3e-5);
    set_gas(us, Gas::HNO3, 5e-5);
    GasColumn col(tables(), us);
    const std::size_t top = us.size() - 1;
    for (double nu : {720.0, 1000.0, 1600.0, 2400.0, 5000.0, 10600.0, 13100.0, 16667.0, 30000.0}) {
        auto tau = col.layer_absorption_depth(nu);
        ASSERT_EQ(tau.size(), top);
        double sum = 0;
        for (std::size_t k = top; k-- > 0;) {
            EXPECT_GE(tau[k], 0.0) << nu << " layer " << k;
            sum += tau[k];
            const double want = -std::log(col.transmittance(nu, k, top, 1.0));
            EXPECT_NEAR(sum, want, 1e-10 * want + 1e-15) << nu << " level " << k;
        }
        EXPECT_GT(sum, 1e-3) << nu << ": pick wavenumbers that absorb";
    }
}

// ---- Independent references ------------------------------------------------------------

struct UsStandardOzone {
    Profile profile;        // ozone only
    double column_cm2 = 0;  // molecules cm-2, from the AFGL table's own air density
};

UsStandardOzone us_standard_ozone() {
    auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt");
    std::vector<double> n_o3;
    for (std::size_t k = 0; k < us.profile.size(); ++k)
        n_o3.push_back(us.n_air_cm3[k] * us.profile.vmr_ppmv[int(Gas::O3)][k] * 1e-6);
    return {only(us.profile, Gas::O3), column_cm2(us.profile.z_km, n_o3)};
}

// Ozone Chappuis band, US standard vertical column (344 DU), against the WMO (1986)
// cross sections (tests/data/atmos/ozone_xsec_wmo1986_400-850nm.txt, air wavelengths,
// Beer's law on the same column). Measured: T(0.6 um) 0.9587 here, 0.9559 WMO; mean tau
// over 540-660 nm 0.0337 here, 0.0348 WMO (-3.0 %).
// Tolerances: LOWTRAN's coefficients are sampled every 200 cm-1 (7 nm) while the WMO
// curve has 1-nm structure of +-6 % around 600 nm, and the two data sets are different
// laboratory compilations (a few percent apart): 10 % of tau at a point (0.005 in T
// for tau 0.045), 5 % for the band mean.
TEST(GasAbsorptionReference, OzoneChappuisMatchesWmo1986) {
    const auto oz = us_standard_ozone();
    EXPECT_NEAR(oz.column_cm2 / 2.6868e16, 344, 5);  // the AFGL US standard column
    GasColumn col(tables(), oz.profile);
    const std::size_t top = oz.profile.size() - 1;
    const auto wmo = read_table(kTestData + "/ozone_xsec_wmo1986_400-850nm.txt");
    auto tau_here = [&](double nm) { return -std::log(col.transmittance(1e7 / nm, 0, top, 1.0)); };
    auto tau_wmo = [&](double nm) { return interpolate(wmo, nm / 1.000277, 1) * oz.column_cm2; };
    EXPECT_NEAR(std::exp(-tau_here(600)), std::exp(-tau_wmo(600)), 0.005);
    EXPECT_LT(std::exp(-tau_here(600)), 0.97);  // Chappuis absorbs a few percent
    const double mean_here = wavelength_mean(540, 660, tau_here);
    const double mean_wmo = wavelength_mean(540, 660, tau_wmo);
    EXPECT_NEAR(mean_here / mean_wmo, 1.0, 0.05) << mean_here << " vs " << mean_wmo;
    unit::record("transmittance_600nm", std::exp(-tau_here(600)));
    unit::record("reference_600nm", std::exp(-tau_wmo(600)));
    unit::record("limit_600nm", 0.005);
    unit::record("mean_tau_540_660nm", mean_here);
    unit::record("reference_mean_tau_540_660nm", mean_wmo);
    unit::record("limit_mean_relative", 0.05);
}

// Ozone Hartley-Huggins edge against SPCTRAL2's ozone coefficients (Bird & Riordan 1984
// after Leckner 1978, tests/data/atmos/spectrl2_*: T = exp(-ao O3), O3 in atm-cm, no
// temperature dependence). LOWTRAN's cross sections (Bass & Paur) depend on temperature;
// at 273.15 K their factor is 1, so the comparison uses a 1 km path at 273.15 K holding
// the US standard column (0.344 atm-cm). Mean transmittance over 300-340 nm; tolerance
// 0.03 in T: SPCTRAL2 samples this steep edge every 5 nm (tau falls 2x per sample) and
// holds room-temperature values (the table's own factor at 295 K is 1.06 at 310 nm).
// Measured: 0.666 here, 0.654 SPCTRAL2.
// For the real US standard column (ozone near 220 K, about 14 % less absorption at
// 310 nm) LOWTRAN transmits more: mean 0.685 against SPCTRAL2's 0.654.
TEST(GasAbsorptionReference, OzoneHartleyHugginsMatchesSpctral2At273K) {
    const double atm_cm = us_standard_ozone().column_cm2 / 2.6868e19;
    Profile prof = homogeneous(2, kP0, kT0);
    // ppmv giving atm_cm over 1 km at STP: atm-cm per km = 2.6868e19 ppmv 3.7194e-21.
    set_gas(prof, Gas::O3, atm_cm / (2.6868e19 * 3.7194e-21));
    GasColumn col(tables(), prof);
    const auto spc = read_table(kTestData + "/spectrl2_bird_riordan_coefficients.txt");
    const double here = wavelength_mean(
        300, 340, [&](double nm) { return col.transmittance(1e7 / nm, 0, 1, 1.0); });
    const double ref = wavelength_mean(
        300, 340, [&](double nm) { return std::exp(-interpolate(spc, nm, 3) * atm_cm); });
    EXPECT_NEAR(here, ref, 0.03);
    EXPECT_LT(col.transmittance(1e7 / 300, 0, 1, 1.0), 0.1);
}

// The Hartley-Huggins temperature dependence is the Bass algorithm of
// o3_hartley_huggins.txt: at 310 nm (32260 cm-1: C0 9.49373 (1e-20 cm2), C1/C0
// 2.588e-3, C2/C0 9.51072e-6) a 220 K path of u atm-cm has
// tau = 0.269 C0 u (1 + C1/C0 (T - 273.15) + C2/C0 (T - 273.15)^2). Rounding only.
TEST(GasAbsorptionReference, OzoneHartleyHugginsTemperatureDependence) {
    Profile prof = homogeneous(2, 100, 220);
    set_gas(prof, Gas::O3, 5.0);
    GasColumn col(tables(), prof);
    const double u = 2.6868e19 * (100 / kP0) * (kT0 / 220) * 5.0 * 3.7194e-21;  // atm-cm
    const double dt = 220 - kT0;
    const double tau = 0.269 * 9.49373 * u * (1 + 2.588e-3 * dt + 9.51072e-6 * dt * dt);
    EXPECT_NEAR(col.continuum_optical_depth(32260, 0, 1, 1.0), tau, 1e-12 * tau);
    EXPECT_NEAR(col.transmittance(32260, 0, 1, 1.0), std::exp(-tau), 1e-12);
}

// O2 A band, US standard vertical column (O2 alone): strongly absorbing at its centre,
// and its mean over 752.5-780 nm against SPCTRAL2's mixed-gas formula
// T = exp(-1.41 au M / (1 + 118.93 au M)^0.45), M = 1 at 1013 mb (O2 is the only mixed
// gas with au > 0 there). Measured: minimum 0.280 (5 cm-1 steps); means 0.877 here, 0.899
// SPCTRAL2. Tolerance 0.03 in T (a quarter of the absorbed fraction): SPCTRAL2 resolves
// the band with three samples 5 nm apart.
TEST(GasAbsorptionReference, OxygenABandAbsorbsStrongly) {
    auto us = only(afgl("afgl_atmosphere_6_us_standard_1976.txt").profile, Gas::O2);
    GasColumn col(tables(), us);
    const std::size_t top = us.size() - 1;
    double lowest = 1;
    for (double nu = 13000; nu <= 13200; nu += 5)
        lowest = std::min(lowest, col.transmittance(nu, 0, top, 1.0));
    EXPECT_LT(lowest, 0.5);
    const auto spc = read_table(kTestData + "/spectrl2_bird_riordan_coefficients.txt");
    const double here = wavelength_mean(
        752.5, 780, [&](double nm) { return col.transmittance(1e7 / nm, 0, top, 1.0); });
    const double ref = wavelength_mean(752.5, 780, [&](double nm) {
        const double au = interpolate(spc, nm, 4);
        return std::exp(-1.41 * au / std::pow(1 + 118.93 * au, 0.45));
    });
    EXPECT_NEAR(here, ref, 0.03);
    unit::record("mean_transmittance", here);
    unit::record("reference", ref);
    unit::record("limit", 0.03);
}

// Water vapour, mid-latitude summer vertical column (2.92 cm precipitable water; H2O
// band model and continuum, nothing else): the 0.94-um band is strongly absorbing, and
// band means over wavelength agree with SPCTRAL2's T = exp(-0.2385 aw W / (1 + 20.07 aw
// W)^0.45). Measured means here / SPCTRAL2: 800-860 nm 0.933 / 0.925, 880-1040 nm
// 0.785 / 0.783, 1040-1240 nm 0.727 / 0.724. Tolerance 0.03 in T: SPCTRAL2 samples
// the bands every 10-40 nm and fits Leckner's coefficients (stated ~10 % accuracy).
// Outside the bands (0.55 um) water vapour transmits > 0.99 (SPCTRAL2: aw = 0).
TEST(GasAbsorptionReference, WaterVapourBandsMatchSpctral2) {
    auto mls = only(afgl("afgl_atmosphere_2_midlatitude_summer.txt").profile, Gas::H2O);
    GasColumn col(tables(), mls);
    const std::size_t top = mls.size() - 1;
    std::vector<double> rho_g_cm3;
    for (double r : mls.h2o_g_m3) rho_g_cm3.push_back(r * 1e-6);
    const double w_cm = column_cm2(mls.z_km, rho_g_cm3);
    EXPECT_NEAR(w_cm, 2.92, 0.05);
    double lowest = 1;
    for (double nu = 10000; nu <= 11200; nu += 5)
        lowest = std::min(lowest, col.transmittance(nu, 0, top, 1.0));
    EXPECT_LT(lowest, 0.5);
    const auto spc = read_table(kTestData + "/spectrl2_bird_riordan_coefficients.txt");
    double worst = 0;
    for (auto [lo, hi] : {std::pair{800.0, 860.0}, {880.0, 1040.0}, {1040.0, 1240.0}}) {
        const double here = wavelength_mean(
            lo, hi, [&](double nm) { return col.transmittance(1e7 / nm, 0, top, 1.0); });
        const double ref = wavelength_mean(lo, hi, [&](double nm) {
            const double aw = interpolate(spc, nm, 2) * w_cm;
            return std::exp(-0.2385 * aw / std::pow(1 + 20.07 * aw, 0.45));
        });
        EXPECT_NEAR(here, ref, 0.03) << lo << "-" << hi << " nm";
        const std::string band = std::to_string(int(lo)) + "_" + std::to_string(int(hi)) + "nm";
        unit::record("mean_transmittance_" + band, here);
        unit::record("reference_" + band, ref);
        worst = std::max(worst, std::abs(here - ref));
    }
    unit::record("largest_difference", worst);
    unit::record("limit", 0.03);
    EXPECT_GT(col.transmittance(1e7 / 550, 0, top, 1.0), 0.99);
}

// ---- LOWTRAN 7's own output ----------------------------------------------------------------

// The scaled absorber amounts per km at sea level in the US standard atmosphere, against
// LOWTRAN 7's printout of the same ('ATMOSPHERIC PROFILES', level 1, of the MODEL 6 run
// TAPE6_Transmittance.ref in github space-physics/lowtran): for each gas the density of
// its FIRST band, rho (P/P0)^n (T0/T)^m, in g cm-2 km-1 (H2O) or atm-cm km-1; N2
// continuum in km-1; HNO3 and ozone (UV/visible) unscaled atm-cm km-1. Each amount is
// recovered from this implementation through a homogeneous 1 km layer: band model
// W = (-ln T)^(1/a) / 10^C' (C', a typed from the tables at the wavenumber given), Beer's
// law terms W = tau / k. Tolerance: half a unit of the 3 or 4 printed digits plus 0.2 %
// (LOWTRAN takes the table's air density, 2.548e19 cm-3; this code the ideal gas at
// 1013 mb and 288.2 K, 2.5459e19: 0.08 %).
TEST(GasAbsorptionLowtranOutput, SeaLevelAmountsMatchTape6) {
    // US standard 0 km: 1013 mb, 288.2 K, n_air 2.548e19; ppmv from the AFGL table and
    // trace_gas_profiles.txt.
    auto sea_level = [](Gas g, double ppmv) {
        Profile prof = homogeneous(2, 1013.0, 288.2);
        if (g == Gas::H2O)
            prof.h2o_g_m3.assign(2, ppmv * 1e-6 * 2.548e19 / 3.3429e16);
        else
            set_gas(prof, g, ppmv);
        return prof;
    };
    double lowest = 0, highest = 0;  // got / printed - 1
    auto within = [&](double got, double printed, double unit) {
        EXPECT_NEAR(got, printed, 0.5 * unit + 0.002 * printed);
        lowest = std::min(lowest, got / printed - 1);
        highest = std::max(highest, got / printed - 1);
    };
    struct BandCase {
        Gas gas;
        double ppmv, nu, cprime, a, mu, tape6, unit;
    };
    const BandCase bands[] = {
        {Gas::H2O, 7745, 300, 2.03781, 0.5274, 1, 5.79e-01, 1e-3},
        {Gas::O3, 0.0266, 100, -1.3771, 0.8559, 1, 2.34e-03, 1e-5},
        {Gas::CO2, 330, 600, -1.9424, 0.6176, 1, 3.53e+01, 1e-1},
        {Gas::CO, 0.15, 100, -4.2799, 0.6397, 1, 1.37e-02, 1e-4},
        {Gas::CH4, 1.7, 1300, -0.4019, 0.5844, 1, 1.65e-01, 1e-3},
        {Gas::N2O, 0.32, 100, -8.2117, 0.8997, 1e-4, 2.88e-02, 1e-4},  // slant: weak band
        {Gas::O2, 209000, 100, -7.352, 0.6011, 1, 1.69e+04, 1e+2},
        {Gas::NH3, 5e-4, 100, -1.0272, 0.4704, 1, 4.97e-05, 1e-7},
        {Gas::NO, 3e-4, 1850, -0.5488, 0.6613, 1, 2.91e-05, 1e-7},
        {Gas::NO2, 2.3e-5, 1600, 1.2697, 0.7249, 1, 2.18e-06, 1e-8},
        {Gas::SO2, 3e-4, 100, -1.4326, 0.8907, 1, 2.66e-05, 1e-7},
    };
    for (const BandCase& c : bands) {
        GasColumn col(tables(), sea_level(c.gas, c.ppmv));
        const double t = col.band_transmittance(c.gas, c.nu, 0, 1, c.mu);
        ASSERT_LT(t, 1.0) << int(c.gas);
        const double w = c.mu * std::pow(-std::log(t), 1 / c.a) / std::pow(10.0, c.cprime);
        SCOPED_TRACE(int(c.gas));
        within(w, c.tape6, c.unit);
    }
    // Beer's-law amounts: N2 continuum (2400 cm-1, C4 0.113) in gas-free air, HNO3
    // (870 cm-1, k 9.217) and ozone Chappuis (16600 cm-1, C8 0.128) alone.
    GasColumn air(tables(), sea_level(Gas::CO2, 0));
    within(air.continuum_optical_depth(2400, 0, 1, 1) / 0.113, 7.203e-01, 1e-4);
    GasColumn hno3(tables(), sea_level(Gas::HNO3, 5e-5));
    within(hno3.continuum_optical_depth(870, 0, 1, 1) / 9.217, 4.738e-06, 1e-9);
    GasColumn o3(tables(), sea_level(Gas::O3, 0.0266));
    within(o3.continuum_optical_depth(16600, 0, 1, 1) / 0.128, 2.519e-03, 1e-6);
    unit::record("lowest_relative_difference", lowest);
    unit::record("highest_relative_difference", highest);
}

// ---- Tables and speed ------------------------------------------------------------------

// The data folder copied to TempDir()/name with the first data line (not a comment)
// of the lowtran7 table `file` changed by `damage`; returns that line's number.
static int damaged_copy(const std::string& name, const std::string& file,
                        const std::function<void(std::string&)>& damage) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(testing::TempDir()) / name;
    fs::create_directories(dir / "atmosphere/lowtran7");
    for (const auto& e : fs::directory_iterator(kDataDir + "/atmosphere/lowtran7"))
        fs::copy_file(e.path(), dir / "atmosphere/lowtran7" / e.path().filename(),
                      fs::copy_options::overwrite_existing);
    const fs::path path = dir / "atmosphere/lowtran7" / file;
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {}), bad;
    in.close();
    int line = 0, damaged = 0;
    std::istringstream lines(text);
    for (std::string l; std::getline(lines, l);) {
        ++line;
        if (!damaged && !l.empty() && l[0] != '#') {
            damage(l);
            damaged = line;
        }
        bad += l + "\n";
    }
    std::ofstream(path) << bad;
    return damaged;
}

// A damaged table is reported with its file and line; a missing folder is an IoError.
TEST(GasAbsorptionTables, BadTableNamesFileAndLine) {
    namespace fs = std::filesystem;
    EXPECT_THROW(GasTables::load("/nonexistent"), IoError);
    const fs::path dir = fs::path(testing::TempDir()) / "gas_tables";
    const int damaged = damaged_copy("gas_tables", "n2_continuum.txt",
                                     [](std::string& l) { l = "   2080  4.807692 2.93x-04"; });
    try {
        GasTables::load(dir.string());
        ADD_FAILURE() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(e.where().line, damaged);
        EXPECT_NE(e.where().file.find("n2_continuum.txt"), std::string::npos);
    }
    fs::remove_all(dir);
}

// A load for a range of wavenumbers (build_radiance's visible .snd: 14285-25000 cm-1)
// reads the tables that reach within 100 cm-1 of it, skips the others (named), and
// answers as the whole tables do, bit for bit, from the range's ends to its middle (the
// water vapour bands, the oxygen A and B bands, the Chappuis band): transmittances,
// layer depths and exponential-sum terms. Outside the range it refuses (a programming
// error: build_radiance asks only for its samples). An infrared range reads the CO2
// band model and skips the ultraviolet ozone table.
TEST(GasAbsorptionTables, ARangedLoadReadsWhatReachesItAndAnswersAlike) {
    const GasTables visible = GasTables::load(kDataDir, 14285, 25000);
    const std::vector<std::string> skipped{
        "band_model_CO2.txt",    "band_model_O3.txt",          "band_model_N2O.txt",
        "band_model_CO.txt",     "band_model_CH4.txt",         "band_model_NO.txt",
        "band_model_SO2.txt",    "band_model_NO2.txt",         "band_model_NH3.txt",
        "n2_continuum.txt",      "o2_continuum_1395_1760.txt", "hno3_band_coefficients.txt",
        "o3_hartley_huggins.txt"};
    EXPECT_EQ(visible.skipped(), skipped);
    EXPECT_TRUE(tables().skipped().empty());
    const auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    const GasColumn part(visible, us), whole(tables(), us);
    const std::size_t top = us.size() - 1;
    for (double nu : {14285.0, 14450.0, 15850.0, 16500.0, 19995.0, 20000.0, 22000.0, 25000.0}) {
        EXPECT_EQ(part.transmittance(nu, 0, top, 0.6), whole.transmittance(nu, 0, top, 0.6)) << nu;
        EXPECT_EQ(part.layer_absorption_depth(nu), whole.layer_absorption_depth(nu)) << nu;
        const auto a = part.absorption_terms(nu, 20, 0.005, 12),
                   b = whole.absorption_terms(nu, 20, 0.005, 12);
        EXPECT_EQ(a.weight, b.weight) << nu;
        EXPECT_EQ(a.depth, b.depth) << nu;
    }
    EXPECT_THROW(part.transmittance(14284, 0, top, 1), std::logic_error);
    EXPECT_THROW(part.layer_absorption_depth(25001), std::logic_error);
    EXPECT_THROW(part.absorption_terms(2000, 20, 0.005, 12), std::logic_error);
    const GasTables infrared = GasTables::load(kDataDir, 600, 1400);
    const auto& ir = infrared.skipped();
    EXPECT_EQ(std::count(ir.begin(), ir.end(), "band_model_CO2.txt"), 0);
    EXPECT_EQ(std::count(ir.begin(), ir.end(), "o3_hartley_huggins.txt"), 1);
    const GasColumn ir_part(infrared, us);
    EXPECT_EQ(ir_part.transmittance(950, 0, top, 1), whole.transmittance(950, 0, top, 1));
}

// A band's wavenumber ranges in band_model_constants.txt (what a ranged load reads by)
// must read A-B[;C-D...]: a damaged one is refused with its line.
TEST(GasAbsorptionTables, BadBandRangesNameTheirLine) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(testing::TempDir()) / "gas_ranges";
    const int damaged = damaged_copy("gas_ranges", "band_model_constants.txt", [](std::string& l) {
        l.replace(l.rfind("0-345"), 5, "0~345");
    });
    try {
        GasTables::load(dir.string(), 14285, 25000);
        ADD_FAILURE() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(e.where().line, damaged);
        EXPECT_NE(std::string(e.what()).find("0~345"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

// One transmittance() call (US standard, 50 levels, every gas) for build_radiance's
// ~125 wavenumbers x ~200 paths. Measured ~0.15 us on the development machine; the
// bound (20 us) only catches an accidental per-call allocation or table scan.
TEST(GasAbsorptionSpeed, TransmittanceCallIsFast) {
    auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    GasColumn col(tables(), us);
    const std::size_t top = us.size() - 1;
    double sum = 0;
    int calls = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (double nu = 2000; nu < 27000; nu += 200)
        for (std::size_t i = 0; i < top; ++i)
            for (double mu : {1.0, 0.5, 0.3, 0.2}) {
                sum += col.transmittance(nu, i, top, mu);
                ++calls;
            }
    const auto t1 = std::chrono::steady_clock::now();
    const double ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / calls;
    RecordProperty("ns_per_transmittance_call", std::to_string(ns));
    std::printf("GasColumn::transmittance: %.0f ns per call (%d calls)\n", ns, calls);
    EXPECT_GT(sum, 0);
    EXPECT_LT(ns, 20000);
}

// ---- Exponential sums for the scattering solver -----------------------------------------

namespace {

// Sum over the terms of w exp(-(depth of layers lo..hi-1) / mu).
double terms_transmittance(const GasColumn::Terms& t, std::size_t lo, std::size_t hi, double mu) {
    double sum = 0;
    for (std::size_t i = 0; i < t.weight.size(); ++i) {
        double tau = 0;
        for (std::size_t k = lo; k < hi; ++k) tau += t.depth[i][k];
        sum += t.weight[i] * std::exp(-tau / mu);
    }
    return sum;
}

}  // namespace

// Every gas alone in the US standard atmosphere, every 20 cm-1 interval of its tables
// (LOWTRAN's resolution) from 0 to 20000 cm-1: the exponential-sum terms transmit like
// the band model (GasColumn::transmittance, the path's summed amounts) on every path from
// the ground or from the top to each level, at 1 to 20 times the vertical amount
// (mu 1 to 0.05), within the 0.005 asked for (exp_sum.hpp: the fit's points are
// within 0.0045, and both curves are monotone between them). The continua are Beer's
// law in both and cancel. Prints the largest error and the largest number of terms.
TEST(GasAbsorptionTerms, ExpSumsReproduceTheBandModelOnEveryInterval) {
    const auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    const std::pair<Gas, double> minor[] = {
        {Gas::NO, 3e-4}, {Gas::SO2, 3e-4}, {Gas::NO2, 2.3e-5}, {Gas::NH3, 5e-4}};
    double worst_all = 0;
    std::size_t most_all = 0;
    for (int g = 0; g < 11; ++g) {
        Profile p = only(us, Gas(g));
        for (const auto& [gas, ppmv] : minor)
            if (int(gas) == g) set_gas(p, gas, ppmv);
        const GasColumn col(tables(), p);
        const std::size_t top = p.size() - 1;
        double worst = 0, worst_nu = 0;
        std::size_t most = 1, fitted = 0;
        for (double nu = 10; nu < 20000; nu += 20) {
            const auto t = col.absorption_terms(nu, 20, 0.005, 16);
            if (t.equivalent) continue;
            ++fitted;
            most = std::max(most, t.weight.size());
            for (double mu : {1.0, 0.5, 0.2, 0.1, 0.05})
                for (std::size_t k = 0; k <= top; ++k)
                    for (auto [lo, hi] : {std::pair{std::size_t{0}, k}, std::pair{k, top}}) {
                        if (lo == hi) continue;
                        const double e = std::abs(terms_transmittance(t, lo, hi, mu) -
                                                  col.transmittance(nu, lo, hi, mu));
                        if (e > worst) worst = e, worst_nu = nu;
                    }
        }
        std::printf(
            "gas %d: %zu intervals fitted, up to %zu terms, largest error %.4f at %g cm-1\n", g,
            fitted, most, worst, worst_nu);
        EXPECT_LE(worst, 0.005) << "gas " << g << " at " << worst_nu << " cm-1";
        worst_all = std::max(worst_all, worst);
        most_all = std::max(most_all, most);
    }
    unit::record("largest_error", worst_all);
    unit::record("most_terms", double(most_all));
    unit::record("limit", 0.005);
}

// Where no gas needs a fit (a window, or terms limited to 1) the one term is the
// equivalent depth of layer_absorption_depth itself, bit for bit.
TEST(GasAbsorptionTerms, OneTermIsTheEquivalentDepth) {
    const auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    const GasColumn col(tables(), us);
    for (double nu : {13100.0, 10600.0, 1000.0}) {  // O2 A band, H2O 0.94 um, O3 9.6 um
        const auto t = col.absorption_terms(nu, 20, 0.005, 1);
        ASSERT_TRUE(t.equivalent);
        ASSERT_EQ(t.weight.size(), 1u);
        EXPECT_EQ(t.depth[0], col.layer_absorption_depth(nu)) << nu;
    }
    EXPECT_FALSE(col.absorption_terms(13100, 20, 0.005, 12).equivalent);
}

// Every gas together in the US standard atmosphere, every 100 cm-1 from 500 to 20000
// cm-1: only the strongest gas is fitted (with a second where it overlaps strongly:
// gas_overlap_test.cpp), the others keep their equivalent depths, so where more bands
// overlap there is no tol bound; on every path from the ground or the top
// to a level at 1 to 20 vertical amounts the terms' error is compared with that of one
// equivalent depth per layer. Printed: the largest of each and the share of paths
// where the terms do better; the terms must do better on most paths and in the worst
// case (measured: see the printout).
TEST(GasAbsorptionTerms, OverlappingGasesImproveOnOneEquivalentDepth) {
    auto us = afgl("afgl_atmosphere_6_us_standard_1976.txt").profile;
    const GasColumn col(tables(), us);
    const std::size_t top = us.size() - 1;
    const double tol = 0.005;
    std::size_t most = 0, paths = 0, better = 0;
    double worst = 0, worst_one = 0;
    for (double nu = 500; nu <= 20000; nu += 100) {
        const auto t = col.absorption_terms(nu, 20, tol, 12);
        if (t.equivalent) continue;
        const auto one = col.absorption_terms(nu, 20, tol, 1);
        most = std::max(most, t.weight.size());
        for (double mu : {1.0, 0.3, 0.05})
            for (std::size_t k = 0; k <= top; ++k)
                for (auto [lo, hi] : {std::pair{std::size_t{0}, k}, std::pair{k, top}}) {
                    if (lo == hi) continue;
                    const double exact = col.transmittance(nu, lo, hi, mu);
                    const double e = std::abs(terms_transmittance(t, lo, hi, mu) - exact);
                    const double e1 = std::abs(terms_transmittance(one, lo, hi, mu) - exact);
                    worst = std::max(worst, e);
                    worst_one = std::max(worst_one, e1);
                    ++paths;
                    better += e <= e1 + 1e-12;
                }
    }
    std::printf(
        "up to %zu terms; largest error %.4f (one equivalent depth %.4f); terms at "
        "least as good on %.1f %% of %zu paths\n",
        most, worst, worst_one, 100.0 * better / paths, paths);
    EXPECT_LT(worst, worst_one);
    EXPECT_GT(better, paths / 2);
}
