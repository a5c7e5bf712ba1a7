// Tests of lib/scenegen/soho: the ground plane and one extruded object per usable
// footprint, the counts, degenerate rings skipped, and the written header.
#include "scenegen/soho.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sg = sigchain::scenegen;

namespace {

// Two footprints: a 10 m square and a degenerate (collinear) ring.
sg::Footprints two_footprints() {
    sg::Footprints fp;
    fp.crs_name = "test CRS";
    fp.origin = {1000, 2000};
    fp.extent = {0, 0, 10, 10};
    fp.buildings.push_back({5, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
    fp.buildings.push_back({6, {{0, 0}, {1, 0}, {2, 0}}});
    return fp;
}

}  // namespace

TEST(SohoScene, GroundThenOneObjectPerUsableFootprint) {
    sg::SohoCounts c;
    const auto gdb = sg::soho_gdb(two_footprints(), 7, c);
    EXPECT_EQ(c.footprints, 2u);
    EXPECT_EQ(c.buildings, 1u);
    EXPECT_EQ(c.skipped, 1u);
    EXPECT_EQ(c.roofs, 2u);  // a square's roof: 2 triangles
    EXPECT_EQ(c.walls, 4u);
    ASSERT_EQ(gdb.objects.size(), 2u);
    EXPECT_EQ(gdb.objects[1].name, "building fid 5");
    // The ground: the extent plus 300 m on every side.
    const auto& ground = gdb.objects[0].parts[0].facets[0];
    EXPECT_EQ(ground.vertices[0][0], -300);
    EXPECT_EQ(ground.vertices[2][1], 310);
    // The roof stands at the storey rule's height for feature 5.
    EXPECT_EQ(gdb.objects[1].parts[0].facets[0].vertices[0][2], sg::building_height_m(5, 7));
}

TEST(SohoScene, WrittenFileStartsWithItsProvenance) {
    const auto fp = two_footprints();
    sg::SohoCounts c;
    const auto gdb = sg::soho_gdb(fp, 9, c);
    const auto path = std::filesystem::temp_directory_path() /
                      ("sigchain_soho_test_" + std::to_string(::getpid()) + ".gdb");
    sg::write_soho_gdb(path.string(), "in.gpkg", fp, 9, gdb);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(path);
    EXPECT_EQ(text.str().rfind("# soho.gdb: written by soho_scene", 0), 0u);
    EXPECT_NE(text.str().find("from in.gpkg\n"), std::string::npos);
    EXPECT_NE(text.str().find("# CRS test CRS;"), std::string::npos);
    EXPECT_NE(text.str().find("# easting 1000, northing 2000;"), std::string::npos);
    EXPECT_NE(text.str().find("; seed 9.\n"), std::string::npos);
}
