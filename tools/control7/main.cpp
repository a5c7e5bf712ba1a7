// control7: write a LOWTRAN 7 atmosphere card deck (.cdk) from the answers to CONTROL7's
// questions (seed 4.2.3.5, fig. 4.30), asked on a terminal or read from a pipe or file.
#include <unistd.h>

#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "atmos/control7.hpp"
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "io/cdk.hpp"

namespace cli = sigchain::cli;
namespace atmos = sigchain::atmos;

int main(int argc, char** argv) {
    cli::Cli tool({"control7",
                   "Write a LOWTRAN 7 atmosphere card deck (.cdk) from the answers to\n"
                   "CONTROL7's questions, asked on a terminal or read from a pipe or file.",
                   "[OPTIONS] [--answers FILE] [-o CDK]"});
    tool.add_options()("answers", cli::po::value<std::string>(),
                       "read the answers from FILE, one per line ('-' standard input)")(
        "answer,a", cli::po::value<std::vector<std::string>>()->composing(),
        "KEY=VALUE: answer question KEY with VALUE (repeatable; see --list-questions)")(
        "list-questions", "print every question's KEY and text, then exit")(
        "output,o", cli::po::value<std::string>(),
        "write the deck to FILE ('-' standard output; default: the deck-name answer)");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        if (vm.count("list-questions")) {
            for (const auto& q : atmos::control7_questions())
                std::cout << q.key << '\t' << q.text << '\n';
            return 0;
        }
        std::map<std::string, std::string> overrides;
        if (vm.count("answer")) {
            for (const auto& kv : vm["answer"].as<std::vector<std::string>>()) {
                auto eq = kv.find('=');
                if (eq == std::string::npos || eq == 0)
                    throw sigchain::UsageError("--answer expects KEY=VALUE, found '" + kv + "'");
                overrides[kv.substr(0, eq)] = std::string(sigchain::trim(kv.substr(eq + 1)));
            }
        }
        std::unique_ptr<atmos::AnswerSource> source;
        atmos::LineAnswers* lines = nullptr;
        if (vm.count("answers")) {
            auto p = std::make_unique<atmos::LineAnswers>(
                sigchain::TextInput::from_file(vm["answers"].as<std::string>()));
            lines = p.get();
            source = std::move(p);
        } else if (::isatty(0) == 1) {
            source = std::make_unique<atmos::TerminalAnswers>(std::cin, std::cerr);
        } else {
            auto p = std::make_unique<atmos::LineAnswers>(sigchain::TextInput::from_file("-"));
            lines = p.get();
            source = std::move(p);
        }
        atmos::Control7Result result = atmos::run_control7(*source, overrides);
        if (lines) {
            if (auto extra = lines->leftover())
                throw sigchain::DataError(lines->where(), "unexpected answer after IRPT 0, found " +
                                                              sigchain::quoted(*extra));
        }
        for (const auto& key : result.unused_overrides)
            ctx.warn("--answer " + key + ": question not asked with these answers");
        // The deck, checked by reading it back as build_radiance will.
        std::ostringstream deck;
        sigchain::io::write_cdk(deck, result.cdk);
        sigchain::io::parse_cdk(sigchain::TextInput::from_string(deck.str(), "<deck>"));
        const std::string path =
            vm.count("output") ? vm["output"].as<std::string>() : result.deck_path;
        sigchain::AtomicOutput out(path);
        out.stream() << deck.str();
        out.commit();
        ctx.info("wrote " + (path == "-" ? std::string("the deck to standard output") : path));
        return 0;
    });
}
