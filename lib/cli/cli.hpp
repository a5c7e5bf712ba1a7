// Shared command-line behaviour of every sigchain tool (STYLE.md "One tool, one thin main").
//
// A tool builds a Cli with its name and one-line purpose, adds its own options and
// positional arguments, and calls run() with the function that does the work. run()
// gives every tool the same: --help (stdout, exit 0, ending "See TOOL(1)."),
// --version, -q/--quiet, -v/--verbose, --progress, and one catch-all that maps
// exceptions to exit codes: 0 ok, 1 bad data or I/O, 2 bad usage.
#pragma once

#include <boost/program_options.hpp>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sigchain::cli {

namespace po = boost::program_options;

// Messages and progress for one tool run. Messages go to stderr as "TOOL: message".
class Context {
public:
    Context(std::string tool, int verbosity, bool progress);
    const std::string& tool() const { return m_tool; }
    // -1 quiet, 0 normal, 1+ verbose.
    int verbosity() const { return m_verbosity; }
    bool progress_enabled() const { return m_progress; }
    void warn(const std::string& message) const;  // "TOOL: warning: message" unless quiet
    void info(const std::string& message) const;  // "TOOL: message" when verbose
    void note(const std::string& message) const;  // "TOOL: message" unless quiet

private:
    std::string m_tool;
    int m_verbosity;
    bool m_progress;
};

// A progress bar on stderr, drawn only when the context enables progress.
class Progress {
public:
    Progress(const Context& ctx, std::size_t total, std::string label);
    ~Progress();
    void update(std::size_t done);

private:
    bool m_enabled;
    std::size_t m_total;
    std::string m_label;
    int m_last_percent = -1;
};

struct ToolInfo {
    std::string name;     // binary name
    std::string purpose;  // one line, for --help
    std::string usage;    // e.g. "[OPTIONS] ADV GDB"
    // The exit-status line of --help; compare follows cmp/diff instead.
    std::string exit_status = "0 ok, 1 bad data or I/O error, 2 bad usage.";
};

class Cli {
public:
    explicit Cli(ToolInfo info);
    // Tool-specific options (added to the "Options" group shown by --help).
    po::options_description_easy_init add_options() { return m_options.add_options(); }
    // A positional argument: `count` 1 for one, -1 for the rest.
    void add_positional(const char* name, int count, const char* help);
    // Adds -o/--output FILE with the given default ("-" means stdout).
    void add_output_option(const std::string& default_value = "-");

    // Parses argv and runs `body`; returns the process exit status.
    int run(int argc, char** argv,
            const std::function<int(const po::variables_map&, Context&)>& body);

private:
    ToolInfo m_info;
    po::options_description m_options;
    po::options_description m_hidden;
    po::positional_options_description m_positional;
    std::string m_positional_help;
    void print_help() const;
};

// The values of a positional argument (empty if absent).
std::vector<std::string> args(const po::variables_map& vm, const char* name);

// Whether standard error is a terminal (progress bars default on only then).
bool stderr_is_terminal();

}  // namespace sigchain::cli
