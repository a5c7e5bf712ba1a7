// Tests for lib/cli: help, version, exit codes and message format shared by every tool.
#include "cli/cli.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"

using namespace sigchain;
namespace po = boost::program_options;

namespace {

struct Result {
    int status;
    std::string out, err;
};

// Runs a Cli named "tool" with `args` and `body`, capturing stdout and stderr.
// `configure` adds options instead of the default -o.
Result run(std::vector<std::string> args,
           std::function<int(const po::variables_map&, cli::Context&)> body,
           const std::function<void(cli::Cli&)>& configure = {}) {
    cli::Cli c({"tool", "Does a thing.", "[OPTIONS] FILE"});
    c.add_positional("file", -1, "input files");
    if (configure)
        configure(c);
    else
        c.add_output_option();
    args.insert(args.begin(), "tool");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    int status = c.run(static_cast<int>(argv.size()), argv.data(), body);
    return {status, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
}

int ok(const po::variables_map&, cli::Context&) { return 0; }

}  // namespace

TEST(Cli, HelpGoesToStdoutAndEndsWithSeeAlso) {
    auto r = run({"--help"}, ok);
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("Usage: tool [OPTIONS] FILE"), std::string::npos);
    EXPECT_NE(r.out.find("See tool(1).\n"), std::string::npos);
    EXPECT_EQ(r.err, "");
}

TEST(Cli, Version) {
    auto r = run({"--version"}, ok);
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out.rfind("tool (sigchain) ", 0), 0u);
}

TEST(Cli, UnknownOptionIsUsageError) {
    auto r = run({"--frobnicate"}, ok);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("Try 'tool --help'."), std::string::npos);
}

TEST(Cli, ExceptionsMapToExitCodes) {
    auto data = run({"f"}, [](const auto&, auto&) -> int {
        throw DataError({"scene.gdb", 12}, "expected a vertex count (3 or 4), found '5'");
    });
    EXPECT_EQ(data.status, 1);
    EXPECT_EQ(data.err, "tool: scene.gdb:12: expected a vertex count (3 or 4), found '5'\n");
    auto usage = run({"f"}, [](const auto&, auto&) -> int { throw UsageError("no input"); });
    EXPECT_EQ(usage.status, 2);
    auto io = run({"f"}, [](const auto&, auto&) -> int { throw IoError("x: cannot open"); });
    EXPECT_EQ(io.status, 1);
    auto ni = run({"f"}, [](const auto&, auto&) -> int { throw NotImplemented("not yet"); });
    EXPECT_EQ(ni.status, 1);
    EXPECT_EQ(ni.err, "tool: not yet\n");
}

TEST(Cli, PositionalsOutputAndVerbosity) {
    auto r =
        run({"-v", "-o", "out.txt", "a", "b"}, [](const po::variables_map& vm, cli::Context& ctx) {
            EXPECT_EQ(cli::args(vm, "file"), (std::vector<std::string>{"a", "b"}));
            EXPECT_EQ(vm["output"].as<std::string>(), "out.txt");
            EXPECT_EQ(ctx.verbosity(), 1);
            ctx.info("skipped the sky");
            return 0;
        });
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "tool: skipped the sky\n");
}

TEST(Cli, QuietSilencesWarnings) {
    auto r = run({"-q", "a"}, [](const auto&, cli::Context& ctx) {
        ctx.warn("odd");
        return 0;
    });
    EXPECT_EQ(r.err, "");
}

TEST(Cli, ProgressOnlyWhenEnabled) {
    auto off = run({"a"}, [](const auto&, cli::Context& ctx) {
        sigchain::ProgressScope p(ctx, "tracing");
        p.callback()(5, 10);
        return 0;
    });
    // Under the test runner stderr is not a terminal: nothing is drawn.
    EXPECT_EQ(off.err, "");
    auto on = run({"--progress", "a"}, [](const auto&, cli::Context& ctx) {
        sigchain::ProgressScope p(ctx, "tracing");
        p.callback()(5, 10);
        return 0;
    });
    EXPECT_NE(on.err.find("tool: tracing ["), std::string::npos);
    EXPECT_NE(on.err.find("50% 0:00"), std::string::npos);
    // The scope ends the line.
    EXPECT_EQ(on.err.back(), '\n');
    auto quiet = run({"--progress", "-q", "a"}, [](const auto&, cli::Context& ctx) {
        sigchain::ProgressScope p(ctx, "tracing");
        p.callback()(5, 10);
        return 0;
    });
    EXPECT_EQ(quiet.err, "");
}

