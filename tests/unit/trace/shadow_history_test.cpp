// trace --shadow-history (shadow_history.hpp): the time grid and SPA sun against therm's
// clock and lib/geo; sunlit fractions, transmittances and sky-view factors against
// geometry worked by hand; key agreement with therm's scene reader; and (the thermal
// chain, trace's emissive part) a blackbody plate rendered through tau2 = 1.
#include "trace/shadow_history.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "../record_property.hpp"
#include "geo/solar_position.hpp"
#include "core/error.hpp"
#include "geo/scene_clock.hpp"
#include "io/snd.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "rt/planck.hpp"
#include "scene/load.hpp"
#include "test_scene.hpp"
#include "thermal/environment.hpp"
#include "thermal/scene_facets.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

constexpr double kPi = 3.14159265358979323846;
using test::Mesh;

const std::string kSnd = SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd";

radiometry::MaterialLibrary grey(std::size_t samples = 3) {
    return radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, samples)});
}

ShadowScene shadow_scene(scene::MeshData m) {
    ShadowScene s;
    s.place(s.add_mesh(std::move(m)), scene::identity_affine());
    s.commit();
    return s;
}

// One step with the sun at (zenith, azimuth), up.
std::vector<SunStep> sun_at(double zenith_deg, double azimuth_deg) {
    SunStep s;
    s.time_hours = 38;
    s.zenith_deg = zenith_deg;
    s.azimuth_deg = azimuth_deg;
    const double z = zenith_deg * kPi / 180, a = azimuth_deg * kPi / 180;
    s.direction = {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
    s.up = zenith_deg < 90;
    return {s};
}

const io::ShdFacet& facet(const io::Shd& shd, const std::string& id) {
    for (const auto& f : shd.facets)
        if (f.id == id) return f;
    throw std::runtime_error("no facet " + id);
}

double mean_sunlit(const io::ShdFacet& f, long step = 0) {
    double sum = 0;
    for (long p = 0; p < f.points; ++p) sum += f.sunlit(step, p);
    return sum / static_cast<double>(f.points);
}

TEST(ShadowHistory, StepsMustDivideTheHistory) {
    EXPECT_EQ(history_steps(24, 15), 97);  // both ends: 96 intervals
    EXPECT_EQ(history_steps(1, 60), 2);
    EXPECT_EQ(history_steps(0.5, 0.5), 61);
    EXPECT_THROW(history_steps(1, 7), UsageError);
    EXPECT_THROW(history_steps(0, 15), UsageError);
    EXPECT_THROW(history_steps(24, 0), UsageError);
    EXPECT_THROW(history_steps(24, -15), UsageError);
    EXPECT_THROW(history_steps(1, 120), UsageError);  // longer than the history
}

TEST(ShadowHistory, TimeGridEndsAtTheSceneTimeOnThermsClock) {
    // The grid's last time is therm's scene time (which it checks against the .snd), the
    // first 24 h before; every step's sun is SPA at therm's UT for that grid time, and
    // the last is the .snd's own moment (19 GMT on 30 Sep 1995, GMT offset 5: 38 h).
    const io::Snd snd = io::read_snd_file(kSnd);
    const auto sun = sun_history(snd, history_steps(24, 15), 0.25);
    ASSERT_EQ(sun.size(), 97u);
    EXPECT_DOUBLE_EQ(sun.back().time_hours, geo::scene_wth_hours(io::scene_site(snd)));
    EXPECT_DOUBLE_EQ(sun.back().time_hours, 38.0);
    EXPECT_DOUBLE_EQ(sun.front().time_hours, 14.0);
    const geo::SolarPosition now = geo::solar_position(io::scene_site(snd));
    // The same moment through two date paths: equal to rounding (1e-9 deg).
    EXPECT_NEAR(sun.back().zenith_deg, now.zenith_deg, 1e-9);
    EXPECT_NEAR(sun.back().azimuth_deg, now.azimuth_deg, 1e-9);
    for (std::size_t k = 0; k < sun.size(); k += 8) {
        const geo::UtTime ut = geo::ut_of_wth_hours(io::scene_site(snd), sun[k].time_hours);
        geo::SolarPositionInput in;
        in.year = ut.year, in.month = ut.month, in.day = ut.day, in.ut_hours = ut.ut_hours;
        in.delta_t_s = geo::default_delta_t_s(ut.year);
        in.latitude_deg = snd.latitude_deg;
        in.longitude_east_deg = snd.longitude_east_deg;
        EXPECT_NEAR(sun[k].zenith_deg, geo::solar_position(in).zenith_deg, 1e-9) << k;
        EXPECT_NEAR(sun[k].time_hours, 14.0 + 0.25 * static_cast<double>(k), 1e-12);
    }
}

TEST(ShadowHistory, FlatPlateAloneIsLitWhenTheSunIsUpAndSeesTheWholeSky) {
    // Nothing occludes a lone plate: sunlit 1 exactly when the sun is above the
    // horizon, 0 at night, transmittance 1, sky view 1 (every cosine-weighted ray
    // goes up and escapes).
    Mesh m;
    m.quad({{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 1);
    const ShadowScene sc = shadow_scene(m.data);
    const io::Snd snd = io::read_snd_file(kSnd);
    const auto sun = sun_history(snd, 97, 0.25);
    ShadowOptions o;
    o.points_per_facet = 4;
    const io::Shd shd = shadow_history(sc, grey(), sun, 0.25, o);
    ASSERT_EQ(shd.facets.size(), 1u);
    const io::ShdFacet& f = shd.facets[0];
    EXPECT_EQ(f.id, "1-1-1");
    EXPECT_EQ(f.sky_view_factor, 1.0);
    long up = 0;
    for (long k = 0; k < shd.steps; ++k) {
        up += sun[static_cast<std::size_t>(k)].up;
        for (long p = 0; p < f.points; ++p) {
            EXPECT_EQ(f.sunlit(k, p), sun[static_cast<std::size_t>(k)].up ? 1.0 : 0.0) << k;
            EXPECT_EQ(f.sun_transmittance(k, p), 1.0);
        }
    }
    // Buffalo on 30 Sep: about 12 h of day in the 24 h window.
    EXPECT_GT(up, 40);
    EXPECT_LT(up, 57);
}

TEST(ShadowHistory, NorthWallAtNoonIsInItsOwnShadow) {
    // 43 N at noon (GMT offset 0, longitude 0; the equation of time is under 17 min):
    // the sun is due south, so a wall facing north (n.s < 0) gets 0 and one facing south
    // gets 1. A lone vertical wall sees half the cosine-weighted hemisphere as sky (the
    // other half is below the horizon): 0.5, within 3 sigma of 4096 independent rays
    // (sigma <= 0.5/64 = 0.0078; stratification only lowers it): 0.024.
    io::Snd snd = io::read_snd_file(kSnd);
    snd.latitude_deg = 43;
    snd.longitude_east_deg = 0;
    snd.gmt_offset_hours = 0;
    snd.time_gmt_hours = 12;
    const auto sun = sun_history(snd, 1, 0.25);
    ASSERT_TRUE(sun[0].up);
    EXPECT_LT(sun[0].direction[1], 0);  // toward the south
    Mesh m;
    m.quad({{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}}, 1);  // normal +y: north
    m.quad({{{0, 5, 0}, {1, 5, 0}, {1, 5, 1}, {0, 5, 1}}}, 1);  // normal -y: south
    const ShadowScene sc = shadow_scene(m.data);
    EXPECT_NEAR(sc.facets()[0].normal[1], 1.0, 1e-12);
    EXPECT_NEAR(sc.facets()[1].normal[1], -1.0, 1e-12);
    ShadowOptions o;
    o.sky_rays = 4096;
    const io::Shd shd = shadow_history(sc, grey(), sun, 0.25, o);
    EXPECT_EQ(facet(shd, "1-1-1").sunlit(0), 0.0);
    EXPECT_EQ(facet(shd, "1-1-2").sunlit(0), 1.0);
    EXPECT_NEAR(facet(shd, "1-1-1").sky_view_factor, 0.5, 0.024);
}

TEST(ShadowHistory, BoxShadowOnTheGroundFollowsTheGeometry) {
    // A 2 x 2 x 2 box (x, y in [0, 2]) under a sun 45 deg from the zenith due south:
    // its shadow on z = 0 covers x in [0, 2], y in [2, 4] (y - 2 = 2 tan 45). Ground
    // facets: one inside the shadow (0), one outside (1), one straddling its north
    // edge, y in [3, 5]: half shadowed. With 1024 stratified points the fraction is
    // 0.5 within 3 sigma of 1024 independent points (sigma <= 0.5/32): 0.047.
    Mesh m;
    m.box({0, 0, 0}, {2, 2, 2}, 1);                                             // facets 1-5
    m.quad({{{0.5, 2.5, 0}, {1.5, 2.5, 0}, {1.5, 3.5, 0}, {0.5, 3.5, 0}}}, 1);  // 1-1-6
    m.quad({{{5, 5, 0}, {6, 5, 0}, {6, 6, 0}, {5, 6, 0}}}, 1);                  // 1-1-7
    m.quad({{{0.5, 3, 0}, {1.5, 3, 0}, {1.5, 5, 0}, {0.5, 5, 0}}}, 1);          // 1-1-8
    const ShadowScene sc = shadow_scene(m.data);
    const auto sun = sun_at(45, 180);
    ShadowOptions o;
    o.sky_rays = 16;
    const io::Shd one = shadow_history(sc, grey(), sun, 0.25, o);
    EXPECT_EQ(facet(one, "1-1-6").sunlit(0), 0.0);
    EXPECT_EQ(facet(one, "1-1-7").sunlit(0), 1.0);
    EXPECT_EQ(facet(one, "1-1-1").sunlit(0), 1.0);  // the box's top
    EXPECT_EQ(facet(one, "1-1-2").sunlit(0), 1.0);  // its south wall (normal -y)
    EXPECT_EQ(facet(one, "1-1-3").sunlit(0), 0.0);  // its north wall: sun behind
    o.points_per_facet = 1024;
    const io::Shd many = shadow_history(sc, grey(), sun, 0.25, o);
    EXPECT_NEAR(mean_sunlit(facet(many, "1-1-8")), 0.5, 0.047);
    unit::record("half_shadowed_sunlit", mean_sunlit(facet(many, "1-1-8")));
    unit::record("half_shadowed_reference", 0.5);
    unit::record("half_shadowed_limit", 0.047);
    EXPECT_EQ(mean_sunlit(facet(many, "1-1-6")), 0.0);
    EXPECT_EQ(mean_sunlit(facet(many, "1-1-7")), 1.0);
}

TEST(ShadowHistory, CanyonFloorSkyViewMatchesTheAnalyticViewFactor) {
    // The floor of an infinite canyon of width W between walls of height H sees the sky
    // with the view factor sqrt(1 + (H/W)^2) - H/W (crossed strings, Hottel; 0.41421 for
    // H = W). Walls 4000 long around a 200-long floor facet: rays that would meet the
    // walls beyond their ends leave at most 5/1900 of the azimuths: bias < 0.002. 64
    // points x 256 rays: sigma <= sqrt(0.42 x 0.58 / 16384) = 0.0039; tolerance 4 sigma
    // + bias = 0.018.
    const double w = 10, h = 10, l = 2000;
    Mesh m;
    m.quad({{{-w / 2, -100, 0}, {w / 2, -100, 0}, {w / 2, 100, 0}, {-w / 2, 100, 0}}}, 1);
    m.quad({{{-w / 2, -l, 0}, {-w / 2, l, 0}, {-w / 2, l, h}, {-w / 2, -l, h}}}, 1);
    m.quad({{{w / 2, l, 0}, {w / 2, -l, 0}, {w / 2, -l, h}, {w / 2, l, h}}}, 1);
    const ShadowScene sc = shadow_scene(m.data);
    ShadowOptions o;
    o.points_per_facet = 64;
    const io::Shd shd = shadow_history(sc, grey(), sun_at(0, 0), 0.25, o);
    const double expected = std::sqrt(1 + (h / w) * (h / w)) - h / w;
    EXPECT_NEAR(facet(shd, "1-1-1").sky_view_factor, expected, 0.018);
    EXPECT_EQ(facet(shd, "1-1-1").sunlit(0, 0), 1.0);  // the sun overhead reaches the floor
    unit::record("sky_view_factor", facet(shd, "1-1-1").sky_view_factor);
    unit::record("reference", expected);
    unit::record("limit", 0.018);
}

TEST(ShadowHistory, TransmissiveSlabGivesTheSlabTransmittance) {
    // A plate under a leaf slab (k = 2e4 /km, d = 1 cm: k d = 0.2) with the sun 60 deg
    // from the zenith: T = exp(-k d / cos 60) = exp(-0.4) in every sample (ext(5)),
    // exact up to rounding; with max_transmissions 0 the slab stops the sun.
    Mesh m;
    m.quad({{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 1);
    m.quad({{{-500, -500, 5}, {500, -500, 5}, {500, 500, 5}, {-500, 500, 5}}}, 2);
    const ShadowScene sc = shadow_scene(m.data);
    radiometry::MaterialOptics leaf = radiometry::grey_material(2, 0.1, 3);
    leaf.transmissive = true;
    leaf.extinction_per_km = {2e4, 2e4, 2e4};
    leaf.thickness_cm = 1;
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, 3), leaf});
    ShadowOptions o;
    o.sky_rays = 16;
    const io::Shd shd = shadow_history(sc, mats, sun_at(60, 90), 0.25, o);
    EXPECT_EQ(facet(shd, "1-1-1").sunlit(0), 1.0);
    EXPECT_NEAR(facet(shd, "1-1-1").sun_transmittance(0), std::exp(-0.4), 1e-12);
    EXPECT_EQ(facet(shd, "1-1-2").sun_transmittance(0), 1.0);  // the slab itself
    o.max_transmissions = 0;
    const io::Shd blocked = shadow_history(sc, mats, sun_at(60, 90), 0.25, o);
    EXPECT_EQ(facet(blocked, "1-1-1").sunlit(0), 0.0);
}

TEST(ShadowHistory, ThreadCountDoesNotChangeTheResult) {
    Mesh m;
    m.quad({{{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}}, 1);
    m.box({-3, -2, 0}, {-1, 2, 3}, 1);
    m.box({1, -1, 0}, {3, 1, 1.5}, 1);
    const ShadowScene sc = shadow_scene(m.data);
    const auto sun = sun_history(io::read_snd_file(kSnd), 9, 1.0);
    ShadowOptions o;
    o.points_per_facet = 8;
    o.sky_rays = 64;
    o.threads = 1;
    const io::Shd a = shadow_history(sc, grey(), sun, 1.0, o);
    o.threads = 3;
    const io::Shd b = shadow_history(sc, grey(), sun, 1.0, o);
    ASSERT_EQ(a.facets.size(), b.facets.size());
    for (std::size_t i = 0; i < a.facets.size(); ++i) {
        EXPECT_EQ(a.facets[i].id, b.facets[i].id);
        EXPECT_EQ(a.facets[i].sky_view_factor, b.facets[i].sky_view_factor);
        EXPECT_EQ(a.facets[i].sunlit_fraction, b.facets[i].sunlit_fraction);
        EXPECT_EQ(a.facets[i].transmittance, b.facets[i].transmittance);
    }
}

TEST(ShadowHistory, KeysAndNormalsAgreeWithThermsSceneReader) {
    // therm finds each facet's history by key: the .odb's keys (object.instance/FACE id)
    // and facing sides must be the ones therm reads, including the turned and the
    // stretched instance.
    for (const std::string path :
         {SIGCHAIN_TEST_DATA "/white1996/neighbourhood.odb", SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb",
          SIGCHAIN_TEST_DATA "/shadow/facing.gdb"}) {
        const ShadowScene sc = load_shadow_scene(path, 1.0, false);
        const auto therm = thermal::read_scene_facets(path);
        ASSERT_EQ(sc.facets().size(), therm.size()) << path;
        for (std::size_t i = 0; i < therm.size(); ++i) {
            EXPECT_EQ(sc.facets()[i].key, therm[i].key);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(sc.facets()[i].normal[k], therm[i].normal[k], 1e-6) << therm[i].key;
        }
    }
}

TEST(ShadowHistory, TheFaceNormalNotTheWindingSaysWhichWayAFacetFaces) {
    // gdb(5): facing.gdb's 1-1-1 is wound clockwise from above with its normal up, 1-1-2
    // counter-clockwise with its normal down. At the .snd's scene time (14:00 local,
    // sun up) 1-1-1 is sunlit and sees the whole sky; 1-1-2 has the sun behind it and
    // sees no sky (its hemisphere is below the horizon).
    const ShadowScene sc = load_shadow_scene(SIGCHAIN_TEST_DATA "/shadow/facing.gdb", 1.0, false);
    ASSERT_EQ(sc.facets().size(), 2u);
    EXPECT_NEAR(sc.facets()[0].normal[2], 1.0, 1e-12);
    EXPECT_NEAR(sc.facets()[1].normal[2], -1.0, 1e-12);
    const auto sun = sun_history(io::read_snd_file(kSnd), 1, 0.25);
    ASSERT_TRUE(sun[0].up);
    const io::Shd shd = shadow_history(sc, grey(), sun, 0.25, ShadowOptions{});
    EXPECT_EQ(facet(shd, "1-1-1").sunlit(0), 1.0);
    EXPECT_EQ(facet(shd, "1-1-1").sky_view_factor, 1.0);
    EXPECT_EQ(facet(shd, "1-1-2").sunlit(0), 0.0);
    EXPECT_EQ(facet(shd, "1-1-2").sky_view_factor, 0.0);
}

TEST(ShadowHistory, SceneIsTheOneLoadSceneBuilds) {
    // load_shadow_scene re-assembles the .odb to keep each facet's triangles; the traced
    // scene must be load_scene's: the same placements, facets (in order, by key),
    // triangles and bounds (the .odb's stretched instance is twice as tall).
    const std::string path = SIGCHAIN_TEST_DATA "/white1996/neighbourhood.odb";
    scene::LoadOptions lo;
    const scene::Scene ref = scene::load_scene(path, lo);
    const ShadowScene sc = load_shadow_scene(path, 1.0, false);
    ASSERT_EQ(sc.scene().placement_count(), ref.placement_count());
    EXPECT_EQ(sc.scene().triangle_count(), ref.triangle_count());
    std::size_t i = 0, triangles = 0;
    for (std::size_t object = 0; object < ref.placement_count(); ++object)
        for (std::uint32_t f = 0; f < ref.facet_count(ref.mesh_of_placement(object)); ++f) {
            scene::Hit h;
            h.object = static_cast<std::uint32_t>(object);
            h.facet = f;
            ASSERT_LT(i, sc.facets().size());
            EXPECT_EQ(sc.facets()[i].key, ref.facet_key(h));
            triangles += sc.facets()[i++].triangles.size();
        }
    EXPECT_EQ(i, sc.facets().size());
    EXPECT_EQ(triangles, ref.triangle_count());
    for (int k = 0; k < 3; ++k) {
        EXPECT_DOUBLE_EQ(sc.scene().bounds().lower[k], ref.bounds().lower[k]);
        EXPECT_DOUBLE_EQ(sc.scene().bounds().upper[k], ref.bounds().upper[k]);
    }
}

TEST(RenderEmission, BlackbodyPlateThroughUnitTransmissionGivesPlanck) {
    // Thermal chain: a blackbody plate (emissivity 1) at 300 K, no sun, no sky, tau2 = 1 and
    // no path radiance: every thermal sample is B(lambda, 300 K). Reference: Planck's
    // law with CODATA 2018 h, c, k written out here (1 W m-2 sr-1 m-1 = 1e-10 W cm-2
    // sr-1 um-1); and B(10 um, 300 K) = 9.924 W m-2 sr-1 um-1 (tabulated). Tolerance:
    // float output, 1e-6 relative.
    const std::vector<double> wl{3.0, 4.0, 8.0, 10.0, 12.0};
    auto planck = [](double um, double t) {
        const double h = 6.62607015e-34, c = 299792458, k = 1.380649e-23, l = um * 1e-6;
        return 2 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * t)) * 1e-10;
    };
    EXPECT_NEAR(planck(10, 300) * 1e4, 9.924, 0.001);
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    const scene::Scene s = test::single(m.data);
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.0, wl.size())});
    const auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(wl, 120, 0, 0.0, 0.0, 1.0, 0.0)}, {"u.rad"});
    test::Ortho cam(1, 1, 1, 0, 0, {0, 0, -1});
    Temperatures temps{{"1-1-1", 300.0}};
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    in.temperatures = &temps;
    const RenderResult res = render(in, RenderOptions{});
    for (std::size_t k = 0; k < wl.size(); ++k)
        EXPECT_NEAR(res.radiance.at(static_cast<int>(k), 0, 0), planck(wl[k], 300),
                    1e-6 * planck(wl[k], 300))
            << wl[k] << " um";
}

