// Tests for the LOWTRAN 7 water-cloud models (lib/atmos/cloud) and their place in the
// column (lib/atmos/column_model).
#include "atmos/cloud.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "atmos/column_model.hpp"
#include "atmos/rayleigh.hpp"
#include "core/error.hpp"
#include "rt/discrete_ordinates.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

const std::string kSource = SIGCHAIN_SOURCE_DIR;
const std::string kData = kSource + "/data";

CloudModel cloud(int icld, double ground_km = 0) {
    io::CdkCard2 c;
    c.icld = icld;
    return *CloudModel::from_deck(c, ground_km, kData);
}

// Pure arithmetic on single-precision table values: double rounding only.
constexpr double kArith = 1e-12;

// Stratus (ICLD 3) 0.55-um column (km-1 x km) from its levels, computed here by hand:
// LWC 0, .15, .3, .15, 0 g m-3 at .16, .33, .66, 1.0, 1.5 km; exponential between two
// positive values (integral h (b - a) / ln(b / a)), linear to zero; LWC_eq 5.272e-3.
double stratus_column055() {
    const double lwc = 0.5 * 0.15 * (0.33 - 0.16) + (0.66 - 0.33) * 0.15 / std::log(2.0) +
                       (1.0 - 0.66) * 0.15 / std::log(2.0) + 0.5 * 0.15 * (1.5 - 1.0);
    return lwc / 5.272e-3;
}

}  // namespace

TEST(AtmosCloud, TabulatedExtinctionAtAWavelength) {
    // cloud_models.txt, stratus columns: ext 1.0559 abs 0.00681 g 0.8328 at 1.536 um;
    // ext 0.91743 at 10 um; ext 1.031 / 1.0559 at 1.06 / 1.536 um (midpoint 1.298).
    const CloudModel s = cloud(3);
    const double beta055 = 0.3 / 5.272e-3;  // LWC 0.3 g m-3 at .66 km
    EXPECT_NEAR(s.extinction_km1(0.66, 0.55), beta055, kArith * beta055);
    EXPECT_NEAR(s.extinction_km1(0.66, 1.536), beta055 * 1.0559, kArith * beta055);
    EXPECT_NEAR(s.extinction_km1(0.66, 10.0), beta055 * 0.91743, kArith * beta055);
    EXPECT_NEAR(s.extinction_km1(0.66, 1.298), beta055 * (1.031 + 1.0559) / 2, kArith * beta055);
    const auto o = s.optics(1.536);
    EXPECT_NEAR(o[1], 0.00681, kArith);
    EXPECT_NEAR(o[2], 0.8328, kArith);
    const AerosolLayerOptics l = s.layer(0.5, 0.8, 1.536);
    EXPECT_NEAR(l.ssa, 1 - 0.00681 / 1.0559, kArith);
    EXPECT_NEAR(l.g, 0.8328, kArith);
    // Non-absorbing where the table's absorption is 0 (0.55 um).
    EXPECT_EQ(s.layer(0.5, 0.8, 0.55).ssa, 1.0);
    // Cumulus 0.55 um at 1.5 km (LWC 1.0): 1 / 7.683e-3 km-1.
    EXPECT_NEAR(cloud(1).extinction_km1(1.5, 0.55), 1 / 7.683e-3, kArith / 7.683e-3);
}

