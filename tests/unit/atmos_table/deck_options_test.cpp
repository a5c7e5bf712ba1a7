// The deck fields build_radiance honours: IMULT 0 (first-order scattering against the
// closed form and against the solver in a thin layer), SALB (the ground's reflection in
// the sky against the solver's own Lambertian surface and the coupling formula), the
// deck's sun (IPARM 0/1/2) and the refusals naming card and columns.
#include "atmos_table/deck_options.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../record_property.hpp"
#include "atmos/ground_albedo.hpp"
#include "atmos/rayleigh.hpp"
#include "atmos/single_scatter.hpp"
#include "atmos_table/build_radiance.hpp"
#include "core/error.hpp"
#include "geo/solar_position.hpp"
#include "rt/coupling.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;
const std::string kSource = SIGCHAIN_SOURCE_DIR;

io::Cdk rural23() { return io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk"); }
io::Cdk hawkeye() { return io::read_cdk_file(kSource + "/tests/golden/control7/hawkeye.cdk"); }
io::Snd small_snd() { return io::read_snd_file(kSource + "/tests/data/build_radiance/small.snd"); }

rt::Layer rayleigh_layer(double tau, int moments) {
    rt::Layer l;
    l.tau = tau;
    l.ssa = 1;
    const auto r = rayleigh_phase_moments();
    l.pmom.assign(static_cast<std::size_t>(moments) + 1, 0.0);
    for (int k = 0; k < 3 && k <= moments; ++k) l.pmom[k] = r[k];
    return l;
}

// A homogeneous Rayleigh layer of optical depth tau split into `pieces` equal layers.
rt::Problem rayleigh_problem(double tau, int pieces, double mu0) {
    rt::Problem p;
    for (int i = 0; i < pieces; ++i) p.layers.push_back(rayleigh_layer(tau / pieces, 32));
    p.beam_flux = 1;
    p.beam_mu0 = mu0;
    p.utau = {0, tau};
    p.umu = {-0.9, -0.5, 0.3, 0.8};
    p.phi_deg = {0, 60, 180};
    return p;
}

// Single scattering of a homogeneous layer in closed form (Liou 2002, eqs. 6.5.4-6.5.5;
// Chandrasekhar 1960, ch. I): reflected at the top
//   I(mu) = omega F0 P / (4 pi) mu0 / (mu0 + mu) (1 - exp(-tau (1/mu0 + 1/mu))),
// transmitted at the bottom
//   I(-m) = omega F0 P / (4 pi) mu0 / (mu0 - m) (exp(-tau/mu0) - exp(-tau/m)),
// with the Rayleigh phase function 1 + 5 m2 P2(cos Theta).
double closed_form(double tau, double mu0, double mu, double phi_deg) {
    const double m2 = rayleigh_phase_moments()[2];
    const double c =
        -mu * mu0 + std::sqrt(1 - mu * mu) * std::sqrt(1 - mu0 * mu0) * std::cos(phi_deg * kDeg);
    const double phase = 1 + 5 * m2 * 0.5 * (3 * c * c - 1);
    const double k = phase / (4 * kPi);
    if (mu > 0) return k * mu0 / (mu0 + mu) * -std::expm1(-tau * (1 / mu0 + 1 / mu));
    const double m = -mu;
    return k * mu0 / (mu0 - m) * (std::exp(-tau / mu0) - std::exp(-tau / m));
}

// Splitting the layer into five must not change the integral: 1e-12 is rounding.
TEST(SingleScattering, ThinRayleighLayerMatchesTheClosedForm) {
    const double tau = 0.05, mu0 = 0.6;
    const rt::Problem p = rayleigh_problem(tau, 5, mu0);
    const rt::Result r = single_scattering(p);
    ASSERT_EQ(r.levels.size(), 2u);
    double worst = 0;
    for (std::size_t i = 0; i < p.umu.size(); ++i)
        for (std::size_t j = 0; j < p.phi_deg.size(); ++j) {
            const double mu = p.umu[i];
            const std::size_t level = mu > 0 ? 0 : 1;  // reflected at the top, transmitted below
            const double want = closed_form(tau, mu0, mu, p.phi_deg[j]);
            EXPECT_NEAR(r.levels[level].intensity[i * 3 + j], want, 1e-12 * want + 1e-15)
                << "mu " << mu << " phi " << p.phi_deg[j];
            worst = std::max(worst, std::abs(r.levels[level].intensity[i * 3 + j] / want - 1));
        }
    EXPECT_NEAR(r.levels[1].direct_down, mu0 * std::exp(-tau / mu0), 1e-15);
    unit::record("relative_difference", worst);
    unit::record("limit", 1e-12);
}

// Energy: a thin layer scatters tau F0 of the beam's horizontal flux mu0 F0 (tau / mu0
// of it) and Rayleigh's phase function, symmetric forward-backward, sends half of it
// down: F_down = tau F0 / 2. The attenuation inside the layer changes that by
// O(tau ln(1/tau)) ~ 1e-4 for tau = 1e-5; 1e-3 relative allowed.
TEST(SingleScattering, ThinLayerSendsHalfTheScatteredFluxDown) {
    const double tau = 1e-5, mu0 = 0.7;
    const rt::Result r = single_scattering(rayleigh_problem(tau, 1, mu0));
    EXPECT_NEAR(r.levels[1].diffuse_down, tau / 2, 1e-3 * tau / 2);
}

// In a thin layer multiple scattering is second order: the solver (16 streams, delta-M,
// Nakajima-Tanaka correction) and first-order scattering agree to O(tau) relative;
// tau = 1e-3 gives < 0.5 %, 1 % allowed.
TEST(SingleScattering, AgreesWithTheSolverInAThinLayer) {
    rt::Problem p = rayleigh_problem(1e-3, 1, 0.5);
    // Half Rayleigh, half a forward aerosol (Henyey-Greenstein g = 0.7, 32 moments).
    rt::Layer aer = rayleigh_layer(1e-3, 32);
    for (std::size_t k = 0; k < aer.pmom.size(); ++k) aer.pmom[k] = std::pow(0.7, double(k));
    p.layers.push_back(aer);
    p.utau = {0, 2e-3};
    const rt::Result ss = single_scattering(p);
    const rt::Result ms = rt::solve(p);
    double worst = 0;
    for (std::size_t l = 0; l < 2; ++l) {
        for (std::size_t i = 0; i < ss.levels[l].intensity.size(); ++i) {
            const double want = ms.levels[l].intensity[i];
            const double mu = p.umu[i / 3];
            if ((l == 0) != (mu > 0)) continue;  // only the scattered directions
            EXPECT_NEAR(ss.levels[l].intensity[i], want, 0.01 * want) << l << " " << i;
            worst = std::max(worst, std::abs(ss.levels[l].intensity[i] / want - 1));
        }
    }
    EXPECT_NEAR(ss.levels[1].diffuse_down, ms.levels[1].diffuse_down,
                0.01 * ms.levels[1].diffuse_down);
    unit::record("relative_difference", worst);
    unit::record("flux_relative_difference",
                 ss.levels[1].diffuse_down / ms.levels[1].diffuse_down - 1);
    unit::record("limit", 0.01);
}

rt::Problem hazy_problem(double albedo) {
    rt::Problem p;
    p.layers.push_back(rayleigh_layer(0.1, 32));
    rt::Layer aer;
    aer.tau = 0.3;
    aer.ssa = 0.9;
    for (int k = 0; k <= 32; ++k) aer.pmom.push_back(std::pow(0.65, k));
    p.layers.push_back(aer);
    p.beam_flux = 1;
    p.beam_mu0 = 0.55;
    p.albedo = albedo;
    p.utau = {0, 0.4};
    p.umu = {-0.95, -0.7, -0.4, -0.1, 0.2, 0.6};
    p.phi_deg = {0, 45, 130, 180};
    return p;
}

// A black-ground solution plus the ground's reflection equals the solver's own
// Lambertian surface (DISORT's bottom boundary): the superposition is exact in the
// discrete-ordinate equations, so 1e-6 relative (the solver's rounding and the
// intensity correction, which depends on the surface only through the diffuse field).
TEST(GroundAlbedo, MatchesTheSolversLambertianSurface) {
    const double rho = 0.35;
    const rt::Problem black = hazy_problem(0);
    rt::Result r = rt::solve(black);
    const double f0 = r.levels[1].direct_down + r.levels[1].diffuse_down;
    add_ground_reflection(black, rho, 1, r);
    const rt::Result want = rt::solve(hazy_problem(rho));
    double worst = std::abs(r.levels[1].diffuse_down / want.levels[1].diffuse_down - 1);
    for (std::size_t i = 0; i < black.umu.size(); ++i) {
        if (black.umu[i] > 0) continue;
        for (std::size_t j = 0; j < black.phi_deg.size(); ++j) {
            const double w = want.levels[1].intensity[i * 4 + j];
            EXPECT_NEAR(r.levels[1].intensity[i * 4 + j], w, 1e-6 * w) << i << " " << j;
            worst = std::max(worst, std::abs(r.levels[1].intensity[i * 4 + j] / w - 1));
        }
    }
    EXPECT_NEAR(r.levels[1].diffuse_down, want.levels[1].diffuse_down,
                1e-6 * want.levels[1].diffuse_down);
    unit::record("relative_difference", worst);
    unit::record("limit", 1e-6);
    // The coupling formula (rt/coupling.hpp): F(rho) = F(0) / (1 - rho S).
    const double s = rt::surface_coupling(black, 0, {1.0}).spherical_albedo;
    EXPECT_NEAR(r.levels[1].direct_down + r.levels[1].diffuse_down, f0 / (1 - rho * s), 1e-9 * f0);
    // Albedo 0 changes nothing.
    rt::Result same = rt::solve(black);
    add_ground_reflection(black, 0, 1, same);
    EXPECT_EQ(same.levels[1].intensity, rt::solve(black).levels[1].intensity);
}

bool any_contains(const std::vector<std::string>& v, const std::string& s) {
    for (const auto& x : v)
        if (x.find(s) != std::string::npos) return true;
    return false;
}

TEST(DeckRefusals, NameCardFieldAndColumns) {
    EXPECT_TRUE(deck_refusals(hawkeye()).empty());
    EXPECT_TRUE(deck_refusals(rural23()).empty());
    io::Cdk d = rural23();
    d.runs[0].card1.boundary_temperature_k = 290;
    EXPECT_TRUE(any_contains(deck_refusals(d), "CARD 1 TBOUND (columns 66-73) is 290"));
    // IEMSCT 1 (thermal radiance, no CARD 3A1) is honoured, 0 and 3 compute no radiance.
    d = rural23();
    d.runs[0].card1.iemsct = 1;
    d.runs[0].geometry = {};
    EXPECT_TRUE(deck_refusals(d).empty());
    for (int mode : {0, 3}) {
        d.runs[0].card1.iemsct = mode;
        EXPECT_TRUE(any_contains(
            deck_refusals(d), "CARD 1 IEMSCT (columns 11-15) is " + std::to_string(mode) + ": a "))
            << mode;
    }
    d = rural23();
    d.runs[0].geometry.iph = 1;
    EXPECT_TRUE(any_contains(deck_refusals(d), "CARD 3A1 IPH (columns 6-10) is 1"));
    d = rural23();
    d.runs[0].geometry.isourc = 1;
    EXPECT_TRUE(any_contains(deck_refusals(d), "CARD 3A1 ISOURC (columns 16-20)"));
    d = rural23();
    d.runs[0].card2.ihaze = 3;  // Navy maritime: modelled
    EXPECT_TRUE(deck_refusals(d).empty());
    // Rain (ICLD 6-10, RAINRT) and cirrus (18, 19 with CARD 2A) are modelled; the NOAA
    // cirrus (20) is refused.
    for (int icld : {6, 10, 18, 19}) {
        d = rural23();
        d.runs[0].card2.icld = icld;
        d.runs[0].card2.rain_rate_mm_h = 5;
        if (icld >= 18) d.runs[0].cirrus = io::CdkCirrus{};
        EXPECT_TRUE(deck_refusals(d).empty()) << icld;
    }
    d.runs[0].card2.icld = 20;
    EXPECT_TRUE(any_contains(deck_refusals(d), "CARD 2 ICLD (columns 21-25) is 20: the NOAA"));
    // A second run with another atmosphere; one that repeats only CARD 4 is accepted.
    d = rural23();
    d.runs[0].irpt = 1;
    d.runs.push_back(d.runs[0]);
    d.runs[1].irpt = 0;
    EXPECT_TRUE(deck_refusals(d).empty());
    d.runs[1].card2.visibility_km = 5;
    EXPECT_TRUE(any_contains(deck_refusals(d), "CARD 5 IRPT (columns 1-5) is 1 and run 2"));
    EXPECT_THROW(check_deck(d, "x.cdk"), DataError);
}

TEST(DeckChoices, ImultAndSalb) {
    io::CdkRun run = rural23().runs[0];
    EXPECT_FALSE(deck_choices(run).single_scattering);
    EXPECT_EQ(deck_choices(run).surface_albedo, 0);
    run.card1.imult = 0;
    run.card1.surface_albedo = 0.2;
    EXPECT_TRUE(deck_choices(run).single_scattering);
    EXPECT_EQ(deck_choices(run).surface_albedo, 0.2);
}

// IEMSCT 1 has no sun and scatters by the Mie functions, as IEMSCT 2 does with IPH 2
// alone (IPH 0 and 1 on CARD 3A1 replace the models' functions).
TEST(DeckChoices, ThermalRadianceOnly) {
    io::CdkRun run = rural23().runs[0];
    EXPECT_TRUE(deck_choices(run).solar);
    EXPECT_TRUE(deck_mie_phase(run.card1, run.geometry));
    run.geometry.iph = 0;
    EXPECT_FALSE(deck_mie_phase(run.card1, run.geometry));
    run.card1.iemsct = 1;
    run.geometry = {};
    EXPECT_FALSE(deck_choices(run).solar);
    EXPECT_TRUE(deck_mie_phase(run.card1, run.geometry));
    EXPECT_FALSE(iemsct_refusal(run.card1));
}

// rural23's IPARM 1 sun (IDAY 273, 19.000 GMT, 43.083 N 77.667 W) against small.snd's
// (30 Sep 1995 19 h GMT, 43.08333 N 77.66667 W): both NREL SPA, so they differ only by
// the deck's 3-decimal rounding of the place (< 0.01 deg).
TEST(DeckSun, IparmOneAgreesWithTheScene) {
    const auto deck = rural23();
    const auto sun = deck_sun(deck.runs[0], 1995, 0);
    ASSERT_TRUE(sun);
    geo::SceneSite site = io::scene_site(small_snd());
    const geo::SolarPosition want = geo::solar_position(site);
    EXPECT_LT(sun_separation_deg(*sun, {want.zenith_deg, want.azimuth_deg}), 0.01);
}

TEST(DeckSun, IparmZeroAndTwo) {
    io::CdkRun run = rural23().runs[0];
    run.geometry.iparm = 0;
    // The sub-solar point due south by 30 deg of latitude: zenith 30, azimuth 180.
    run.geometry.parm = {40, 80, 10, 80};
    auto sun = deck_sun(run, 1995, 0);
    ASSERT_TRUE(sun);
    EXPECT_NEAR(sun->zenith_deg, 30, 1e-9);
    EXPECT_NEAR(sun->azimuth_deg, 180, 1e-9);
    // Due east along the equator: 20 deg west of the observer's longitude is west.
    run.geometry.parm = {0, 80, 0, 100};
    sun = deck_sun(run, 1995, 0);
    EXPECT_NEAR(sun->zenith_deg, 20, 1e-9);
    EXPECT_NEAR(sun->azimuth_deg, 270, 1e-9);
    run.geometry.iparm = 2;
    run.geometry.parm = {-30, 40, 0, 0};  // sun 30 deg clockwise of the line of sight
    sun = deck_sun(run, 1995, 100);
    EXPECT_NEAR(sun->zenith_deg, 40, 1e-12);
    EXPECT_NEAR(sun->azimuth_deg, 130, 1e-12);
    run.card1.iemsct = 0;
    EXPECT_FALSE(deck_sun(run, 1995, 0));
    EXPECT_NEAR(sun_separation_deg({10, 0}, {10, 180}), 20, 1e-9);
    EXPECT_NEAR(sun_separation_deg({0, 0}, {0, 123}), 0, 1e-6);
}

// --- build_radiance with the deck's options (small grids: two samples, one view) -------

RadianceOptions quick() {
    RadianceOptions o;
    o.data_dir = kSource + "/data";
    o.streams = 8;
    o.sky_zenith_step_deg = 30;
    o.sky_azimuth_step_deg = 90;
    o.sky_subsamples = 1;
    o.upwelled_azimuth_step_deg = 90;
    o.threads = 1;
    return o;
}

io::Snd one_sample_snd() {
    io::Snd snd = small_snd();
    snd.bands = {{18000, 18000, 1}};
    snd.view_min_deg = snd.view_max_deg = 0;
    snd.view_increment_deg = 1;
    return snd;
}

TEST(BuildRadianceDeck, ImultZeroIsSingleScatteringAndDiffers) {
    io::Cdk deck = rural23();
    const auto multiple = build_radiance(deck, one_sample_snd(), quick());
    deck.runs[0].card1.imult = 0;
    RadianceReport rep;
    const auto single = build_radiance(deck, one_sample_snd(), quick(), &rep);
    const double lm = multiple[0].views[0].path[0].scattered_radiance;
    const double ls = single[0].views[0].path[0].scattered_radiance;
    // Multiple scattering adds light: over a black ground at 0.556 um with VIS 23 km
    // (total optical depth ~0.35) the second and higher orders add > 5 %.
    EXPECT_GT(lm, 1.05 * ls);
    EXPECT_GT(ls, 0);
    EXPECT_TRUE(any_contains(rep.notes, "IMULT 0"));
    // The direct transmission is the same.
    EXPECT_EQ(multiple[0].views[0].path[0].transmission, single[0].views[0].path[0].transmission);
}

TEST(BuildRadianceDeck, SalbBrightensTheSkyOnly) {
    io::Cdk deck = rural23();
    const auto black = build_radiance(deck, one_sample_snd(), quick());
    deck.runs[0].card1.surface_albedo = 0.5;
    const auto bright = build_radiance(deck, one_sample_snd(), quick());
    // The path radiance and the upwelled grid are the atmosphere's (the ground is the scene's).
    EXPECT_EQ(black[0].views[0].path[0].scattered_radiance,
              bright[0].views[0].path[0].scattered_radiance);
    // The sky holds the ground now: no COUPLING terms for trace to add it again.
    EXPECT_TRUE(black[0].sky->coupling);
    EXPECT_FALSE(bright[0].sky->coupling);
    EXPECT_EQ(bright[0].sky->version_minor, 1);
    // Every sky cell gains, as L_g t_down(mu) > 0 says.
    for (std::size_t c = 0; c < black[0].sky->cells.size(); ++c)
        EXPECT_GT(bright[0].sky->cells[c].scattered_radiance[0],
                  black[0].sky->cells[c].scattered_radiance[0]);
}

TEST(BuildRadianceDeck, IparmTwoWithTheScenesSunGivesTheSameTables) {
    const io::Cdk deck1 = rural23();
    RadianceReport rep;
    const auto a = build_radiance(deck1, one_sample_snd(), quick(), &rep);
    io::Cdk deck2 = deck1;
    io::CdkGeometry& g = deck2.runs[0].geometry;
    g.iparm = 2;
    g.parm = {rep.view_azimuth_deg - rep.sun_azimuth_deg, rep.sun_zenith_deg, 0, 0};
    const auto b = build_radiance(deck2, one_sample_snd(), quick());
    EXPECT_EQ(a[0].views[0].path[0].scattered_radiance, b[0].views[0].path[0].scattered_radiance);
    EXPECT_EQ(a[0].sky->cells[0].scattered_radiance, b[0].sky->cells[0].scattered_radiance);
    // Five degrees off is refused, naming the fields.
    g.parm[1] += 5;
    try {
        build_radiance(deck2, one_sample_snd(), quick());
        FAIL() << "a disagreeing sun was accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("CARD 3A2 PARM1 (columns 1-10"), std::string::npos);
    }
}

TEST(BuildRadianceDeck, IphZeroUsesTheDecksAsymmetry) {
    io::Cdk deck = rural23();
    const auto mie = build_radiance(deck, one_sample_snd(), quick());
    deck.runs[0].geometry.iph = 0;
    deck.runs[0].geometry.asymmetry_g = 0;  // isotropic aerosol: less forward light
    const auto iso = build_radiance(deck, one_sample_snd(), quick());
    EXPECT_NE(mie[0].views[0].path[0].scattered_radiance,
              iso[0].views[0].path[0].scattered_radiance);
}

}  // namespace
}  // namespace sigchain::atmos_table
