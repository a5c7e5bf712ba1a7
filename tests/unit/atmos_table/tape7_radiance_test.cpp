// Tests for build_radiance with LOWTRAN 7 as the solver (lib/atmos_table/tape7_radiance): the
// decks of the paths, and the .rad assembled from TAPE7s written here in LOWTRAN 7's
// layout (tape7(5)) with analytic values, so that every table entry is known.
#include "atmos_table/tape7_radiance.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "atmos_table/build_radiance.hpp"
#include "core/error.hpp"
#include "io/fortran_columns.hpp"

using namespace sigchain;

namespace {

namespace fs = std::filesystem;
using io::fortran::format_fixed;
using io::fortran::format_integer;

const std::string kHawkeye = SIGCHAIN_SOURCE_DIR "/tests/golden/control7/hawkeye.cdk";

// A thermal band (1000-1010 cm-1, 3 samples), nadir only, the Hawkeye time and place.
io::Snd thermal_snd() {
    return io::parse_snd(TextInput::from_string(
        "1.0\n1\n1000.0 1010.0 5.0\n0.0 0.0 1.0\n9 30 95\n19\n5\n43.08333 77.66667\n", "t.snd"));
}

// Planck's law as LOWTRAN 7 writes it (BBFN; LOWTRAN 7 formulas item 7), per cm-1:
// an independent reference for the converter's (CODATA) Planck.
double lowtran_planck_per_cm1(double nu, double t_k) {
    return 1.190956e-16 * std::pow(nu, 5) / (std::exp(1.43879 * nu / t_k) - 1) * 1e4 / (nu * nu);
}

std::string e92(double v) {
    char b[16];
    std::snprintf(b, sizeof b, "%9.2E", v);
    return b;
}

// The LOWTRAN 7 TAPE7 of one deck: transmittance `t`, path emission `lp` (per cm-1),
// plus the boundary's B(TBOUND) t on paths that end at the ground; no sunlight.
std::string tape7_of(const io::CdkRun& run, double t, double lp, double tbound_k) {
    const io::CdkGeometry& g = run.geometry;
    const bool ground = g.zenith_angle_deg > 90;
    std::string s = format_integer(run.card1.model, 5) + format_integer(run.card1.itype, 5) +
                    format_integer(run.card1.iemsct, 5) + std::string(50, ' ') +
                    format_fixed(ground ? tbound_k : 0, 8, 3) + format_fixed(0, 7, 2) + "\n";
    s += std::string(70, ' ') + format_fixed(run.card2.ground_altitude_km, 10, 3) + "\n\n\n    0\n";
    s += format_fixed(g.h1_km, 10, 3) + format_fixed(g.h2_km, 10, 3) +
         format_fixed(g.zenith_angle_deg, 10, 3) + "\n\n\n";
    s += format_fixed(run.spectral.v1_cm1, 10, 3) + format_fixed(run.spectral.v2_cm1, 10, 3) +
         format_fixed(run.spectral.dv_cm1, 10, 3) + "\n    0\n";
    if (run.card1.iemsct == 3) {  // the sun path: 1e-6 W cm-2 (cm-1)-1 above the atmosphere
        s += "  FREQ   TRANS     SOL TR  SOLAR    \n";
        for (double nu = run.spectral.v1_cm1; nu <= run.spectral.v2_cm1; nu += run.spectral.dv_cm1)
            s += format_fixed(nu, 7, 0) + format_fixed(t, 8, 4) + e92(1e-6 * t) + e92(1e-6) + "\n";
        return s + " -9999.\n";
    }
    s += "  FREQ   TRANS     ATMOS   PATH     SINGLE   GROUND DIRECT   TOTAL RAD\n";
    for (double nu = run.spectral.v1_cm1; nu <= run.spectral.v2_cm1; nu += run.spectral.dv_cm1) {
        const double atmos = lp + (ground ? lowtran_planck_per_cm1(nu, tbound_k) * t : 0);
        s += format_fixed(nu, 7, 0) + format_fixed(t, 8, 4) + e92(atmos) + "\n";
    }
    return s + " -9999.\n";
}

struct Runs {
    fs::path dir;
    io::Cdk deck;
    atmos_table::RadianceOptions options;
    atmos_table::Tape7Decks decks;
    Runs(const io::Snd& snd, double t, double lp, double tbound_k)
        : dir(fs::temp_directory_path() / ("tape7_test_" + std::to_string(::getpid()))),
          deck(io::read_cdk_file(kHawkeye)) {
        options.sky_zenith_step_deg = 45;
        options.sky_azimuth_step_deg = 180;
        options.snd_path = "t.snd";
        decks = atmos_table::tape7_decks(deck, snd, options);
        fs::create_directories(dir);
        for (const auto& [name, cdk] : decks.decks) {
            std::ofstream(dir / (name.substr(0, name.size() - 4) + ".tp7"))
                << tape7_of(cdk.runs.front(), t, lp, tbound_k);
        }
        std::ofstream(dir / "runs.t7m") << "";
    }
    ~Runs() { fs::remove_all(dir); }
    std::vector<io::Rad> rad(const io::Snd& snd) const {
        return atmos_table::tape7_radiance(decks.list, (dir / "runs.t7m").string(), deck, snd,
                                           options);
    }
};

}  // namespace

