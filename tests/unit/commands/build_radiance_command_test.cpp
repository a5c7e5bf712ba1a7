// build_radiance's command line to its Job (lib/commands/build_radiance_command): the
// solver's defaults as the command line gives them, each option's way into the Job, the
// usage errors, without a process.
#include "commands/build_radiance_command.hpp"

#include <gtest/gtest.h>

#include "command_line.hpp"

namespace sigchain::commands {
namespace {

using testing::parse_line;
using testing::usage_error_of;

atmos_table::BuildRadianceJob job_of(const std::vector<std::string>& args) {
    return build_radiance_job(parse_line(build_radiance_info(), add_build_radiance_options, args));
}

std::string usage_error(const std::vector<std::string>& args) {
    return usage_error_of([&] { job_of(args); });
}

TEST(BuildRadianceCommand, DefaultsAreTheSolversOwn) {
    const auto job = job_of({"d.cdk", "s.snd", "-o", "band-%d.rad"});
    EXPECT_EQ(job.cdk_path, "d.cdk");
    EXPECT_EQ(job.snd_path, "s.snd");
    EXPECT_EQ(job.output_pattern, "band-%d.rad");
    EXPECT_TRUE(job.data_dir.empty() && job.write_decks_dir.empty() && job.from_tape7.empty());
    const atmos_table::RadianceOptions defaults;
    const auto& o = job.options;
    EXPECT_EQ(o.streams, defaults.streams);
    EXPECT_DOUBLE_EQ(o.stream_tolerance, defaults.stream_tolerance);
    EXPECT_DOUBLE_EQ(o.sky_zenith_step_deg, defaults.sky_zenith_step_deg);
    EXPECT_DOUBLE_EQ(o.sky_azimuth_step_deg, defaults.sky_azimuth_step_deg);
    EXPECT_EQ(o.sky_subsamples, defaults.sky_subsamples);
    EXPECT_DOUBLE_EQ(o.upwelled_azimuth_step_deg, defaults.upwelled_azimuth_step_deg);
    EXPECT_DOUBLE_EQ(o.top_km, defaults.top_km);
    EXPECT_DOUBLE_EQ(o.thermal_min_wavelength_um, defaults.thermal_min_wavelength_um);
    EXPECT_FALSE(o.view_azimuth_deg || o.merge_tau);
    EXPECT_EQ(o.threads, 0u);
}

TEST(BuildRadianceCommand, EachOptionReachesTheJob) {
    const auto job = job_of({"d.cdk",
                             "-",
                             "-o",
                             "b%d.rad",
                             "--streams",
                             "auto",
                             "--stream-tolerance",
                             "0.02",
                             "--sky-zenith-step",
                             "10",
                             "--sky-azimuth-step",
                             "30",
                             "--sky-subsamples",
                             "3",
                             "--upwelled-azimuth-step",
                             "45",
                             "--view-azimuth",
                             "-90",
                             "--top",
                             "80",
                             "--merge-tau",
                             "0",
                             "--thermal-from",
                             "3",
                             "--threads",
                             "2",
                             "--data-dir",
                             "data",
                             "--from-tape7",
                             "runs.t7m"});
    const auto& o = job.options;
    EXPECT_EQ(o.streams, atmos_table::kAutoStreams);
    EXPECT_DOUBLE_EQ(o.stream_tolerance, 0.02);
    EXPECT_DOUBLE_EQ(o.sky_zenith_step_deg, 10);
    EXPECT_DOUBLE_EQ(o.sky_azimuth_step_deg, 30);
    EXPECT_EQ(o.sky_subsamples, 3);
    EXPECT_DOUBLE_EQ(o.upwelled_azimuth_step_deg, 45);
    EXPECT_DOUBLE_EQ(*o.view_azimuth_deg, -90);
    EXPECT_DOUBLE_EQ(o.top_km, 80);
    EXPECT_DOUBLE_EQ(*o.merge_tau, 0);
    EXPECT_DOUBLE_EQ(o.thermal_min_wavelength_um, 3);
    EXPECT_EQ(o.threads, 2u);
    EXPECT_EQ(job.data_dir, "data");
    EXPECT_EQ(job.from_tape7, "runs.t7m");
    EXPECT_EQ(job_of({"d.cdk", "s.snd", "-o", "b%d.rad", "--streams", "8"}).options.streams, 8);
}

TEST(BuildRadianceCommand, WriteDecksNeedsNoOutput) {
    const auto job = job_of({"d.cdk", "s.snd", "--write-decks", "decks"});
    EXPECT_EQ(job.write_decks_dir, "decks");
    EXPECT_TRUE(job.output_pattern.empty());
}

TEST(BuildRadianceCommand, UsageErrors) {
    EXPECT_EQ(usage_error({"d.cdk", "-o", "b%d.rad"}), "expected two inputs: CDK SND");
    EXPECT_EQ(usage_error({"d.cdk", "s.snd"}), "-o FILE is required");
    EXPECT_EQ(usage_error({"d.cdk", "s.snd", "-o", "b%d.rad", "--streams", "many"}).substr(0, 25),
              "--streams: many: must be ");
}

}  // namespace
}  // namespace sigchain::commands
