// build_radiance --streams auto (stream_choice.hpp): the tables it gives against the
// solver at 32 streams, the independent reference of the discrete-ordinate error (the
// solver itself is checked against DISORT's test problems in tests/unit/rt), and the
// streams it picks for a clear and a hazy sky.
#include "atmos_table/stream_choice.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "../record_property.hpp"
#include "atmos_table/build_radiance.hpp"
#include "core/error.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

const std::string kSource = SIGCHAIN_SOURCE_DIR;

io::Cdk hawkeye_deck() { return io::read_cdk_file(kSource + "/tests/golden/control7/hawkeye.cdk"); }
io::Snd small_snd() { return io::read_snd_file(kSource + "/tests/data/build_radiance/small.snd"); }

// A coarse sky (15 x 30 deg cells, one direction each) keeps the 32-stream reference
// quick; every cell is still compared.
RadianceOptions options(int streams) {
    RadianceOptions o;
    o.data_dir = kSource + "/data";
    o.streams = streams;
    o.sky_zenith_step_deg = 15;
    o.sky_azimuth_step_deg = 30;
    o.sky_subsamples = 1;
    o.upwelled_azimuth_step_deg = 30;
    return o;
}

// One line of sight (nadir) and one sky cell (the hemisphere's mean): the single-view
// case of bench_build_radiance, where the streams follow the scattering alone.
RadianceOptions one_cell(int streams) {
    RadianceOptions o = options(streams);
    o.sky_zenith_step_deg = 90;
    o.sky_azimuth_step_deg = 360;
    o.upwelled_azimuth_step_deg = 360;
    return o;
}

io::Snd nadir(io::Snd snd) {
    snd.view_min_deg = snd.view_max_deg = 0;
    snd.view_increment_deg = 1;
    return snd;
}

// The largest relative difference (table_difference's measure) of every sample of
// every band of `a` from `b`, the tables rebuilt as SampleResults.
double largest_difference(const std::vector<io::Rad>& a, const std::vector<io::Rad>& b) {
    auto sample = [](const io::Rad& r, std::size_t s) {
        SampleResult out;
        for (const auto& v : r.views) out.path.push_back(v.path[s]);
        for (const auto& c : r.sky->cells) {
            out.ls.push_back(c.scattered_radiance[s]);
            out.le.push_back(c.emitted_radiance[s]);
        }
        for (const auto& c : r.sky->upwelled->cells) {
            out.us.push_back(c.scattered_radiance[s]);
            out.ue.push_back(c.emitted_radiance[s]);
        }
        if (r.sky->coupling) {
            out.spherical_albedo = r.sky->coupling->spherical_albedo[s];
            out.diffuse_down = r.sky->coupling->diffuse_down[s];
            for (const auto& up : r.sky->coupling->diffuse_up) out.diffuse_up.push_back(up[s]);
        }
        return out;
    };
    double worst = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        for (std::size_t s = 0; s < a[k].samples.size(); ++s)
            worst = std::max(worst, table_difference(sample(a[k], s), sample(b[k], s)));
    return worst;
}

struct AutoAgainst32 {
    RadianceReport report;
    double difference = 0;  // auto's tables from 32 streams'
};

// Records (scripts/accuracy) the difference from 32 streams, the tolerance asked and the
// streams chosen in each band, the keys prefixed with `prefix`.
void record(const std::string& prefix, const AutoAgainst32& r, double tolerance) {
    unit::record(prefix + "difference", r.difference);
    unit::record(prefix + "tolerance", tolerance);
    for (std::size_t b = 0; b < r.report.band_streams.size(); ++b)
        unit::record(prefix + "streams_band" + std::to_string(b + 1),
                     r.report.band_streams[b].streams);
}

AutoAgainst32 auto_against_32(const io::Cdk& deck, const io::Snd& snd, double tolerance,
                              RadianceOptions (*make)(int) = options) {
    AutoAgainst32 out;
    RadianceOptions automatic = make(kAutoStreams);
    automatic.stream_tolerance = tolerance;
    const auto a = build_radiance(deck, snd, automatic, &out.report);
    const auto ref = build_radiance(deck, snd, make(32));
    out.difference = largest_difference(a, ref);
    return out;
}

TEST(StreamChoice, TableDifferenceIsRelativeWithATableFloor) {
    SampleResult a, b;
    b.ls = {1.0, 0.5, 1e-6};
    a.ls = {1.01, 0.5, 2e-6};  // +1 %; the faint cell's 1e-6 against the floor 1e-3
    EXPECT_NEAR(table_difference(a, b), 0.01, 1e-12);
    a.ls = {1.0, 0.45, 1e-6};
    EXPECT_NEAR(table_difference(a, b), 0.1, 1e-12);
    EXPECT_EQ(table_difference(b, b), 0.0);
}

// The training deck (White (1996)'s Hawkeye deck, urban aerosol, VIS 23 km, LOWTRAN 7's
// Mie phase functions) over the small scene node: auto's tables lie within the
// default tolerance (1 %) of the 32-stream solution in every entry the .rad holds.
// (At 0.5 % the sky near the sun asks more than 32 streams: 32 against 64 differ by
// 0.49 %, an estimated 0.97 %.)
TEST(StreamChoice, AutoIsWithinTheToleranceOf32StreamsOnTheTrainingDeck) {
    const double tolerance = 0.01;
    const AutoAgainst32 r = auto_against_32(hawkeye_deck(), small_snd(), tolerance);
    ASSERT_EQ(r.report.band_streams.size(), 2u);
    for (const auto& c : r.report.band_streams) {
        EXPECT_TRUE(c.within_tolerance);
        EXPECT_LT(c.streams, 32);
        EXPECT_LE(c.estimated_error, tolerance);
    }
    EXPECT_LE(r.difference, tolerance);
    record("", r, tolerance);
}

