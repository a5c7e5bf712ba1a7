// Shared command-line behaviour of every sigchain tool (one tool, one thin
// main: docs/ARCHITECTURE.md).
//
// A tool builds a Cli with its name and one-line purpose, adds its own options and
// positional arguments, and calls run() with the function that does the work. run()
// gives every tool the same: --help (stdout, exit 0, ending "See TOOL(1)."),
// --version, -q/--quiet, -v/--verbose, --progress, and one catch-all that maps
// exceptions to exit codes: 0 ok, 1 bad data or I/O, 2 bad usage.
#pragma once

#include <boost/program_options.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "core/tile.hpp"

namespace sigchain::cli {

namespace po = boost::program_options;

// The reporter of one tool run, built by Cli::run from -q, -v and --progress: messages
// go to stderr as "TOOL: message", progress as a bar with the elapsed time and an
// estimate of the time left ("TOOL: rendering [#####     ] 25% 0:12, 0:36 left"),
// drawn only on a terminal or with --progress, never when quiet.
class Context final : public Reporter {
public:
    Context(std::string tool, int verbosity, bool progress);
    const std::string& tool() const { return m_tool; }
    // -1 quiet, 0 normal, 1+ verbose.
    int verbosity() const { return m_verbosity; }
    bool progress_enabled() const { return m_progress; }
    void warn(const std::string& message) const override;  // "TOOL: warning: message" unless quiet
    void alarm(const std::string& message) const override;  // "TOOL: warning: message" always
    void info(const std::string& message) const override;  // "TOOL: message" when verbose
    void note(const std::string& message) const override;  // "TOOL: message" unless quiet
    bool verbose() const override { return m_verbosity >= 1; }
    // The command line as outputs record it (provenance_command); set by Cli::run.
    const std::string& command() const { return m_command; }
    void set_command(std::string command) { m_command = std::move(command); }
    // The same command's arguments one by one (provenance_args); set by Cli::run.
    const std::vector<std::string>& command_args() const { return m_command_args; }
    void set_command_args(std::vector<std::string> args) { m_command_args = std::move(args); }
    void progress_update(const std::string& label, long done, long total) const override;
    void progress_finish(const std::string& label) const override;

private:
    std::string m_tool;
    std::string m_command;
    std::vector<std::string> m_command_args;
    int m_verbosity;
    bool m_progress;
    // The bar being drawn (one at a time).
    mutable std::mutex m_mutex;
    mutable std::string m_bar_label;
    mutable std::chrono::steady_clock::time_point m_bar_start;
    mutable int m_bar_percent = -1;
    mutable long m_bar_seconds = -1;
};

// "M:SS" or "H:MM:SS" for a duration in seconds (progress bars).
std::string format_duration(double seconds);

// The documented range of a numeric option. Every number of every tool's command line
// is read by parse_number against one: finite, whole where `integer`, and within
// [min, max] (an end excluded when open), else a usage error (exit 2)
// "TOOL: --OPTION: VALUE: must be DESCRIPTION".
struct Range {
    bool integer = false;
    long double min = -std::numeric_limits<long double>::infinity();
    long double max = std::numeric_limits<long double>::infinity();
    bool min_open = false;  // min itself excluded
    bool max_open = false;  // max itself excluded
    // "an integer from 4 to 64", "a number > 0 and <= 3600", "a finite number", ...
    std::string describe() const;
};
// Whole numbers in [min, max].
Range integers(long double min, long double max);
// Finite real numbers in [min, max]; with `min_open`, min itself excluded.
Range reals(long double min, long double max, bool min_open = false);
// Finite real numbers > 0 (up to `max`).
Range positive(long double max = std::numeric_limits<long double>::infinity());
// The shared options' ranges: --threads 0 to 4096, --seed 0 to 2^64 - 1.
Range threads_range();
Range seed_range();

// Reads `text` as the value of `option` (e.g. "--top"): decimal digits with an optional
// sign (integers) or a decimal number as strtod reads it in the C locale, nothing
// before or after; NaN, infinities and values outside `range` are rejected.
// Exact for integers up to 2^64 - 1. Throws UsageError "--top: inf: must be ...".
long double parse_number(const std::string& option, const std::string& text, const Range& range);
// Reads `text` as comma-separated numbers, one per range, each through parse_number
// (e.g. --convergence 4,64,0.01); `form` names them ("MIN,MAX,THRESHOLD") in the usage
// error for a wrong count: "--convergence: 4,64: expected MIN,MAX,THRESHOLD".
std::vector<long double> parse_number_list(const std::string& option, const std::string& text,
                                           const std::vector<Range>& ranges,
                                           const std::string& form);

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
    // The shared options: defined here once, with one meaning in every tool.
    // -o/--output FILE, default standard output ("-").
    void add_output_option(const std::string& default_value = "-");
    // -o/--output FILE (or PATTERN) with no default: the tool fails with a usage
    // error when it is missing (output_path() checks).
    void add_required_output_option(const char* value_name = "FILE", const char* help =
                                        "write to FILE ('-' is standard output); required");
    // --threads N: worker threads, 0 (the default) every core; outputs never depend on it.
    void add_threads_option();
    // --seed N: the seed of every random choice (default 1); outputs depend only on it.
    void add_seed_option(const char* help = "seed of the random numbers (default 1)",
                         std::uint64_t default_value = 1);
    // --co KEY=VALUE, repeatable: a GDAL creation option for GeoTIFF outputs (as
    // gdal_translate -co), e.g. COMPRESS=DEFLATE.
    void add_creation_option();
    // The scene options of every tool that reads a scene (odb(5), SCENE ARGUMENT), so
    // that one command line's serve the whole chain: --material-map FILE,
    // --material-id N, --landuse FILE, --landuse-map FILE (the materials of a mesh or DEM
    // raster given as the scene itself), --up-axis AXIS (a lone mesh's up axis),
    // --allow-degenerate (a .gdb's or DEM's degenerate facets skipped, not an error)
    // and --strict-mesh (a mesh file's degenerate facets an error, not skipped).
    void add_scene_input_options();
    // --strict: what a tool otherwise only warns about (its man page lists what) is an
    // error (exit status 1).
    void add_strict_option(const char* help = "make warnings about the inputs errors");
    // --tile K/N: compute only the K-th of N equal parts of the work (the tool's page says
    // of what: trace's rows), rounded as sigchain::Tile::range; `help` names the parts.
    void add_tile_option(const char* help);
    // A numeric option --NAME VALUE_NAME checked against `range` (parse_number) when the
    // command line is parsed, its default (if any) included; read it with real() or
    // integer(). `help` should state the range as the man page does.
    void add_number(const char* name, const char* value_name, const Range& range,
                    const char* help, const char* default_value = nullptr, bool hidden = false);
    // The same for an option that also takes one word instead of a number (--streams
    // N|auto): `keyword` is accepted as it is, anything else is checked against `range`,
    // its usage error then reading "--NAME: VALUE: must be KEYWORD or DESCRIPTION". Read
    // it with keyword_given(), then real() or integer().
    void add_number_or(const char* name, const char* keyword, const char* value_name,
                       const Range& range, const char* help, const char* default_value = nullptr);
    // Options parsed but not listed by --help (deprecated aliases kept for old scripts).
    po::options_description_easy_init add_hidden_options() { return m_hidden.add_options(); }

