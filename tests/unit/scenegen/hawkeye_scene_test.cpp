// Tests of lib/scenegen/hawkeye: the hawkeye scene's terrain (the 60 m gorge, hills of
// 15-25 m), its counts against the targets "about 850 structures" and "about 3000
// trees", raised pavement, placement on the terrain, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "io/gdb.hpp"
#include "io/odb.hpp"
#include "scenegen/hawkeye.hpp"

namespace sg = sigchain::scenegen;

namespace {

// Heights are sums and products of a few doubles of magnitude <= 100 m: exact to
// ~1e-13 m, so 1e-9 m cannot hide a wrong depth, raise or interpolation.
constexpr double kTolM = 1e-9;

std::string serialise(const sg::HawkeyeScene& s) {
    std::ostringstream o;
    o.precision(17);
    for (const auto& [name, gdb] : s.files) {
        o << name << "\n";
        sigchain::io::write_gdb(o, gdb);
    }
    sigchain::io::write_odb(o, s.odb);
    return o.str();
}

std::size_t instances_of(const sg::HawkeyeScene& s, const std::string& prefix) {
    std::size_t n = 0;
    for (const auto& o : s.odb.objects)
        if (o.path.rfind(prefix, 0) == 0) n += o.instances.size();
    return n;
}

}  // namespace

TEST(HawkeyeTerrain, GorgeIs60MetresBelowTheHillsBaseAndRunsSouthToNorth) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const auto t = sg::hawkeye_terrain(seed);
        for (int j = 0; j < t.nodes; ++j) {
            // Every row (south to north) has its lowest node 60 m below z = 0, near the
            // middle of the scene (the centre line meanders at most 40 m; floor 60 m wide).
            double zmin = 1e9, xmin = 0;
            for (int i = 0; i < t.nodes; ++i)
                if (t.node_z(i, j) < zmin) zmin = t.node_z(i, j), xmin = t.node_x(i);
            EXPECT_NEAR(zmin, -sg::kGorgeDepthM, kTolM) << "seed " << seed << " row " << j;
            EXPECT_LE(std::abs(xmin), 40 + sg::kGorgeFloorHalfWidthM);
            // The rims (beyond 110 m from the centre line) are the hills, >= 0.
            const double c = t.gorge_centre_m(t.node_x(j));
            for (int i = 0; i < t.nodes; ++i) {
                const double d = std::abs(t.node_x(i) - c);
                if (d >= sg::kGorgeRimHalfWidthM) {
                    EXPECT_GE(t.node_z(i, j), 0.0);
                }
                if (d <= sg::kGorgeFloorHalfWidthM) {
                    EXPECT_NEAR(t.node_z(i, j), -sg::kGorgeDepthM, kTolM);
                }
            }
        }
    }
}

TEST(HawkeyeTerrain, HillsAreWithin15To25MetresAndVaryWithTheSeed) {
    std::set<long> amplitudes_cm;
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const auto t = sg::hawkeye_terrain(seed);
        // Peak-to-trough of the plateau's heights (nodes outside the gorge), measured
        // from the heights themselves, not from the stored amplitude.
        double lo = 1e9, hi = -1e9;
        for (int j = 0; j < t.nodes; ++j)
            for (int i = 0; i < t.nodes; ++i)
                if (t.gorge_weight(t.node_x(i), t.node_x(j)) == 0) {
                    lo = std::min(lo, t.node_z(i, j));
                    hi = std::max(hi, t.node_z(i, j));
                }
        EXPECT_GE(hi - lo, 0.8 * sg::kMinHillM)
            << "seed " << seed;  // extremes may fall in the gorge
        EXPECT_LE(hi - lo, sg::kMaxHillM + kTolM) << "seed " << seed;
        const auto [hlo, hhi] = std::minmax_element(t.hills_m.begin(), t.hills_m.end());
        EXPECT_GE(*hhi - *hlo, sg::kMinHillM);
        EXPECT_LE(*hhi - *hlo, sg::kMaxHillM);
        amplitudes_cm.insert(std::lround((*hhi - *hlo) * 100));
    }
    EXPECT_GT(amplitudes_cm.size(), 40u);  // the seed sets the amplitude
}

TEST(HawkeyeTerrain, HeightIsTheTriangulatedGrid) {
    const auto t = sg::hawkeye_terrain(4);
    for (int j = 0; j + 1 < t.nodes; j += 7)
        for (int i = 0; i + 1 < t.nodes; i += 5) {
            const double x = t.node_x(i), y = t.node_x(j), h = t.spacing_m;
            EXPECT_NEAR(t.height_m(x, y), t.node_z(i, j), kTolM);
            // Linear along the cell's edges and its diagonal.
            EXPECT_NEAR(t.height_m(x + h / 2, y), (t.node_z(i, j) + t.node_z(i + 1, j)) / 2, kTolM);
            EXPECT_NEAR(t.height_m(x, y + h / 2), (t.node_z(i, j) + t.node_z(i, j + 1)) / 2, kTolM);
            EXPECT_NEAR(t.height_m(x + h / 2, y + h / 2),
                        (t.node_z(i, j) + t.node_z(i + 1, j + 1)) / 2, kTolM);
        }
}

