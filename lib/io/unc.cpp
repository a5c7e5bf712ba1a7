// Reading and writing .unc input-uncertainty files (man unc(5)).
#include "io/unc.hpp"

#include <array>
#include <map>
#include <utility>

#include "io/header_lines.hpp"

namespace sigchain::io {
namespace {

struct TermName {
    UncTerm term;
    const char* name;
    bool absolute_ok, relative_ok;
};

// Es and L_ds are spectra (and L_ds a table over the sky): one absolute sigma for
// every wavelength and sky cell has no meaning, so they take per cent only; the sun
// zenith is an angle, absolute only.
constexpr std::array<TermName, 8> kTerms{{
    {UncTerm::SolarIrradiance, "Es", false, true},
    {UncTerm::SunTransmission, "tau1", true, true},
    {UncTerm::PathTransmission, "tau2", true, true},
    {UncTerm::UpwelledRadiance, "L_us", true, true},
    {UncTerm::SkyRadiance, "L_ds", false, true},
    {UncTerm::SunZenith, "sun_zenith", true, false},
    {UncTerm::Reflectance, "reflectance", true, true},
    {UncTerm::Specularity, "specularity", true, true},
}};

// The largest absolute sigma of L_us, W cm-2 sr-1 um-1: far above any path radiance
// (the sun's whole exoatmospheric irradiance is about 0.2 W cm-2 um-1).
constexpr double kMaxAbsoluteRadiance = 1;

const TermName& term_info(UncTerm term) {
    for (const auto& t : kTerms)
        if (t.term == term) return t;
    return kTerms[0];
}

const TermName* find_term(std::string_view name, bool material) {
    for (const auto& t : kTerms) {
        const bool per_material = t.term == UncTerm::Reflectance || t.term == UncTerm::Specularity;
        if (name == t.name && per_material == material) return &t;
    }
    return nullptr;
}

// "SIGMA", "SIGMA%" or "SIGMA %" at the end of `f` (removed from it).
void take_sigma(std::vector<std::string_view>& f, const SourceLocation& at, UncRow& row) {
    if (f.back() == "%") {
        row.relative = true;
        f.pop_back();
    }
    if (f.size() < 2) throw DataError(at, "expected a term and its sigma");
    std::string_view s = f.back();
    if (!row.relative && s.size() > 1 && s.back() == '%') {
        row.relative = true;
        s.remove_suffix(1);
    }
    row.sigma = parse_double(s, at, "sigma");
    if (row.sigma < 0) throw DataError(at, "expected sigma at or above 0, found " + quoted(s));
    f.pop_back();
}

UncRow parse_row(const Line& line, const SourceLocation& at) {
    auto f = split_fields(line.text);
    UncRow row;
    row.line = line.number;
    take_sigma(f, at, row);
    const bool material = f.front() == "material";
    if (material && f.size() < 3)
        throw DataError(at, "expected 'material ID_OR_NAME QUANTITY SIGMA [%]', found " +
                                quoted(line.text));
    if (!material && f.size() != 1)
        throw DataError(at, "expected 'TERM SIGMA [%]', found " + quoted(line.text));
    const std::string_view name = f.back();
    const TermName* t = find_term(name, material);
    if (!t)
        throw DataError(at, std::string("expected ") +
                                (material ? "reflectance or specularity"
                                          : "Es, tau1, tau2, L_us, L_ds, sun_zenith or material") +
                                ", found " + quoted(name));
    row.term = t->term;
    for (std::size_t i = 1; material && i + 1 < f.size(); ++i)
        row.material += (i > 1 ? " " : "") + std::string(f[i]);
    if (row.relative && !t->relative_ok)
        throw DataError(at, std::string(t->name) + " takes an absolute sigma only, found per cent");
    if (!row.relative && !t->absolute_ok)
        throw DataError(at, std::string(t->name) +
                                " takes a relative sigma only (per cent: it is a spectrum), "
                                "found an absolute one");
    // Bounds where first-order propagation still means something, and where the squares
    // of the truth cube stay finite (1e300 % made 474 infinities): a relative sigma up
    // to 100 %, an absolute one up to the whole range of its input.
    const double most = row.relative ? 100
                        : row.term == UncTerm::SunZenith ? 90
                        : row.term == UncTerm::UpwelledRadiance ? kMaxAbsoluteRadiance
                                                                : 1;
    if (row.sigma > most) {
        std::string bound = format_number(most);
        if (row.relative) bound += " %";
        throw DataError(at, "expected sigma at most " + bound + " for " + std::string(t->name) +
                                ", found " + format_number(row.sigma));
    }
    return row;
}

std::string row_key(const UncRow& r) { return unc_term_name(r.term) + "\n" + r.material; }

}  // namespace

std::string unc_term_name(UncTerm term) { return term_info(term).name; }

Unc parse_unc(const TextInput& in) {
    Unc unc;
    unc.minor_version = require_magic_line(in, "unc", 1);
    LineCursor cur(in);
    std::map<std::string, int> first_line;
    while (!cur.at_end()) {
        const Line& line = cur.next("uncertainty row");
        const SourceLocation at = cur.where(line);
        UncRow row = parse_row(line, at);
        auto [it, fresh] = first_line.emplace(row_key(row), line.number);
        if (!fresh)
            throw DataError(at, "expected each term once, found " +
                                    quoted(row.material.empty()
                                               ? unc_term_name(row.term)
                                               : row.material + " " + unc_term_name(row.term)) +
                                    " again (first on line " + std::to_string(it->second) + ")");
        unc.rows.push_back(std::move(row));
    }
    require_end_marker(in, "unc", unc.minor_version, unc.rows.size());
    return unc;
}

void write_unc(std::ostream& out, const Unc& unc) {
    out << "# sigchain-unc 1.1\n";
    out << "# term [material] sigma [%]\n";
    for (const auto& r : unc.rows) {
        if (!r.material.empty()) out << "material " << r.material << ' ';
        out << unc_term_name(r.term) << ' ' << format_number(r.sigma) << (r.relative ? " %" : "")
            << '\n';
    }
    out << end_marker_line(unc.rows.size());
}

FormatHandler unc_format() {
    return {"unc", "input uncertainties for trace --uncertainty (sigchain)",
            [](const TextInput& in) {
                const Unc u = parse_unc(in);
                std::size_t materials = 0;
                for (const auto& r : u.rows) materials += !r.material.empty();
                return std::to_string(u.rows.size()) + " uncertainties (" +
                       std::to_string(materials) + " of materials)";
            },
            [](const TextInput& in, std::ostream& out) { write_unc(out, parse_unc(in)); }};
}

}  // namespace sigchain::io
