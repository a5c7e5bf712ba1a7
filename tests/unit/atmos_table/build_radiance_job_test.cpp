// build_radiance's job (lib/atmos_table/build_radiance_job): usage checks, band output names,
// and one small run written through run() against build_radiance() itself.
#include "atmos_table/build_radiance_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

BuildRadianceJob quick_job() {
    BuildRadianceJob job;
    job.cdk_path = SIGCHAIN_SOURCE_DIR "/tests/data/build_radiance/rural23.cdk";
    job.snd_path = SIGCHAIN_SOURCE_DIR "/tests/data/build_radiance/small.snd";
    job.data_dir = SIGCHAIN_SOURCE_DIR "/data";
    job.options.streams = 8;
    job.options.sky_zenith_step_deg = 15;
    job.options.sky_azimuth_step_deg = 30;
    job.options.sky_subsamples = 1;
    return job;
}

TEST(BuildRadianceJob, UsageErrorsBeforeAnyWork) {
    BuildRadianceJob job = quick_job();
    EXPECT_NO_THROW(check_job(job));
    job.cdk_path.assign(1, '-');  // (GCC 12 warns, wrongly, on = "-" here)
    job.snd_path.assign(1, '-');
    EXPECT_THROW(check_job(job), UsageError);
    job = quick_job();
    job.options.top_km = 0;
    EXPECT_THROW(check_job(job), UsageError);
    job = quick_job();
    job.options.merge_tau = 1.5;
    EXPECT_THROW(check_job(job), UsageError);
    job = quick_job();
    job.options.streams = 5;
    EXPECT_THROW(check_job(job), UsageError);
}

TEST(BuildRadianceJob, BandOutputPaths) {
    io::Snd snd;
    snd.bands.resize(2);
    EXPECT_EQ(band_output_paths("b-%d.rad", snd), (std::vector<std::string>{"b-1.rad", "b-2.rad"}));
    EXPECT_THROW(band_output_paths("-", snd), UsageError);
    snd.bands.resize(1);
    EXPECT_EQ(band_output_paths("-", snd), std::vector<std::string>{"-"});
}

TEST(BuildRadianceJob, WritesWhatBuildRadianceComputes) {
    BuildRadianceJob job = quick_job();
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("build_radiance_job." + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    job.output_pattern = (dir / "t-%d.rad").string();
    run(job, Reporter{});

    RadianceOptions o = job.options;
    o.data_dir = job.data_dir;
    const auto rads =
        build_radiance(io::read_cdk_file(job.cdk_path), io::read_snd_file(job.snd_path), o);
    ASSERT_EQ(rads.size(), 2u);
    for (std::size_t b = 0; b < rads.size(); ++b) {
        std::ostringstream expected;
        io::write_rad(expected, rads[b]);
        std::ifstream in(dir / ("t-" + std::to_string(b + 1) + ".rad"));
        std::ostringstream got;
        got << in.rdbuf();
        EXPECT_EQ(got.str(), expected.str()) << "band " << b + 1;
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sigchain::atmos_table
