// Tests for the LOWTRAN 7 aerosol models (lib/atmos/aerosol).
#include "atmos/aerosol.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "../record_property.hpp"
#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

const std::string kData = SIGCHAIN_SOURCE_DIR "/data";

io::CdkCard2 card2(int ihaze, double vis_km, int iseasn = 0, int ivulcn = 0) {
    io::CdkCard2 c;
    c.ihaze = ihaze;
    c.visibility_km = vis_km;
    c.iseasn = iseasn;
    c.ivulcn = ivulcn;
    return c;
}

// The US standard profile with a uniform relative humidity.
Profile uniform_rh(double rh) {
    Profile p = afgl_profile(6, kData);
    for (double& v : p.rh_percent) v = rh;
    return p;
}

// The numbers of a data/atmosphere/lowtran7 table ('#' lines skipped), read here.
std::vector<std::vector<double>> table_rows(const std::string& name) {
    std::ifstream in(kData + "/atmosphere/lowtran7/" + name);
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        std::vector<double> row;
        for (double v; f >> v;) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

// A deck (rural23.cdk's cards, MODEL 6) with CARD 2 IHAZE `ihaze`, ICLD `icld`, VIS 23
// and CARD 2D giving the regions flagged in `ireg` the table columns ext/abs/g of
// `rows` (every region the same), CARD 2D2 written with printf's F6.2,2F7.5,F6.4.
std::string deck_with_card2d(int ihaze, int icld, const std::array<int, 4>& ireg,
                             const std::vector<std::vector<double>>& rows, int ext, int abs,
                             int g) {
    char c2[128];
    std::snprintf(c2, sizeof c2, "%5d%5d%5d%5d%5d%5d%10.3f%10.3f%10.3f%10.3f%10.3f", ihaze, 0, 0, 0,
                  icld, 0, 23.0, 0.0, 0.0, 0.0, 0.0);
    std::string d =
        "    6    2    2    1    0    0    0    0    0    0    1    0    1   0.000   0.00\n";
    d += std::string(c2) + "\n";
    char ir[32];
    std::snprintf(ir, sizeof ir, "%5d%5d%5d%5d", ireg[0], ireg[1], ireg[2], ireg[3]);
    d += std::string(ir) + "\n";
    for (int r : ireg) {
        if (!r) continue;
        d += " 0.000E+00TEST\n";
        for (std::size_t i = 0; i < rows.size(); ++i) {
            char grp[40];
            std::snprintf(grp, sizeof grp, "%6.2f%7.5f%7.5f%6.4f", rows[i][0],
                          rows[i][std::size_t(ext)], rows[i][std::size_t(abs)],
                          rows[i][std::size_t(g)]);
            d += grp;
            if (i % 3 == 2 || i + 1 == rows.size()) d += "\n";
        }
    }
    d += "     1.000     0.000   180.000     0.000     0.000     0.000    0\n";
    d += "    1    2  273    0\n";
    d += "    43.083    77.667     0.000     0.000    19.000    90.000     0.000     0.000\n";
    d += " 14000.000 25000.000   100.000\n    0\n";
    return d;
}

io::CdkRun parsed(const std::string& deck) {
    return io::parse_cdk(TextInput::from_string(deck, "t.cdk")).runs.at(0);
}

}  // namespace

TEST(AtmosAerosol, ColumnOpticalDepthMatchesLowtranVis23SpringSummer) {
    // LOWTRAN 7's TAPE6, 0-100 km vertical path, rural VIS 23 spring-summer:
    // AER1+AER2+AER3+AER4 = 0.3249 (a reference LOWTRAN 7 run). Required: 0.5 %.
    const auto m = AerosolModel::from_deck(card2(1, 23, 1), afgl_profile(2, kData), kData);
    EXPECT_NEAR(m.layer(0, 100, 0.55).tau_ext, 0.3249, 0.005 * 0.3249);
    sigchain::unit::record("tau_550nm", m.layer(0, 100, 0.55).tau_ext);
    sigchain::unit::record("reference", 0.3249);
    sigchain::unit::record("limit_relative", 0.005);
}

