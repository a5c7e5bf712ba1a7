// Reading and writing relative spectral response tables (man rsr(5)).
#include "io/rsr.hpp"

namespace sigchain::io {

namespace {

// The physical lines of a text, numbered from 1, CR removed.
template <class F>
void for_each_line(const std::string& text, F&& f) {
    std::size_t pos = 0;
    for (int number = 1; pos < text.size(); ++number) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        f(number, line);
        pos = end + 1;
    }
}

}  // namespace

RsrTable parse_rsr(const TextInput& in) {
    RsrTable t;
    std::string columns;
    int columns_line = 0;
    bool rows_started = false;
    for_each_line(in.text(), [&](int number, std::string_view raw) {
        std::string_view line = trim(raw);
        if (line.empty()) return;
        if (line.front() == '#') {
            if (!rows_started) {
                t.header.emplace_back(line.substr(1));
                columns = std::string(line.substr(1));
                columns_line = number;
            }
            return;
        }
        const SourceLocation where = in.at(number);
        if (!rows_started) {
            rows_started = true;
            auto names = split_fields(columns);
            if (columns_line == 0 || names.size() < 2 || names[0] != "wavelength_nm")
                throw DataError(columns_line ? in.at(columns_line) : where,
                                "expected a '# wavelength_nm BAND ...' line naming the columns "
                                "before the first row");
            t.header.pop_back();  // the column line is kept as names, not as header text
            t.wavelength_column = std::string(names[0]);
            for (std::size_t i = 1; i < names.size(); ++i) t.band_names.emplace_back(names[i]);
            t.response.resize(t.band_names.size());
        }
        if (auto hash = line.find('#'); hash != std::string_view::npos)
            line = trim(line.substr(0, hash));
        auto f = split_fields(line);
        if (f.size() != t.band_names.size() + 1)
            throw DataError(where, "expected " + std::to_string(t.band_names.size() + 1) +
                                       " fields (the columns on line " +
                                       std::to_string(columns_line) + "), found " +
                                       std::to_string(f.size()));
        const double wl = parse_double(f[0], where, "wavelength (nm)");
        if (!(wl > 0)) throw DataError(where, "expected a wavelength above 0 nm, found " + quoted(f[0]));
        if (!t.wavelength_nm.empty() && !(wl > t.wavelength_nm.back()))
            throw DataError(where, "expected wavelengths strictly increasing, found " +
                                       quoted(f[0]) + " after " +
                                       format_number(t.wavelength_nm.back()));
        t.wavelength_nm.push_back(wl);
        for (std::size_t b = 0; b < t.band_names.size(); ++b)
            t.response[b].push_back(parse_double(f[b + 1], where, "response of " + t.band_names[b]));
        t.row_lines.push_back(number);
    });
    if (t.wavelength_nm.size() < 2)
        throw DataError(in.at(0), "expected at least 2 rows of a response table, found " +
                                      std::to_string(t.wavelength_nm.size()));
    return t;
}

void write_rsr(std::ostream& out, const RsrTable& t) {
    for (const auto& h : t.header) out << '#' << h << '\n';
    out << "# " << t.wavelength_column;
    for (const auto& n : t.band_names) out << ' ' << n;
    out << '\n';
    for (std::size_t i = 0; i < t.wavelength_nm.size(); ++i) {
        out << format_number(t.wavelength_nm[i]);
        for (const auto& r : t.response) out << ' ' << format_number(r[i]);
        out << '\n';
    }
}

int rsr_column(const RsrTable& t, const std::string& name) {
    for (std::size_t i = 0; i < t.band_names.size(); ++i)
        if (t.band_names[i] == name || t.band_names[i] == "B" + name) return static_cast<int>(i);
    return -1;
}

FormatHandler rsr_format() {
    return {"rsr", "relative spectral response table (nm, one column per band)",
            [](const TextInput& in) {
                RsrTable t = parse_rsr(in);
                return std::to_string(t.band_names.size()) + " bands, " +
                       std::to_string(t.wavelength_nm.size()) + " wavelengths " +
                       format_number(t.wavelength_nm.front()) + "-" +
                       format_number(t.wavelength_nm.back()) + " nm";
            },
            [](const TextInput& in, std::ostream& out) { write_rsr(out, parse_rsr(in)); }};
}

}  // namespace sigchain::io