TEST(Cli, DurationsAsClockTimes) {
    EXPECT_EQ(cli::format_duration(0), "0:00");
    EXPECT_EQ(cli::format_duration(59.4), "0:59");
    EXPECT_EQ(cli::format_duration(61), "1:01");
    EXPECT_EQ(cli::format_duration(3600 + 125), "1:02:05");
    EXPECT_EQ(cli::format_duration(-3), "0:00");
}

TEST(Cli, SharedOptionsMeanTheSameEverywhere) {
    auto r = run({"--threads", "3", "--seed", "42", "-o", "x", "a"},
                 [](const auto& vm, cli::Context&) {
                     EXPECT_EQ(cli::threads(vm), 3u);
                     EXPECT_EQ(cli::seed(vm), 42u);
                     EXPECT_EQ(cli::output_path(vm), "x");
                     return 0;
                 },
                 [](cli::Cli& c) {
                     c.add_threads_option();
                     c.add_seed_option();
                     c.add_required_output_option();
                 });
    EXPECT_EQ(r.status, 0);
    auto missing = run({"a"}, [](const auto& vm, cli::Context&) {
        (void)cli::output_path(vm);
        return 0;
    }, [](cli::Cli& c) { c.add_required_output_option(); });
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("-o FILE is required"), std::string::npos);
}

TEST(Cli, SceneOptionsAreOneBlockForEveryTool) {
    auto configure = [](cli::Cli& c) { c.add_scene_input_options(); };
    auto r = run(
        {"--up-axis", "+Y", "--strict-mesh", "--allow-degenerate", "--material-id", "3", "a"},
        [](const auto& vm, cli::Context&) {
            const cli::SceneInputOptions in = cli::scene_input(vm);
            EXPECT_EQ(in.up_axis, "+Y");  // read by lib/scene (parse_up_axis)
            EXPECT_TRUE(in.strict_mesh);
            EXPECT_TRUE(in.allow_degenerate);
            EXPECT_EQ(in.material_id, 3);
            return 0;
        },
        configure);
    EXPECT_EQ(r.status, 0);
    auto none = run(
        {"a"},
        [](const auto& vm, cli::Context&) {
            const cli::SceneInputOptions in = cli::scene_input(vm);
            EXPECT_EQ(in.up_axis, "");
            EXPECT_FALSE(in.strict_mesh);
            EXPECT_FALSE(in.allow_degenerate);
            return 0;
        },
        configure);
    EXPECT_EQ(none.status, 0);
}

// Outputs record this command (cube(5), PROVENANCE): paths to base names, options that
// cannot change an output left out, so that the checksum script's two runs (other
// folders, --threads 1 and 2) record the same text.
TEST(Cli, ProvenanceCommandDropsPathsAndThreads) {
    const char* a[] = {"/x/build/bin/sensorize", "-q", "--threads", "2", "/tmp/t1/cube.img",
                       "../data/red.sen", "--co", "COMPRESS=DEFLATE", "--psf=/k/a.psf",
                       "--progress", "-v", "--threads=1", "-o", "/tmp/t1/out.tif"};
    EXPECT_EQ(cli::provenance_command(14, a),
              "sensorize cube.img red.sen --co COMPRESS=DEFLATE --psf=a.psf -o out.tif");
    const char* b[] = {"sensorize", "--threads", "1", "/tmp/t2/cube.img", "red.sen", "--co",
                       "COMPRESS=DEFLATE", "--psf=a.psf", "-o", "out.tif"};
    EXPECT_EQ(cli::provenance_command(10, b), cli::provenance_command(14, a));
}