TEST(AtmosAerosol, ColumnOpticalDepthMatchesLowtranVis5FallWinter) {
    // Same check, rural VIS 5 (IHAZE 2's default, VIS 0) fall-winter: LOWTRAN 1.1416.
    const auto m = AerosolModel::from_deck(card2(2, 0, 2), afgl_profile(3, kData), kData);
    EXPECT_DOUBLE_EQ(m.visibility_km(), 5);
    EXPECT_NEAR(m.layer(0, 100, 0.55).tau_ext, 1.1416, 0.005 * 1.1416);
    sigchain::unit::record("tau_550nm", m.layer(0, 100, 0.55).tau_ext);
    sigchain::unit::record("reference", 1.1416);
    sigchain::unit::record("limit_relative", 0.005);
    // ISEASN 0 with MODEL 3 (mid-latitude winter) is fall-winter too.
    const auto d = AerosolModel::from_deck(card2(2, 0, 0), afgl_profile(3, kData), kData);
    EXPECT_NEAR(d.layer(0, 100, 0.55).tau_ext, m.layer(0, 100, 0.55).tau_ext, 1e-12);
}

TEST(AtmosAerosol, SurfaceExtinctionFollowsKoschmieder) {
    // LOWTRAN's convention VIS = 3.912 / (beta_aer(0.55, 0 km) + 0.01159 km-1); the
    // tabulated visibilities follow it within 0.7 % (README sanity check 5) and the
    // 1/VIS interpolation is exact for it in between: tolerance 1 %.
    for (double vis : {2.0, 5.0, 8.0, 15.0, 23.0, 35.0, 50.0}) {
        const auto m = AerosolModel::from_deck(card2(1, vis, 1), uniform_rh(50), kData);
        const double lhs = m.extinction_km1(0, 0.55) + 0.01159;
        EXPECT_NEAR(lhs, 3.912 / vis, 0.01 * 3.912 / vis) << "VIS " << vis;
    }
}

TEST(AtmosAerosol, TableOpticsAtTabulatedHumidity) {
    // Within 0-1 km only the boundary layer contributes, so the slab's ssa and g are the
    // rural table's at the profile's RH: RH 0 at 0.55 um: abs 0.0593, g 0.6479;
    // RH 80 at 1.06 um: ext 0.43228, abs 0.04158, g 0.665 (aerosol_rural.txt).
    const auto dry = AerosolModel::from_deck(card2(1, 23, 1), uniform_rh(0), kData);
    EXPECT_NEAR(dry.boundary_layer_rh_percent(), 0, 1e-9);
    const auto a = dry.layer(0, 1, 0.55);
    EXPECT_NEAR(a.ssa, 1 - 0.0593, 1e-9);
    EXPECT_NEAR(a.g, 0.6479, 1e-9);
    const auto wet = AerosolModel::from_deck(card2(1, 23, 1), uniform_rh(80), kData);
    EXPECT_NEAR(wet.boundary_layer_rh_percent(), 80, 1e-9);
    const auto b = wet.layer(0, 1, 1.06);
    EXPECT_NEAR(b.ssa, 1 - 0.04158 / 0.43228, 1e-9);
    EXPECT_NEAR(b.g, 0.665, 1e-9);
    // Extinction at 1.06 um relative to 0.55 um is the table's normalised value.
    EXPECT_NEAR(wet.extinction_km1(0.5, 1.06) / wet.extinction_km1(0.5, 0.55), 0.43228, 1e-9);
}

// A slab's per-region 0.55-um columns (slab_columns055, integrated once by a caller
// with fixed slabs) against references that do not share their integration: a thin
// slab's columns sum to the extinction at its middle times its depth (extinction_km1,
// midpoint rule: 1e-6 over 1 m); columns add over adjacent slabs (1e-12); and at
// 0.55 um, where every region's extinction is normalised to 1, the optics built from
// the columns have tau_ext equal to their sum (1e-12). An empty slab has none.
TEST(AtmosAerosol, SlabColumnsIntegrateTheExtinction) {
    const auto m = AerosolModel::from_deck(card2(5, 23, 1), uniform_rh(60), kData);
    auto sum = [](const std::array<double, 4>& c) { return c[0] + c[1] + c[2] + c[3]; };
    for (double z : {0.2, 1.7, 5.0, 15.0, 40.0}) {
        const double thin = sum(m.slab_columns055(z, z + 0.001));
        const double ref = m.extinction_km1(z + 0.0005, 0.55) * 0.001;
        EXPECT_NEAR(thin, ref, 1e-6 * ref) << z;
    }
    for (const auto& [lo, mid, hi] : {std::tuple{0.0, 0.3, 2.4}, {1.7, 2.0, 9.5},
                                       {11.0, 21.0, 30.0}, {0.0, 50.0, 100.0}}) {
        const auto whole = m.slab_columns055(lo, hi);
        const auto a = m.slab_columns055(lo, mid), b = m.slab_columns055(mid, hi);
        for (std::size_t r = 0; r < whole.size(); ++r)
            EXPECT_NEAR(a[r] + b[r], whole[r], 1e-12 * whole[r]) << lo << " " << r;
        const AerosolLayerOptics o = m.layer(whole, 0.55);
        EXPECT_NEAR(o.tau_ext, sum(whole), 1e-12 * sum(whole)) << lo;
        EXPECT_GT(o.tau_ext, 0) << lo;
    }
    for (double c : m.slab_columns055(3, 3)) EXPECT_EQ(c, 0);
}

