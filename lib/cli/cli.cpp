// Shared command-line behaviour: parsing, help, version, messages, exit codes.
#include "cli/cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <thread>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/output.hpp"
#include "sigchain/libraries.hpp"
#include "sigchain/version.hpp"

namespace sigchain::cli {

bool stderr_is_terminal() { return ::isatty(2) == 1; }

Context::Context(std::string tool, int verbosity, bool progress)
    : m_tool(std::move(tool)), m_verbosity(verbosity), m_progress(progress) {}

void Context::warn(const std::string& message) const {
    if (m_verbosity >= 0) std::cerr << m_tool << ": warning: " << message << '\n';
}
void Context::alarm(const std::string& message) const {
    std::cerr << m_tool << ": warning: " << message << '\n';
}
void Context::info(const std::string& message) const {
    if (m_verbosity >= 1) std::cerr << m_tool << ": " << message << '\n';
}
void Context::note(const std::string& message) const {
    if (m_verbosity >= 0) std::cerr << m_tool << ": " << message << '\n';
}

std::string format_duration(double seconds) {
    long s = seconds > 0 ? static_cast<long>(seconds + 0.5) : 0;
    const long h = s / 3600, m = (s / 60) % 60;
    s %= 60;
    char buf[32];
    if (h > 0)
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", h, m, s);
    else
        std::snprintf(buf, sizeof buf, "%ld:%02ld", m, s);
    return buf;
}

void Context::progress_update(const std::string& label, long done, long total) const {
    if (!m_progress || m_verbosity < 0 || total <= 0) return;
    std::lock_guard lock(m_mutex);
    const auto now = std::chrono::steady_clock::now();
    if (label != m_bar_label || m_bar_percent < 0) {
        m_bar_label = label;
        m_bar_start = now;
        m_bar_percent = -1;
        m_bar_seconds = -1;
    }
    const double fraction =
        std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0);
    const int percent = static_cast<int>(100.0 * fraction);
    const double elapsed = std::chrono::duration<double>(now - m_bar_start).count();
    const long whole_seconds = static_cast<long>(elapsed);
    if (percent == m_bar_percent && whole_seconds == m_bar_seconds) return;
    m_bar_percent = percent;
    m_bar_seconds = whole_seconds;
    const int filled = percent / 5;
    std::cerr << '\r' << m_tool << ": " << label << " [" << std::string(filled, '#')
              << std::string(20 - filled, ' ') << "] " << percent << "% "
              << format_duration(elapsed);
    // The time left, extrapolated from the rate so far once there is a rate to go by.
    if (fraction > 0 && fraction < 1 && elapsed > 0.5)
        std::cerr << ", " << format_duration(elapsed * (1 - fraction) / fraction) << " left";
    std::cerr << "\x1b[K" << std::flush;
}

void Context::progress_finish(const std::string& label) const {
    std::lock_guard lock(m_mutex);
    if (label == m_bar_label && m_bar_percent >= 0) std::cerr << '\n';
    m_bar_label.clear();
    m_bar_percent = -1;
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
    m_options.add_options()(
        "output,o", po::value<std::string>()->default_value(default_value)->value_name("FILE"),
        "write to FILE ('-' is standard output)");
}

void Cli::add_required_output_option(const char* value_name, const char* help) {
    m_options.add_options()("output,o", po::value<std::string>()->value_name(value_name), help);
}

void Cli::add_threads_option() {
    add_number("threads", "N", threads_range(),
               "worker threads, 0 to 4096 (0: all cores); outputs do not depend on it", "0");
}

void Cli::add_seed_option(const char* help, std::uint64_t default_value) {
    const std::string text = std::to_string(default_value);
    add_number("seed", "N", seed_range(), help, text.c_str());
}

void Cli::add_number(const char* name, const char* value_name, const Range& range,
                     const char* help, const char* default_value, bool hidden) {
    const std::string long_name(name);  // "bits,b": --bits
    const std::string option = "--" + long_name.substr(0, long_name.find(','));
    auto* value = po::value<std::string>()->value_name(value_name)->notifier(
        [option, range](const std::string& text) { parse_number(option, text, range); });
    if (default_value) value->default_value(default_value);
    (hidden ? m_hidden : m_options).add_options()(name, value, help);
}

