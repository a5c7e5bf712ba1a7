// render_streamed(): rows handed on in order through a ring of any size are the rows of
// render()'s whole image, bit for bit, truth layers included, with any thread count;
// the sink's exception ends the render.
#include "trace/render_stream.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "test_scene.hpp"

namespace sigchain::trace {
namespace {

const std::vector<double> kWl{0.5, 0.6, 0.7};
using test::Mesh;
using test::Ortho;
using test::single;

// A plate with two boxes (one glossy), sun and sky: rows of uneven cost.
scene::Scene busy_scene() {
    Mesh m;
    m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    m.box({-3, -2, 0}, {-1, 2, 3}, 2);
    m.box({1, -1, 0}, {3, 1, 1.5}, 1);
    return single(m.data);
}

struct Inputs {
    scene::Scene scene = busy_scene();
    radiometry::MaterialLibrary materials = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.3, kWl.size()),
         radiometry::grey_material(2, 0.5, kWl.size(), 0.4, radiometry::Brdf::phong(20))});
    radiometry::Atmosphere atmosphere = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 40, 120, 0.2, 0.004, 0.9, 0.001)}, {"u.rad"});
    Ortho camera{13, 12, 0.7, -4, 4, {0.2, 0.1, -1}};
    RenderInputs in() const {
        RenderInputs r = test::inputs(&scene, &materials, &atmosphere, &camera);
        return r;
    }
};

// Copies rows [slot, slot + count) of every channel of `ring` to rows [first, ...) of
// `whole` (an image of the render's rows).
void put_rows(const image::Image& ring, long slot, long first, long count, image::Image& whole) {
    for (int c = 0; c < ring.channels; ++c)
        std::memcpy(&whole.at(c, first, 0),
                    ring.data.data() + (static_cast<std::size_t>(c) * ring.rows + slot) * ring.columns,
                    sizeof(float) * static_cast<std::size_t>(count * ring.columns));
}

}  // namespace

TEST(RenderStreamed, RowsThroughARingOfAnySizeAreTheWholeImage) {
    const Inputs inputs;
    RenderOptions o;
    o.sampling = Sampling::MonteCarlo;
    o.samples_per_pixel = 3;
    o.hemisphere_samples = 8;
    o.truth = true;
    o.sampling_layers = true;
    o.row_begin = 1;  // a slice: rows 1 to 11 of 13
    o.row_end = 12;
    const RenderResult whole = render(inputs.in(), o);
    const long rows = whole.radiance.rows;
    ASSERT_EQ(rows, 11);
    for (unsigned threads : {1u, 2u, 3u})
        for (long ring : {1L, 3L, 4L, 11L, 50L}) {
            o.threads = threads;
            image::Image radiance(rows, whole.radiance.columns, whole.radiance.channels, -7.0f);
            image::Image truth(rows, whole.truth.columns, whole.truth.channels, -7.0f);
            long next = 0;
            const RenderResult streamed = render_streamed(
                inputs.in(), o, ring, [&](const RenderedRows& r) {
                    EXPECT_EQ(r.first, next);  // in order, each row once
                    EXPECT_EQ(r.slot, r.first % std::min(ring, rows));
                    put_rows(r.radiance, r.slot, r.first, r.count, radiance);
                    put_rows(r.truth, r.slot, r.first, r.count, truth);
                    next += r.count;
                });
            EXPECT_EQ(next, rows);
            EXPECT_EQ(streamed.radiance.rows, std::min(ring, rows));
            EXPECT_EQ(radiance.data, whole.radiance.data) << threads << " threads, ring " << ring;
            EXPECT_EQ(truth.data, whole.truth.data) << threads << " threads, ring " << ring;
            EXPECT_EQ(streamed.stats.primary_rays, whole.stats.primary_rays);
            EXPECT_EQ(streamed.stats.hits, whole.stats.hits);
        }
}

TEST(RenderStreamed, TheSinksExceptionEndsTheRender) {
    const Inputs inputs;
    RenderOptions o;
    o.sampling = Sampling::Golfball;
    for (unsigned threads : {1u, 2u}) {
        o.threads = threads;
        long calls = 0;
        EXPECT_THROW(render_streamed(inputs.in(), o, 2,
                                     [&](const RenderedRows&) {
                                         ++calls;
                                         throw std::runtime_error("full disk");
                                     }),
                     std::runtime_error);
        EXPECT_EQ(calls, 1);
    }
}

}  // namespace sigchain::trace