TEST(AtmosAerosol, EveryModelGivesPhysicalOptics) {
    for (int ihaze : {1, 2, 3, 4, 5, 6, 8, 9, 10}) {
        for (int ivulcn : {0, 2, 3, 8}) {
            auto c = card2(ihaze, 0, 0, ivulcn);
            c.wind_speed_m_s = 7;
            const auto m = AerosolModel::from_deck(c, uniform_rh(85), kData);
            EXPECT_GT(m.visibility_km(), 0);
            for (double l : {0.3, 0.55, 1.0, 2.2, 10.0}) {
                for (auto [lo, hi] :
                     {std::pair{0.0, 1.0}, {2.5, 8.0}, {12.0, 20.0}, {40.0, 60.0}}) {
                    const auto o = m.layer(lo, hi, l);
                    EXPECT_GT(o.tau_ext, 0) << ihaze << " " << l << " " << lo;
                    EXPECT_GE(o.ssa, 0);
                    EXPECT_LE(o.ssa, 1);
                    EXPECT_GT(o.g, -1);
                    EXPECT_LT(o.g, 1);
                }
            }
        }
    }
}

TEST(AtmosAerosol, DefaultVisibilities) {
    // LOWTRAN's defaults (aerosol_vertical_profiles.txt): urban 5, tropospheric 50,
    // maritime 23, advection fog 0.2, radiation fog 0.5 km.
    const Profile p = uniform_rh(70);
    EXPECT_DOUBLE_EQ(AerosolModel::from_deck(card2(5, 0), p, kData).visibility_km(), 5);
    EXPECT_DOUBLE_EQ(AerosolModel::from_deck(card2(6, 0), p, kData).visibility_km(), 50);
    EXPECT_DOUBLE_EQ(AerosolModel::from_deck(card2(4, 0), p, kData).visibility_km(), 23);
    EXPECT_DOUBLE_EQ(AerosolModel::from_deck(card2(8, 0), p, kData).visibility_km(), 0.2);
    EXPECT_DOUBLE_EQ(AerosolModel::from_deck(card2(9, 0), p, kData).visibility_km(), 0.5);
    // Desert with VIS 0: VIS = 3.912 / (ext(0.55) + 0.01159); at 10 m/s the table's
    // ext(0.55) is 0.057144 km-1, so 56.99 km.
    auto d = card2(10, 0);
    d.wind_speed_m_s = 10;
    EXPECT_NEAR(AerosolModel::from_deck(d, p, kData).visibility_km(), 3.912 / (0.057144 + 0.01159),
                1e-9);
    // No aerosol: zero extinction.
    const auto none = AerosolModel::from_deck(card2(0, 0), p, kData);
    EXPECT_EQ(none.layer(0, 100, 0.55).tau_ext, 0);
    EXPECT_EQ(none.extinction_km1(0.5, 0.55), 0);
}

TEST(AtmosAerosol, ElevatedGroundCompressesTheLowerProfile) {
    // Below 6 km the profile is read at z' = 6 (z - G) / (6 - G), so the column from the
    // ground to 6 km is (6 - G) / 6 of the sea-level one (dz = (6 - G)/6 dz'); above 6
    // km nothing changes. Exact up to rounding.
    auto c0 = card2(1, 23, 1);
    auto c1 = c0;
    c1.ground_altitude_km = 1.5;
    const auto m0 = AerosolModel::from_deck(c0, uniform_rh(50), kData);
    const auto m1 = AerosolModel::from_deck(c1, uniform_rh(50), kData);
    EXPECT_NEAR(m1.layer(1.5, 6, 0.55).tau_ext, 0.75 * m0.layer(0, 6, 0.55).tau_ext, 1e-12);
    EXPECT_NEAR(m1.layer(6, 100, 0.55).tau_ext, m0.layer(6, 100, 0.55).tau_ext, 1e-12);
    EXPECT_NEAR(m1.extinction_km1(1.5, 0.55), m0.extinction_km1(0, 0.55), 1e-12);
}

