// hawkeye_scene's command line (hawkeye_scene(1)): SEED OUTDIR into the generator's Job
// (or a UsageError naming what is wrong), the run and its one-line summary;
// tools/hawkeye_scene/main.cpp only wires them to cli::Cli.
#pragma once

#include <cstdint>
#include <string>

#include "cli/cli.hpp"
#include "scenegen/hawkeye.hpp"

namespace sigchain::commands {

// What a command line asks for: the scene of `seed`, written into `outdir`.
struct HawkeyeSceneJob {
    std::string seed_text;  // SEED as given (the summary names it so)
    std::uint64_t seed = 0;
    std::string outdir;  // an existing folder
};

// The tool's name, purpose and usage line (--help).
cli::ToolInfo hawkeye_scene_info();
// hawkeye_scene's positional SEED OUTDIR, added to `tool`.
void add_hawkeye_scene_options(cli::Cli& tool);
// The Job of a parsed command line; UsageError for other than two arguments, a SEED
// that is not decimal digits or is larger than 2^64 - 1.
HawkeyeSceneJob hawkeye_scene_job(const cli::po::variables_map& vm);
// "seed S: N structures (...), N trees, N vehicles; N files, ...; T s", the note a run
// ends with.
std::string hawkeye_scene_summary(const std::string& seed, const scenegen::HawkeyeScene& scene,
                                  double seconds);
// The whole command: the scene generated and written, the summary noted through `ctx`.
// Returns the exit status.
int run_hawkeye_scene_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