// A part's recorded options (cube(5), Parts): the output and the part's own options
// left out with their values, in every spelling, so that the tiles of one render agree.
TEST(Cli, PartOptionsDropTheOutputAndThePartOptions) {
    const char* a[] = {"/b/trace", "-q", "--tile", "1/3", "x/box.adv", "--seed", "7",
                       "-o", "/t/part1.img", "--truth", "t1.img"};
    const char* b[] = {"trace", "--tile=3/3", "box.adv", "--seed", "7", "--truth=/u/t3.img",
                       "--output=/t/part3.img"};
    const std::vector<std::string> parts{"--tile", "--rows", "--truth"};
    EXPECT_EQ(cli::part_options(cli::provenance_args(11, a), parts), "box.adv --seed 7");
    EXPECT_EQ(cli::part_options(cli::provenance_args(7, b), parts), "box.adv --seed 7");
    const char* c[] = {"trace", "box.adv", "-opart.img", "--rows", "0:4"};
    EXPECT_EQ(cli::part_options(cli::provenance_args(5, c), parts), "box.adv");
}

TEST(Cli, ParseTileChecksKAndN) {
    EXPECT_EQ(cli::parse_tile("2/3").index, 2);
    EXPECT_EQ(cli::parse_tile("2/3").count, 3);
    EXPECT_EQ(cli::parse_tile("1/1").count, 1);
    for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "-1/2", "1/3/4", "1.5/3", "/3", "1/"})
        EXPECT_THROW(cli::parse_tile(bad), UsageError) << bad;
}

// ---- The checked number parser (parse_number, add_number) ----

TEST(ParseNumber, ReadsFiniteNumbersInRange) {
    EXPECT_EQ(cli::parse_number("--top", "100", cli::positive(1000)), 100.0L);
    EXPECT_EQ(cli::parse_number("--top", "+2.5e1", cli::positive(1000)), 25.0L);
    EXPECT_EQ(cli::parse_number("--top", "1000", cli::positive(1000)), 1000.0L);
    EXPECT_EQ(cli::parse_number("--roc", "-1", cli::reals(-1, 1)), -1.0L);
    EXPECT_EQ(cli::parse_number("--n", "-3", cli::integers(-5, 5)), -3.0L);
    EXPECT_EQ(cli::parse_number("--n", "0", cli::threads_range()), 0.0L);
}

TEST(ParseNumber, SeedsAreExactUpTo2To64) {
    // 2^64 - 1 is not a double; the parser keeps every integer of a seed exact.
    const long double v =
        cli::parse_number("--seed", "18446744073709551615", cli::seed_range());
    EXPECT_EQ(static_cast<std::uint64_t>(v), UINT64_MAX);
    EXPECT_THROW(cli::parse_number("--seed", "18446744073709551616", cli::seed_range()),
                 UsageError);
    EXPECT_THROW(cli::parse_number("--seed", "-1", cli::seed_range()), UsageError);
}