TEST(AtmosAerosol, LayersAddUp) {
    // The slab integral is exact, so slabs add to the column (and extinction integrated
    // by a fine trapezoid agrees with layer() to 1e-4 relative).
    const auto m = AerosolModel::from_deck(card2(5, 10, 1), uniform_rh(60), kData);
    const double whole = m.layer(0, 40, 0.7).tau_ext;
    double parts = 0, trap = 0;
    for (double z = 0; z < 40 - 1e-9; z += 0.37)
        parts += m.layer(z, std::min(z + 0.37, 40.0), 0.7).tau_ext;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
        const double a = 40.0 * i / n, b = 40.0 * (i + 1) / n;
        trap += 0.5 * (m.extinction_km1(a, 0.7) + m.extinction_km1(b, 0.7)) * (b - a);
    }
    EXPECT_NEAR(parts, whole, 1e-12 * whole);
    EXPECT_NEAR(trap, whole, 1e-4 * whole);
}

TEST(AtmosAerosol, RejectsUnsupportedModels) {
    const Profile p = uniform_rh(70);
    for (int ihaze : {7, 11}) {
        try {
            AerosolModel::from_deck(card2(ihaze, 0), p, kData);
            FAIL() << "IHAZE " << ihaze << " accepted";
        } catch (const DataError& e) {
            EXPECT_NE(std::string(e.what()).find("CARD 2 IHAZE"), std::string::npos) << e.what();
        }
    }
    auto c = card2(1, 0);
    c.icld = 1;
    EXPECT_THROW(AerosolModel::from_deck(c, p, kData), DataError);
}

TEST(AtmosAerosol, SeedFlyoverDeck) {
    // The deck of White (1996): MODEL 7 (Hawkeye sonde), IHAZE 5 urban, VIS 0 (urban default 5 km),
    // ISEASN 2, GNDALT 0.218 km. At the ground the extinction must follow Koschmieder
    // for 5 km (1 %, as in SurfaceExtinctionFollowsKoschmieder), and the 0.55-um
    // optical depth of the column lies between LOWTRAN's VIS 5 fall-winter column at sea
    // level (1.1416) and that column with the elevated ground's 3.6 % compression of the
    // lower 6 km (GNDALT 0.218: factor 5.782/6).
    const auto run =
        io::read_cdk_file(SIGCHAIN_SOURCE_DIR "/tests/data/white1996/flyover.cdk").runs.at(0);
    const Profile p = profile_from_deck(run, kData);
    const auto m = AerosolModel::from_deck(run.card2, p, kData);
    EXPECT_DOUBLE_EQ(m.visibility_km(), 5);
    EXPECT_NEAR(m.extinction_km1(0.218, 0.55) + 0.01159, 3.912 / 5, 0.01 * 3.912 / 5);
    const double tau = m.layer(0.218, 100, 0.55).tau_ext;
    EXPECT_LT(tau, 1.1416);
    EXPECT_GT(tau, 1.1416 * 5.782 / 6 - 0.001);
    EXPECT_GT(m.boundary_layer_rh_percent(), 0);
    EXPECT_LT(m.boundary_layer_rh_percent(), 99);
}

// Navy maritime (IHAZE 3) against the mode table by hand (aerosol_navy_maritime_modes.txt,
// the 0.55-um and 10-um rows at RH 85 %, a node, so no interpolation): ICSTL 3, WSS =
// WHH = 10 m/s give A1 = 2000 * 9, A2 = 5.866 (10 - 2.2), A3 = 10^(0.6 - 2.8);
// ext(0.55) = pi/1000 sum A_i 10^T_i / F (F the growth factor at 85 %); VIS 0 is
// 3.912 / (ext(0.55) + 0.01159). The surface extinction then follows Koschmieder
// (1 %, as for the other models), and ext(10 um) / ext(0.55) is the table's ratio to
// 1e-9 (the model's wavelength interpolation hits the table's own 10-um node).
TEST(AtmosAerosol, NavyMaritimeFollowsTheModeTable) {
    io::CdkCard2 c = card2(3, 0);
    c.icstl = 3;
    c.wind_speed_m_s = c.wind_speed_24h_m_s = 10;
    const double a1 = 2000 * 9, a2 = 5.866 * 7.8, a3 = std::pow(10.0, 0.6 - 2.8);
    auto ext = [&](double t1, double t2, double t3) {
        return a1 * std::pow(10.0, t1) + a2 * std::pow(10.0, t2) + a3 * std::pow(10.0, t3);
    };
    const double growth = std::cbrt((2 - 0.85) / (6 * (1 - 0.85)));
    const double e055 = M_PI / 1000 * ext(-3.251, -0.1258, 2.5562) / growth;
    const double e10 = M_PI / 1000 * ext(-5.0793, -1.0867, 2.6075) / growth;
    const auto m = AerosolModel::from_deck(c, uniform_rh(85), kData);
    EXPECT_NEAR(m.visibility_km(), 3.912 / (e055 + 0.01159), 1e-9 * m.visibility_km());
    EXPECT_NEAR(m.extinction_km1(0, 0.55) + 0.01159, 3.912 / m.visibility_km(),
                0.01 * 3.912 / m.visibility_km());
    // At the ground only the boundary layer has aerosol (the troposphere starts above
    // 2 km): a thin slab there has the boundary layer's own spectral ratio.
    const auto l055 = m.layer(0, 1e-3, 0.55), l10 = m.layer(0, 1e-3, 10);
    EXPECT_NEAR(l10.tau_ext / l055.tau_ext, e10 / e055, 1e-9 * e10 / e055);
    // The asymmetry parameter is the maritime model's (IHAZE 4) at the same humidity.
    io::CdkCard2 mar = card2(4, 0);
    const auto m4 = AerosolModel::from_deck(mar, uniform_rh(85), kData);
    EXPECT_NEAR(m.layer(0, 1e-3, 0.55).g, m4.layer(0, 1e-3, 0.55).g, 1e-12);
    // More wind, more sea salt: a shorter visibility.
    c.wind_speed_m_s = 20;
    EXPECT_LT(AerosolModel::from_deck(c, uniform_rh(85), kData).visibility_km(), m.visibility_km());
}