// A hazy deck (the same, VIS 2 km), one line of sight and one sky cell: within the
// tolerance of 32 streams. (More aerosol does not ask for more streams here: the
// hazy probes settle at 12, as the training deck's.)
TEST(StreamChoice, AHazyDeckIsWithinTheToleranceOf32Streams) {
    const double tolerance = 0.01;
    io::Cdk hazy = hawkeye_deck();
    hazy.runs.front().card2.visibility_km = 2;
    const AutoAgainst32 r = auto_against_32(hazy, nadir(small_snd()), tolerance, one_cell);
    ASSERT_EQ(r.report.band_streams.size(), 2u);
    for (const auto& c : r.report.band_streams) {
        EXPECT_TRUE(c.within_tolerance);
        EXPECT_LT(c.streams, 16);
    }
    EXPECT_LE(r.difference, tolerance);
    record("", r, tolerance);
}

// A clear nadir case (no aerosol, a near-infrared band: Rayleigh optical depth about
// 0.016 at 0.86 um), one sky cell: within the tolerance of 32 streams, and fewer
// streams for a looser tolerance. Not few streams: the thin column's diffuse field
// converges slowly with the order (0.59 % between 4 and 8 streams, 0.35 % between 12
// and 24), so 0.5 % asks 16 and 1 % asks 12.
TEST(StreamChoice, AClearNadirCaseIsWithinTheToleranceOf32Streams) {
    io::Cdk clear = hawkeye_deck();
    clear.runs.front().card2.ihaze = 0;
    io::Snd snd = nadir(small_snd());
    snd.bands = {{11600, 11700, 50}};
    const AutoAgainst32 strict = auto_against_32(clear, snd, 0.005, one_cell);
    ASSERT_EQ(strict.report.band_streams.size(), 1u);
    EXPECT_TRUE(strict.report.band_streams[0].within_tolerance);
    EXPECT_LE(strict.difference, 0.005);
    const AutoAgainst32 loose = auto_against_32(clear, snd, 0.01, one_cell);
    EXPECT_LT(loose.report.band_streams[0].streams, strict.report.band_streams[0].streams);
    EXPECT_LE(loose.difference, 0.01);
    record("strict_", strict, 0.005);
    record("loose_", loose, 0.01);
}

// A tolerance no candidate meets: the largest candidate, flagged (and -v says so).
TEST(StreamChoice, AnUnreachableToleranceGivesTheLargestCandidateFlagged) {
    io::Snd snd = nadir(small_snd());
    snd.bands = {{18000, 18000, 1}};
    RadianceOptions o = one_cell(kAutoStreams);
    o.stream_tolerance = 1e-9;
    RadianceReport report;
    (void)build_radiance(hawkeye_deck(), snd, o, &report);
    ASSERT_EQ(report.band_streams.size(), 1u);
    EXPECT_EQ(report.band_streams[0].streams, 32);
    EXPECT_EQ(report.band_streams[0].check_streams, 64);
    EXPECT_FALSE(report.band_streams[0].within_tolerance);
    EXPECT_GT(report.band_streams[0].estimated_error, 1e-9);
}

TEST(StreamChoice, ProbesAreTheCentreAndTheMostScatteringSample) {
    const io::Cdk deck = hawkeye_deck();
    const RadianceOptions o = options(16);
    const ColumnModel column(deck.runs.front(), 1.0, o);
    // Rayleigh and the aerosols scatter most at the largest wavenumber.
    const auto probes = probe_wavenumbers(column, {20000, 25000, 125});
    ASSERT_EQ(probes.size(), 2u);
    EXPECT_EQ(probes[0], 22500);
    EXPECT_EQ(probes[1], 25000);
    EXPECT_EQ(probe_wavenumbers(column, {18000, 18000, 1}).size(), 1u);
}

// The probes' scattering optical depth, formed without the gas absorption, is the same
// number as the sum over the full layers (bit for bit: the choice of probe must not
// change), at wavenumbers across the visible and the near infrared.
TEST(StreamChoice, ScatteringDepthEqualsTheLayersSum) {
    const io::Cdk deck = hawkeye_deck();
    const ColumnModel column(deck.runs.front(), 1.0, options(16));
    for (double nu : {10000.0, 14400.0, 18000.0, 22500.0, 25000.0}) {
        double tau = 0;
        for (const LayerOptics& l : column.layers(nu))
            tau += l.tau_rayleigh + l.tau_aerosol * l.ssa_aerosol;
        EXPECT_EQ(column.scattering_optical_depth(nu), tau) << nu;
        EXPECT_GT(tau, 0) << nu;
    }
}

TEST(StreamChoice, ToleranceOutOfRangeIsUsageError) {
    RadianceOptions o = options(kAutoStreams);
    EXPECT_NO_THROW(check_radiance_options(o));
    o.stream_tolerance = 0;
    EXPECT_THROW(check_radiance_options(o), UsageError);
    o.stream_tolerance = 1.5;
    EXPECT_THROW(check_radiance_options(o), UsageError);
}

}  // namespace
}  // namespace sigchain::atmos_table
