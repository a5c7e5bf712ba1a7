// Tests of reading a scene's facets for therm: keys, normals under placements, OBJ and DEM
// objects keyed as trace keys them.
#include "thermal/scene_facets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace th = sigchain::thermal;
namespace sc = sigchain::scene;

namespace {

const th::SceneFacet& find(const std::vector<th::SceneFacet>& facets, const std::string& key) {
    for (const auto& f : facets)
        if (f.key == key) return f;
    throw std::runtime_error("no facet " + key);
}

void expect_normal(const th::SceneFacet& f, double x, double y, double z) {
    // Unit normals computed from exact inputs (0/90 deg rotations): 1e-12 is rounding.
    EXPECT_NEAR(f.normal[0], x, 1e-12) << f.key;
    EXPECT_NEAR(f.normal[1], y, 1e-12) << f.key;
    EXPECT_NEAR(f.normal[2], z, 1e-12) << f.key;
}

// The facets of a scene as lib/scene places them, keyed as trace keys them (the keys
// of its .shd and of its renders' facet names).
std::vector<std::string> scene_keys(const std::string& path, const sc::LoadOptions& options) {
    const sc::Scene s = sc::load_scene(path, options);
    std::vector<std::string> keys;
    for (std::size_t p = 0; p < s.placement_count(); ++p)
        for (std::uint32_t f = 0; f < s.facet_count(s.mesh_of_placement(p)); ++f) {
            sc::Hit h;
            h.object = static_cast<std::uint32_t>(p);
            h.facet = f;
            keys.push_back(s.facet_key(h));
        }
    return keys;
}

std::vector<std::string> keys_of(const std::vector<th::SceneFacet>& facets) {
    std::vector<std::string> keys;
    for (const auto& f : facets) keys.push_back(f.key);
    return keys;
}

}  // namespace

TEST(SceneFacets, GdbKeysNormalsAndOverrides) {
    auto facets = th::read_scene_facets(SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb");
    ASSERT_EQ(facets.size(), 6u);
    EXPECT_EQ(facets[0].key, "1-1-1");
    expect_normal(find(facets, "2-1-1"), 0, 0, 1);
    expect_normal(find(facets, "2-1-2"), 0, -1, 0);  // south wall
    const auto& top = find(facets, "2-1-1");
    EXPECT_EQ(top.material_id, 37);
    EXPECT_EQ(top.thickness_cm, 5);
    EXPECT_EQ(top.temperature_c, -1);
    EXPECT_EQ(top.where.line, 44);
}

// tests/data/white1996/neighbourhood.odb places box_on_plane.gdb three times: as built,
// turned a quarter turn counter-clockwise about z (the south wall then faces east:
// Rz(90) maps (0,-1,0) to (1,0,0)), and stretched x2 in z (normals of the walls and
// the top keep their directions: the inverse transpose of diag(1,1,2) is
// diag(1,1,0.5)).
TEST(SceneFacets, OdbPlacementsPrefixKeysAndTurnNormals) {
    auto facets = th::read_scene_facets(SIGCHAIN_TEST_DATA "/white1996/neighbourhood.odb");
    ASSERT_EQ(facets.size(), 18u);
    expect_normal(find(facets, "1.1/2-1-2"), 0, -1, 0);
    expect_normal(find(facets, "1.2/2-1-2"), 1, 0, 0);
    expect_normal(find(facets, "1.2/2-1-1"), 0, 0, 1);
    expect_normal(find(facets, "1.3/2-1-1"), 0, 0, 1);
    expect_normal(find(facets, "1.3/2-1-2"), 0, -1, 0);
}

// quad_tri.odb places quad_tri.obj (a grass quad and an asphalt triangle at z = 0,
// wound counter-clockwise from above) as it is and doubled in size.
TEST(SceneFacets, OdbObjObjectsAreKeyedAsTraceKeysThem) {
    const std::string path = SIGCHAIN_TEST_DATA "/scene/quad_tri.odb";
    auto facets = th::read_scene_facets(path);
    EXPECT_EQ(keys_of(facets), scene_keys(path, {}));
    ASSERT_EQ(facets.size(), 4u);
    EXPECT_EQ(facets[0].key, "1.1/1-1-1");
    EXPECT_EQ(facets[3].key, "1.2/1-2-2");
    for (const auto& f : facets) expect_normal(f, 0, 0, 1);  // the winding's side: up
    EXPECT_EQ(facets[0].material_id, 1);                     // grass (quad_tri.map)
    EXPECT_EQ(facets[1].material_id, 7);                     // asphalt
    EXPECT_EQ(facets[0].where.line, 12);                     // its `f` line
    EXPECT_EQ(facets[0].thickness_cm, -1);                   // the material's
    EXPECT_EQ(facets[0].temperature_c, -1);                  // therm computes it
}

// flat.odb: a flat DEM at height 0 about 100 m north-east of the origin below.
TEST(SceneFacets, DemObjectsArePlacedAboutTheOrigin) {
    const std::string path = SIGCHAIN_TEST_DATA "/scene/flat.odb";
    EXPECT_THROW(th::read_scene_facets(path), sigchain::DataError);  // no origin
    sc::LoadOptions options;
    options.origin = sc::GeoOrigin{43.0, -77.6, 0.0};
    auto facets = th::read_scene_facets(path, options.origin);
    ASSERT_FALSE(facets.empty());
    EXPECT_EQ(keys_of(facets), scene_keys(path, options));
    for (const auto& f : facets) {
        // Up to the ellipsoid's curvature over ~200 m (2e-5 rad of tilt: z > 1 - 1e-9).
        EXPECT_GT(f.normal[2], 1 - 1e-9) << f.key;
        EXPECT_EQ(f.material_id, 1) << f.key;
    }
}