TEST(Tape7Radiance, DecksFollowThePaths) {
    const io::Snd snd = thermal_snd();
    atmos_table::RadianceOptions o;
    o.sky_zenith_step_deg = 45;
    o.sky_azimuth_step_deg = 180;
    const atmos_table::Tape7Decks d = atmos_table::tape7_decks(io::read_cdk_file(kHawkeye), snd, o);
    // The sun (up at 10:00 local on 30 Sep 95 at Rochester), one view, 2 x 2 sky cells.
    ASSERT_EQ(d.decks.size(), 6u);
    EXPECT_EQ(d.decks[0].first, "sun.tp5");
    const io::CdkRun& view = d.decks[1].second.runs.front();
    EXPECT_EQ(view.card1.iemsct, 2);
    EXPECT_EQ(view.card1.surface_albedo, 0);
    EXPECT_EQ(view.geometry.h1_km, 1.0);
    EXPECT_EQ(view.geometry.h2_km, 0.218);  // GNDALT of the Hawkeye deck
    EXPECT_EQ(view.geometry.zenith_angle_deg, 180);
    EXPECT_EQ(view.geometry.iparm, 2);
    EXPECT_NEAR(view.geometry.parm[1], d.list.sun_zenith_deg, 1e-12);
    // CARD 4: 1000 - 2.5 .. 1010 + 2.5 on a 5 cm-1 grid.
    EXPECT_EQ(view.spectral.v1_cm1, 995);
    EXPECT_EQ(view.spectral.v2_cm1, 1015);
    EXPECT_EQ(view.spectral.dv_cm1, 5);
    const io::CdkRun& sky = d.decks[2].second.runs.front();
    EXPECT_EQ(sky.card1.itype, 3);
    EXPECT_EQ(sky.geometry.zenith_angle_deg, 22.5);
    EXPECT_EQ(d.list.sky[1].azimuth_deg, 270);
}

TEST(Tape7Radiance, ThermalPathRadianceLeavesOutTheBoundary) {
    // LOWTRAN 7's ATMOS on a path to the ground is L_path + B(TBOUND) T; the .rad's
    // L_ue is L_path alone. With L_path 4e-6 W cm-2 sr-1 (cm-1)-1 constant, L_ue is its
    // mean over each sample's 5 cm-1 interval per um: 4e-6 <nu^2> / 1e4.
    const io::Snd snd = thermal_snd();
    const double t = 0.5, lp = 4e-6;
    const Runs runs(snd, t, lp, 300);
    const std::vector<io::Rad> rads = runs.rad(snd);
    ASSERT_EQ(rads.size(), 1u);
    const io::Rad& rad = rads.front();
    ASSERT_EQ(rad.samples.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        const double nu = rad.samples[k].wavenumber_cm1;
        const double nu2 = nu * nu + 5.0 * 5.0 / 12;  // <nu^2> over [nu - 2.5, nu + 2.5]
        const io::RadPathSample& p = rad.views[0].path[k];
        EXPECT_EQ(p.transmission, t);
        // TAPE7 prints ATMOS with 3 digits (1PE9.2): up to 5e-9 per cm-1 off at ~9e-6,
        // and the converter's Planck (CODATA) differs from LOWTRAN's constants by
        // ~1e-5 relative: 2e-3 of L_ue covers both, far below B T (~5e-6, 125 %).
        EXPECT_NEAR(p.emitted_radiance, lp * nu2 / 1e4, 2e-3 * lp * nu2 / 1e4) << nu;
        EXPECT_EQ(p.scattered_radiance, 0);
        // Sky paths end in space: ATMOS is all path emission.
        EXPECT_NEAR(rad.sky->cells[0].emitted_radiance[k], lp * nu2 / 1e4, 2e-3 * lp * nu2 / 1e4);
    }
    // The sky's solid angles sum to 2 pi sr.
    double omega = 0;
    for (const auto& c : rad.sky->cells) omega += c.solid_angle_sr;
    EXPECT_NEAR(omega, 2 * std::numbers::pi, 1e-12);
    EXPECT_FALSE(rad.sky->coupling);
    EXPECT_FALSE(rad.sky->upwelled);
}

