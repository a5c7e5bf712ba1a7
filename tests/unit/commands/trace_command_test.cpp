// trace's command line to its two Jobs (lib/commands/trace_command): what only a process
// could check before: each option's way into the render's Job or the shadow history's,
// the defaults, the usage errors that name an option, and the exclusivity of the two
// commands' options, read from the groups they are declared in.
#include "commands/trace_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "command_line.hpp"

namespace sigchain::commands {
namespace {

const std::vector<std::string> kRender{"a.adv", "s.snd", "g.gdb", "m.mat", "b1.rad", "b2.rad"};
const std::vector<std::string> kHistory{"--shadow-history", "s.snd", "g.gdb", "m.mat"};

// `base` followed by `more`.
std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
    base.insert(base.end(), more.begin(), more.end());
    return base;
}

// The command line `args` (after the tool's name) as trace parses it.
cli::po::variables_map parsed(const std::vector<std::string>& args) {
    return testing::parse_line(trace_info(), add_trace_options, args);
}

trace::TraceJob render_job(const std::vector<std::string>& args) {
    const cli::Context ctx("trace", -1, false);
    return trace_job(parsed(args), ctx);
}

trace::ShadowJob history_job(const std::vector<std::string>& args) {
    return shadow_job(parsed(args));
}

// The usage error of `args` for the Job that --shadow-history chooses, or "" when none.
std::string usage_error(const std::vector<std::string>& args) {
    return testing::usage_error_of([&] {
        const auto vm = parsed(args);
        if (vm.count("shadow-history"))
            shadow_job(vm);
        else
            trace_job(vm, cli::Context("trace", -1, false));
    });
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(TraceCommand, RenderInputsOutputAndDefaults) {
    const auto job = render_job(with(kRender, {"-o", "cube.img"}));
    EXPECT_EQ(job.adv_path, "a.adv");
    EXPECT_EQ(job.snd_path, "s.snd");
    EXPECT_EQ(job.scene_path, "g.gdb");
    EXPECT_EQ(job.mat_path, "m.mat");
    EXPECT_EQ(job.rad_paths, (std::vector<std::string>{"b1.rad", "b2.rad"}));
    EXPECT_EQ(job.output_path, "cube.img");
    // Without --sampling or a count of samples: the sampling chosen by accuracy
    // (trace(1) SAMPLING BY ACCURACY), as --sampling auto, which sets its own counts.
    EXPECT_TRUE(trace::sampling_by_accuracy(job));
    EXPECT_TRUE(trace::sampling_by_accuracy(
        render_job(with(kRender, {"-o", "cube.img", "--sampling", "auto"}))));
    // A count named without a strategy: the golf ball, as before there was a choice.
    for (const std::vector<std::string>& count :
         {std::vector<std::string>{"--samples-per-pixel", "4"},
          std::vector<std::string>{"--hemisphere-samples", "16"},
          std::vector<std::string>{"--golfball-jitter"},
          std::vector<std::string>{"--convergence", "4,16,0.1"}}) {
        std::vector<std::string> args{"-o", "c.img"};
        args.insert(args.end(), count.begin(), count.end());
        const auto counted = render_job(with(kRender, args));
        EXPECT_FALSE(trace::sampling_by_accuracy(counted)) << count[0];
        EXPECT_EQ(counted.sampling, trace::Sampling::Golfball) << count[0];
    }
    const auto named = render_job(with(kRender, {"-o", "c.img", "--sampling", "montecarlo"}));
    EXPECT_FALSE(trace::sampling_by_accuracy(named));
    EXPECT_EQ(named.sampling, trace::Sampling::MonteCarlo);
    const auto both = render_job(
        with(kRender, {"-o", "c.img", "--sampling", "auto", "--samples-per-pixel", "4"}));
    EXPECT_EQ(testing::usage_error_of([&] { trace::check_job(both); }),
              "--sampling auto chooses its own samples: not with --samples-per-pixel");
    EXPECT_EQ(job.seed, 1u);
    EXPECT_EQ(job.threads, 0u);
    EXPECT_EQ(job.background, "mean");
    EXPECT_TRUE(job.adjacency);
    EXPECT_FALSE(job.samples_per_pixel || job.hemisphere_samples || job.max_transmissions ||
                 job.bounces || job.rows || job.tile || job.convergence || job.adjacency_radius_m);
    EXPECT_FALSE(job.strict || job.golfball_jitter || job.si_radiance_units || job.standard_error ||
                 job.allow_degenerate);
    EXPECT_TRUE(job.truth_path.empty() && job.tmp_path.empty() && job.crs.empty() &&
                job.like_path.empty() && job.uncertainty_path.empty() && job.igm_path.empty() &&
                job.glt_path.empty());
}

TEST(TraceCommand, EachRenderingOptionReachesTheJob) {
    const auto job = render_job(with(kRender, {"-o",
                                               "c.tif",
                                               "--sampling",
                                               "montecarlo",
                                               "--samples-per-pixel",
                                               "9",
                                               "--hemisphere-samples",
                                               "32",
                                               "--max-transmissions",
                                               "3",
                                               "--bounces",
                                               "2",
                                               "--background",
                                               "none",
                                               "--seed",
                                               "5",
                                               "--threads",
                                               "2",
                                               "--tile",
                                               "2/3",
                                               "--truth",
                                               "t.img",
                                               "--tmp",
                                               "f.tmp",
                                               "--strict",
                                               "--golfball-jitter",
                                               "--adjacency-radius",
                                               "250",
                                               "--crs",
                                               "EPSG:32618",
                                               "--like",
                                               "l.tif",
                                               "--radiance-units",
                                               "W/m2/sr/um",
                                               "--standard-error",
                                               "--convergence",
                                               "4,64,0.01",
                                               "--convergence-error",
                                               "rms",
                                               "--uncertainty",
                                               "u.unc",
                                               "--igm",
                                               "i.tif",
                                               "--glt",
                                               "g.tif",
                                               "--allow-degenerate",
                                               "--material-id",
                                               "7"}));
    EXPECT_EQ(job.sampling, trace::Sampling::MonteCarlo);
    EXPECT_EQ(job.samples_per_pixel, 9);
    EXPECT_EQ(job.hemisphere_samples, 32);
    EXPECT_EQ(job.max_transmissions, 3);
    EXPECT_EQ(job.bounces, 2);
    EXPECT_EQ(job.background, "none");
    EXPECT_EQ(job.seed, 5u);
    EXPECT_EQ(job.threads, 2u);
    ASSERT_TRUE(job.tile);
    EXPECT_EQ(job.tile->index, 2);
    EXPECT_EQ(job.tile->count, 3);
    EXPECT_EQ(job.truth_path, "t.img");
    EXPECT_EQ(job.tmp_path, "f.tmp");
    EXPECT_TRUE(job.strict && job.golfball_jitter && job.si_radiance_units && job.standard_error);
    EXPECT_EQ(job.adjacency_radius_m, 250);
    EXPECT_EQ(job.crs, "EPSG:32618");
    EXPECT_EQ(job.like_path, "l.tif");
    ASSERT_TRUE(job.convergence);
    EXPECT_EQ(job.convergence->min, 4);
    EXPECT_EQ(job.convergence->max, 64);
    EXPECT_DOUBLE_EQ(job.convergence->threshold, 0.01);
    EXPECT_EQ(job.convergence->error, trace::ConvergenceError::Rms);
    EXPECT_EQ(job.uncertainty_path, "u.unc");
    EXPECT_EQ(job.igm_path, "i.tif");
    EXPECT_EQ(job.glt_path, "g.tif");
    EXPECT_TRUE(job.allow_degenerate);
    EXPECT_EQ(job.scene_input.material_id, 7);
    EXPECT_FALSE(render_job(with(kRender, {"-o", "c.img", "--no-adjacency"})).adjacency);
    EXPECT_EQ(render_job(with(kRender, {"-o", "c.img", "--rows", "2:5"})).rows,
              (std::pair<long, long>{2, 5}));
}

TEST(TraceCommand, TheCubesRecordTheCommandLineAndAPartItsOptions) {
    cli::Context ctx("trace", -1, false);
    ctx.set_command("trace a.adv -o c.img");
    ctx.set_command_args({"trace", "--tile", "1/2", "--bounces", "2", "a.adv", "-o", "c.img"});
    const auto job = trace_job(parsed(with(kRender, {"-o", "c.img"})), ctx);
    EXPECT_EQ(job.write_options.command, "trace a.adv -o c.img");
    EXPECT_EQ(job.part_options, "--bounces 2 a.adv");
}

TEST(TraceCommand, ShadowHistoryInputsOutputAndDefaults) {
    const auto job = history_job(with(kHistory, {"-o", "f.shd"}));
    EXPECT_EQ(job.snd_path, "s.snd");
    EXPECT_EQ(job.scene_path, "g.gdb");
    EXPECT_EQ(job.mat_path, "m.mat");
    EXPECT_EQ(job.output_path, "f.shd");
    const trace::ShadowOptions defaults;
    EXPECT_DOUBLE_EQ(job.options.history_hours, defaults.history_hours);
    EXPECT_DOUBLE_EQ(job.options.step_minutes, defaults.step_minutes);
    EXPECT_EQ(job.options.points_per_facet, 1);
    EXPECT_EQ(job.options.sky_rays, trace::kDefaultSkyRays);
    EXPECT_EQ(job.options.max_transmissions, 8);
    EXPECT_EQ(job.options.seed, 1u);
    EXPECT_FALSE(job.allow_degenerate);
    // Without -o the Job keeps it empty: run_shadow_history's message names the .shd.
    EXPECT_TRUE(history_job(kHistory).output_path.empty());
}

TEST(TraceCommand, EachShadowHistoryOptionReachesTheJob) {
    const auto job = history_job(
        with(kHistory, {"-o", "f.shd", "--history-hours", "12", "--history-step-minutes", "30",
                        "--points-per-facet", "16", "--sky-rays", "64", "--max-transmissions", "2",
                        "--seed", "9", "--threads", "3", "--allow-degenerate", "--up-axis", "y"}));
    EXPECT_DOUBLE_EQ(job.options.history_hours, 12);
    EXPECT_DOUBLE_EQ(job.options.step_minutes, 30);
    EXPECT_EQ(job.options.points_per_facet, 16);
    EXPECT_EQ(job.options.sky_rays, 64);
    EXPECT_EQ(job.options.max_transmissions, 2);
    EXPECT_EQ(job.options.seed, 9u);
    EXPECT_EQ(job.options.threads, 3u);
    EXPECT_TRUE(job.allow_degenerate);
    EXPECT_EQ(job.scene_input.up_axis, "y");
}

TEST(TraceCommand, TheGroupsHoldEachCommandsOwnOptions) {
    const auto groups = trace_option_groups();
    EXPECT_EQ(groups.history, (std::vector<std::string>{"history-hours", "history-step-minutes",
                                                        "points-per-facet", "sky-rays"}));
    for (const char* o : {"sampling", "co", "tile", "strict", "truth", "convergence", "igm"})
        EXPECT_TRUE(contains(groups.rendering, o)) << o;
    // What both commands take is in neither group.
    for (const char* o : {"output", "seed", "threads", "max-transmissions", "material-id",
                          "allow-degenerate", "up-axis", "shadow-history"}) {
        EXPECT_FALSE(contains(groups.rendering, o)) << o;
        EXPECT_FALSE(contains(groups.history, o)) << o;
    }
    for (const auto& o : groups.history) EXPECT_FALSE(contains(groups.rendering, o)) << o;
}

// A value each rendering option accepts; the switches take none. An option declared
// later without a value here fails this test by name (po: its argument is missing).
const std::map<std::string, std::string> kRenderValues{{"co", "COMPRESS=DEFLATE"},
                                                       {"tile", "1/2"},
                                                       {"sampling", "golfball"},
                                                       {"bounces", "2"},
                                                       {"background", "none"},
                                                       {"rows", "0:1"},
                                                       {"truth", "t.img"},
                                                       {"tmp", "f.tmp"},
                                                       {"crs", "none"},
                                                       {"like", "l.tif"},
                                                       {"sky-lookup", "table"},
                                                       {"open-sky", "sampled"},
                                                       {"radiance-units", "W/m2/sr/um"},
                                                       {"igm", "i.tif"},
                                                       {"glt", "g.tif"},
                                                       {"uncertainty", "u.unc"},
                                                       {"convergence", "4,8,0.1"},
                                                       {"convergence-error", "rms"},
                                                       {"samples-per-pixel", "4"},
                                                       {"hemisphere-samples", "16"},
                                                       {"adjacency-radius", "500"},
                                                       {"sun-images", "4"}};

TEST(TraceCommand, EveryRenderingOptionIsRefusedWithTheShadowHistory) {
    for (const auto& o : trace_option_groups().rendering) {
        auto args = with(kHistory, {"-o", "f.shd", "--" + o});
        if (const auto v = kRenderValues.find(o); v != kRenderValues.end())
            args.push_back(v->second);
        EXPECT_EQ(usage_error(args), "--" + o + " does not apply to --shadow-history");
    }
    // --sampling's default is no choice of the user's: the history runs.
    EXPECT_EQ(usage_error(with(kHistory, {"-o", "f.shd"})), "");
}

TEST(TraceCommand, EveryShadowHistoryOptionNeedsIt) {
    for (const auto& o : trace_option_groups().history)
        EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--" + o, "4"})),
                  "--" + o + " needs --shadow-history");
}

TEST(TraceCommand, ContradictionsAreNamedUsageErrors) {
    EXPECT_EQ(usage_error({"a.adv", "s.snd", "g.gdb", "m.mat", "-o", "c.img"}),
              "expected ADV SND SCENE MAT and at least one RAD");
    EXPECT_EQ(usage_error({"--shadow-history", "s.snd", "g.gdb", "-o", "f.shd"}),
              "--shadow-history: expected SND SCENE MAT");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--sampling", "random"})),
              "--sampling: unknown strategy 'random' (dirsig, golfball, montecarlo or proposed)");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--radiance-units", "W/sr"})),
              "--radiance-units W/sr: expected W/cm2/sr/um or W/m2/sr/um");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--convergence-error", "rms"})),
              "--convergence-error: only with --convergence");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--convergence", "4,64"})),
              "--convergence: 4,64: expected MIN,MAX,THRESHOLD");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--co", "COMPRESS=DEFLATE"})),
              "c.img: --co applies to GeoTIFF (.tif) outputs only");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.tif", "--co", "COMPRESS"})),
              "--co COMPRESS: expected KEY=VALUE");
    EXPECT_EQ(usage_error(with(kRender, {"-o", "c.img", "--tile", "3/2"})),
              "--tile: expected K/N (part K of N, 1 <= K <= N), found '3/2'");
    // A value out of its range is refused when parsed (cli::Cli::add_number).
    EXPECT_EQ(usage_error(with(kHistory, {"-o", "f.shd", "--points-per-facet", "0"})),
              "--points-per-facet: 0: must be an integer from 1 to 1000000");
}

}  // namespace
}  // namespace sigchain::commands