void Cli::add_number_or(const char* name, const char* keyword, const char* value_name,
                        const Range& range, const char* help, const char* default_value) {
    const std::string option = std::string("--") + name;
    const std::string word(keyword);
    auto* value = po::value<std::string>()->value_name(value_name)->notifier(
        [option, word, range](const std::string& text) {
            if (text == word) return;
            try {
                parse_number(option, text, range);
            } catch (const UsageError&) {
                throw UsageError(option + ": " + text + ": must be " + word + " or " +
                                 range.describe());
            }
        });
    if (default_value) value->default_value(default_value);
    m_options.add_options()(name, value, help);
}

bool keyword_given(const po::variables_map& vm, const char* name, const char* keyword) {
    return vm.count(name) && vm[name].as<std::string>() == keyword;
}

namespace {

// A range end as text: integers in full, other numbers as %Lg.
std::string end_text(long double v) {
    if (v == std::floor(v) && std::fabs(v) < 1e20L) {
        if (v < 0) return std::to_string(static_cast<long long>(v));
        return std::to_string(static_cast<unsigned long long>(v));
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%Lg", v);
    return buf;
}

}  // namespace

std::string Range::describe() const {
    const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
    const std::string kind = integer ? "an integer" : has_min || has_max ? "a number"
                                                                          : "a finite number";
    if (has_min && has_max && !min_open && !max_open)
        return kind + " from " + end_text(min) + " to " + end_text(max);
    std::string text = kind;
    if (has_min) text += (min_open ? " > " : " >= ") + end_text(min);
    if (has_min && has_max) text += " and";
    if (has_max) text += (max_open ? " < " : " <= ") + end_text(max);
    return text;
}

Range integers(long double min, long double max) {
    Range r;
    r.integer = true;
    r.min = min;
    r.max = max;
    return r;
}

Range reals(long double min, long double max, bool min_open) {
    Range r;
    r.min = min;
    r.max = max;
    r.min_open = min_open;
    return r;
}

Range positive(long double max) { return reals(0, max, true); }

Range threads_range() { return integers(0, 4096); }

Range seed_range() { return integers(0, 18446744073709551615.0L); }

long double parse_number(const std::string& option, const std::string& text, const Range& range) {
    const auto fail = [&] {
        throw UsageError(option + ": " + text + ": must be " + range.describe());
    };
    // One optional sign, then the number and nothing else (from_chars takes no '+').
    std::string_view body(text);
    const bool negative = !body.empty() && body[0] == '-';
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
    if (body.empty() || body[0] == '+' || body[0] == '-') fail();
    long double value = 0;
    if (range.integer) {
        unsigned long long magnitude = 0;
        const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), magnitude);
        if (ec != std::errc() || end != body.data() + body.size()) fail();
        value = static_cast<long double>(magnitude);
    } else {
        double parsed = 0;
        const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), parsed,
                                               std::chars_format::general);
        if (ec != std::errc() || end != body.data() + body.size() || !std::isfinite(parsed))
            fail();
        value = parsed;
    }
    if (negative) value = -value;
    if (value < range.min || value > range.max || (range.min_open && value == range.min) ||
        (range.max_open && value == range.max))
        fail();
    return value;
}

std::vector<long double> parse_number_list(const std::string& option, const std::string& text,
                                           const std::vector<Range>& ranges,
                                           const std::string& form) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (parts.size() != ranges.size())
        throw UsageError(option + ": " + text + ": expected " + form);
    std::vector<long double> values;
    for (std::size_t i = 0; i < parts.size(); ++i)
        values.push_back(parse_number(option, parts[i], ranges[i]));
    return values;
}

double real(const po::variables_map& vm, const char* name) {
    return static_cast<double>(
        parse_number(std::string("--") + name, vm[name].as<std::string>(), Range{}));
}

long long integer(const po::variables_map& vm, const char* name) {
    return static_cast<long long>(parse_number(std::string("--") + name,
                                               vm[name].as<std::string>(),
                                               integers(-9.2e18L, 9.2e18L)));
}

