// Tests of lib/scenegen: ring cleaning, ear-clipping triangulation, extrusion, height rule.
#include "scenegen/extrude.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/gdb.hpp"

namespace sg = sigchain::scenegen;
using sigchain::geo::Vec3;

namespace {

// Tolerances: footprints of tens of metres; areas are sums of a few products of
// coordinates, exact to ~1e-13 relative in double, so 1e-9 m^2 cannot hide a missing or
// overlapping triangle (the smallest triangle in these tests has an area of 50 m^2).
constexpr double kAreaTolM2 = 1e-9;

double triangle_area(const sg::Ring& r, const std::array<int, 3>& t) {
    const auto &a = r[t[0]], &b = r[t[1]], &c = r[t[2]];
    return ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Newell's normal of the facet's vertices (direction from their order).
Vec3 newell(const std::vector<Vec3>& v) {
    Vec3 n{0, 0, 0};
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto &p = v[i], &q = v[(i + 1) % v.size()];
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    return n;
}

// Even-odd point-in-polygon test (ray crossing), independent of the triangulation.
bool inside(const sg::Ring& r, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i][1] > y) != (r[j][1] > y) &&
            x < (r[j][0] - r[i][0]) * (y - r[i][1]) / (r[j][1] - r[i][1]) + r[i][0])
            in = !in;
    return in;
}

// Every triangle counter-clockwise with positive area, its centroid inside the
// polygon, and the areas summing to the polygon's (shoelace) area.
void expect_valid_triangulation(const sg::Ring& ring, double expected_area) {
    const auto tris = sg::triangulate(ring);
    ASSERT_EQ(tris.size(), ring.size() - 2);
    double sum = 0;
    for (const auto& t : tris) {
        const double a = triangle_area(ring, t);
        EXPECT_GT(a, 0);
        const double cx = (ring[t[0]][0] + ring[t[1]][0] + ring[t[2]][0]) / 3;
        const double cy = (ring[t[0]][1] + ring[t[1]][1] + ring[t[2]][1]) / 3;
        EXPECT_TRUE(inside(ring, cx, cy)) << "triangle centroid " << cx << ", " << cy;
        sum += a;
    }
    EXPECT_NEAR(sum, expected_area, kAreaTolM2);
}

}  // namespace

TEST(ScenegenRing, CleanDropsClosingDuplicateAndCollinearVerticesAndMakesCounterClockwise) {
    // A 10 x 10 m square, clockwise, closed, with a repeated vertex and an edge midpoint.
    const sg::Ring input{{0, 0}, {0, 10}, {0, 10}, {10, 10}, {10, 5}, {10, 0}, {0, 0}};
    const sg::Ring ring = sg::clean_ring(input);
    ASSERT_EQ(ring.size(), 4u);
    EXPECT_NEAR(sg::signed_area(ring), 100.0, kAreaTolM2);
}

TEST(ScenegenRing, DegenerateRingsComeBackEmpty) {
    EXPECT_TRUE(sg::clean_ring({{0, 0}, {1, 1}, {2, 2}}).empty());  // collinear
    EXPECT_TRUE(sg::clean_ring({{0, 0}, {1, 0}}).empty());
    EXPECT_TRUE(sg::clean_ring({{3, 3}, {3, 3}, {3, 3}, {3, 3}}).empty());
}

TEST(ScenegenTriangulate, LShapedConcaveFootprintAreasSumToPolygonArea) {
    // L: 20 x 10 m foot plus a 10 x 20 m leg: 200 + 200 = 400 m^2; reflex vertex (10, 10).
    const sg::Ring ring{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 30}, {0, 30}};
    expect_valid_triangulation(ring, 400.0);
}

TEST(ScenegenTriangulate, CombShapedFootprintWithSeveralReflexVertices) {
    // A comb: 30 x 10 m base with three 6 x 15 m teeth (gaps of 6 m): 300 + 3 * 90 m^2.
    const sg::Ring ring{{0, 0},   {30, 0},  {30, 25}, {24, 25}, {24, 10}, {18, 10},
                        {18, 25}, {12, 25}, {12, 10}, {6, 10},  {6, 25},  {0, 25}};
    ASSERT_GT(sg::signed_area(ring), 0);
    expect_valid_triangulation(ring, 570.0);
}

