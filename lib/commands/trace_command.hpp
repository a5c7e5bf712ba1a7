// trace's command line (trace(1)): its two commands in one binary, the render (ADV SND
// SCENE MAT RAD... -o CUBE) and --shadow-history (SND SCENE MAT -o FILE.shd); the options
// each takes, the Job a command line makes (options in, Job out, or a UsageError naming
// the option); tools/trace/main.cpp only wires them to cli::Cli.
//
// The options come in three groups, declared apart: the shared ones (inputs, -o, --seed,
// --threads, the scene options, --max-transmissions), the rendering ones and the
// shadow history's. A rendering option given with --shadow-history, or a shadow-history
// option without it, is a usage error; which options those are is read from the groups
// as declared, so that a new option is placed by where it is declared, never by a list
// kept beside it.
#pragma once

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "trace/shadow_history.hpp"
#include "trace/trace_job.hpp"

namespace sigchain::commands {

// The long names of the options of each command's own group, in declaration order.
struct TraceOptionGroups {
    std::vector<std::string> rendering;  // not with --shadow-history
    std::vector<std::string> history;    // only with --shadow-history
};

// The tool's name, purpose and usage lines (--help).
cli::ToolInfo trace_info();
// trace's options and positional arguments, added to `tool`; returns the two groups.
TraceOptionGroups add_trace_options(cli::Cli& tool);
// The groups of add_trace_options (declared on a Cli of their own).
TraceOptionGroups trace_option_groups();

// The render's Job of a parsed command line (without --shadow-history); UsageError for
// a shadow-history option, fewer than five arguments, a bad --sampling, --bounces,
// --rows, --radiance-units, --convergence or --convergence-error, --convergence-error
// without --convergence, a malformed --co or one for an ENVI cube. The cubes'
// provenance and a part's recorded options come from `ctx`'s command line.
trace::TraceJob trace_job(const cli::po::variables_map& vm, const cli::Context& ctx);
// The shadow history's Job of a parsed command line (with --shadow-history);
// UsageError for a rendering option (--sampling when not its default) or other than
// three arguments.
trace::ShadowJob shadow_job(const cli::po::variables_map& vm);
// The whole command: the Job --shadow-history chooses, its run. Returns the exit status.
int run_trace_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
