// The library behind tools/control7 (GDAL-apps style: an options struct in, the work
// done here): ask CONTROL7's questions or read their answers, check the deck by reading
// it back, write it atomically.
#pragma once

#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "core/report.hpp"

namespace sigchain::control7 {

struct Control7Job {
    // Where the answers come from: a file of answers, one per line ("-" standard
    // input), or, when `terminal` is set, typed on a terminal after prompts written
    // to `prompts` (both streams outlive the run).
    std::string answers_path = "-";
    std::istream* terminal = nullptr;
    std::ostream* prompts = nullptr;
    std::map<std::string, std::string> overrides;  // question KEY -> answer (--answer)
    std::string output_path;  // "-" standard output; empty: the deck-name answer
};

// The --answer KEY=VALUE arguments as a map (values trimmed; a later KEY wins).
// Throws UsageError for an argument without '=' or without a key.
std::map<std::string, std::string> parse_answer_overrides(const std::vector<std::string>& args);

// Asks or reads the answers, builds the deck, checks it by reading it back as
// build_radiance will, and writes it atomically. Warns on `reporter` about an --answer
// whose question was not asked. Throws DataError for a bad answer (WHERE: ...) or an
// answer left after IRPT 0.
void run(const Control7Job& job, const Reporter& reporter);

}  // namespace sigchain::control7
