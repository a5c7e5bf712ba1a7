// Tests of lib/landcover/landsat_scene_job: the command line mapped onto the steps,
// without a process: each command's argument count, the numbers it reads and the
// options a step needs are usage errors (exit 2) before any file is opened.
#include "landcover/landsat_scene_job.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "core/error.hpp"

namespace lc = sigchain::landcover;

namespace {

// The UsageError's message of running `args` with `options`, or "" when there is none.
std::string usage_error(const std::vector<std::string>& args,
                        const lc::LandsatSceneOptions& options = {}) {
    std::ostringstream out, report;
    try {
        lc::run_landsat_scene(args, options, out, report);
    } catch (const sigchain::UsageError& e) {
        return e.what();
    } catch (const sigchain::Error&) {
        return "";  // a data or I/O error: past the command line
    }
    return "";
}

}  // namespace

TEST(LandsatSceneJob, CommandsAndTheirArgumentCounts) {
    EXPECT_EQ(usage_error({}), "expected a COMMAND");
    EXPECT_EQ(usage_error({"frobnicate"}), "unknown command 'frobnicate'");
    EXPECT_EQ(usage_error({"fit", "a.cpt", "b.tif"}), "fit takes 4 arguments, found 2");
    EXPECT_EQ(usage_error({"terrain", "a", "b", "c", "d"}), "terrain takes 3 arguments, found 4");
    EXPECT_EQ(usage_error({"classify", "r", "-", "o.tif"}),
              "classify takes 4 or more arguments, found 3");
    EXPECT_EQ(usage_error({"stats", "r", "i"}), "stats takes 3 arguments, found 2");
    EXPECT_EQ(usage_error({"crosstab", "a", "b", "c"}), "crosstab takes 4 arguments, found 3");
}

TEST(LandsatSceneJob, NumbersOfTheArgumentsAreChecked) {
    EXPECT_EQ(usage_error({"points", "r", "c", "-", "many", "1", "5", "p"}),
              "PER_CLASS must be an integer from 1 to 1048576, found 'many'");
    EXPECT_EQ(usage_error({"points", "r", "c", "-", "10", "-1", "5", "p"}),
              "SEED must be an integer from 0 to 4294967295, found '-1'");
    EXPECT_EQ(usage_error({"difference", "s", "r", "0", "30", "o.png"}),
              "BAND must be an integer from 1 to 1000, found '0'");
    EXPECT_EQ(usage_error({"difference", "s", "r", "4", "x", "o.png"}),
              "RANGE: expected a number, found 'x'");
    EXPECT_EQ(usage_error({"side-by-side", "s", "r", "3,2,x", "o.png"}),
              "a band must be an integer from 1 to 1000, found 'x'");
    EXPECT_EQ(usage_error({"pairs", "r", "s", "f", "c", "4", "0"}),
              "STEP must be an integer from 1 to 1073741824, found '0'");
}

TEST(LandsatSceneJob, MaskNeedsTheSunAndSaneHeights) {
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}), "mask needs --sun ELEVATION,AZIMUTH");
    lc::LandsatSceneOptions o;
    o.sun = "61.4";
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}, o),
              "--sun: expected two numbers A,B, found '61.4'");
    o.sun = "95,120";
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}, o),
              "--sun: the elevation must be > 0 and <= 90 deg");
    o.sun = "45,120";
    o.heights = "3000,500";
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}, o),
              "--heights: expected 0 <= MIN <= MAX <= 20000 m");
    o.heights = "500,3000";
    o.cloud = "b1 >";  // a malformed test is a bad option value: a usage error
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}, o),
              "--cloud: expected terms of three fields (VALUE OP NUMBER), found 2 fields");
    o.cloud = "b1 > 110";
    o.dark = "x4 < 60";
    EXPECT_EQ(usage_error({"mask", "m.tif", "i.tif"}, o),
              "--dark: expected a band (b4) or a normalised difference (nd(4,3)), found 'x4'");
}

TEST(LandsatSceneJob, AnOutputThatIsAnInputIsRefused) {
    EXPECT_NE(usage_error({"classify", "r", "-", "i.tif", "i.tif"}), "");
    EXPECT_NE(usage_error({"side-by-side", "s.tif", "r.tif", "3,2,1", "s.tif"}), "");
}
