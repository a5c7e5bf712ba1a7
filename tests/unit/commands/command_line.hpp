// The command lines of the commands' tests: arguments after the tool's name, parsed by
// the tool's own cli::Cli as the tool would parse them.
#pragma once

#include <exception>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "core/error.hpp"

namespace sigchain::commands::testing {

// `args` parsed by a Cli made from `info` and the options `add` adds to it.
template <class Add>
cli::po::variables_map parse_line(const cli::ToolInfo& info, Add add,
                                  std::vector<std::string> args) {
    cli::Cli tool(info);
    add(tool);
    args.insert(args.begin(), info.name);
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    return tool.parse(static_cast<int>(argv.size()), argv.data());
}

// The message of the UsageError `make` throws, "po: ..." for a malformed command line
// (an unknown option, a missing value), or "" when it throws none.
template <class Make>
std::string usage_error_of(Make make) {
    try {
        make();
    } catch (const UsageError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("po: ") + e.what();
    }
    return "";
}

}  // namespace sigchain::commands::testing