TEST(ScenegenExtrude, SquareGivesFourOutwardWallsAndARoofOfTheFootprintArea) {
    const sg::Ring ring = sg::clean_ring({{5, 5}, {15, 5}, {15, 15}, {5, 15}});
    const double h = 12.8;
    const auto object = sg::extrude(ring, h, 2, "box");
    ASSERT_EQ(object.parts.size(), 2u);
    const auto& roof = object.parts[0].facets;
    const auto& walls = object.parts[1].facets;
    ASSERT_EQ(walls.size(), 4u);
    double roof_area = 0;
    for (const auto& f : roof) {
        roof_area += sg::facet_area(f);
        EXPECT_EQ(f.normal, (Vec3{0, 0, 1}));
        EXPECT_GT(dot(newell(f.vertices), f.normal), 0);  // counter-clockwise from above
        for (const auto& v : f.vertices) EXPECT_EQ(v[2], h);
        EXPECT_EQ(f.material_name, "roof");
    }
    EXPECT_NEAR(roof_area, 100.0, kAreaTolM2);
    for (const auto& f : walls) {
        EXPECT_NEAR(sg::facet_area(f), 10 * h, kAreaTolM2);
        EXPECT_EQ(f.normal[2], 0);
        EXPECT_NEAR(std::hypot(f.normal[0], f.normal[1]), 1.0, 1e-15);
        // Outward: from the footprint's centre (10, 10) to the wall's centre.
        Vec3 c{0, 0, 0};
        for (const auto& v : f.vertices)
            for (int k = 0; k < 3; ++k) c[k] += v[k] / 4;
        EXPECT_GT(dot(f.normal, {c[0] - 10, c[1] - 10, 0}), 4.99);  // 5 m to each wall
        EXPECT_GT(dot(newell(f.vertices), f.normal), 0);  // counter-clockwise from outside
        EXPECT_NEAR(f.slope_zenith_deg, 90.0, 1e-12);
        EXPECT_EQ(f.material_name, "brick");
    }
    // The .gdb reader's own geometry checks (planarity, normal vs vertices) find nothing.
    sigchain::io::Gdb gdb;
    gdb.file = "box.gdb";
    gdb.objects.push_back(object);
    EXPECT_TRUE(sigchain::io::gdb_problems(gdb).empty());
}

TEST(ScenegenExtrude, LShapeWallsCoverThePerimeterAndFaceOutward) {
    const sg::Ring ring{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 30}, {0, 30}};
    const double h = 9.6;
    const auto object = sg::extrude(ring, h, 3, "L");
    const auto& walls = object.parts[1].facets;
    ASSERT_EQ(walls.size(), 6u);
    double wall_area = 0;
    for (const auto& f : walls) {
        wall_area += sg::facet_area(f);
        // A point 1 cm outside the wall's centre is outside the footprint.
        double cx = 0, cy = 0;
        for (const auto& v : f.vertices) cx += v[0] / 4, cy += v[1] / 4;
        EXPECT_FALSE(inside(ring, cx + 0.01 * f.normal[0], cy + 0.01 * f.normal[1]));
        EXPECT_TRUE(inside(ring, cx - 0.01 * f.normal[0], cy - 0.01 * f.normal[1]));
    }
    EXPECT_NEAR(wall_area, 100.0 * h, kAreaTolM2);  // perimeter 100 m
    double roof_area = 0;
    for (const auto& f : object.parts[0].facets) roof_area += sg::facet_area(f);
    EXPECT_NEAR(roof_area, 400.0, kAreaTolM2);
}

TEST(ScenegenExtrude, SlopeAzimuthIsTheWallNormalsCompassDirection) {
    const auto object = sg::extrude({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 5, 2, "box");
    std::map<long, int> seen;  // rounded compass azimuth -> count
    for (const auto& f : object.parts[1].facets) ++seen[std::lround(f.slope_azimuth_deg)];
    // South wall 180, east 90, north 0, west -90 (clockwise from north, atan2 range).
    EXPECT_EQ(seen, (std::map<long, int>{{-90, 1}, {0, 1}, {90, 1}, {180, 1}}));
}

TEST(ScenegenHeight, StoreyRuleIsSeededDeterministicAndCoversThreeToSeven) {
    std::map<int, int> counts;
    int changed = 0;
    for (std::int64_t id = 1; id <= 1000; ++id) {
        const int s = sg::storeys(id, 7);
        EXPECT_EQ(s, sg::storeys(id, 7));
        ++counts[s];
        changed += s != sg::storeys(id, 8);
        EXPECT_DOUBLE_EQ(sg::building_height_m(id, 7), s * 3.2);
    }
    ASSERT_EQ(counts.size(), 5u);
    EXPECT_EQ(counts.begin()->first, 3);
    EXPECT_EQ(counts.rbegin()->first, 7);
    // Uniform over 5 values: 200 each, binomial sd sqrt(1000 * 0.2 * 0.8) = 12.6; 60 is
    // 4.7 sd. Another seed changes about 4/5 of the buildings.
    for (const auto& [s, n] : counts) EXPECT_NEAR(n, 200, 60) << s << " storeys";
    EXPECT_NEAR(changed, 800, 70);
}

TEST(ScenegenGround, PlaneIsOneUpwardQuadOfTheGivenArea) {
    const auto g = sg::ground_plane(-10, -20, 30, 40, 1, 1, "asphalt");
    ASSERT_EQ(g.parts.size(), 1u);
    ASSERT_EQ(g.parts[0].facets.size(), 1u);
    const auto& f = g.parts[0].facets[0];
    EXPECT_NEAR(sg::facet_area(f), 40.0 * 60.0, kAreaTolM2);
    EXPECT_GT(dot(newell(f.vertices), f.normal), 0);
    EXPECT_EQ(f.normal, (Vec3{0, 0, 1}));
}
