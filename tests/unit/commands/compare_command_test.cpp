// compare's command line to its Job (lib/commands/compare_command): the defaults, each
// option's way into the Job, the usage errors (the count of inputs, --bands, an output
// that is an input), without a process.
#include "commands/compare_command.hpp"

#include <gtest/gtest.h>

#include "command_line.hpp"

namespace sigchain::commands {
namespace {

using testing::parse_line;
using testing::usage_error_of;

compare::CompareJob job_of(const std::vector<std::string>& args) {
    return compare_job(parse_line(compare_info(), add_compare_options, args));
}

std::string usage_error(const std::vector<std::string>& args) {
    return usage_error_of([&] { job_of(args); });
}

TEST(CompareCommand, ControlPointsAndDefaults) {
    const auto job = job_of({"syn.tif", "ref.tif", "p.cpt"});
    EXPECT_EQ(job.synthetic_path, "syn.tif");
    EXPECT_EQ(job.reference_path, "ref.tif");
    EXPECT_EQ(job.cpt_path, "p.cpt");
    EXPECT_FALSE(job.pixelwise || job.json);
    EXPECT_EQ(job.histogram_bins, 16);
    EXPECT_TRUE(job.band_map.empty() && job.plot_dir.empty() && job.error_map_path.empty());
    EXPECT_FALSE(job.fail_rms || job.fail_roc || job.fail_max);
}

TEST(CompareCommand, EachOptionReachesTheJob) {
    const auto job =
        job_of({"a.tif",      "b.tif",  "--pixelwise", "--bands",     "3,2,1", "--bins",     "8",
                "--json",     "--plot", "plots",       "--error-map", "e.tif", "--fail-rms", "2.5",
                "--fail-roc", "0.9",    "--fail-max",  "7",           "-o",    "r.txt"});
    EXPECT_TRUE(job.pixelwise && job.json);
    EXPECT_TRUE(job.cpt_path.empty());
    EXPECT_EQ(job.band_map, (compare::BandMap{3, 2, 1}));
    EXPECT_EQ(job.histogram_bins, 8);
    EXPECT_EQ(job.plot_dir, "plots");
    EXPECT_EQ(job.error_map_path, "e.tif");
    EXPECT_DOUBLE_EQ(*job.fail_rms, 2.5);
    EXPECT_DOUBLE_EQ(*job.fail_roc, 0.9);
    EXPECT_DOUBLE_EQ(*job.fail_max, 7);
}

TEST(CompareCommand, UsageErrors) {
    EXPECT_EQ(usage_error({"a.tif", "b.tif"}), "expected SYNTHETIC REFERENCE CPT");
    EXPECT_EQ(usage_error({"a.tif", "b.tif", "c.cpt", "--pixelwise"}),
              "expected two images with --pixelwise");
    EXPECT_EQ(usage_error({"a.tif", "b.tif", "c.cpt", "--bands", "0"}),
              "--bands: expected band numbers from 1, found '0'");
    EXPECT_EQ(usage_error({"a.tif", "b.tif", "--pixelwise", "--error-map", "b.tif"}),
              "b.tif: is also the input b.tif (refusing to overwrite an input)");
    EXPECT_EQ(usage_error({"a.tif", "b.tif", "c.cpt", "--fail-roc", "2"}).substr(0, 14),
              "--fail-roc: 2:");
}

}  // namespace
}  // namespace sigchain::commands
