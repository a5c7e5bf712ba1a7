// Reading and writing the .wth weather history (White (1996), fig. 4.32; man wth(5)).
#include "io/wth.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace sigchain::io {

// Widths sum to kWthFixedRecordWidth (76). The file of White (1996) is in the whitespace form;
// this fixed-width layout is sigchain's reading of DIRSIG's later files (man wth(5)).
const WthColumn kWthColumns[kWthFields] = {
    {"time (h)", 6, 2},
    {"air temperature (C)", 6, 2},
    {"pressure (mb)", 8, 2},
    {"relative humidity (%)", 7, 2},
    {"dew point (C)", 6, 2},
    {"wind speed (m/s)", 6, 2},
    {"direct insolation (Ly/h)", 7, 2},
    {"diffuse insolation (Ly/h)", 7, 2},
    {"sky exposure", 5, 2},
    {"cloud type", 3, 0},
    {"precipitation type", 3, 0},
    {"precipitation rate (cm/h)", 6, 2},
    {"precipitation temperature (C)", 6, 2},
};

namespace {

constexpr double kAbsoluteZero_c = -273.15;

// A data line: comment (from '#') and trailing blanks removed; leading blanks kept,
// since they place the fields of the fixed-width form.
struct DataLine {
    int number;
    std::string_view text;
};

std::vector<DataLine> data_lines(const TextInput& in) {
    std::vector<DataLine> out;
    LineCursor cur(in, LineCursor::Mode::Raw);
    while (!cur.at_end()) {
        const Line& line = cur.next("");
        std::string_view t = line.text.substr(0, line.text.find('#'));
        auto end = t.find_last_not_of(" \t");
        if (end == std::string_view::npos) continue;
        out.push_back({line.number, t.substr(0, end + 1)});
    }
    return out;
}

// Column range text "columns 7-12" of fixed field i.
std::string columns_of(int i) {
    int start = 1;
    for (int k = 0; k < i; ++k) start += kWthColumns[k].width;
    return "columns " + std::to_string(start) + "-" +
           std::to_string(start + kWthColumns[i].width - 1);
}

std::vector<std::string_view> fixed_slices(std::string_view text) {
    std::vector<std::string_view> out;
    std::size_t at = 0;
    for (const auto& c : kWthColumns) {
        out.push_back(trim(text.substr(at, static_cast<std::size_t>(c.width))));
        at += static_cast<std::size_t>(c.width);
    }
    return out;
}

// The fixed-width form: exactly the record width, no tab, one number-like token per
// field, and a whitespace split that either agrees with the fields or cannot work
// (fewer than 13 tokens, because values touch).
bool looks_fixed(std::string_view text) {
    if (text.find('\t') != std::string_view::npos ||
        text.size() != static_cast<std::size_t>(kWthFixedRecordWidth))
        return false;
    auto slices = fixed_slices(text);
    for (auto s : slices)
        if (s.empty() || s.find(' ') != std::string_view::npos) return false;
    auto tokens = split_fields(text);
    return tokens.size() < static_cast<std::size_t>(kWthFields) || tokens == slices;
}

std::vector<std::string_view> row_fields(const DataLine& line, WthForm form, int form_line,
                                         const TextInput& in) {
    SourceLocation at = in.at(line.number);
    if (form == WthForm::Whitespace) {
        auto f = split_fields(line.text);
        if (f.size() != static_cast<std::size_t>(kWthFields))
            throw DataError(at,
                            "expected 13 fields (time, air temperature, pressure, relative "
                            "humidity, dew point, wind speed, direct and diffuse insolation, "
                            "sky exposure, cloud type, precipitation type, rate and "
                            "temperature), found " +
                                std::to_string(f.size()) + ": " + quoted(line.text));
        return f;
    }
    std::string form_note = " (the fixed-width form of line " + std::to_string(form_line) + ")";
    if (line.text.find('\t') != std::string_view::npos ||
        line.text.size() != static_cast<std::size_t>(kWthFixedRecordWidth))
        throw DataError(at, "expected a row of 76 columns without tabs" + form_note + ", found " +
                                std::to_string(line.text.size()) +
                                " columns: " + quoted(line.text));
    auto slices = fixed_slices(line.text);
    for (int i = 0; i < kWthFields; ++i) {
        auto s = slices[static_cast<std::size_t>(i)];
        if (s.empty() || s.find(' ') != std::string_view::npos)
            throw DataError(at, "expected " + std::string(kWthColumns[i].name) + " in " +
                                    columns_of(i) + form_note + ", found " +
                                    (s.empty() ? std::string("blanks")
                                               : quoted(s) + " (a blank inside the number)"));
    }
    return slices;
}

double number(std::string_view token, const SourceLocation& at, int i) {
    return parse_double(token, at, kWthColumns[i].name);
}

double at_least(std::string_view token, const SourceLocation& at, int i, double lo) {
    double v = number(token, at, i);
    if (v < lo)
        throw DataError(at, "expected " + std::string(kWthColumns[i].name) + " at least " +
                                format_number(lo) + ", found " + quoted(token));
    return v;
}

double in_range(std::string_view token, const SourceLocation& at, int i, double lo, double hi) {
    return parse_in_range(token, at, kWthColumns[i].name, lo, hi);
}

long category(std::string_view token, const SourceLocation& at, int i) {
    return parse_count(token, at, kWthColumns[i].name);
}

WthRow parse_row(const std::vector<std::string_view>& f, const SourceLocation& at) {
    WthRow r;
    r.time_h = number(f[0], at, 0);
    r.air_temperature_c = at_least(f[1], at, 1, kAbsoluteZero_c);
    r.pressure_mb = number(f[2], at, 2);
    if (r.pressure_mb <= 0)
        throw DataError(at, "expected pressure (mb) above 0, found " + quoted(f[2]));
    r.relative_humidity_pct = number(f[3], at, 3);
    if (r.relative_humidity_pct != -1 &&
        (r.relative_humidity_pct < 0 || r.relative_humidity_pct > 100))
        throw DataError(at,
                        "expected relative humidity (%) in [0, 100], or -1 to use the dew "
                        "point, found " +
                            quoted(f[3]));
    r.dew_point_c = at_least(f[4], at, 4, kAbsoluteZero_c);
    r.wind_speed_m_s = at_least(f[5], at, 5, 0);
    r.direct_insolation_ly_h = at_least(f[6], at, 6, 0);
    r.diffuse_insolation_ly_h = at_least(f[7], at, 7, 0);
    r.sky_exposure = in_range(f[8], at, 8, 0, 1);
    r.cloud_type = category(f[9], at, 9);
    r.precipitation_type = category(f[10], at, 10);
    r.precipitation_rate_cm_h = at_least(f[11], at, 11, 0);
    r.precipitation_temperature_c = at_least(f[12], at, 12, kAbsoluteZero_c);
    return r;
}

void check_times(const Wth& w, const std::vector<DataLine>& lines, const TextInput& in) {
    for (std::size_t i = 1; i < w.rows.size(); ++i) {
        double previous = w.rows[i - 1].time_h, t = w.rows[i].time_h;
        double want = previous + w.increment_h;
        if (std::fabs(t - want) <= kWthTimeTolerance_h) continue;
        std::string why = t <= previous ? " (times must increase)" : "";
        throw DataError(in.at(lines[i + 1].number),
                        "expected time (h) " + format_number(want) + " (the previous row's " +
                            format_number(previous) + " + the header's increment " +
                            format_number(w.increment_h) + "), found " + format_number(t) + why);
    }
}

void check_count(long count, const Wth& w, const std::vector<DataLine>& lines,
                 const TextInput& in) {
    auto found = static_cast<long>(w.rows.size());
    if (found == count) return;
    std::string msg = "header (line " + std::to_string(lines[0].number) + ") says " +
                      std::to_string(count) + " rows, found " + std::to_string(found);
    if (found < count)
        throw DataError(in.at(lines.back().number), msg + " (unexpected end of file)");
    throw DataError(in.at(lines[static_cast<std::size_t>(count) + 1].number), msg);
}

std::string fixed_field(double value, const WthColumn& c) {
    char buf[400];
    auto fits = [&](const std::string& s) { return s.size() <= static_cast<std::size_t>(c.width); };
    auto pad = [&](const std::string& s) {
        return std::string(static_cast<std::size_t>(c.width) - s.size(), ' ') + s;
    };
    for (int d = c.decimals; d <= c.decimals + 8; ++d) {
        std::snprintf(buf, sizeof buf, "%.*f", d, value);
        if (!fits(buf)) break;
        if (std::strtod(buf, nullptr) == value) return pad(buf);
    }
    std::string shortest = format_number(value);
    if (fits(shortest)) return pad(shortest);
    throw Error(std::string("cannot write ") + c.name + " " + shortest + " in " +
                std::to_string(c.width) + " columns");
}

std::vector<double> row_values(const WthRow& r) {
    return {r.time_h,
            r.air_temperature_c,
            r.pressure_mb,
            r.relative_humidity_pct,
            r.dew_point_c,
            r.wind_speed_m_s,
            r.direct_insolation_ly_h,
            r.diffuse_insolation_ly_h,
            r.sky_exposure,
            static_cast<double>(r.cloud_type),
            static_cast<double>(r.precipitation_type),
            r.precipitation_rate_cm_h,
            r.precipitation_temperature_c};
}

std::string summary(const Wth& w) {
    std::ostringstream s;
    s << w.rows.size() << " rows at " << format_number(w.increment_h) << " h, "
      << format_number(w.rows.front().time_h) << "-" << format_number(w.rows.back().time_h)
      << " h, " << (w.form == WthForm::Whitespace ? "whitespace" : "fixed-width") << " form";
    return s.str();
}

}  // namespace

