// landsat_sensor's command line to its Job (lib/commands/landsat_sensor_command): the
// defaults, each option's way into the Job and the usage errors, without a process.
#include "commands/landsat_sensor_command.hpp"

#include <gtest/gtest.h>

#include "command_line.hpp"

namespace sigchain::commands {
namespace {

using testing::parse_line;
using testing::usage_error_of;

sensor_response::LandsatJob job_of(const std::vector<std::string>& args) {
    return landsat_sensor_job(parse_line(landsat_sensor_info(), add_landsat_sensor_options, args));
}

std::string usage_error(const std::vector<std::string>& args) {
    return usage_error_of([&] { job_of(args); });
}

TEST(LandsatSensorCommand, Defaults) {
    const auto job = job_of({"L7_MTL.txt", "--rsr", "r.txt", "-o", "out"});
    EXPECT_EQ(job.mtl_path, "L7_MTL.txt");
    EXPECT_EQ(job.rsr_paths, (std::vector<std::string>{"r.txt"}));
    EXPECT_TRUE(job.data_dir.empty());  // the responses are given: no data directory
    EXPECT_EQ(job.out_dir, "out");
    EXPECT_DOUBLE_EQ(job.altitude_km, 705);
    EXPECT_DOUBLE_EQ(job.view_min_deg, -8);
    EXPECT_DOUBLE_EQ(job.view_max_deg, 8);
    EXPECT_DOUBLE_EQ(job.view_increment_deg, 1);
    EXPECT_EQ(job.spectral.samples, 64);
    EXPECT_DOUBLE_EQ(job.spectral.increment_cm1, 0);
    EXPECT_DOUBLE_EQ(job.spectral.threshold, 0.001);
    EXPECT_FALSE(job.target_latitude_deg || job.target_longitude_east_deg);
    EXPECT_TRUE(job.bands.empty() && job.name.empty() && job.gain_overrides.empty());
}

TEST(LandsatSensorCommand, EachOptionReachesTheJob) {
    const auto job = job_of({"m.txt",
                             "--data-dir",
                             SIGCHAIN_SOURCE_DIR "/data",
                             "--bands",
                             "1,4,7",
                             "--target",
                             "50.8,8.77",
                             "--view-angles",
                             "-4,6,0.5",
                             "--name",
                             "marburg",
                             "--altitude",
                             "700",
                             "--increment",
                             "20",
                             "--threshold",
                             "0.01",
                             "--gain",
                             "4=L",
                             "-o",
                             "d"});
    EXPECT_EQ(job.data_dir, SIGCHAIN_SOURCE_DIR "/data");
    EXPECT_EQ(job.bands, (std::vector<std::string>{"1", "4", "7"}));
    EXPECT_DOUBLE_EQ(*job.target_latitude_deg, 50.8);
    EXPECT_DOUBLE_EQ(*job.target_longitude_east_deg, 8.77);
    EXPECT_DOUBLE_EQ(job.view_min_deg, -4);
    EXPECT_DOUBLE_EQ(job.view_max_deg, 6);
    EXPECT_DOUBLE_EQ(job.view_increment_deg, 0.5);
    EXPECT_EQ(job.name, "marburg");
    EXPECT_DOUBLE_EQ(job.altitude_km, 700);
    EXPECT_DOUBLE_EQ(job.spectral.increment_cm1, 20);
    EXPECT_DOUBLE_EQ(job.spectral.threshold, 0.01);
    EXPECT_EQ(job.gain_overrides.at("4"), 'L');
}

TEST(LandsatSensorCommand, PrintBandsNeedsNoOutput) {
    EXPECT_TRUE(job_of({"m.txt", "--rsr", "r.txt", "--print-bands"}).out_dir.empty());
}

TEST(LandsatSensorCommand, UsageErrorsNameTheOption) {
    EXPECT_EQ(usage_error({"m.txt", "--rsr", "r", "-o", "d", "--bands", "1,,3"}),
              "--bands: 1,,3: empty band name");
    EXPECT_EQ(usage_error({"m.txt", "--rsr", "r", "-o", "d", "--view-angles", "5,-5,1"}),
              "--view-angles: MAX below MIN");
    EXPECT_EQ(usage_error({"m.txt", "--rsr", "r", "-o", "d", "--target", "50"}),
              "--target: 50: expected LAT,LON");
    EXPECT_EQ(usage_error({"m.txt", "--rsr", "r", "-o", "d", "--target", "95,8"}).substr(0, 13),
              "--target: 95:");
    EXPECT_EQ(usage_error({"m.txt", "--rsr", "r"}), "-o FILE is required");
}

}  // namespace
}  // namespace sigchain::commands
