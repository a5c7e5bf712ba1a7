// Reading the TAPE7 of one LOWTRAN 7 or MODTRAN run (see tape7.hpp, man tape7(5)).
#include "io/tape7.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "io/fortran_columns.hpp"

namespace sigchain::io {

namespace {

// The card echo LOWTRAN 7 writes before its table (MAIN, statements 560 on): CARD 1,
// 2, 2A, 2B, the profile's ML line, CARD 3, 3A1, 3A2, 4 and CARD 5 (IRPT).
constexpr int kLowtranEchoLines = 10;

// LOWTRAN 7's column headings (TRANS, FORMAT 931, 932, 933) by IEMSCT, blanks collapsed.
constexpr std::array<const char*, 4> kLowtranHeadings = {
    "FREQ TOTAL H2O CO2+ OZONE TRACE N2 CON H2O CON MOL SCAT AER-HYD HNO3 AER-HYD",
    "FREQ TRANS ATMOS PATH SINGLE GROUND DIRECT TOTAL RAD",
    "FREQ TRANS ATMOS PATH SINGLE GROUND DIRECT TOTAL RAD",
    "FREQ TRANS SOL TR SOLAR",
};

// MODTRAN's two-word column names (older versions separate the words with a blank,
// newer ones with '_'): joined so that every name is one word.
constexpr std::array<const char*, 13> kModtranTwoWordNames = {
    "TOT TRANS", "PTH THRML", "THRML SCT", "SURF EMIS", "SOL SCAT", "SING SCAT", "GRND RFLT",
    "DRCT RFLT", "TOTAL RAD", "REF SOL",   "SOL TR",    "DIR EM",   "TOA SUN"};

// The heading in upper case, its words separated by one blank.
std::string collapse_blanks(std::string_view text) {
    std::string out;
    for (auto f : split_fields(text)) {
        if (!out.empty()) out += ' ';
        out += f;
    }
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::vector<std::string> modtran_names(std::string heading) {
    for (const char* two : kModtranTwoWordNames) {
        std::string joined(two);
        joined[joined.find(' ')] = '_';
        for (auto at = heading.find(two); at != std::string::npos; at = heading.find(two))
            heading.replace(at, joined.size(), joined);
    }
    std::vector<std::string> names;
    for (auto f : split_fields(heading)) names.emplace_back(f);
    return names;
}

Tape7Echo read_echo(const std::vector<Line>& lines, const TextInput& in) {
    using fortran::Card;
    Tape7Echo e;
    const Card c1(lines[0].text, in.at(lines[0].number), "echoed CARD 1");
    e.model = static_cast<int>(c1.integer(1, 5, "MODEL"));
    e.itype = static_cast<int>(c1.integer(6, 5, "ITYPE"));
    e.iemsct = static_cast<int>(c1.integer(11, 5, "IEMSCT"));
    e.imult = static_cast<int>(c1.integer(16, 5, "IMULT"));
    e.boundary_temperature_k = c1.real(66, 8, 3, "TBOUND");
    e.surface_albedo = c1.real(74, 7, 2, "SALB");
    e.card1_line = lines[0].number;
    if (e.iemsct < 0 || e.iemsct > 3) c1.fail("IEMSCT", 11, 5, "expected 0 to 3");
    const Card c2(lines[1].text, in.at(lines[1].number), "echoed CARD 2");
    e.ground_km = c2.real(71, 10, 3, "GNDALT");
    if (e.model != 0) {  // MODEL 0 echoes its layer altitudes in place of CARD 3
        const Card c3(lines[5].text, in.at(lines[5].number), "echoed CARD 3");
        e.h1_km = c3.real(1, 10, 3, "H1");
        e.h2_km = c3.real(11, 10, 3, "H2");
        e.zenith_angle_deg = c3.real(21, 10, 3, "ANGLE");
        e.card3_line = lines[5].number;
    }
    const Card c4(lines[8].text, in.at(lines[8].number), "echoed CARD 4");
    e.v1_cm1 = c4.real(1, 10, 3, "V1");
    e.v2_cm1 = c4.real(11, 10, 3, "V2");
    e.dv_cm1 = c4.real(21, 10, 3, "DV");
    return e;
}

// One LOWTRAN 7 row by its FORMAT (TRANS, statements 907, 917, 927, 937).
Tape7Row lowtran_row(const Line& line, const TextInput& in, int iemsct) {
    const fortran::Card c(line.text, in.at(line.number), "TAPE7 row");
    Tape7Row r;
    r.line = line.number;
    r.wavenumber_cm1 = c.real(1, 7, 0, "FREQ");
    r.transmittance = c.real(8, 8, 4, iemsct == 0 ? "TOTAL" : "TRANS");
    if (iemsct == 1 || iemsct == 2) r.path_thermal = c.real(16, 9, 2, "ATMOS");
    if (iemsct == 2) r.path_solar = c.real(25, 9, 2, "PATH");
    if (iemsct == 3) {
        r.solar_transmitted = c.real(16, 9, 2, "SOL TR");
        r.solar_exo = c.real(25, 9, 2, "SOLAR");
    }
    return r;
}

// Where MODTRAN's heading puts each quantity (-1: absent).
struct ModtranColumns {
    int trans = -1, thermal = -1, thermal_scatter = -1, solar = -1, solar_exo = -1, solar_tr = -1;
    std::size_t count = 0;  // values a row needs: up to the last column read
};

ModtranColumns modtran_columns(const std::vector<std::string>& names, const SourceLocation& at) {
    ModtranColumns c;
    c.count = 1;
    for (std::size_t i = 1; i < names.size(); ++i) {
        const std::string& n = names[i];
        const int k = static_cast<int>(i);
        if ((n == "TOT_TRANS" || n == "COMBIN" || n == "TRANS") && c.trans < 0) c.trans = k;
        if (n == "PTH_THRML") c.thermal = k;
        if (n == "THRML_SCT") c.thermal_scatter = k;
        if (n == "SOL_SCAT") c.solar = k;
        if (n == "SOLAR") c.solar_exo = k;
        if (n == "SOL_TR") c.solar_tr = k;
    }
    for (int k : {c.trans, c.thermal, c.thermal_scatter, c.solar, c.solar_exo, c.solar_tr})
        c.count = std::max(c.count, static_cast<std::size_t>(k + 1));
    if (c.trans < 0)
        throw DataError(at,
                        "expected a transmittance column (TOT_TRANS, COMBIN or TRANS) "
                        "in the heading");
    return c;
}

int modtran_iemsct(const ModtranColumns& c) {
    if (c.solar_exo >= 0) return 3;
    if (c.solar >= 0) return 2;
    return c.thermal >= 0 ? 1 : 0;
}

Tape7Row modtran_row(const Line& line, const TextInput& in, const ModtranColumns& c) {
    const SourceLocation at = in.at(line.number);
    const auto f = split_fields(line.text);
    if (f.size() < c.count)
        throw DataError(at, "expected " + std::to_string(c.count) +
                                " values (up to the last heading name read), found " +
                                std::to_string(f.size()));
    auto value = [&](int k, const char* what) {
        return k < 0 ? 0.0 : parse_double(f[static_cast<std::size_t>(k)], at, what);
    };
    Tape7Row r;
    r.line = line.number;
    r.wavenumber_cm1 = parse_double(f[0], at, "FREQ (cm-1)");
    r.transmittance = value(c.trans, "transmittance");
    r.path_thermal = value(c.thermal, "PTH_THRML") + value(c.thermal_scatter, "THRML_SCT");
    r.path_solar = value(c.solar, "SOL_SCAT");
    r.solar_exo = value(c.solar_exo, "SOLAR");
    r.solar_transmitted = value(c.solar_tr, "SOL_TR");
    return r;
}

void check_row(const Tape7Row& r, const Tape7Row* previous, const SourceLocation& at) {
    if (!(r.wavenumber_cm1 > 0))
        throw DataError(at, "expected FREQ > 0 cm-1, found " + format_number(r.wavenumber_cm1));
    if (previous && !(r.wavenumber_cm1 > previous->wavenumber_cm1))
        throw DataError(at, "expected FREQ above the previous row's " +
                                format_number(previous->wavenumber_cm1) + " cm-1, found " +
                                format_number(r.wavenumber_cm1) +
                                " (wavelength output is not read: use cm-1)");
    if (!(r.transmittance >= 0 && r.transmittance <= 1))
        throw DataError(
            at, "expected a transmittance in [0, 1], found " + format_number(r.transmittance));
    for (double v : {r.path_thermal, r.path_solar, r.solar_exo, r.solar_transmitted})
        if (v < 0)
            throw DataError(at,
                            "expected radiances and irradiances >= 0, found " + format_number(v));
}

// The rows from `from` to the " -9999." marker; nothing but blank lines may follow it.
void read_rows(const std::vector<Line>& lines, std::size_t from, const TextInput& in, Tape7& t,
               const ModtranColumns* modtran) {
    std::size_t i = from;
    for (; i < lines.size(); ++i) {
        const std::string_view text = trim(lines[i].text);
        if (text.empty()) continue;
        if (text.substr(0, 6) == "-9999.") break;
        const SourceLocation at = in.at(lines[i].number);
        Tape7Row r =
            modtran ? modtran_row(lines[i], in, *modtran) : lowtran_row(lines[i], in, t.iemsct);
        check_row(r, t.rows.empty() ? nullptr : &t.rows.back(), at);
        t.rows.push_back(r);
    }
    if (i == lines.size())
        throw DataError(in.at(lines.back().number),
                        "unexpected end of file, expected the ' -9999.' end marker");
    if (t.rows.size() < 2)
        throw DataError(in.at(lines[i].number),
                        "expected at least 2 rows before the end marker, found " +
                            std::to_string(t.rows.size()));
    for (++i; i < lines.size(); ++i)
        if (!trim(lines[i].text).empty())
            throw DataError(in.at(lines[i].number),
                            "expected nothing after the end marker (one run per file), found " +
                                quoted(lines[i].text));
}

std::vector<Line> raw_lines(const TextInput& in) {
    LineCursor cur(in, LineCursor::Mode::Raw);
    std::vector<Line> lines;
    while (!cur.at_end()) lines.push_back(cur.next("line"));
    if (lines.empty()) throw DataError(in.at(0), "empty file, expected a TAPE7");
    return lines;
}

std::size_t heading_index(const std::vector<Line>& lines, const TextInput& in) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto f = split_fields(lines[i].text);
        if (f.empty()) continue;
        const std::string first = ascii_lower(f[0]);
        if (first == "freq") return i;
        if (first == "wavlen" || first == "wavelength")
            throw DataError(in.at(lines[i].number),
                            "expected FREQ (cm-1) as the first column, found " + quoted(f[0]) +
                                ": wavelength output is not read");
    }
    throw DataError(in.at(lines.front().number),
                    "expected a column heading line starting with FREQ, found none");
}

// LOWTRAN 7 when the heading is one of its own, after its 10-line card echo whose
// first line starts with an integer (MODEL; MODTRAN's CARD 1 starts with its MODTRN
// and SPEED letters, and MODTRAN 4-5 print LOWTRAN 7's IEMSCT 3 heading too).
bool is_lowtran(const std::vector<Line>& lines, std::size_t h, const std::string& heading) {
    if (std::find(kLowtranHeadings.begin(), kLowtranHeadings.end(), heading) ==
            kLowtranHeadings.end() ||
        h != kLowtranEchoLines)
        return false;
    const std::string_view model = lines[0].text.substr(0, 5);
    const std::string_view digits = trim(model);
    return !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
}

// MODTRAN's echoed CARD 1 (its first line: the MODTRN and SPEED letters, in MODTRAN 5
// and later BINARY and LYMOLC too, then MODEL, ITYPE, IEMSCT, IMULT, M1-M6, MDEF, ...,
// TPTEMP, and SURREF last). Its layout differs between versions, so it is checked by
// its blank-separated fields: each between the letters and SURREF is a finite number
// (sigchain takes nothing from it, but a NaN there means the run was not what it says).
void check_modtran_card1(const Line& line, const TextInput& in) {
    const auto f = split_fields(line.text);
    if (f.size() < 3 || !std::isalpha(static_cast<unsigned char>(f[0][0]))) return;  // no echo
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
        double v;
        if (!try_parse_double(f[i], v))
            throw DataError(in.at(line.number), "echoed CARD 1: expected a number, found " +
                                                    quoted(std::string(f[i])));
    }
}

}  // namespace