TEST(ParseNumber, ListsReadEachNumberAgainstItsRange) {
    const std::vector<cli::Range> r{cli::integers(2, 64), cli::integers(2, 64),
                                    cli::reals(0, 1, true)};
    const auto v = cli::parse_number_list("--convergence", "4,32,0.01", r, "MIN,MAX,THRESHOLD");
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[1], 32.0L);
    EXPECT_EQ(v[2], static_cast<long double>(0.01));
    const auto message = [&](const std::string& text) -> std::string {
        try {
            cli::parse_number_list("--convergence", text, r, "MIN,MAX,THRESHOLD");
        } catch (const UsageError& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_EQ(message("4,32"), "--convergence: 4,32: expected MIN,MAX,THRESHOLD");
    EXPECT_EQ(message("4,32,0.1,"), "--convergence: 4,32,0.1,: expected MIN,MAX,THRESHOLD");
    EXPECT_EQ(message("4,,0.1"), "--convergence: : must be an integer from 2 to 64");
    EXPECT_EQ(message("4,32,0"), "--convergence: 0: must be a number > 0 and <= 1");
}

// The message of each rejected value: "--OPTION: VALUE: must be RANGE".
std::string rejection(const std::string& text, const cli::Range& range) {
    try {
        cli::parse_number("--x", text, range);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(ParseNumber, RejectsNanInfinityAndJunk) {
    const cli::Range r = cli::reals(0, 10);
    for (const char* bad : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e999", "", "+",
                            "-", "1x", " 1", "1 ", "0x10", "1,5", "--1", "+-1", "e5"})
        EXPECT_EQ(rejection(bad, r), std::string("--x: ") + bad + ": must be a number from 0 to 10")
            << bad;
}

TEST(ParseNumber, RejectsOutOfRangeAndFractionsOfIntegers) {
    EXPECT_EQ(rejection("-1", cli::threads_range()), "--x: -1: must be an integer from 0 to 4096");
    EXPECT_EQ(rejection("1.5", cli::integers(1, 8)), "--x: 1.5: must be an integer from 1 to 8");
    EXPECT_EQ(rejection("1e3", cli::integers(1, 8)), "--x: 1e3: must be an integer from 1 to 8");
    EXPECT_EQ(rejection("0", cli::positive(3600)), "--x: 0: must be a number > 0 and <= 3600");
    EXPECT_EQ(rejection("3600.5", cli::positive(3600)),
              "--x: 3600.5: must be a number > 0 and <= 3600");
    EXPECT_EQ(rejection("-0.1", cli::reals(0, 1e300)), "--x: -0.1: must be a number from 0 to 1e+300");
    EXPECT_EQ(rejection("nan", cli::Range{}), "--x: nan: must be a finite number");
    cli::Range only_min = cli::integers(1, 0);
    only_min.max = std::numeric_limits<long double>::infinity();
    EXPECT_EQ(rejection("0", only_min), "--x: 0: must be an integer >= 1");
}

// An option that takes a number or one word (build_radiance --streams N|auto): the
// word passes as it is, a number is checked against the range, anything else is a
// usage error naming both.
TEST(ParseNumber, NumberOrKeywordAcceptsTheWordAndCheckedNumbers) {
    auto configure = [](cli::Cli& c) {
        c.add_number_or("streams", "auto", "N|auto", cli::integers(4, 64), "streams", "16");
    };
    bool automatic = true;
    long long n = 0;
    auto body = [&](const po::variables_map& vm, cli::Context&) {
        automatic = cli::keyword_given(vm, "streams", "auto");
        if (!automatic) n = cli::integer(vm, "streams");
        return 0;
    };
    EXPECT_EQ(run({}, body, configure).status, 0);
    EXPECT_FALSE(automatic);
    EXPECT_EQ(n, 16);
    EXPECT_EQ(run({"--streams", "auto"}, body, configure).status, 0);
    EXPECT_TRUE(automatic);
    EXPECT_EQ(run({"--streams", "8"}, body, configure).status, 0);
    EXPECT_FALSE(automatic);
    EXPECT_EQ(n, 8);
    for (const char* bad : {"nan", "3", "65", "Auto", "auto2", "4.5"}) {
        const Result r = run({"--streams", bad}, body, configure);
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err, std::string("tool: --streams: ") + bad +
                             ": must be auto or an integer from 4 to 64\nTry 'tool --help'.\n");
    }
}

TEST(ParseNumber, OptionsAreCheckedWhenParsedDefaultsIncluded) {
    auto configure = [](cli::Cli& c) {
        c.add_number("top", "KM", cli::positive(1000), "top", "100");
        c.add_number("bits,b", "N", cli::integers(8, 16), "bits", "8");
        c.add_threads_option();
    };
    double top = 0;
    long long bits = 0;
    unsigned threads = 99;
    auto body = [&](const po::variables_map& vm, cli::Context&) {
        top = cli::real(vm, "top");
        bits = cli::integer(vm, "bits");
        threads = cli::threads(vm);
        return 0;
    };
    EXPECT_EQ(run({}, body, configure).status, 0);
    EXPECT_EQ(top, 100);
    EXPECT_EQ(bits, 8);
    EXPECT_EQ(threads, 0u);
    EXPECT_EQ(run({"--top", "2.5", "-b", "12", "--threads", "3"}, body, configure).status, 0);
    EXPECT_EQ(top, 2.5);
    EXPECT_EQ(bits, 12);
    EXPECT_EQ(threads, 3u);
    Result r = run({"--top", "inf"}, body, configure);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "tool: --top: inf: must be a number > 0 and <= 1000\nTry 'tool --help'.\n");
    r = run({"-b", "nan"}, body, configure);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "tool: --bits: nan: must be an integer from 8 to 16\nTry 'tool --help'.\n");
    r = run({"--threads", "-1"}, body, configure);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "tool: --threads: -1: must be an integer from 0 to 4096\nTry 'tool --help'.\n");
}
