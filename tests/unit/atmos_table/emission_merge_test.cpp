// Layer merging (RadianceOptions::merge_tau) in the layer emission solve: a merged slab
// carries Planck linear in optical depth between its end levels, so thin layers merge
// only where the temperature profile keeps Planck on that line. Checked against the
// same tables with every profile layer kept (merge_tau 0), an independent layering of
// the same column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../record_property.hpp"
#include "atmos_table/build_radiance.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

const std::string kSource = SIGCHAIN_SOURCE_DIR;

// The demo's thermal band (8-12.5 um, 10 samples) under the Hawkeye deck of White
// (1996); nadir, the sky in 15-deg rings, 8 streams.
io::Rad solve(double merge_tau) {
    const io::Cdk deck = io::read_cdk_file(kSource + "/tests/golden/control7/hawkeye.cdk");
    io::Snd snd = io::read_snd_file(kSource + "/data/demo/lwir.snd");
    snd.view_min_deg = snd.view_max_deg = 0;
    snd.view_increment_deg = 1;
    RadianceOptions o;
    o.data_dir = kSource + "/data";
    o.streams = 8;
    o.merge_tau = merge_tau;
    o.sky_zenith_step_deg = 15;
    o.sky_azimuth_step_deg = 360;
    o.sky_subsamples = 1;
    o.upwelled_azimuth_step_deg = 360;
    o.threads = 2;
    return build_radiance(deck, snd, o).front();
}

// Largest |a - b| / max(|b|, 1e-3 max |b|) over one table (as --streams auto compares).
double difference(const std::vector<double>& a, const std::vector<double>& b) {
    double largest = 0, worst = 0;
    for (double v : b) largest = std::max(largest, std::abs(v));
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), 1e-3 * largest));
    return worst;
}

// The sky's emission at the default merge_tau (0.01) against every layer kept: within
// 1e-3 (measured 3.6e-6 here, 3.6e-4 over the demo's full tables). Before merging
// heeded Planck, the upper atmosphere's thin layers became one slab and the sky's
// emission near the zenith moved by 0.8 % in the window (7.9e-3 here), beyond this.
TEST(EmissionMerge, SkyEmissionMatchesEveryLayerKept) {
    const io::Rad merged = solve(0.01), all = solve(0);
    ASSERT_TRUE(merged.sky && all.sky);
    ASSERT_EQ(merged.sky->cells.size(), all.sky->cells.size());
    double worst = 0;
    for (std::size_t c = 0; c < all.sky->cells.size(); ++c)
        worst = std::max(worst, difference(merged.sky->cells[c].emitted_radiance,
                                           all.sky->cells[c].emitted_radiance));
    std::printf("sky emission, merged against every layer kept: %.2g\n", worst);
    EXPECT_LT(worst, 1e-3);
    unit::record("sky_relative_difference", worst);
    unit::record("limit", 1e-3);
    EXPECT_GT(worst, 0);  // merged indeed: a different layering
    // The path's emission (sensor 30 m above the ground, its level always kept).
    std::vector<double> a, b;
    for (const auto& p : merged.views.front().path) a.push_back(p.emitted_radiance);
    for (const auto& p : all.views.front().path) b.push_back(p.emitted_radiance);
    EXPECT_LT(difference(a, b), 1e-3);
}

}  // namespace
}  // namespace sigchain::atmos_table
