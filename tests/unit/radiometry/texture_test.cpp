// Texture maps (White (1996), section 5.2.5.3): a raster of .ems curve numbers placed over the scene
// by its geotransform.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "radiometry/material.hpp"

namespace sigchain::radiometry {
namespace {

const std::string kData = SIGCHAIN_TEST_DATA "/trace/";

MaterialOptics two_curves() {
    MaterialOptics m = grey_material(1, 0.3, 3);
    m.emissivity.push_back({0.2, 0.2, 0.2});
    m.mat_file = "textured.mat";
    m.line = 7;
    return m;
}

TEST(Texture, CurveAtInvertsAGeneralGeotransform) {
    // A rotated grid: x = 100 + 2 col - 1 row, y = 50 + 1 col + 2 row (by hand: cell
    // (row 1, col 2) spans the point x = 100 + 2*2.5 - 1.5 = 103.5, y = 50 + 2.5 + 3 = 55.5).
    TextureMap t;
    t.rows = 2, t.columns = 3;
    t.geotransform = {100, 2, -1, 50, 1, 2};
    t.curve = {0, 1, 2, 3, 4, 5};
    EXPECT_EQ(t.curve_at(103.5, 55.5), 5);
    EXPECT_EQ(t.curve_at(100 + 0.5 * 2 - 0.5, 50 + 0.5 + 1), 0);
    EXPECT_EQ(t.curve_at(99, 40), -1);  // outside
}

TEST(Texture, ReadsAnAsciiGridAndPlacesItInSceneCoordinates) {
    MaterialOptics m = two_curves();
    auto t = read_texture_map(kData + "halves.asc", m);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->rows, 1);
    EXPECT_EQ(t->columns, 2);
    // halves.asc: 2 cells of 10 m from (0, 0): x 0-10 is curve 0, x 10-20 curve 1.
    EXPECT_EQ(t->curve_at(5, 5), 0);
    EXPECT_EQ(t->curve_at(15, 5), 1);
    EXPECT_EQ(t->curve_at(15, 15), -1);
    m.texture = t;
    EXPECT_EQ(m.curve_at(15, 5, 0), 1);
    EXPECT_EQ(m.curve_at(15, 15, 0), 0);  // outside the map: the facet's own curve
}

TEST(Texture, ACellThatIsNotACurveNumberNamesTheMatLine) {
    MaterialOptics m = grey_material(1, 0.3, 3);  // one curve only
    m.mat_file = "textured.mat";
    m.line = 7;
    try {
        read_texture_map(kData + "halves.asc", m);
        FAIL() << "expected a DataError";
    } catch (const DataError& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("textured.mat:7:"), std::string::npos) << what;
        EXPECT_NE(what.find("column 1) holds 1"), std::string::npos) << what;
    }
    EXPECT_THROW(read_texture_map(kData + "no_such.asc", m), DataError);
}

}  // namespace
}  // namespace sigchain::radiometry
