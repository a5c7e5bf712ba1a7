// sensorize's command line to its Job (lib/commands/sensorize_command): what only a
// process could check before, each option's way into the Job and each contradiction's
// usage error, without running anything.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "commands/sensorize_command.hpp"
#include "core/error.hpp"

namespace sigchain::commands {
namespace {

// The Job of `args` (after the tool's name), as sensorize would make it.
sensor_response::SensorizeJob job_of(std::vector<std::string> args) {
    cli::Cli tool(sensorize_info());
    add_sensorize_options(tool);
    args.insert(args.begin(), "sensorize");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    const auto vm = tool.parse(static_cast<int>(argv.size()), argv.data());
    const cli::Context ctx("sensorize", -1, false);  // quiet: the deprecation warning
    return sensorize_job(vm, ctx);
}

// The usage error's message for `args`, or "" when there is none.
std::string usage_error(std::vector<std::string> args) {
    try {
        job_of(std::move(args));
    } catch (const UsageError& e) {
        return e.what();
    } catch (const std::exception& e) {  // po::error: a malformed value or unknown option
        return std::string("po: ") + e.what();
    }
    return "";
}

TEST(SensorizeCommand, InputsOutputAndDefaults) {
    const auto job = job_of({"cube.img", "b1.sen", "b2.sen", "-o", "out.tif"});
    EXPECT_EQ(job.cube_path, "cube.img");
    EXPECT_EQ(job.sen_paths, (std::vector<std::string>{"b1.sen", "b2.sen"}));
    EXPECT_EQ(job.output_path, "out.tif");
    EXPECT_EQ(job.bits, 8);
    EXPECT_FALSE(job.float_output);
    EXPECT_EQ(job.noise.seed, 0u);  // sensorize's own default (sensorize(1))
    EXPECT_FALSE(job.mtf.enabled);
    EXPECT_FALSE(job.calibrate);
    EXPECT_TRUE(job.preview_path.empty());
}

TEST(SensorizeCommand, EachOptionReachesTheJob) {
    const auto job = job_of({"c.tif", "b.sen", "-o", "o.tif", "--bits", "12", "--float",
                             "--shot-noise", "40", "--read-noise", "1.5", "--seed", "7",
                             "--psf-sigma", "0.8", "--mtf-fnumber", "4", "--mtf-pitch", "9",
                             "--mtf-smear", "0.5,30", "--mtf-electronics", "2000,1e-4,3",
                             "--preview", "p.png", "--preview-stretch", "common", "--co",
                             "COMPRESS=DEFLATE"});
    EXPECT_EQ(job.bits, 12);
    EXPECT_TRUE(job.float_output);
    EXPECT_DOUBLE_EQ(job.noise.electrons_per_count, 40);
    EXPECT_DOUBLE_EQ(job.noise.read_noise_counts, 1.5);
    EXPECT_EQ(job.noise.seed, 7u);
    EXPECT_DOUBLE_EQ(job.psf_sigma_px, 0.8);
    EXPECT_TRUE(job.mtf.enabled);
    EXPECT_DOUBLE_EQ(job.mtf.f_number, 4);
    EXPECT_DOUBLE_EQ(job.mtf.pitch_um, 9);
    EXPECT_DOUBLE_EQ(job.mtf.smear_px, 0.5);
    EXPECT_DOUBLE_EQ(job.mtf.smear_angle_deg, 30);
    EXPECT_DOUBLE_EQ(job.mtf.electronics_cutoff_hz, 2000);
    EXPECT_DOUBLE_EQ(job.mtf.dwell_s, 1e-4);
    EXPECT_EQ(job.mtf.poles, 3);
    EXPECT_EQ(job.preview_path, "p.png");
    EXPECT_TRUE(job.preview_common);
    EXPECT_EQ(job.write_options.creation_options, (std::vector<std::string>{"COMPRESS=DEFLATE"}));
}

TEST(SensorizeCommand, TheDeprecatedSeedStillWorks) {
    EXPECT_EQ(job_of({"c.tif", "b.sen", "-o", "o.tif", "--noise-seed", "9"}).noise.seed, 9u);
}

TEST(SensorizeCommand, TheUncertaintyCubeAndItsDeprecatedName) {
    const std::vector<std::string> base{"c.tif", "b.sen", "-o", "o.tif", "--uncertainty-output",
                                        "u.tif"};
    auto with = [&](std::vector<std::string> more) {
        std::vector<std::string> args = base;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    EXPECT_EQ(job_of(with({"--uncertainty-cube", "t.img"})).uncertainty_path, "t.img");
    EXPECT_EQ(job_of(with({"--uncertainty", "old.img"})).uncertainty_path, "old.img");
    EXPECT_EQ(job_of(with({})).uncertainty_path, "");
    EXPECT_EQ(usage_error(with({"--uncertainty-cube", "t.img", "--uncertainty", "t.img"})),
              "give --uncertainty-cube or --uncertainty, not both");
}

TEST(SensorizeCommand, CalibrationNeedsItsCardsAndTargets) {
    const auto job = job_of({"c.tif", "b.sen", "-o", "dir", "--calibrate", "--card1", "0,0,2,2",
                             "--card2", "4,4,6,6", "--target1", "20", "--target2", "200,210"});
    EXPECT_TRUE(job.calibrate);
    EXPECT_EQ(job.calibration.target1, (std::vector<double>{20}));
    EXPECT_EQ(job.calibration.target2, (std::vector<double>{200, 210}));
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "d", "--calibrate", "--card1", "0,0,2,2"}),
              "--calibrate needs --card2");
}

TEST(SensorizeCommand, ContradictionsAreNamedUsageErrors) {
    EXPECT_EQ(usage_error({"c.tif"}), "expected a cube and at least one .sen file");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--preview-stretch", "common"}),
              "--preview-stretch needs --preview");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--preview", "p.png",
                           "--preview-stretch", "max"}),
              "--preview-stretch max: expected band or common");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--seed", "3", "--noise-seed", "4"}),
              "give --seed or --noise-seed, not both");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--mtf-electronics", "2000"}),
              "--mtf-electronics: expected HZ,SECONDS or HZ,SECONDS,POLES, found '2000'");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--mtf-electronics", "2000,1e-4,2.5"}),
              "--mtf-electronics: the number of poles must be 1 to 8");
    EXPECT_EQ(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--target1", "x", "--calibrate",
                           "--card1", "0,0,1,1", "--card2", "0,0,1,1", "--target2", "1"})
                  .substr(0, 10),
              "--target1:");
    // A value out of its range is refused when parsed (cli::Cli::add_number).
    EXPECT_NE(usage_error({"c.tif", "b.sen", "-o", "o.tif", "--bits", "20"}), "");
}

}  // namespace
}  // namespace sigchain::commands
