// Tests for the GLT of lib/imaging/ground_layers: every cell names the pixel whose ground
// point is nearest its centre (checked by brute force), within reach, and none beyond.
#include "imaging/ground_layers.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

using namespace sigchain;

namespace {

// A 30 x 20 image whose ground points lie on a sheared, wavy grid: column spacing 1.0,
// row spacing 2.0 (rows run south), with a sideways wobble like a jittering platform.
imaging::GroundGrid wavy_grid() {
    imaging::GroundGrid g;
    g.rows = 30;
    g.columns = 20;
    for (long r = 0; r < g.rows; ++r)
        for (long c = 0; c < g.columns; ++c) {
            const double x = c + 0.4 * std::sin(0.7 * r) + 0.1 * r, y = -2.0 * r;
            g.scene.push_back({x, y, 0});
            g.map_xy.push_back({x, y});
        }
    g.map_xy[5] = {NAN, NAN};  // a pixel that sees no ground
    return g;
}

}  // namespace

TEST(GroundLayers, GltIsTheNearestPixelWithinReach) {
    const imaging::GroundGrid g = wavy_grid();
    const imaging::Glt t = imaging::make_glt(g, "t.tif");
    // sqrt(1 x 2) from the median spacings; the sideways shift between rows (0.1 plus
    // the wobble's change) lengthens the row spacing of 2 by under 1 %.
    EXPECT_NEAR(t.cell, std::sqrt(2.0), 0.01 * std::sqrt(2.0));
    EXPECT_NEAR(t.reach, 2.0, 0.02);
    long filled = 0;
    for (long cy = 0; cy < t.rows; ++cy)
        for (long cx = 0; cx < t.columns; ++cx) {
            const double x = t.x0 + (cx + 0.5) * t.cell, y = t.y0 - (cy + 0.5) * t.cell;
            double best = t.reach * t.reach;
            long want = -1;
            for (std::size_t i = 0; i < g.map_xy.size(); ++i) {
                if (!std::isfinite(g.map_xy[i][0])) continue;
                const double d2 = std::pow(g.map_xy[i][0] - x, 2) + std::pow(g.map_xy[i][1] - y, 2);
                if (d2 < best) best = d2, want = static_cast<long>(i);
            }
            const std::size_t o = static_cast<std::size_t>(cy * t.columns + cx);
            if (want < 0) {
                EXPECT_EQ(t.column[o], 0) << cx << "," << cy;
                continue;
            }
            ++filled;
            EXPECT_EQ(t.column[o], want % g.columns + 1) << cx << "," << cy;
            EXPECT_EQ(t.row[o], want / g.columns + 1) << cx << "," << cy;
        }
    EXPECT_GT(filled, 300);  // the 600-pixel footprint covers ~420 cells of 2 m^2
}

TEST(GroundLayers, NoGroundIsAnError) {
    imaging::GroundGrid g;
    g.rows = 2;
    g.columns = 2;
    g.map_xy.assign(4, {NAN, NAN});
    EXPECT_THROW(imaging::make_glt(g, "t.tif"), DataError);
}
