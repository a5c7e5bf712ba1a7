// Tests of therm's job: the box_on_plane scene of White (1996) end to end, facet resolution and
// its errors, the sun/shadow lookup, and refused weather windows.
#include "thermal/therm_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "scene/load.hpp"
#include "scene/scene.hpp"

namespace th = sigchain::thermal;
namespace io = sigchain::io;

namespace {

const std::string kSeed = SIGCHAIN_TEST_DATA "/white1996/";
const std::string kTherm = SIGCHAIN_TEST_DATA "/therm/";

th::ThermJob seed_job() {
    th::ThermJob job;
    job.shd_path = kSeed + "box_on_plane.shd";
    job.wth_path = kSeed + "weather_30_Sep_95.wth";
    job.mat_path = kTherm + "box_on_plane.mat";
    job.scene_path = kSeed + "box_on_plane.gdb";
    job.snd_path = kSeed + "hawkeye.snd";
    return job;
}

// The message of the DataError thrown by f, or "" if none.
template <class F>
std::string data_error(F f) {
    try {
        f();
    } catch (const sigchain::DataError& e) {
        return e.what();
    }
    return "";
}

std::string write_temp(const std::string& name, const std::string& text) {
    auto path = std::filesystem::temp_directory_path() / ("therm_test_" + name);
    std::ofstream(path) << text;
    return path.string();
}

}  // namespace

// The scene of White (1996) at 14:00 on 30 Sep 1995 (air 17 C): every facet solved, sunlit
// horizontal surfaces warmer than the air, the north wall (sun behind it, half the
// sky) cooler than the south wall, all within physical bounds of the air temperature.
TEST(ThermJob, SeedBoxOnPlane) {
    th::ThermResult r = th::compute_temperatures(seed_job(), {});
    ASSERT_EQ(r.tmp.facets.size(), 6u);
    EXPECT_EQ(r.facets_solved, 6);
    ASSERT_TRUE(r.tmp.time_hours);
    EXPECT_DOUBLE_EQ(*r.tmp.time_hours, 38);
    std::map<std::string, double> t;
    for (const auto& f : r.tmp.facets) t[f.facet_id] = f.temperature_k;
    io::Wth wth = io::read_wth_file(seed_job().wth_path);
    const double air_k = wth.rows[38].air_temperature_c + 273.15;
    for (const auto& [id, k] : t) {
        EXPECT_GT(k, air_k - 10) << id;  // no facet far below the air by day
        EXPECT_LT(k, air_k + 40) << id;  // nor hotter than asphalt in summer
    }
    EXPECT_GT(t["1-1-1"], air_k);       // sunlit grass
    EXPECT_GT(t["2-1-1"], air_k);       // sunlit box top
    EXPECT_GT(t["2-1-2"], t["2-1-4"]);  // south wall warmer than the north wall
    // Spin-up: the runs from the first run's state 24 h in converge (the start no longer
    // matters): the last two agree within the tolerance, in few runs for these thin
    // facets (grass 1.3 cm, wood 5 cm: time constants of hours).
    EXPECT_LT(r.spinup_residual_k, th::kSpinUpToleranceK) << r.spinup_facet;
    EXPECT_LE(r.spinup_runs_max, 4);
    for (const auto& [id, k] : t) std::printf("%s %.3f K\n", id.c_str(), k);
    std::printf("spin-up residual %.3g K (%s), up to %d runs\n", r.spinup_residual_k,
                r.spinup_facet.c_str(), r.spinup_runs_max);
}