TEST(AtmosCloud, ProfileHeightsAreLowtranCloudLevels) {
    // The levels (km above ground) of LOWTRAN 7's FLAYZ; bases and tops as its cloud menu
    // states them (cumulus: the LWC table ends at 3.0 km, the menu says 2.7 km top).
    const auto& z = CloudModel::level_heights_km();
    const double expected[12] = {0, .16, .33, .66, 1, 1.5, 2, 2.4, 2.7, 3, 3.5, 4};
    for (int i = 0; i < 12; ++i) EXPECT_EQ(z[i], expected[i]);
    const double base[5] = {0.66, 2.4, 0.33, 0.66, 0.16}, top[5] = {3.0, 3.0, 1.0, 2.0, 0.66};
    const double ground = 0.25;  // the levels stand on the ground
    for (int m = 1; m <= 5; ++m) {
        const CloudModel c = cloud(m, ground);
        double lo = 99, hi = -1;
        for (double h : z)
            if (c.lwc_g_m3(ground + h) > 0) lo = std::min(lo, h), hi = std::max(hi, h);
        EXPECT_NEAR(lo, base[m - 1], 1e-12) << "ICLD " << m;
        EXPECT_NEAR(hi, top[m - 1], 1e-12) << "ICLD " << m;
    }
    // The level numbers read as these heights agree with the rain menu White (1996),
    // section 4.2.3.5 reproduces: ICLD 6 "2.0MM/HR AT 0KM TO .22MM/HR AT 1.5KM" (RR1,
    // level 5), ICLD 9 "25.0MM/HR AT 0KM TO .2MM/HR AT 3.0KM" (RR4, level 9).
    std::ifstream f(kData + "/atmosphere/lowtran7/cloud_rain_profiles.txt");
    std::string line;
    std::vector<std::vector<double>> rows;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream in(line);
        rows.emplace_back(std::istream_iterator<double>(in), std::istream_iterator<double>());
    }
    ASSERT_EQ(rows.size(), 12u);
    EXPECT_EQ(z[5], 1.5);
    EXPECT_EQ(rows[0][6], 2.0);
    EXPECT_EQ(rows[5][6], 0.22);
    EXPECT_EQ(z[9], 3.0);
    EXPECT_EQ(rows[0][9], 25.0);
    EXPECT_EQ(rows[9][9], 0.2);
    EXPECT_EQ(rows[10][9], 0.0);
    // Stratus values on its levels (cloud_rain_profiles.txt CLD3).
    const CloudModel s = cloud(3, ground);
    EXPECT_EQ(s.lwc_g_m3(ground + 0.33), 0.15);
    EXPECT_EQ(s.lwc_g_m3(ground + 0.66), 0.3);
    EXPECT_EQ(s.lwc_g_m3(ground + 1.0), 0.15);
    EXPECT_EQ(s.lwc_g_m3(ground + 0.1), 0.0);
    EXPECT_EQ(s.lwc_g_m3(ground + 5.0), 0.0);
}

TEST(AtmosCloud, ColumnIsTheExactIntegralOfTheLevels) {
    const CloudModel s = cloud(3);
    const double tau = s.layer(0, 20, 0.55).tau_ext;
    EXPECT_NEAR(tau, stratus_column055(), kArith * tau);
    // Splitting the slab anywhere gives the same column (the integral is exact).
    const double split = s.layer(0, 0.5, 0.55).tau_ext + s.layer(0.5, 0.8, 0.55).tau_ext +
                         s.layer(0.8, 20, 0.55).tau_ext;
    EXPECT_NEAR(split, tau, kArith * tau);
}

// The rain models 6-10 carry LOWTRAN 7's clouds 3, 5, 5, 1, 1 (their rain is
// rain_test.cpp's); cirrus 18-19 has no water cloud; 11 and 20 are not modelled.
TEST(AtmosCloud, RainModelsCarryTheirCloudAndCirrusNone) {
    const int pair[5] = {3, 5, 5, 1, 1};
    for (int icld = 6; icld <= 10; ++icld) {
        EXPECT_TRUE(CloudModel::modelled(icld));
        const CloudModel r = cloud(icld), c = cloud(pair[icld - 6]);
        for (double z : {0.2, 0.5, 0.8, 1.7, 2.5})
            EXPECT_EQ(r.extinction_km1(z, 1.06), c.extinction_km1(z, 1.06)) << icld << " " << z;
    }
    io::CdkCard2 noaa;
    noaa.icld = 20;
    EXPECT_THROW(CloudModel::from_deck(noaa, 0, kData), DataError);
    EXPECT_FALSE(CloudModel::modelled(20));
    for (int icld : {0, 18, 19}) {
        io::CdkCard2 c;
        c.icld = icld;
        EXPECT_FALSE(CloudModel::from_deck(c, 0, kData).has_value()) << icld;
    }
}

TEST(AtmosCloud, CombineWeightsSsaByExtinctionAndGByScattering) {
    // tau 1, ssa .5, g .2 with tau 3, ssa 1, g .8: scattering .5 + 3 = 3.5.
    const AerosolLayerOptics c = combine({1, 0.5, 0.2}, {3, 1, 0.8});
    EXPECT_NEAR(c.tau_ext, 4, kArith);
    EXPECT_NEAR(c.ssa, 3.5 / 4, kArith);
    EXPECT_NEAR(c.g, (0.5 * 0.2 + 3 * 0.8) / 3.5, kArith);
}

