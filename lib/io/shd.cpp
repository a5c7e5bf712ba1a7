// .shd sun/shadow history (man shd(5)): reader and writer.
#include "io/shd.hpp"
#include "io/header_lines.hpp"
#include "io/tmp.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/error.hpp"

namespace sigchain::io {

namespace {

// Tolerance for matching a row's time to the grid, in hours (well below any useful
// step, well above the rounding of times written with format_number).
constexpr double kTimeToleranceHours = 1e-6;

struct Header {
    std::map<std::string, std::pair<std::string, SourceLocation>, std::less<>> values;
};

// `key = value` lines up to the first FACET.
Header read_header(LineCursor& c) {
    Header h;
    while (!c.at_end()) {
        const Line& line = c.peek("a header line");
        if (line.text.substr(0, 6) == "FACET " || line.text == "FACET") break;
        c.next("a header line");
        auto kv = split_key_value(line.text, c.where(line));
        std::string_view key = kv ? kv->key : std::string_view();
        if (key != "scene_time_hours" && key != "steps" && key != "step_hours" && key != "facets")
            throw DataError(c.where(line),
                            "expected a header key (scene_time_hours, steps, "
                            "step_hours, facets) or FACET, found " +
                                sigchain::quoted(line.text));
        auto it = h.values.find(key);
        if (it != h.values.end())
            throw DataError(c.where(line), "repeated key " + std::string(key) + " (first at line " +
                                               std::to_string(it->second.second.line) + ")");
        h.values.emplace(std::string(key), std::pair{std::string(kv->value), c.where(line)});
    }
    return h;
}

void apply_header(const Header& h, const LineCursor& c, Shd& shd, long& facets) {
    // A missing key is reported at the first FACET (or the end of the file).
    SourceLocation end = c.at_end() ? c.where() : c.where(c.peek(""));
    for (auto key : {"scene_time_hours", "steps", "step_hours", "facets"})
        if (!h.values.count(key))
            throw DataError(end, "expected header key " + std::string(key) +
                                     " before the first FACET, found none");
    auto get = [&](const char* key) -> const auto& { return h.values.at(key); };
    shd.scene_time_hours = parse_double(get("scene_time_hours").first,
                                        get("scene_time_hours").second, "scene_time_hours");
    shd.steps = parse_count(get("steps").first, get("steps").second, "steps");
    if (shd.steps < 1)
        throw DataError(get("steps").second,
                        "expected steps 1 or more, found " + sigchain::quoted(get("steps").first));
    shd.step_hours = parse_double(get("step_hours").first, get("step_hours").second, "step_hours");
    if (shd.step_hours <= 0)
        throw DataError(get("step_hours").second, "expected step_hours greater than 0, found " +
                                                      sigchain::quoted(get("step_hours").first));
    facets = parse_count(get("facets").first, get("facets").second, "facets");
}

ShdFacet read_facet_line(LineCursor& c, long index, long count) {
    std::string what = "FACET " + std::to_string(index + 1) + " of " + std::to_string(count) +
                       " (facets = " + std::to_string(count) + ")";
    const Line& line = c.next(what);
    auto f = split_fields(line.text);
    if (f.empty() || f[0] != "FACET")
        throw DataError(c.where(line),
                        "expected " + what + ", found " + sigchain::quoted(line.text));
    if (f.size() != 4)
        throw DataError(c.where(line),
                        "expected FACET id sky_view_factor points (4 fields), found " +
                            std::to_string(f.size()) + ": " + sigchain::quoted(line.text));
    ShdFacet facet;
    facet.line = line.number;
    if (!is_facet_id(f[1]))
        throw DataError(c.where(line), "expected a facet id such as 1-1-1 or 2.3/1-1-1, found " +
                                sigchain::quoted(f[1]));
    facet.id = std::string(f[1]);
    facet.sky_view_factor = parse_in_range(f[2], c.where(line), "sky view factor", 0, 1);
    facet.points = parse_count(f[3], c.where(line), "points");
    if (facet.points < 1)
        throw DataError(c.where(line),
                        "expected points 1 or more, found " + sigchain::quoted(f[3]));
    return facet;
}

void read_row(LineCursor& c, const Shd& shd, long step, ShdFacet& facet) {
    std::string what = "time step " + std::to_string(step + 1) + " of " +
                       std::to_string(shd.steps) + " for facet " + sigchain::quoted(facet.id);
    const Line& line = c.next(what);
    auto f = split_fields(line.text);
    if (!f.empty() && f[0] == "FACET")
        throw DataError(c.where(line),
                        "expected " + what + ", found " + sigchain::quoted(line.text));
    std::size_t want = 1 + 2 * static_cast<std::size_t>(facet.points);
    if (f.size() != want)
        throw DataError(c.where(line), "expected " + std::to_string(want) +
                                           " fields (time, then sunlit fraction and transmittance "
                                           "for each of " +
                                           std::to_string(facet.points) + " points), found " +
                                           std::to_string(f.size()) + ": " +
                                           sigchain::quoted(line.text));
    double t = parse_double(f[0], c.where(line), "time (hours)");
    double expected = shd.time_hours(step);
    if (std::abs(t - expected) > kTimeToleranceHours * std::max(1.0, std::abs(expected)))
        throw DataError(c.where(line), "expected time " + format_number(expected) + " (hours, " +
                                           what + "), found " + sigchain::quoted(f[0]));
    for (long p = 0; p < facet.points; ++p) {
        facet.sunlit_fraction.push_back(
            parse_in_range(f[1 + 2 * p], c.where(line), "sunlit fraction", 0, 1));
        facet.transmittance.push_back(
            parse_in_range(f[2 + 2 * p], c.where(line), "sun transmittance", 0, 1));
    }
}

}  // namespace

Shd parse_shd(const TextInput& in) {
    require_magic_line(in, "shd", 1);
    Shd shd;
    LineCursor c(in);
    Header h = read_header(c);
    long count = 0;
    apply_header(h, c, shd, count);
    std::set<std::string, std::less<>> ids;
    for (long i = 0; i < count; ++i) {
        ShdFacet facet = read_facet_line(c, i, count);
        if (!ids.insert(facet.id).second)
            throw DataError(in.at(facet.line), "duplicate facet id " + sigchain::quoted(facet.id));
        for (long k = 0; k < shd.steps; ++k) read_row(c, shd, k, facet);
        shd.facets.push_back(std::move(facet));
    }
    if (!c.at_end()) {
        const Line& line = c.peek("");
        bool extra_row = line.text.substr(0, 5) != "FACET";
        std::string why = extra_row && count > 0 ? "the last facet already has its steps = " +
                                                       std::to_string(shd.steps) + " time rows"
                                                 : "facets = " + std::to_string(count);
        throw DataError(c.where(line),
                        "expected end of file (" + why + "), found " + sigchain::quoted(line.text));
    }
    return shd;
}

void write_shd(std::ostream& out, const Shd& shd) {
    out << kShdMagic << '\n';
    out << "scene_time_hours = " << format_number(shd.scene_time_hours) << '\n';
    out << "steps = " << shd.steps << '\n';
    out << "step_hours = " << format_number(shd.step_hours) << '\n';
    out << "facets = " << shd.facets.size() << '\n';
    for (const auto& f : shd.facets) {
        out << "\nFACET " << f.id << ' ' << format_number(f.sky_view_factor) << ' ' << f.points
            << '\n';
        for (long k = 0; k < shd.steps; ++k) {
            out << format_number(shd.time_hours(k));
            for (long p = 0; p < f.points; ++p)
                out << ' ' << format_number(f.sunlit(k, p)) << ' '
                    << format_number(f.sun_transmittance(k, p));
            out << '\n';
        }
    }
}

namespace {

// "1 facet", "2 facets" (for summaries).
std::string plural(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

FormatHandler shd_format() {
    return {"shd", "sun/shadow history (sigchain)",
            [](const TextInput& in) {
                Shd s = parse_shd(in);
                std::ostringstream o;
                o << plural(s.facets.size(), "facet") << ", "
                  << plural(static_cast<std::size_t>(s.steps), "step") << " of "
                  << format_number(s.step_hours) << " h ending at "
                  << format_number(s.scene_time_hours) << " h";
                return o.str();
            },
            [](const TextInput& in, std::ostream& out) { write_shd(out, parse_shd(in)); }};
}

}  // namespace sigchain::io