TEST(RenderEmission, EmittedSkyAndPathAreAddedOnlyWithTemperatures) {
    // A grey Lambertian plate (r = 0.3) at 300 K under a sky that only emits (uniform
    // L_de = 2e-4), seen through tau2 = 0.8 with an emitting path (L_ue = 1e-4), no sun
    // (zenith 120): L = tau2 [(1 - r) B(300 K) + r L_de] + L_ue (White (1996), section 3.4; the golf
    // ball's diffuse weights sum to 1 and every ray escapes the 1800 m plate upward).
    // Without temperatures all three emitted terms are left out: L = 0. Tolerance:
    // float output, 1e-6 relative.
    const std::vector<double> wl{4.0, 10.0};
    const double r = 0.3, ld = 2e-4, lu = 1e-4, tau2 = 0.8;
    io::Rad rad = radiometry::uniform_rad(wl, 120, 0, 0.0, 0.0, tau2, 0.0);
    for (auto& v : rad.views)
        for (auto& p : v.path) p.emitted_radiance = lu;
    for (auto& c : rad.sky->cells) c.emitted_radiance.assign(wl.size(), ld);
    const auto atm = radiometry::Atmosphere::from_rads({rad}, {"e.rad"});
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    const scene::Scene s = test::single(m.data);
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, r, wl.size())});
    test::Ortho cam(1, 1, 1, 0, 0, {0, 0, -1});
    Temperatures temps{{"1-1-1", 300.0}};
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    in.temperatures = &temps;
    RenderResult res = render(in, RenderOptions{});
    for (std::size_t k = 0; k < wl.size(); ++k) {
        const double b = rt::planck_radiance(wl[k], 300);
        const double expected = tau2 * ((1 - r) * b + r * ld) + lu;
        EXPECT_NEAR(res.radiance.at(static_cast<int>(k), 0, 0), expected, 1e-6 * expected)
            << wl[k] << " um";
    }
    in.temperatures = nullptr;
    res = render(in, RenderOptions{});
    for (std::size_t k = 0; k < wl.size(); ++k)
        EXPECT_EQ(res.radiance.at(static_cast<int>(k), 0, 0), 0.0f) << wl[k] << " um";
}

}  // namespace
}  // namespace sigchain::trace
