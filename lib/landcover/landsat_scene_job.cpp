// landsat_scene(1): each command's arguments checked and passed to its step.
#include "landcover/landsat_scene_job.hpp"

#include <functional>
#include <map>
#include <stdexcept>

#include "core/error.hpp"
#include "core/output.hpp"
#include "landcover/landsat_scene.hpp"

namespace sigchain::landcover {

namespace {

long long whole(const std::string& text, const char* name, long long min, long long max) {
    std::size_t end = 0;
    long long v = 0;
    try {
        v = std::stoll(text, &end);
    } catch (const std::logic_error&) {
        end = 0;
    }
    if (end == 0 || end != text.size() || v < min || v > max)
        throw UsageError(std::string(name) + " must be an integer from " + std::to_string(min) +
                         " to " + std::to_string(max) + ", found '" + text + "'");
    return v;
}

double real(const std::string& text, const char* name) {
    double v = 0;
    if (!try_parse_double(text, v)) throw UsageError(std::string(name) + ": expected a number, found '" + text + "'");
    return v;
}

// "A,B" as two numbers.
std::pair<double, double> pair_of(const std::string& text, const char* name) {
    const auto comma = text.find(',');
    if (comma == std::string::npos)
        throw UsageError(std::string(name) + ": expected two numbers A,B, found '" + text + "'");
    return {real(text.substr(0, comma), name), real(text.substr(comma + 1), name)};
}

std::vector<int> band_list(const std::string& text) {
    std::vector<int> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto comma = text.find(',', start);
        const auto item = text.substr(start, comma == std::string::npos ? std::string::npos
                                                                          : comma - start);
        out.push_back(static_cast<int>(whole(item, "a band", 1, 1000)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::string optional_path(const std::string& s) { return s == "-" ? std::string() : s; }

std::vector<std::string> rest(const std::vector<std::string>& a, std::size_t from) {
    return {a.begin() + static_cast<long>(std::min(from, a.size())), a.end()};
}

// The terms of an option (classes(5)'s syntax); a malformed one is a usage error.
std::vector<Term> option_terms(const std::string& text, const char* option) {
    try {
        return parse_terms(text, {option, 0});
    } catch (const DataError& e) {
        throw UsageError(e.what());
    }
}

CloudMaskRequest mask_request(const LandsatSceneOptions& o) {
    if (o.sun.empty()) throw UsageError("mask needs --sun ELEVATION,AZIMUTH");
    CloudMaskRequest rq;
    rq.cloud = option_terms(o.cloud, "--cloud");
    rq.dark = option_terms(o.dark, "--dark");
    std::tie(rq.sun_elevation_deg, rq.sun_azimuth_deg) = pair_of(o.sun, "--sun");
    std::tie(rq.min_height_m, rq.max_height_m) = pair_of(o.heights, "--heights");
    if (!(rq.sun_elevation_deg > 0 && rq.sun_elevation_deg <= 90))
        throw UsageError("--sun: the elevation must be > 0 and <= 90 deg");
    if (!(rq.min_height_m >= 0 && rq.max_height_m >= rq.min_height_m && rq.max_height_m <= 20000))
        throw UsageError("--heights: expected 0 <= MIN <= MAX <= 20000 m");
    if (o.buffer < 0 || o.buffer > 100) throw UsageError("--buffer must be 0 to 100");
    if (!(o.pixel_m > 0)) throw UsageError("--pixel must be above 0");
    rq.buffer_px = o.buffer;
    rq.pixel_m = o.pixel_m;
    return rq;
}

// A command's argument count: n after the command, or with `more` at least n.
void need(const std::vector<std::string>& a, std::size_t n, bool more = false) {
    if (a.size() < n + 1 || (!more && a.size() != n + 1))
        throw UsageError(a[0] + " takes " + std::to_string(n) + (more ? " or more" : "") +
                         " arguments, found " + std::to_string(a.size() - 1));
}

using Commands = std::map<std::string, std::function<void()>>;

// The commands that make the scene's products: classes, cloud masks, terrain, training
// points, the reflectance-scale fit and the .ems files.
void add_making_commands(Commands& commands, const std::vector<std::string>& a,
                         const LandsatSceneOptions& o, std::ostream& out, std::ostream& report) {
    commands["classify"] = [&] {
        need(a, 4, true);
        require_outputs_distinct({a[3]}, rest(a, 4));
        classify_step(a[1], rest(a, 4), optional_path(a[2]), a[3], report);
    };
    commands["mask"] = [&] {
        need(a, 2, true);
        require_outputs_distinct({a[1]}, rest(a, 2));
        mask_step(mask_request(o), rest(a, 2), a[1], report);
    };
    commands["terrain"] = [&] {
        need(a, 3);
        terrain_step(a[1], a[2], a[3], report);
    };
    commands["points"] = [&] {
        need(a, 7);
        PointsRequest rq{a[1], a[2], optional_path(a[3]),
                         static_cast<int>(whole(a[4], "PER_CLASS", 1, 1 << 20)),
                         static_cast<std::uint32_t>(whole(a[5], "SEED", 0, 4294967295)),
                         static_cast<long>(whole(a[6], "MARGIN", 0, 1 << 20)), a[7]};
        points_step(rq, report);
    };
    commands["fit"] = [&] {
        need(a, 4);
        fit_step(a[1], a[2], a[3], a[4], out);
    };
    commands["ems"] = [&] {
        need(a, 4);
        ems_step(a[1], a[2], a[3], a[4]);
    };
}

// The commands that judge the products: scores, images side by side and of the
// difference, statistics, cross tabulation and pairs of values.
void add_judging_commands(Commands& commands, const std::vector<std::string>& a,
                          const LandsatSceneOptions& o, std::ostream& out) {
    commands["score"] = [&] {
        need(a, 4);
        score_step({a[1], a[2], a[3], a[4], o.masks, o.points, o.bands}, out);
    };
    commands["side-by-side"] = [&] {
        need(a, 4);
        require_outputs_distinct({a[4]}, {a[1], a[2]});
        side_by_side_step(a[1], a[2], band_list(a[3]), a[4]);
    };
    commands["difference"] = [&] {
        need(a, 5);
        require_outputs_distinct({a[5]}, {a[1], a[2]});
        difference_step(a[1], a[2], static_cast<int>(whole(a[3], "BAND", 1, 1000)),
                        real(a[4], "RANGE"), o.masks, a[5]);
    };
    commands["stats"] = [&] {
        need(a, 3);
        stats_step(a[1], a[2], a[3], o.masks, out);
    };
    commands["crosstab"] = [&] {
        need(a, 4);
        crosstab_step(a[1], a[2], a[3], a[4], o.masks, out);
    };
    commands["pairs"] = [&] {
        need(a, 6);
        pairs_step(a[1], a[2], a[3], a[4], o.masks, static_cast<int>(whole(a[5], "BAND", 1, 1000)),
                   static_cast<long>(whole(a[6], "STEP", 1, 1 << 30)), out);
    };
}

}  // namespace

int run_landsat_scene(const std::vector<std::string>& a, const LandsatSceneOptions& o,
                      std::ostream& out, std::ostream& report) {
    const std::string command = a.empty() ? "" : a[0];
    Commands commands;
    add_making_commands(commands, a, o, out, report);
    add_judging_commands(commands, a, o, out);
    const auto it = commands.find(command);
    if (it == commands.end())
        throw UsageError(command.empty() ? "expected a COMMAND" : "unknown command '" + command + "'");
    it->second();
    return 0;
}

}  // namespace sigchain::landcover
