// sigchain-check: validate sigchain files of any format, or rewrite one canonically.
#include <iostream>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "io/check.hpp"
#include "io/registry.hpp"

namespace cli = sigchain::cli;

int main(int argc, char** argv) {
    cli::Cli tool({"sigchain-check", "Validate sigchain input files, or rewrite one canonically.",
                   "[OPTIONS] FILE..."});
    tool.add_positional("file", -1, "files to check ('-' reads standard input; needs --format)");
    tool.add_options()(
        "format,f", cli::po::value<std::string>()->default_value("")->value_name("EXT"),
        "format of every FILE (extension without the dot), instead of each name's extension")(
        "rewrite", "write the one FILE back in canonical form (to -o)")(
        "list-formats", "list the known formats and exit");
    tool.add_output_option();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        if (vm.count("list-formats")) {
            for (const auto& f : sigchain::io::formats())
                std::cout << f.extension << '\t' << f.description << '\n';
            return 0;
        }
        auto files = cli::args(vm, "file");
        if (files.empty()) throw sigchain::UsageError("no input files");
        const auto& format = vm["format"].as<std::string>();
        if (vm.count("rewrite")) {
            if (files.size() != 1) throw sigchain::UsageError("--rewrite takes exactly one FILE");
            sigchain::require_outputs_distinct({cli::output_path(vm)}, files);
            sigchain::AtomicOutput out(cli::output_path(vm));
            sigchain::io::check_file(files[0], format, &out.stream());
            out.commit();
            return 0;
        }
        int status = 0;
        for (const auto& file : files) {
            try {
                std::string summary = sigchain::io::check_file(file, format, nullptr);
                if (ctx.verbosity() >= 0) std::cout << file << ": ok: " << summary << '\n';
            } catch (const sigchain::DataError& e) {
                std::cerr << ctx.tool() << ": " << e.what() << '\n';
                status = 1;
            } catch (const sigchain::IoError& e) {
                std::cerr << ctx.tool() << ": " << e.what() << '\n';
                status = 1;
            }
        }
        return status;
    });
}
