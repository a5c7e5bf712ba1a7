// control7: write a LOWTRAN 7 atmosphere card deck (.cdk) from the answers to CONTROL7's
// questions (White (1996), section 4.2.3.5, fig. 4.30), asked on a terminal or read from
// a pipe or file.
#include <unistd.h>

#include <iostream>

#include "cli/cli.hpp"
#include "control7/control7.hpp"
#include "control7/control7_job.hpp"
#include "core/error.hpp"

namespace cli = sigchain::cli;
namespace control7 = sigchain::control7;

int main(int argc, char** argv) {
    cli::Cli tool({"control7",
                   "Write a LOWTRAN 7 atmosphere card deck (.cdk) from the answers to\n"
                   "CONTROL7's questions, asked on a terminal or read from a pipe or file.",
                   "[OPTIONS] [--answers FILE] [-o CDK]"});
    tool.add_options()("answers", cli::po::value<std::string>()->value_name("FILE"),
                       "read the answers from FILE, one per line ('-' standard input)")(
        "answer,a",
        cli::po::value<std::vector<std::string>>()->composing()->value_name("KEY=VALUE"),
        "answer question KEY with VALUE (repeatable; see --list-questions)")(
        "list-questions", "print every question's KEY and text, then exit")(
        // Not the shared -o: it is optional, the deck-name answer is its default.
        "output,o", cli::po::value<std::string>()->value_name("FILE"),
        "write the deck to FILE ('-' standard output; default: the deck-name answer)");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        if (vm.count("list-questions")) {
            for (const auto& q : control7::control7_questions())
                std::cout << q.key << '\t' << q.text << '\n';
            return 0;
        }
        control7::Control7Job job;
        if (vm.count("answer"))
            job.overrides =
                control7::parse_answer_overrides(vm["answer"].as<std::vector<std::string>>());
        if (vm.count("answers")) {
            job.answers_path = vm["answers"].as<std::string>();
        } else if (::isatty(0) == 1) {
            job.terminal = &std::cin;
            job.prompts = &std::cerr;
        }
        if (vm.count("output")) job.output_path = vm["output"].as<std::string>();
        control7::run(job, ctx);
        return 0;
    });
}
