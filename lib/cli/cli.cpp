// Shared command-line behaviour: parsing, help, version, messages, exit codes.
#include "cli/cli.hpp"

#include <unistd.h>

#include <iostream>
#include <new>

#include "core/error.hpp"
#include "sigchain/version.hpp"

namespace sigchain::cli {

bool stderr_is_terminal() { return ::isatty(2) == 1; }

Context::Context(std::string tool, int verbosity, bool progress)
    : m_tool(std::move(tool)), m_verbosity(verbosity), m_progress(progress) {}

void Context::warn(const std::string& message) const {
    if (m_verbosity >= 0) std::cerr << m_tool << ": warning: " << message << '\n';
}
void Context::info(const std::string& message) const {
    if (m_verbosity >= 1) std::cerr << m_tool << ": " << message << '\n';
}
void Context::note(const std::string& message) const {
    if (m_verbosity >= 0) std::cerr << m_tool << ": " << message << '\n';
}

Progress::Progress(const Context& ctx, std::size_t total, std::string label)
    : m_enabled(ctx.progress_enabled() && ctx.verbosity() >= 0 && total > 0),
      m_total(total),
      m_label(ctx.tool() + ": " + std::move(label)) {}

Progress::~Progress() {
    if (m_enabled && m_last_percent >= 0) std::cerr << '\n';
}

void Progress::update(std::size_t done) {
    if (!m_enabled) return;
    int percent =
        static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(m_total));
    if (percent == m_last_percent) return;
    m_last_percent = percent;
    int filled = percent / 5;
    std::cerr << '\r' << m_label << " [" << std::string(filled, '#')
              << std::string(20 - filled, ' ') << "] " << percent << '%' << std::flush;
}

Cli::Cli(ToolInfo info) : m_info(std::move(info)), m_options("Options"), m_hidden("hidden") {
    m_options.add_options()("help,h", "print this help and exit")(
        "version", "print the version and exit (with -v, also library versions)")(
        "quiet,q", "print no warnings or notes")("verbose,v",
                                                 "print what is done and what is skipped")(
        "progress", "draw a progress bar on stderr even when it is not a terminal");
}

void Cli::add_positional(const char* name, int count, const char* help) {
    m_hidden.add_options()(name, po::value<std::vector<std::string>>(), help);
    m_positional.add(name, count);
    std::string n(name);
    m_positional_help +=
        "  " + n + std::string(n.size() < 18 ? 18 - n.size() : 1, ' ') + help + '\n';
}

void Cli::add_output_option(const std::string& default_value) {
    m_options.add_options()("output,o", po::value<std::string>()->default_value(default_value),
                            "write to FILE ('-' is standard output)");
}

void Cli::print_help() const {
    std::cout << "Usage: " << m_info.name << ' ' << m_info.usage << "\n"
              << m_info.purpose << "\n\n";
    if (!m_positional_help.empty()) std::cout << "Arguments:\n" << m_positional_help << '\n';
    std::cout << m_options << "\nExit status: " << m_info.exit_status << '\n'
              << "See " << m_info.name << "(1).\n";
}

int Cli::run(int argc, char** argv,
             const std::function<int(const po::variables_map&, Context&)>& body) {
    const std::string& tool = m_info.name;
    try {
        po::options_description all;
        all.add(m_options).add(m_hidden);
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(m_positional).run(),
                  vm);
        po::notify(vm);
        if (vm.count("help")) {
            print_help();
            return 0;
        }
        int verbosity = vm.count("quiet") ? -1 : (vm.count("verbose") ? 1 : 0);
        if (vm.count("version")) {
            std::cout << tool << " (sigchain) " << kVersion << '\n';
            if (verbosity > 0) std::cout << "Boost " << BOOST_LIB_VERSION << '\n';
            return 0;
        }
        Context ctx(tool, verbosity, vm.count("progress") > 0 || stderr_is_terminal());
        return body(vm, ctx);
    } catch (const po::error& e) {
        std::cerr << tool << ": " << e.what() << "\nTry '" << tool << " --help'.\n";
        return 2;
    } catch (const UsageError& e) {
        std::cerr << tool << ": " << e.what() << "\nTry '" << tool << " --help'.\n";
        return 2;
    } catch (const NotImplemented& e) {
        std::cerr << tool << ": " << e.what() << '\n';
        return 1;
    } catch (const Error& e) {
        std::cerr << tool << ": " << e.what() << '\n';
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr << tool << ": out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << tool << ": internal error: " << e.what() << '\n';
        return 1;
    }
}

std::vector<std::string> args(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return {};
    return vm[name].as<std::vector<std::string>>();
}

}  // namespace sigchain::cli
