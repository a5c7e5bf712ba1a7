// compare's command line (compare(1)): its options, the Job a command line makes (options
// in, Job out, or a UsageError naming what is wrong) and the run with idiff's exit
// statuses; tools/compare/main.cpp only wires them to cli::Cli.
#pragma once

#include "cli/cli.hpp"
#include "compare/compare_job.hpp"

namespace sigchain::commands {

// The tool's name, purpose, usage line and exit statuses (--help).
cli::ToolInfo compare_info();
// compare's own options and positional arguments, added to `tool`.
void add_compare_options(cli::Cli& tool);
// The Job of a parsed command line; UsageError for other than three inputs (two with
// --pixelwise), a bad --bands, or an output (-o, --error-map) that is an input.
compare::CompareJob compare_job(const cli::po::variables_map& vm);
// The whole command: the report written atomically to -o, a note per threshold
// exceeded. Returns 0 within the thresholds, 1 outside; trouble in the run (bad or
// unreadable inputs) is reported through `ctx`'s tool name and returns 2, as idiff's;
// a UsageError is thrown (exit 2 through cli::Cli).
int run_compare_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