Wth parse_wth(const TextInput& in) {
    auto lines = data_lines(in);
    if (lines.empty())
        throw DataError(in.at(0), "empty file, expected a .wth header (row count, increment h)");
    Wth w;
    SourceLocation header_at = in.at(lines[0].number);
    auto h = split_fields(lines[0].text);
    if (h.size() != 2)
        throw DataError(header_at, "expected 2 header fields (row count, increment (h)), found " +
                                       std::to_string(h.size()) + ": " + quoted(lines[0].text));
    long count = parse_count(h[0], header_at, "row count");
    if (count == 0) throw DataError(header_at, "expected a row count above 0, found '0'");
    w.increment_h = parse_double(h[1], header_at, "increment (h)");
    if (w.increment_h <= 0)
        throw DataError(header_at, "expected increment (h) above 0, found " + quoted(h[1]));
    if (lines.size() > 1 && looks_fixed(lines[1].text)) w.form = WthForm::FixedWidth;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        auto f = row_fields(lines[i], w.form, lines[1].number, in);
        w.rows.push_back(parse_row(f, in.at(lines[i].number)));
    }
    check_count(count, w, lines, in);
    check_times(w, lines, in);
    return w;
}

void write_wth(std::ostream& out, const Wth& w) {
    bool fixed = w.form == WthForm::FixedWidth;
    out << w.rows.size() << (fixed ? " " : "\t") << format_number(w.increment_h) << '\n';
    for (const auto& r : w.rows) {
        auto v = row_values(r);
        for (int i = 0; i < kWthFields; ++i) {
            double x = v[static_cast<std::size_t>(i)];
            if (fixed)
                out << fixed_field(x, kWthColumns[i]);
            else
                out << (i ? "\t" : "") << format_number(x);
        }
        out << '\n';
    }
}

FormatHandler wth_format() {
    return {"wth", "weather history (White (1996), fig. 4.32)",
            [](const TextInput& in) { return summary(parse_wth(in)); },
            [](const TextInput& in, std::ostream& out) { write_wth(out, parse_wth(in)); }};
}

}  // namespace sigchain::io