// The overcast column darkens the sun's direct beam by exp(-tau_cloud m), tau_cloud from
// the tables by hand (stratus column x ext(lambda), linear between 0.55 and 0.6943 um)
// and m the air mass through the cloud, independently of the model's ray tracing: the
// apparent zenith from Saemundsson's refraction (Sky & Telescope 72, 70, 1986) at the
// true altitude, carried up to the cloud's centre of extinction (0.68 km above the
// ground, GNDALT 0) on LOWTRAN 7's sphere of 6371.23 km.
TEST(AtmosCloud, OvercastDeckDarkensTheDirectBeam) {
    auto deck = io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk");
    ColumnOptions o;
    o.data_dir = kData;
    const io::CdkRun clear = deck.runs[0];
    io::CdkRun overcast = clear;
    overcast.card2.icld = 3;
    const ColumnModel a(clear, 1.0, o), b(overcast, 1.0, o);
    EXPECT_GT(b.profile().size(), a.profile().size());  // the cloud levels are added
    const double mu0 = 0.6;
    const double deg = std::numbers::pi / 180;
    const double altitude_deg = 90 - std::acos(mu0) / deg;
    const double refraction_deg =
        1.02 / std::tan((altitude_deg + 10.3 / (altitude_deg + 5.11)) * deg) / 60;
    const double earth_km = 6371.23;
    const double s = earth_km * std::sin(std::acos(mu0) - refraction_deg * deg) / (earth_km + 0.68);
    const double air_mass = 1 / std::sqrt(1 - s * s);
    for (double nu : {18000.0, 17000.0}) {
        const double lambda = 1e4 / nu;
        const double ext = 1 + (lambda - 0.55) / (0.6943 - 0.55) * (1.0089 - 1);
        const double tau_cloud = stratus_column055() * ext;
        const double ta = a.sun_transmittance(nu, a.layers(nu), 0, mu0);
        const double tb = b.sun_transmittance(nu, b.layers(nu), 0, mu0);
        // 1e-4 relative: Saemundsson's standard atmosphere against the deck's (a few % of
        // its 1.35 arcmin: 2e-5 of m) and the cloud's extent about its centre (0.16-1.5 km:
        // 5e-5 of m); the cloud levels' re-layering of the gas path is 1.3e-8.
        EXPECT_NEAR(std::log(tb / ta), -tau_cloud * air_mass, 1e-4 * tau_cloud * air_mass) << nu;
    }
}

// Energy conservation through an overcast column that absorbs nothing: stratus at
// 0.55 um (tabulated absorption 0, so ssa 1), Rayleigh, no aerosol, the gas depths set
// to 0, over a black ground. The solver's reflected flux at the top and the flux
// reaching the ground (direct and diffuse) add up to the incident mu0 F0.
TEST(AtmosCloud, NonAbsorbingOvercastColumnConservesEnergy) {
    auto deck = io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk");
    ColumnOptions o;
    o.data_dir = kData;
    io::CdkRun run = deck.runs[0];
    run.card2.ihaze = 0;
    run.card2.icld = 3;
    const ColumnModel column(run, 1.0, o);
    const double nu = 1e4 / 0.55;
    const auto col = column.layers(nu);
    rt::Problem p;
    double tau_cloud = 0;
    const int moments = 32;
    for (auto it = col.rbegin(); it != col.rend(); ++it) {  // top first
        EXPECT_TRUE(it->tau_aerosol == 0 || it->ssa_aerosol == 1.0);
        tau_cloud += it->tau_aerosol;
        rt::Layer l;
        l.tau = it->tau_rayleigh + it->tau_aerosol;
        l.ssa = 1;
        l.pmom.assign(moments + 1, 0.0);
        const auto ray = rayleigh_phase_moments();
        double gk = 1;
        for (int k = 0; k <= moments; ++k, gk *= it->g_aerosol)
            l.pmom[k] = ((k < 3 ? ray[k] : 0.0) * it->tau_rayleigh + gk * it->tau_aerosol) / l.tau;
        p.layers.push_back(std::move(l));
    }
    EXPECT_NEAR(tau_cloud, stratus_column055(), kArith * tau_cloud);
    double total = 0;
    for (const auto& l : p.layers) total += l.tau;
    p.streams = 16;
    p.beam_flux = 1;
    p.beam_mu0 = 0.6;
    p.utau = {0, total};
    p.umu = {-1, 1};
    p.phi_deg = {0};
    const rt::Result r = rt::solve(p);
    const double up = r.levels[0].diffuse_up;
    const double down = r.levels[1].direct_down + r.levels[1].diffuse_down;
    std::printf("overcast tau %.4g: reflected %.6f transmitted %.6f sum %.9f of mu0 %.1f\n", total,
                up, down, up + down, p.beam_mu0);
    // 1e-6: the solver computes ssa 1 as 1 - 1e-9 (DISORT's dither), absorbing about
    // 1e-9 per scattering over the few hundred scatterings in a tau-37 cloud (~1e-7;
    // measured 4e-8). A cloud ssa of 0.99999 would lose ~1e-3.
    EXPECT_NEAR(up + down, p.beam_mu0, 1e-6);
    EXPECT_GT(up / p.beam_mu0, 0.5);  // overcast: most of the sunlight goes back up (0.81)
}