void Cli::add_scene_input_options() {
    m_options.add_options()("material-map", po::value<std::string>()->value_name("FILE"),
                            "a mesh scene's material names to .mat ids (odb(5) MAP FILES)")(
        "landuse", po::value<std::string>()->value_name("FILE"),
        "a DEM scene's land-use raster (with --landuse-map)")(
        "landuse-map", po::value<std::string>()->value_name("FILE"),
        "the land-use classes to .mat ids (odb(5) MAP FILES)");
    // 0 to 2^24, the range of MATERIAL_ID in every format (mat(5); io::kMaxMaterialId).
    add_number("material-id", "N", integers(0, 16777216),
               "one .mat id for every face of a mesh scene, or for a DEM scene's terrain "
               "(0-16777216)");
    m_options.add_options()("up-axis", po::value<std::string>()->value_name("AXIS"),
                            "a mesh scene's up axis, +X -X +Y -Y +Z or -Z (default: +Z for "
                            "OBJ, PLY, STL; glTF and FBX have their own)")(
        "allow-degenerate", "skip a .gdb's or DEM's degenerate facets, with a warning each")(
        "strict-mesh", "make a mesh file's degenerate facets an error instead of skipping them");
}

void Cli::add_creation_option() {
    m_options.add_options()(
        "co", po::value<std::vector<std::string>>()->composing()->value_name("KEY=VALUE"),
        "GDAL creation option of GeoTIFF outputs (repeatable), e.g. COMPRESS=DEFLATE");
}

void Cli::add_strict_option(const char* help) { m_options.add_options()("strict", help); }

void Cli::add_tile_option(const char* help) {
    m_options.add_options()("tile", po::value<std::string>()->value_name("K/N"), help);
}

void Cli::print_help() const {
    std::cout << "Usage: " << m_info.name << ' ' << m_info.usage << "\n"
              << m_info.purpose << "\n\n";
    if (!m_positional_help.empty()) std::cout << "Arguments:\n" << m_positional_help << '\n';
    std::cout << m_options << "\nExit status: " << m_info.exit_status << '\n'
              << "See " << m_info.name << "(1).\n";
}

namespace {

// How long a worker rank waits before reporting an error met before its parts began.
constexpr auto kWorkerReportDelay = std::chrono::seconds(2);

// "TOOL: MESSAGE" on stderr in one write, so that processes sharing the stream never
// interleave it. Under an MPI launcher a worker rank names itself ("TOOL: rank K:
// ..."). An error a worker meets before its parts began is most often one every rank
// meets the same way (the same inputs): the worker waits kWorkerReportDelay first, so
// that when rank 0 failed too the launcher ends the job (Open MPI's mpirun kills every
// rank once one exits non-zero) and rank 0's message is the only one; an error of the
// worker's alone (a file its node lacks) is still reported, late.
void report_error(const std::string& tool, const std::string& message) {
    if (farm_worker() && !farm_worker_working()) std::this_thread::sleep_for(kWorkerReportDelay);
    const std::string rank = farm_worker() ? "rank " + std::to_string(farm_rank()) + ": " : "";
    std::cerr.flush();
    const std::string line = tool + ": " + rank + message + "\n";
    for (std::size_t at = 0; at < line.size();) {
        const ssize_t n = ::write(STDERR_FILENO, line.data() + at, line.size() - at);
        if (n <= 0 && errno != EINTR) break;
        if (n > 0) at += static_cast<std::size_t>(n);
    }
}

}  // namespace