TEST(HawkeyeScene, CountsAreNearTheSeeds850StructuresAnd3000Trees) {
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
        const auto s = sg::hawkeye_scene(seed);
        const auto& c = s.counts;
        // "about 850 structures", "about 3000 trees": within 12 % and 7 %.
        EXPECT_GE(c.structures(), 750u) << "seed " << seed;
        EXPECT_LE(c.structures(), 950u) << "seed " << seed;
        EXPECT_GE(c.trees, 2800u);
        EXPECT_LE(c.trees, 3200u);
        EXPECT_EQ(c.plants, 1u);
        EXPECT_EQ(c.bridges, 1u);
        EXPECT_GT(c.large_buildings, 5u);
        EXPECT_GT(c.vehicles, 100u);
        // The counts agree with the .odb's instances.
        EXPECT_EQ(
            instances_of(s, "fancy-") + instances_of(s, "house1-") + instances_of(s, "house2-"),
            c.houses);
        EXPECT_EQ(instances_of(s, "garage-"), c.garages);
        EXPECT_EQ(instances_of(s, "tree.gdb"), c.trees);
        EXPECT_EQ(instances_of(s, "vehicle-"), c.vehicles);
    }
    // Three house types and a garage in ten colours: 40 meshes, all used for seed 4.
    const auto s = sg::hawkeye_scene(4);
    int house_files = 0;
    for (const auto& [name, gdb] : s.files)
        if (name.rfind("fancy-", 0) == 0 || name.rfind("house", 0) == 0 ||
            name.rfind("garage-", 0) == 0)
            ++house_files;
    EXPECT_EQ(house_files, 40);
}

TEST(HawkeyeScene, PavementIsRaisedOnTheTerrain) {
    const auto s = sg::hawkeye_scene(4);
    const auto& terrain = s.files.at(0).second;
    ASSERT_EQ(s.files.at(0).first, "terrain.gdb");
    ASSERT_EQ(terrain.objects.size(), 2u);
    std::size_t checked = 0;
    for (const auto& part : terrain.objects[1].parts) {
        const double raise = part.name == "sidewalks" ? sg::kSidewalkRaiseM : sg::kStreetRaiseM;
        for (const auto& f : part.facets)
            for (const auto& v : f.vertices) {
                EXPECT_NEAR(v[2] - s.terrain.height_m(v[0], v[1]), raise, kTolM) << f.id;
                ++checked;
            }
    }
    EXPECT_GT(checked, 10000u);
    EXPECT_EQ(checked,
              6 * (s.counts.street_cells + s.counts.parking_cells + s.counts.sidewalk_strips));
}

TEST(HawkeyeScene, HousesStandOnThePlateauAtTheirLowestCorner) {
    const auto s = sg::hawkeye_scene(4);
    const auto& t = s.terrain;
    for (const auto& o : s.odb.objects) {
        const bool house = o.path.rfind("fancy-", 0) == 0 || o.path.rfind("house", 0) == 0;
        if (!house) continue;
        for (const auto& in : o.instances) {
            const double x = in.translation[0], y = in.translation[1], z = in.translation[2];
            EXPECT_EQ(t.gorge_weight(x, y), 0.0);
            // The base is the lowest terrain under the 12 m x 10 m footprint box; walls
            // reach 1 m below it, so no corner floats.
            for (double dx : {-6.0, 6.0})
                for (double dy : {-5.0, 5.0}) EXPECT_LE(z, t.height_m(x + dx, y + dy) + kTolM);
            EXPECT_GE(z, -kTolM);
        }
    }
}

TEST(HawkeyeScene, SameSeedSameSceneOtherSeedOtherScene) {
    const std::string a = serialise(sg::hawkeye_scene(4));
    EXPECT_EQ(a, serialise(sg::hawkeye_scene(4)));
    EXPECT_NE(a, serialise(sg::hawkeye_scene(5)));
}

TEST(HawkeyeScene, EveryFileHasNoGeometryProblems) {
    const auto s = sg::hawkeye_scene(4);
    for (const auto& [name, gdb] : s.files) {
        const auto problems = sigchain::io::gdb_problems(gdb);
        EXPECT_TRUE(problems.empty()) << name << ": " << (problems.empty() ? "" : problems[0]);
    }
}