Tape7 parse_tape7(const TextInput& in) {
    const std::vector<Line> lines = raw_lines(in);
    const std::size_t h = heading_index(lines, in);
    const std::string heading = collapse_blanks(lines[h].text);
    Tape7 t;
    t.heading_line = lines[h].number;
    if (is_lowtran(lines, h, heading)) {
        t.program = Tape7Program::Lowtran7;
        t.echo = read_echo(lines, in);
        t.iemsct = t.echo->iemsct;
        if (heading != kLowtranHeadings[static_cast<std::size_t>(t.iemsct)])
            throw DataError(in.at(lines[h].number),
                            "expected the column heading of IEMSCT " + std::to_string(t.iemsct) +
                                " (echoed CARD 1), found " + quoted(heading));
        t.thermal_includes_boundary = t.iemsct == 1 || t.iemsct == 2;
        read_rows(lines, h + 1, in, t, nullptr);
        return t;
    }
    t.program = Tape7Program::Modtran;
    if (h > 0) check_modtran_card1(lines[0], in);
    const ModtranColumns columns = modtran_columns(modtran_names(heading), in.at(lines[h].number));
    t.iemsct = modtran_iemsct(columns);
    std::size_t first = h + 1;  // a units line ("CM-1 ...") may follow the heading
    while (first < lines.size()) {
        const auto f = split_fields(lines[first].text);
        if (!f.empty() &&
            (std::isdigit(static_cast<unsigned char>(f[0][0])) || f[0][0] == '.' || f[0][0] == '-'))
            break;
        ++first;
    }
    read_rows(lines, first, in, t, &columns);
    return t;
}

}  // namespace sigchain::io