int Cli::run(int argc, char** argv,
             const std::function<int(const po::variables_map&, Context&)>& body) {
    const std::string& tool = m_info.name;
    try {
        const po::variables_map vm = parse(argc, argv);
        if (vm.count("help")) {
            print_help();
            return 0;
        }
        int verbosity = vm.count("quiet") ? -1 : (vm.count("verbose") ? 1 : 0);
        if (vm.count("version")) {
            std::cout << tool << " (sigchain) " << kVersion << '\n';
            if (verbosity > 0) std::cout << "built with:\n" << kLibraryVersions;
            return 0;
        }
        // Temporaries of the run are removed on SIGTERM, SIGINT and SIGHUP (exit 128 + N).
        install_output_signal_handlers();
        Context ctx(tool, verbosity, vm.count("progress") > 0 || stderr_is_terminal());
        ctx.set_command(provenance_command(argc, argv));
        ctx.set_command_args(provenance_args(argc, argv));
        return body(vm, ctx);
    } catch (const po::error& e) {
        report_error(tool, e.what() + ("\nTry '" + tool + " --help'."));
        return 2;
    } catch (const UsageError& e) {
        report_error(tool, e.what() + ("\nTry '" + tool + " --help'."));
        return 2;
    } catch (const NotImplemented& e) {
        report_error(tool, e.what());
        return 1;
    } catch (const Error& e) {
        report_error(tool, e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        report_error(tool, "out of memory");
        return 1;
    } catch (const std::exception& e) {
        report_error(tool, std::string("internal error: ") + e.what());
        return 1;
    }
}

std::vector<std::string> args(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return {};
    return vm[name].as<std::vector<std::string>>();
}

std::string output_path(const po::variables_map& vm) {
    if (!vm.count("output")) throw UsageError("-o FILE is required");
    return vm["output"].as<std::string>();
}

unsigned threads(const po::variables_map& vm) {
    return static_cast<unsigned>(parse_number("--threads", vm["threads"].as<std::string>(),
                                              threads_range()));
}

std::uint64_t seed(const po::variables_map& vm) {
    return static_cast<std::uint64_t>(
        parse_number("--seed", vm["seed"].as<std::string>(), seed_range()));
}

bool strict(const po::variables_map& vm) { return vm.count("strict") > 0; }

std::vector<std::string> creation_options(const po::variables_map& vm) { return args(vm, "co"); }

Tile parse_tile(const std::string& text) {
    const auto slash = text.find('/');
    const std::string what = "--tile: expected K/N (part K of N, 1 <= K <= N), found '" + text + "'";
    if (slash == std::string::npos) throw UsageError(what);
    const Range counts = integers(1, 1000000);
    Tile tile;
    try {
        tile.index = static_cast<long>(parse_number("--tile", text.substr(0, slash), counts));
        tile.count = static_cast<long>(parse_number("--tile", text.substr(slash + 1), counts));
    } catch (const UsageError&) {
        throw UsageError(what);
    }
    if (tile.index > tile.count) throw UsageError(what);
    return tile;
}

std::optional<Tile> tile(const po::variables_map& vm) {
    if (!vm.count("tile")) return std::nullopt;
    return parse_tile(vm["tile"].as<std::string>());
}

SceneInputOptions scene_input(const po::variables_map& vm) {
    SceneInputOptions o;
    auto text = [&](const char* name) {
        return vm.count(name) ? vm[name].as<std::string>() : std::string();
    };
    o.material_map = text("material-map");
    o.landuse = text("landuse");
    o.landuse_map = text("landuse-map");
    if (vm.count("material-id")) o.material_id = static_cast<long>(integer(vm, "material-id"));
    o.up_axis = text("up-axis");
    o.allow_degenerate = vm.count("allow-degenerate") > 0;
    o.strict_mesh = vm.count("strict-mesh") > 0;
    return o;
}

namespace {

// A path's base name ("a/b/c.img" -> "c.img"); other text unchanged.
std::string base_name(const std::string& arg) {
    const auto slash = arg.find_last_of('/');
    return slash == std::string::npos ? arg : arg.substr(slash + 1);
}

}  // namespace

std::vector<std::string> provenance_args(int argc, const char* const* argv) {
    std::vector<std::string> out;
    if (argc > 0) out.push_back(base_name(argv[0]));
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--threads") {
            ++i;  // and its value
            continue;
        }
        if (arg.rfind("--threads=", 0) == 0 || arg == "-q" || arg == "--quiet" || arg == "-v" ||
            arg == "--verbose" || arg == "--progress")
            continue;
        const auto eq = arg.find('=');
        // --tile K/N holds a '/' but no path.
        if (arg.rfind("--tile=", 0) == 0 || (!out.empty() && out.back() == "--tile"))
            out.push_back(arg);
        else if (arg.rfind("--", 0) == 0 && eq != std::string::npos)
            out.push_back(arg.substr(0, eq + 1) + base_name(arg.substr(eq + 1)));
        else
            out.push_back(base_name(arg));
    }
    return out;
}

std::string provenance_command(int argc, const char* const* argv) {
    std::string command;
    for (const std::string& arg : provenance_args(argc, argv))
        command += (command.empty() ? "" : " ") + arg;
    return command;
}

std::string part_options(const std::vector<std::string>& args,
                         const std::vector<std::string>& part_options) {
    std::vector<std::string> dropped = part_options;
    dropped.insert(dropped.end(), {"-o", "--output"});
    std::string out;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        bool drop = arg.rfind("-o", 0) == 0 && arg.size() > 2 && arg[1] == 'o';  // -oFILE
        for (const std::string& o : dropped) {
            if (arg == o) {
                drop = true;
                ++i;  // and its value
            } else if (arg.rfind(o + "=", 0) == 0) {
                drop = true;
            }
        }
        if (!drop) out += (out.empty() ? "" : " ") + arg;
    }
    return out;
}

}  // namespace sigchain::cli
