// Tests of reading a scene's facets for therm: keys, normals under placements, refusals.
#include "thermal/scene_facets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace th = sigchain::thermal;

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

}  // namespace

TEST(SceneFacets, GdbKeysNormalsAndOverrides) {
    auto facets = th::read_scene_facets(SIGCHAIN_TEST_DATA "/seed/box_on_plane.gdb");
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

// The seed's neighbourhood.odb places box_on_plane.gdb three times: as built, turned a
// quarter turn counter-clockwise about z (the south wall then faces east: Rz(90)
// maps (0,-1,0) to (1,0,0)), and stretched x2 in z (normals of the walls and the top
// keep their directions: the inverse transpose of diag(1,1,2) is diag(1,1,0.5)).
TEST(SceneFacets, OdbPlacementsPrefixKeysAndTurnNormals) {
    auto facets = th::read_scene_facets(SIGCHAIN_TEST_DATA "/seed/neighbourhood.odb");
    ASSERT_EQ(facets.size(), 18u);
    expect_normal(find(facets, "1.1/2-1-2"), 0, -1, 0);
    expect_normal(find(facets, "1.2/2-1-2"), 1, 0, 0);
    expect_normal(find(facets, "1.2/2-1-1"), 0, 0, 1);
    expect_normal(find(facets, "1.3/2-1-1"), 0, 0, 1);
    expect_normal(find(facets, "1.3/2-1-2"), 0, -1, 0);
}

TEST(SceneFacets, OdbObjectsFromObjFilesAreRefused) {
    auto dir = std::filesystem::temp_directory_path() / "therm_scene_facets";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "s.odb") << "OBJECT {\n    OBJ_FILENAME = a.obj\n"
                                    "    MATERIAL_MAP = a.map\n    UNITS = m\n}\n";
    try {
        th::read_scene_facets((dir / "s.odb").string());
        FAIL() << "an OBJ object was accepted";
    } catch (const sigchain::DataError& e) {
        EXPECT_NE(std::string(e.what()).find("s.odb:1: "), std::string::npos) << e.what();
    }
}