TEST(ThermJob, ResolvesUnitsFromTheMat) {
    io::Mat mat = io::read_mat_file(kTherm + "box_on_plane.mat");
    th::SceneFacet f;
    f.key = "1-1-1";
    f.material_id = 41;  // concrete, 20 cm from the .mat
    th::FacetThermal ft = th::resolve_facet(f, mat);
    EXPECT_NEAR(ft.slab.thickness_m, 0.20, 1e-12);
    EXPECT_NEAR(ft.slab.density_kg_m3, 2300, 1e-9);
    EXPECT_NEAR(ft.slab.specific_heat_j_kg_k, 0.21 * 4184, 1e-9);
    EXPECT_NEAR(ft.slab.conductivity_w_m_k, 33.5 * 0.04184, 1e-12);
    EXPECT_EQ(ft.back_exposure, 0);
    f.material_id = 40;  // aluminium, EXPOSED_AREA 2: both faces
    EXPECT_EQ(th::resolve_facet(f, mat).back_exposure, 1);
    f.thickness_cm = 1;
    f.power = 100;  // W/m2 over 1 cm
    EXPECT_NEAR(th::resolve_facet(f, mat).slab.volumetric_power_w_m3, 1e4, 1e-9);
}

TEST(ThermJob, MissingOrNonPhysicalMaterialsAreErrors) {
    io::Mat mat = io::read_mat_file(kTherm + "box_on_plane.mat");
    th::SceneFacet f;
    f.key = "1-1-1";
    f.where = {"scene.gdb", 16};
    f.material_id = 99;
    EXPECT_NE(data_error([&] { th::resolve_facet(f, mat); }).find("scene.gdb:16: "),
              std::string::npos);
    f.material_id = 37;
    f.thickness_cm = 0;
    EXPECT_NE(data_error([&] { th::resolve_facet(f, mat); }).find("thickness"), std::string::npos);
    f.thickness_cm = -1;
    mat.materials[1].thickness_cm.reset();
    EXPECT_NE(data_error([&] { th::resolve_facet(f, mat); }).find("no thickness"),
              std::string::npos);
    f.thickness_cm = 5;
    mat.materials[1].mass_density_g_cm3 = 0;
    std::string m = data_error([&] { th::resolve_facet(f, mat); });
    EXPECT_NE(m.find("MASS_DENSITY"), std::string::npos) << m;
    EXPECT_NE(m.find(":" + std::to_string(mat.materials[1].line) + ": "), std::string::npos) << m;
}

// Inside the .shd window: interpolated sunlit x transmittance. Outside a window of
// 24 h or more: the same time of day inside it. Outside a shorter window: unshadowed.
TEST(ThermJob, SunFactorsFromTheHistory) {
    io::Shd shd;
    shd.scene_time_hours = 38;
    shd.steps = 3;
    shd.step_hours = 1;
    io::ShdFacet f;
    f.id = "1-1-1";
    f.sunlit_fraction = {1, 0.5, 0};
    f.transmittance = {1, 1, 0.5};
    shd.facets = {f};
    std::vector<th::EnvironmentStep> env(3);
    env[0].time_h = 36.5;
    env[1].time_h = 10;
    env[2].time_h = 37.5;
    auto s = th::sun_factors(shd, shd.facets[0], env);
    EXPECT_NEAR(s[0], 0.75, 1e-12);
    EXPECT_EQ(s[1], 1.0);
    EXPECT_NEAR(s[2], 0.25, 1e-12);
    shd.steps = 25;  // 14 h .. 38 h
    f.sunlit_fraction.assign(25, 1.0);
    f.transmittance.assign(25, 1.0);
    f.sunlit_fraction[24 - 14] = 0.0;  // 24 h: shadowed
    shd.facets = {f};
    env[1].time_h = 0;  // wraps to 24 h
    EXPECT_EQ(th::sun_factors(shd, shd.facets[0], env)[1], 0.0);
}

TEST(ThermJob, WeatherWindowMustCoverTheHistory) {
    // The weather of White (1996) cut to 0..30 h: the scene time (38 h) is outside.
    std::ifstream in(kSeed + "weather_30_Sep_95.wth");
    std::string text, line;
    int row = -1;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (row < 0) line = "31\t1";
        if (row <= 30) text += line + "\n";
        ++row;
    }
    th::ThermJob job = seed_job();
    job.wth_path = write_temp("short.wth", text);
    std::string m = data_error([&] { th::compute_temperatures(job, {}); });
    EXPECT_NE(m.find(job.wth_path), std::string::npos) << m;
    EXPECT_NE(m.find("does not cover 38"), std::string::npos) << m;
}