TEST(Tape7Radiance, ASampleOutsideTheRowsIsAnError) {
    const io::Snd snd = thermal_snd();
    const Runs runs(snd, 0.5, 4e-6, 300);
    io::Snd wider = snd;
    wider.bands.front().min_wavenumber_cm1 = 990;  // 990-1000: below the rows' 995
    wider.bands.front().increment_cm1 = 10;
    try {
        runs.rad(wider);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("expected rows covering 990 cm-1"), std::string::npos)
            << e.what();
    }
}

namespace {

// Per cm-1 from per um at `nu` (the inverse of io::per_micrometre).
double per_cm1(double per_um, double nu) { return per_um * 1e4 / (nu * nu); }

// The TAPE7 LOWTRAN 7 would write for `run` if it were sigchain's own solver: the
// values of `fine` (tables at every row's wavenumber) for the run's path.
std::string tape7_from_tables(const io::CdkRun& run, const io::Rad& fine, std::size_t view,
                              std::size_t cell, bool is_view) {
    std::string s = tape7_of(run, 1, 0, 0);
    s = s.substr(0, s.find("  FREQ"));
    const bool sun = run.card1.iemsct == 3;
    s += sun ? "  FREQ   TRANS     SOL TR  SOLAR    \n"
             : "  FREQ   TRANS     ATMOS   PATH     SINGLE   GROUND DIRECT   TOTAL RAD\n";
    for (std::size_t r = fine.samples.size(); r-- > 0;) {  // wavenumber increasing
        const io::RadSample& x = fine.samples[r];
        const double nu = x.wavenumber_cm1;
        if (sun) {
            const double es = per_cm1(x.solar_irradiance, nu);
            s += format_fixed(nu, 7, 0) + format_fixed(x.sun_transmission, 8, 4) +
                 e92(es * x.sun_transmission) + e92(es) + "\n";
            continue;
        }
        double t = 0, thermal = 0, solar = 0;
        if (is_view) {
            const io::RadPathSample& p = fine.views[view].path[r];
            t = p.transmission, thermal = p.emitted_radiance, solar = p.scattered_radiance;
        } else {
            t = 1;  // a sky path's transmittance is not used
            thermal = fine.sky->cells[cell].emitted_radiance[r];
            solar = fine.sky->cells[cell].scattered_radiance[r];
        }
        s += format_fixed(nu, 7, 0) + format_fixed(t, 8, 4) + e92(per_cm1(thermal, nu)) +
             e92(per_cm1(solar, nu)) + "\n";
    }
    return s + " -9999.\n";
}

}  // namespace

