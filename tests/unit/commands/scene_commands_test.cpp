// The demo and validation scenes' command lines (lib/commands: landsat_scene,
// hawkeye_scene, olinda_scene): what each makes of its arguments and the usage errors
// that name the argument, without a process.
#include <gtest/gtest.h>

#include "command_line.hpp"
#include "commands/hawkeye_scene_command.hpp"
#include "commands/landsat_scene_command.hpp"
#include "commands/olinda_scene_command.hpp"

namespace sigchain::commands {
namespace {

using testing::parse_line;
using testing::usage_error_of;

landcover::LandsatSceneOptions landsat_options(const std::vector<std::string>& args) {
    return landsat_scene_options(parse_line(landsat_scene_info(), add_landsat_scene_options, args));
}

TEST(LandsatSceneCommand, DefaultsAreTheOptionsStructs) {
    const auto o = landsat_options({"stats", "r.txt", "i.tif", "c.tif"});
    const landcover::LandsatSceneOptions defaults;
    EXPECT_TRUE(o.masks.empty() && o.points.empty() && o.sun.empty());
    EXPECT_EQ(o.bands, 0);
    EXPECT_EQ(o.cloud, defaults.cloud);
    EXPECT_EQ(o.dark, defaults.dark);
    EXPECT_EQ(o.heights, defaults.heights);
    EXPECT_EQ(o.buffer, defaults.buffer);
    EXPECT_DOUBLE_EQ(o.pixel_m, defaults.pixel_m);
}

TEST(LandsatSceneCommand, EachOptionReachesTheOptions) {
    const auto o = landsat_options(
        {"mask",    "--mask",   "a.tif",   "--mask",  "b.tif",  "--points",  "p.cpt",   "--cloud",
         "b1 > 90", "--dark",   "b4 < 50", "--sun",   "40,150", "--heights", "100,900", "--bands",
         "3",       "--buffer", "0",       "--pixel", "15",     "out.tif",   "img.tif"});
    EXPECT_EQ(o.masks, (std::vector<std::string>{"a.tif", "b.tif"}));
    EXPECT_EQ(o.points, "p.cpt");
    EXPECT_EQ(o.cloud, "b1 > 90");
    EXPECT_EQ(o.dark, "b4 < 50");
    EXPECT_EQ(o.sun, "40,150");
    EXPECT_EQ(o.heights, "100,900");
    EXPECT_EQ(o.bands, 3);
    EXPECT_EQ(o.buffer, 0);
    EXPECT_DOUBLE_EQ(o.pixel_m, 15);
    EXPECT_EQ(usage_error_of([] {
                  landsat_options({"mask", "--buffer", "101"});
              }).substr(0, 14),
              "--buffer: 101:");
}

HawkeyeSceneJob hawkeye_job(const std::vector<std::string>& args) {
    return hawkeye_scene_job(parse_line(hawkeye_scene_info(), add_hawkeye_scene_options, args));
}

TEST(HawkeyeSceneCommand, SeedAndFolder) {
    const auto job = hawkeye_job({"18446744073709551615", "out"});
    EXPECT_EQ(job.seed, 18446744073709551615ull);
    EXPECT_EQ(job.seed_text, "18446744073709551615");
    EXPECT_EQ(job.outdir, "out");
}

TEST(HawkeyeSceneCommand, UsageErrorsNameTheSeed) {
    auto error = [](const std::vector<std::string>& args) {
        return usage_error_of([&] { hawkeye_job(args); });
    };
    EXPECT_EQ(error({"1"}), "expected SEED (a non-negative integer) and OUTDIR");
    EXPECT_EQ(error({"7x", "out"}),
              "expected SEED (a non-negative integer) and OUTDIR, found SEED '7x'");
    EXPECT_EQ(error({"18446744073709551616", "out"}),
              "SEED 18446744073709551616 is larger than 2^64 - 1");
}

TEST(OlindaSceneCommand, EachCommandsArguments) {
    const auto points = olinda_step({"points", "c.tif", "l.tif", "30", "7", "6", "pre"});
    EXPECT_EQ(points.command, "points");
    EXPECT_EQ(points.points.classes_path, "c.tif");
    EXPECT_EQ(points.points.landuse_path, "l.tif");
    EXPECT_EQ(points.points.per_class, 30);
    EXPECT_EQ(points.points.seed, 7u);
    EXPECT_EQ(points.points.margin, 6);
    EXPECT_EQ(points.points.prefix, "pre");
    EXPECT_EQ(olinda_step({"fit", "f.cpt", "d.tif", "b.tif", "r.tif"}).paths,
              (std::vector<std::string>{"f.cpt", "d.tif", "b.tif", "r.tif"}));
    EXPECT_EQ(olinda_step({"ems", "r.txt", "-", "out"}).paths.size(), 3u);
}

TEST(OlindaSceneCommand, UsageErrorsNameTheArgument) {
    auto error = [](const std::vector<std::string>& args) {
        return usage_error_of([&] { olinda_step(args); });
    };
    EXPECT_EQ(error({}), "expected a COMMAND");
    EXPECT_EQ(error({"frobnicate"}), "unknown command 'frobnicate'");
    EXPECT_EQ(error({"fit", "a", "b"}), "fit takes 4 arguments, found 2");
    EXPECT_EQ(error({"points", "c", "l", "0", "7", "6", "p"}),
              "PER_CLASS must be an integer from 1 to 1048576, found '0'");
    EXPECT_EQ(error({"points", "c", "l", "3", "4294967296", "6", "p"}),
              "SEED must be an integer from 0 to 4294967295, found '4294967296'");
    EXPECT_EQ(error({"points", "c", "l", "3", "1", "6x", "p"}),
              "MARGIN must be an integer from 0 to 1048576, found '6x'");
    EXPECT_EQ(error({"preview", "s.tif", "r.tif", "s.tif"}),
              "s.tif: is also the input s.tif (refusing to overwrite an input)");
}

}  // namespace
}  // namespace sigchain::commands
