// Reading and writing .tmp facet-temperature files (man tmp(5)).
#include "io/tmp.hpp"

#include <algorithm>
#include <unordered_map>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

// The header's `key = value` lines (before the first facet row); only time_hours is known.
void parse_header_keys(LineCursor& cur, Tmp& tmp) {
    int time_line = 0;
    while (!cur.at_end()) {
        const Line& line = cur.peek("facet row");
        SourceLocation at = cur.where(line);
        auto kv = split_key_value(line.text, at);
        if (!kv) return;
        cur.next("key = value");
        if (kv->key != "time_hours")
            throw DataError(at, "expected key time_hours, found " + quoted(kv->key));
        if (time_line)
            throw DataError(at,
                            "expected each key once, found 'time_hours' again (first on "
                            "line " +
                                std::to_string(time_line) + ")");
        time_line = line.number;
        double h = parse_double(kv->value, at, "time_hours");
        if (h < 0)
            throw DataError(at, "expected time_hours at or above 0, found " + quoted(kv->value));
        tmp.time_hours = h;
    }
}

FacetTemperature parse_row(const Line& line, const SourceLocation& at) {
    if (line.text.find('=') != std::string_view::npos)
        throw DataError(at,
                        "expected 'key = value' lines only before the first facet row, "
                        "found " +
                            quoted(line.text));
    auto f = split_fields(line.text);
    if (f.size() != 2)
        throw DataError(at, "expected 2 fields (facet id, temperature K), found " +
                                std::to_string(f.size()) + ": " + quoted(line.text));
    if (!is_facet_id(f[0]))
        throw DataError(at, "expected a facet id such as 1-1-1 or 2.3/1-1-1, found " +
                                quoted(f[0]));
    double t = parse_double(f[1], at, "temperature (K)");
    if (t <= 0 || t >= kTmpMaxTemperature_k)
        throw DataError(at,
                        "expected temperature (K) above 0 and below 10000, found " + quoted(f[1]));
    return {std::string(f[0]), t, line.number};
}

}  // namespace

namespace {
// `count` positive or non-negative integers joined by `sep`, each at most 9 digits.
bool is_joined_integers(std::string_view text, char sep, int count, bool positive) {
    int parts = 0;
    std::size_t start = 0;
    while (true) {
        auto end = text.find(sep, start);
        std::string_view part = text.substr(start, end == text.npos ? text.npos : end - start);
        if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != part.npos)
            return false;
        if (positive && part.find_first_not_of('0') == part.npos) return false;
        ++parts;
        if (end == text.npos) break;
        start = end + 1;
    }
    return parts == count;
}
}  // namespace

bool is_facet_id(std::string_view id) {
    auto slash = id.find('/');
    if (slash == id.npos) return is_joined_integers(id, '-', 3, false);
    return is_joined_integers(id.substr(0, slash), '.', 2, true) &&
           is_joined_integers(id.substr(slash + 1), '-', 3, false);
}

Tmp parse_tmp(const TextInput& in) {
    Tmp tmp;
    tmp.minor_version = require_magic_line(in, "tmp", 1);
    LineCursor cur(in);
    parse_header_keys(cur, tmp);
    std::unordered_map<std::string, int> first_line;  // facet id -> line
    while (!cur.at_end()) {
        const Line& line = cur.next("facet row");
        SourceLocation at = cur.where(line);
        FacetTemperature row = parse_row(line, at);
        auto [it, fresh] = first_line.emplace(row.facet_id, line.number);
        if (!fresh)
            throw DataError(at, "expected each facet once, found " + quoted(row.facet_id) +
                                    " again (first on line " + std::to_string(it->second) + ")");
        tmp.facets.push_back(std::move(row));
    }
    require_end_marker(in, "tmp", tmp.minor_version, tmp.facets.size());
    return tmp;
}

void write_tmp(std::ostream& out, const Tmp& tmp) {
    out << "# sigchain-tmp 1.1\n";
    if (tmp.time_hours) out << "time_hours = " << format_number(*tmp.time_hours) << '\n';
    out << "# facet_id temperature_K\n";
    for (const auto& f : tmp.facets)
        out << f.facet_id << ' ' << format_number(f.temperature_k) << '\n';
    out << end_marker_line(tmp.facets.size());
}

FormatHandler tmp_format() {
    return {"tmp", "facet temperatures (sigchain)",
            [](const TextInput& in) {
                Tmp t = parse_tmp(in);
                std::string s = std::to_string(t.facets.size()) + " facets";
                if (!t.facets.empty()) {
                    auto [lo, hi] = std::minmax_element(
                        t.facets.begin(), t.facets.end(), [](const auto& a, const auto& b) {
                            return a.temperature_k < b.temperature_k;
                        });
                    s += ", " + format_number(lo->temperature_k) + "-" +
                         format_number(hi->temperature_k) + " K";
                }
                if (t.time_hours) s += ", time " + format_number(*t.time_hours) + " h";
                return s;
            },
            [](const TextInput& in, std::ostream& out) { write_tmp(out, parse_tmp(in)); }};
}

}  // namespace sigchain::io
