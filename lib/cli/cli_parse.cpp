// Cli::parse: the command line into a variables_map (cli.hpp), shared by run() and by
// the tests of each tool's command (lib/commands); Cli::option_names, the options
// declared so far.
#include "cli/cli.hpp"

namespace sigchain::cli {

po::variables_map Cli::parse(int argc, const char* const* argv) const {
    po::options_description all;
    all.add(m_options).add(m_hidden);
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(all).positional(m_positional).run(), vm);
    po::notify(vm);
    return vm;
}

std::vector<std::string> Cli::option_names() const {
    std::vector<std::string> names;
    for (const auto& option : m_options.options()) names.push_back(option->long_name());
    return names;
}

}  // namespace sigchain::cli