TEST(ThermJob, SceneTimeMustMatchTheSnd) {
    th::ThermJob job = seed_job();
    std::ifstream in(kSeed + "hawkeye.snd");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    auto pos = text.find("19\t# time of day");
    ASSERT_NE(pos, std::string::npos);
    text.replace(pos, 2, "20");
    job.snd_path = write_temp("late.snd", text);
    EXPECT_NE(data_error([&] { th::compute_temperatures(job, {}); }).find("scene time"),
              std::string::npos);
}

// An .odb of an OBJ object (quad_tri.obj: a grass quad, an asphalt triangle taken as
// wood) and a DEM (flat.odb's grass terrain), every facet given the history of the
// sunlit ground 1-1-1 of White's (1996) scene under the keys trace gives them (scene::load_scene).
// The rows are those keys in scene order. The grass facets share history and
// material; flat.asc lies about 9 km south-east of hawkeye.snd's point, about which it
// is placed, so its ellipsoid surface is tilted by ~1.4e-3 rad in the scene frame:
// the sun's cosine on it differs by ~1e-3 from the OBJ's level quad (~0.01 K), and
// across its 100 m the tilt varies by ~1.6e-5 rad (~1e-4 K between its facets).
TEST(ThermJob, OdbOfObjAndDemObjects) {
    namespace sc = sigchain::scene;
    const std::string data = SIGCHAIN_TEST_DATA "/scene/";
    const std::string map = write_temp("obj_dem.map", "grass 1\nasphalt 37\n");
    th::ThermJob job = seed_job();
    job.scene_path =
        write_temp("obj_dem.odb", "OBJECT {\n  OBJ_FILENAME = " + data +
                                      "quad_tri.obj\n  MATERIAL_MAP = " + map +
                                      "\n  UNITS = m\n}\nOBJECT {\n  DEM_FILENAME = " + data +
                                      "flat.asc\n  MATERIAL_ID = 1\n"
                                      "  UNITS = m\n}\n");
    const io::Snd snd = io::read_snd_file(job.snd_path);
    sc::LoadOptions options;
    options.origin = sc::GeoOrigin{snd.latitude_deg, snd.longitude_east_deg, 0.0};
    const sc::Scene scene = sc::load_scene(job.scene_path, options);
    io::Shd shd = io::read_shd_file(job.shd_path);
    const io::ShdFacet ground = shd.facets.front();
    ASSERT_EQ(ground.id, "1-1-1");
    shd.facets.clear();
    for (std::size_t p = 0; p < scene.placement_count(); ++p)
        for (std::uint32_t f = 0; f < scene.facet_count(scene.mesh_of_placement(p)); ++f) {
            sc::Hit h;
            h.object = static_cast<std::uint32_t>(p);
            h.facet = f;
            shd.facets.push_back(ground);
            shd.facets.back().id = scene.facet_key(h);
        }
    std::ostringstream text;
    io::write_shd(text, shd);
    job.shd_path = write_temp("obj_dem.shd", text.str());

    const th::ThermResult r = th::compute_temperatures(job, {});
    ASSERT_EQ(r.tmp.facets.size(), shd.facets.size());
    ASSERT_GT(r.tmp.facets.size(), 3u);  // the quad, the triangle and the terrain
    for (std::size_t i = 0; i < shd.facets.size(); ++i)
        EXPECT_EQ(r.tmp.facets[i].facet_id, shd.facets[i].id);
    EXPECT_EQ(r.tmp.facets[0].facet_id, "1.1/1-1-1");  // the OBJ's grass quad
    EXPECT_EQ(r.tmp.facets[1].facet_id, "1.1/1-2-2");  // its triangle, wood here
    const double grass = r.tmp.facets[0].temperature_k;
    EXPECT_GT(std::abs(r.tmp.facets[1].temperature_k - grass), 0.1);  // another material
    const double terrain = r.tmp.facets[2].temperature_k;
    EXPECT_NEAR(terrain, grass, 0.05);
    for (std::size_t i = 2; i < r.tmp.facets.size(); ++i)
        EXPECT_NEAR(r.tmp.facets[i].temperature_k, terrain, 1e-3) << r.tmp.facets[i].facet_id;
}