// IHAZE 7 whose CARD 2D2 boundary-layer coefficients are the rural model's at RH 0 %
// (aerosol_rural.txt's first ext, abs and g columns, exact in F7.5 and F6.4) gives the
// optics of IHAZE 1 over a dry profile: the same 0.55-um profile (VIS 23), the same
// coefficients, the same linear interpolation in wavelength (LOWTRAN 7 AEREXT). An
// independent check of reading CARD 2D2 and of its scaling by the VIS profile.
TEST(AtmosAerosol, UserDefinedRuralCoefficientsGiveTheRuralModel) {
    const auto rural = table_rows("aerosol_rural.txt");
    ASSERT_EQ(rural.size(), 47u);
    const io::CdkRun run = parsed(deck_with_card2d(7, 0, {1, 0, 0, 0}, rural, 1, 5, 9));
    ASSERT_TRUE(run.user_optics);
    const Profile dry = uniform_rh(0);
    const auto user =
        AerosolModel::from_deck(run.card2, dry, kData, std::nullopt, &*run.user_optics);
    const auto ihaze1 = AerosolModel::from_deck(card2(1, 23), dry, kData);
    EXPECT_EQ(user.visibility_km(), 23);
    for (double lambda : {0.25, 0.55, 0.6, 1.06, 2.2, 3.9, 10.6, 250.0})
        for (auto [lo, hi] : {std::pair{0.0, 0.4}, {0.4, 1.7}, {1.7, 3.5}, {3.5, 12.0}}) {
            const AerosolLayerOptics a = user.layer(lo, hi, lambda),
                                     b = ihaze1.layer(lo, hi, lambda);
            // 1e-12 relative: IHAZE 1's effective RH over a uniform 0 % profile is
            // 100 - exp(mean ln 100), 0 to a few ulps, so its ln-ln interpolation weight
            // differs from 0 by about 1e-16; everything else is the same arithmetic.
            EXPECT_NEAR(a.tau_ext, b.tau_ext, 1e-12 * b.tau_ext) << lambda << " " << lo;
            EXPECT_NEAR(a.ssa, b.ssa, 1e-12) << lambda << " " << lo;
            EXPECT_NEAR(a.g, b.g, 1e-12) << lambda << " " << lo;
            EXPECT_GT(b.tau_ext, 0);
        }
}

// CARD 2D without the boundary layer (IREG(1) 0) under IHAZE 7: LOWTRAN 7's EXABIN
// leaves that region's coefficients 0, so no aerosol below the troposphere's reach;
// IHAZE 7 without CARD 2D is refused.
TEST(AtmosAerosol, UserDefinedAerosolWithoutTheBoundaryLayer) {
    const auto rural = table_rows("aerosol_rural.txt");
    const io::CdkRun run = parsed(deck_with_card2d(7, 0, {0, 1, 0, 0}, rural, 1, 5, 9));
    const auto m =
        AerosolModel::from_deck(run.card2, uniform_rh(50), kData, std::nullopt, &*run.user_optics);
    EXPECT_EQ(m.layer(0, 1.0, 0.55).tau_ext, 0);
    EXPECT_GT(m.layer(3, 9, 0.55).tau_ext, 0);
    EXPECT_THROW(AerosolModel::from_deck(card2(7, 23), uniform_rh(50), kData), DataError);
}