TEST(Tape7Radiance, SigchainsOwnSolverThroughTape7sGivesItsTables) {
    // build_radiance's tables at every 20 cm-1 row of the decks' CARD 4, written as
    // LOWTRAN 7 TAPE7s and assembled back onto the 100 cm-1 band, against the tables
    // build_radiance computes on that band directly.
    const io::Cdk deck = io::read_cdk_file(kHawkeye);
    const std::string tail = "-10.0 10.0 10.0\n9 30 95\n19\n5\n43.08333 77.66667\n";
    const io::Snd coarse = io::parse_snd(
        TextInput::from_string("1.0\n1\n18000.0 18100.0 100.0\n" + tail, "coarse.snd"));
    atmos_table::RadianceOptions o;
    o.data_dir = SIGCHAIN_SOURCE_DIR "/data";
    o.streams = 8;
    o.sky_zenith_step_deg = 45;
    o.sky_azimuth_step_deg = 180;
    o.sky_subsamples = 1;
    o.coupling = false;
    const atmos_table::Tape7Decks decks = atmos_table::tape7_decks(deck, coarse, o);
    const io::CdkSpectral span = decks.decks.front().second.runs.front().spectral;
    ASSERT_EQ(span.v1_cm1, 17940);
    ASSERT_EQ(span.v2_cm1, 18160);
    const io::Snd fine_snd =
        io::parse_snd(TextInput::from_string("1.0\n1\n17940.0 18160.0 20.0\n" + tail, "fine.snd"));
    const io::Rad fine = atmos_table::build_radiance(deck, fine_snd, o).front();
    const io::Rad direct = atmos_table::build_radiance(deck, coarse, o).front();

    const fs::path dir = fs::temp_directory_path() / ("tape7_solver_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::size_t view = 0, cell = 0;
    for (const auto& [name, cdk] : decks.decks) {
        const bool is_view = name.rfind("view-", 0) == 0, is_sky = name.rfind("sky-", 0) == 0;
        std::ofstream(dir / (name.substr(0, name.size() - 4) + ".tp7"))
            << tape7_from_tables(cdk.runs.front(), fine, view, cell, is_view);
        view += is_view;
        cell += is_sky;
    }
    const io::Rad back =
        atmos_table::tape7_radiance(decks.list, (dir / "runs.t7m").string(), deck, coarse, o)
            .front();
    fs::remove_all(dir);

    // The largest deviations, relative (radiances, Es) or absolute (transmittances).
    double tau = 0, es = 0, path = 0, sky = 0;
    auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
    ASSERT_EQ(back.samples.size(), direct.samples.size());
    for (std::size_t k = 0; k < direct.samples.size(); ++k) {
        tau = std::max(
            tau, std::abs(back.samples[k].sun_transmission - direct.samples[k].sun_transmission));
        es =
            std::max(es, rel(back.samples[k].solar_irradiance, direct.samples[k].solar_irradiance));
        for (std::size_t v = 0; v < direct.views.size(); ++v) {
            const io::RadPathSample &a = back.views[v].path[k], &b = direct.views[v].path[k];
            tau = std::max(tau, std::abs(a.transmission - b.transmission));
            path = std::max(path, rel(a.scattered_radiance, b.scattered_radiance));
            EXPECT_EQ(back.views[v].range_km, direct.views[v].range_km);
        }
        for (std::size_t c = 0; c < direct.sky->cells.size(); ++c) {
            sky = std::max(sky, rel(back.sky->cells[c].scattered_radiance[k],
                                    direct.sky->cells[c].scattered_radiance[k]));
            EXPECT_NEAR(back.sky->cells[c].solid_angle_sr, direct.sky->cells[c].solid_angle_sr,
                        1e-12);
        }
    }
    // Tolerances: TAPE7 keeps 3 significant digits of a radiance or irradiance (up to
    // 0.5 %) and 4 decimals of a transmittance (5e-5). Each .rad sample of the TAPE7
    // route is the mean over +-50 cm-1 of the 20 cm-1 rows, the direct one the value at
    // the centre: the solar spectrum's structure makes the mean of Es differ from its
    // centre value by up to 0.95 % here, and the scattered terms, proportional to Es,
    // follow (measured: tau 2.5e-5, Es 0.95 %, L_us 0.93 %, L_ds 1.16 %). Budget: 1e-4
    // for transmittances, 0.95 % + 0.5 % = 1.5 % for the rest.
    std::printf("tau %.3g, Es %.3g, L_us %.3g, L_ds %.3g\n", tau, es, path, sky);
    EXPECT_LT(tau, 1e-4);
    EXPECT_LT(es, 0.015);
    EXPECT_LT(path, 0.015);
    EXPECT_LT(sky, 0.015);
    EXPECT_EQ(back.sky->sun_zenith_deg, direct.sky->sun_zenith_deg);
}
