// The library behind tools/control7 (see control7_job.hpp).
#include "control7/control7_job.hpp"

#include <memory>
#include <sstream>

#include "atmos_table/deck_options.hpp"
#include "control7/control7.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "io/cdk.hpp"

namespace sigchain::control7 {

std::map<std::string, std::string> parse_answer_overrides(const std::vector<std::string>& args) {
    std::map<std::string, std::string> overrides;
    for (const auto& kv : args) {
        auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw UsageError("--answer expects KEY=VALUE, found '" + kv + "'");
        overrides[kv.substr(0, eq)] = std::string(trim(kv.substr(eq + 1)));
    }
    return overrides;
}

namespace {

// The answers of a job: typed on its terminal, or its answers file read line by line.
Control7Result ask(const Control7Job& job) {
    // -o naming the answers file: refused before anything is read.
    require_outputs_distinct({job.output_path}, {job.answers_path});
    if (job.terminal && job.prompts) {
        TerminalAnswers source(*job.terminal, *job.prompts);
        return run_control7(source, job.overrides);
    }
    LineAnswers lines(TextInput::from_file(job.answers_path));
    Control7Result result = run_control7(lines, job.overrides);
    if (auto extra = lines.leftover())
        throw DataError(lines.where(), "unexpected answer after IRPT 0, found " + quoted(*extra));
    return result;
}

}  // namespace

void run(const Control7Job& job, const Reporter& reporter) {
    const Control7Result result = ask(job);
    for (const auto& key : result.unused_overrides)
        reporter.warn("--answer " + key + ": question not asked with these answers");
    // The deck, checked by reading it back as build_radiance will.
    std::ostringstream deck;
    io::write_cdk(deck, result.cdk);
    io::parse_cdk(TextInput::from_string(deck.str(), "<deck>"));
    const std::string path = job.output_path.empty() ? result.deck_path : job.output_path;
    require_outputs_distinct({path}, {job.answers_path});
    // A valid LOWTRAN 7 deck that build_radiance would refuse: said now, not later.
    for (const std::string& why : atmos_table::deck_refusals(result.cdk))
        reporter.warn("build_radiance will refuse this deck: " + why);
    AtomicOutput out(path);
    out.stream() << deck.str();
    out.commit();
    reporter.info("wrote " + (path == "-" ? std::string("the deck to standard output") : path));
}

}  // namespace sigchain::control7