    // The long names of the options added so far (not the hidden ones), in the order
    // they were added, the shared ones first: a command that declares its options in
    // groups (trace's rendering and shadow-history options) learns each group's names
    // from the names its declarations added.
    std::vector<std::string> option_names() const;
    // Parses argv as run() does (po::error or UsageError on a bad command line), for a
    // command's tests (lib/commands) that check the Job a command line makes.
    po::variables_map parse(int argc, const char* const* argv) const;
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

// The values of add_scene_input_options() (empty, unset or false when not given).
// UsageError for a negative --material-id. --up-axis is passed as given (lib/scene
// reads it: scene::parse_up_axis).
struct SceneInputOptions {
    std::string material_map;
    std::optional<long> material_id;
    std::string landuse, landuse_map;
    std::string up_axis;
    bool allow_degenerate = false;
    bool strict_mesh = false;
};
SceneInputOptions scene_input(const po::variables_map& vm);

// The values of a positional argument (empty if absent).
std::vector<std::string> args(const po::variables_map& vm, const char* name);

// The value of a numeric option added with add_number (checked when parsed).
double real(const po::variables_map& vm, const char* name);
long long integer(const po::variables_map& vm, const char* name);

// Whether an option added with add_number_or was given its keyword (or defaults to it).
bool keyword_given(const po::variables_map& vm, const char* name, const char* keyword);

// The shared options' values (the options must have been added).
std::string output_path(const po::variables_map& vm);  // UsageError if -o is required and missing
unsigned threads(const po::variables_map& vm);
std::uint64_t seed(const po::variables_map& vm);
bool strict(const po::variables_map& vm);  // --strict given
std::vector<std::string> creation_options(const po::variables_map& vm);  // --co, as given
// --tile K/N (add_tile_option), when given; UsageError unless 1 <= K <= N (integers).
std::optional<Tile> tile(const po::variables_map& vm);
Tile parse_tile(const std::string& text);

// The command line as outputs record it (cube(5), PROVENANCE): the tool's name and its
// arguments, each path reduced to its base name (an argument, or an option's =VALUE,
// holding a '/', but the K/N of --tile), without the options that cannot change an
// output (--threads N, -q, -v, --progress), so that a rerun elsewhere or with other
// threads is byte-identical.
std::string provenance_command(int argc, const char* const* argv);
// The same, argument by argument (the tool's name first).
std::vector<std::string> provenance_args(int argc, const char* const* argv);
// The options of a part of a whole (cube(5), Parts): the recorded arguments without the
// tool's name, the output (-o, --output) and the options that choose the part
// (`part_options`, e.g. --tile and --rows), each with its value; joined by spaces.
// Parts of one whole record the same text, and the merge compares it.
std::string part_options(const std::vector<std::string>& args,
                         const std::vector<std::string>& part_options);

// Whether standard error is a terminal (progress bars default on only then).
bool stderr_is_terminal();

}  // namespace sigchain::cli