namespace {

// CARD 2D region 2 (the cloud's) with the columns ext/abs/g of cloud_models.txt, through
// the deck reader: CARD 2D2 written with printf's F6.2,2F7.5,F6.4.
io::CdkUserOptics user_cloud(int ext, int abs, int g, double ext_scale = 1) {
    std::ifstream in(kData + "/atmosphere/lowtran7/cloud_models.txt");
    std::string text =
        "    6    2    2    1    0    0    0    0    0    0    1    0    1   0.000   0.00\n"
        "    1    0    0    0   11    0    23.000     0.000     0.000     0.000     0.000\n"
        "    0    1    0    0\n"
        " 7.683E-03CLOUD\n";
    int i = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        std::vector<double> v;
        for (double x; f >> x;) v.push_back(x);
        char grp[40];
        std::snprintf(grp, sizeof grp, "%6.2f%7.5f%7.5f%6.4f", v[0],
                      ext < 0 ? ext_scale : v[std::size_t(ext)], v[std::size_t(abs)],
                      v[std::size_t(g)]);
        text += grp;
        if (++i % 3 == 0 || i == 47) text += "\n";
    }
    text +=
        "     1.000     0.000   180.000     0.000     0.000     0.000    0\n"
        "    1    2  273    0\n"
        "    43.083    77.667     0.000     0.000    19.000    90.000     0.000     0.000\n"
        " 14000.000 25000.000   100.000\n    0\n";
    return *io::parse_cdk(TextInput::from_string(text, "t.cdk")).runs.at(0).user_optics;
}

}  // namespace

// ICLD 11 with the cumulus's coefficients (cloud_models.txt's first three columns, exact
// in F7.5/F6.4) is the cumulus (ICLD 1) exactly: LOWTRAN 7's LAYCLD gives ICLD 11 the
// cumulus's liquid water (MC=1) and HAZEC divides it by the cumulus's CULWC.
TEST(AtmosCloud, UserDefinedCloudWithCumulusCoefficientsIsTheCumulus) {
    const io::CdkUserOptics u = user_cloud(1, 2, 3);
    io::CdkCard2 c;
    c.icld = 11;
    EXPECT_TRUE(CloudModel::modelled(11));
    const CloudModel user = *CloudModel::from_deck(c, 0.3, kData, std::nullopt, &u);
    const CloudModel cumulus = cloud(1, 0.3);
    const CloudModel fallback = *CloudModel::from_deck(c, 0.3, kData);  // IREG(2) 0
    for (double lambda : {0.3, 0.55, 0.9, 3.0, 11.0})
        for (auto [lo, hi] : {std::pair{0.3, 1.0}, {1.0, 2.2}, {2.2, 3.4}, {0.3, 6.0}}) {
            const AerosolLayerOptics a = user.layer(lo, hi, lambda);
            const AerosolLayerOptics b = cumulus.layer(lo, hi, lambda);
            const AerosolLayerOptics f = fallback.layer(lo, hi, lambda);
            EXPECT_EQ(a.tau_ext, b.tau_ext) << lambda << " " << lo;
            EXPECT_EQ(a.ssa, b.ssa) << lambda << " " << lo;
            EXPECT_EQ(a.g, b.g) << lambda << " " << lo;
            EXPECT_EQ(f.tau_ext, b.tau_ext) << lambda << " " << lo;
            EXPECT_GT(b.tau_ext, 0);
        }
}

// ICLD 11 with a grey extinction of 2 (every wavelength) over the cumulus's liquid
// water: tau = 2 x the LWC column / CULWC (7.683e-3 g m-3 per km-1), the column
// computed here by hand from CLD1 (0 .2 .35 1 1 1 .3 .15 0 g m-3 at .33 .66 1 1.5 2 2.4
// 2.7 3 3.5 km above the ground), exponential between positive values, linear to 0.
TEST(AtmosCloud, UserDefinedGreyCloudOpticalDepthIsExtinctionTimesColumn) {
    const io::CdkUserOptics u = user_cloud(-1, 2, 3, 2.0);
    io::CdkCard2 c;
    c.icld = 11;
    const CloudModel m = *CloudModel::from_deck(c, 0, kData, std::nullopt, &u);
    auto expo = [](double h, double a, double b) { return h * (b - a) / std::log(b / a); };
    const double lwc = 0.5 * 0.2 * (0.66 - 0.33) + expo(0.34, 0.2, 0.35) + expo(0.5, 0.35, 1.0) +
                       1.0 * (2.4 - 1.5) + expo(0.3, 1.0, 0.3) + expo(0.3, 0.3, 0.15) +
                       0.5 * 0.15 * (3.5 - 3.0);
    for (double lambda : {0.4, 1.06, 10.0})
        EXPECT_NEAR(m.layer(0, 8, lambda).tau_ext, 2 * lwc / 7.683e-3, kArith * 2 * lwc / 7.683e-3)
            << lambda;
}
