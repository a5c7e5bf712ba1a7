// The library behind tools/build_radiance (GDAL-apps style: an options struct in, the
// work done here): read the card deck and the scene node, build the tables, write one
// .rad per band atomically, report what was computed.
#pragma once

#include <string>
#include <vector>

#include "atmos_table/build_radiance.hpp"
#include "core/report.hpp"

namespace sigchain::atmos_table {

struct BuildRadianceJob {
    std::string cdk_path;        // LOWTRAN 7 card deck; "-" standard input
    std::string snd_path;        // scene node; "-" standard input (not both)
    std::string output_pattern;  // band N is written to the pattern with %d -> N
    std::string data_dir;        // reference data; empty: core/data_dir's default
    RadianceOptions options;     // its data_dir, snd_path and cdk_path are set by run
    // --write-decks DIR: write a LOWTRAN 7 deck per path and DIR/runs.t7m instead of
    // tables (tape7_decks); --from-tape7 LIST: assemble the tables from the TAPE7s a
    // run list (.t7m, or a directory holding runs.t7m) names (tape7_radiance).
    std::string write_decks_dir;
    std::string from_tape7;
};

// Throws UsageError for a job that cannot run: both inputs on standard input, --top or
// --merge-tau out of range, an option out of range (check_radiance_options).
void check_job(const BuildRadianceJob& job);

// The output file of every band of `snd`, from the job's pattern; UsageError for a bad
// pattern or "-" with several bands.
std::vector<std::string> band_output_paths(const std::string& pattern, const io::Snd& snd);

// Checks the job, reads its inputs, builds the tables (progress and --verbose details
// on `reporter`) and writes every band's .rad atomically: no band is written unless the
// tables of every band were computed.
void run(const BuildRadianceJob& job, const Reporter& reporter);

}  // namespace sigchain::atmos_table
