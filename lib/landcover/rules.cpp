// Class rules (classes(5)): parsing, per-pixel tests, classification and gap filling.
#include "landcover/rules.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <set>

#include "core/error.hpp"

namespace sigchain::landcover {

namespace {

int band_number(std::string_view text, const SourceLocation& where) {
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc{} || end != text.data() + text.size() || v < 1 || v > 1000)
        throw DataError(where, "expected a band number from 1 to 1000, found '" +
                                   std::string(text) + "'");
    return v;
}

// "b4" or "nd(4,3)".
void parse_value(std::string_view text, Term& t, const SourceLocation& where) {
    if (text.size() > 1 && text[0] == 'b') {
        t.band_a = band_number(text.substr(1), where);
        return;
    }
    if (text.size() > 4 && text.substr(0, 3) == "nd(" && text.back() == ')') {
        const auto inner = text.substr(3, text.size() - 4);
        const auto comma = inner.find(',');
        if (comma != std::string_view::npos) {
            t.band_a = band_number(inner.substr(0, comma), where);
            t.band_b = band_number(inner.substr(comma + 1), where);
            return;
        }
    }
    throw DataError(where, "expected a band (b4) or a normalised difference (nd(4,3)), found '" +
                               std::string(text) + "'");
}

void parse_operator(std::string_view text, Term& t, const SourceLocation& where) {
    if (text == "<" || text == "<=" || text == ">" || text == ">=") {
        t.less = text[0] == '<';
        t.or_equal = text.size() == 2;
        return;
    }
    throw DataError(where, "expected one of < <= > >=, found '" + std::string(text) + "'");
}

std::vector<Term> terms_of(const std::vector<std::string_view>& f, std::size_t first,
                           const SourceLocation& where) {
    if ((f.size() - first) % 3 != 0)
        throw DataError(where, "expected terms of three fields (VALUE OP NUMBER), found " +
                                   std::to_string(f.size() - first) + " fields");
    std::vector<Term> terms;
    for (std::size_t i = first; i < f.size(); i += 3) {
        Term t;
        parse_value(f[i], t, where);
        parse_operator(f[i + 1], t, where);
        t.threshold = parse_double(f[i + 2], where, "a threshold");
        terms.push_back(t);
    }
    return terms;
}

}  // namespace

bool Term::holds(const std::vector<double>& pixel) const {
    double v = pixel[band_a - 1];
    if (band_b > 0) {
        const double a = v, b = pixel[band_b - 1];
        v = a + b == 0 ? 0.0 : (a - b) / (a + b);
    }
    if (less) return or_equal ? v <= threshold : v < threshold;
    return or_equal ? v >= threshold : v > threshold;
}

int ClassRules::highest_band() const {
    int h = 0;
    for (const auto& r : rules)
        for (const auto& t : r.terms) h = std::max({h, t.band_a, t.band_b});
    return h;
}

const ClassRule* ClassRules::by_id(int id) const {
    for (const auto& r : rules)
        if (r.id == id) return &r;
    return nullptr;
}

const ClassRule* ClassRules::by_name(const std::string& name) const {
    for (const auto& r : rules)
        if (r.name == name) return &r;
    return nullptr;
}

ClassRules parse_class_rules(const TextInput& in) {
    ClassRules out;
    out.path = in.name();
    LineCursor cursor(in);
    cursor.require_not_empty("a class rule");
    std::set<int> ids;
    std::set<std::string> names;
    while (!cursor.at_end()) {
        const Line& line = cursor.next("a class rule");
        const auto where = cursor.where(line);
        const auto f = split_fields(line.text);
        if (f.size() < 2) throw DataError(where, "expected ID NAME [TERM ...]");
        ClassRule rule;
        rule.line = line.number;
        const double id = parse_double(f[0], where, "a class ID");
        if (id != static_cast<int>(id) || id < 1 || id > 255)
            throw DataError(where, "expected a class ID from 1 to 255, found '" +
                                       std::string(f[0]) + "'");
        rule.id = static_cast<int>(id);
        rule.name = std::string(f[1]);
        if (!ids.insert(rule.id).second)
            throw DataError(where, "class ID " + std::to_string(rule.id) + " given twice");
        if (!names.insert(rule.name).second)
            throw DataError(where, "class name '" + rule.name + "' given twice");
        rule.terms = terms_of(f, 2, where);
        out.rules.push_back(std::move(rule));
    }
    return out;
}

std::vector<Term> parse_terms(const std::string& text, const SourceLocation& where) {
    const auto f = split_fields(text);
    if (f.empty()) throw DataError(where, "expected at least one term (VALUE OP NUMBER)");
    return terms_of(f, 0, where);
}

std::vector<double> stacked_pixel(const std::vector<const geo::GeoRaster*>& images, long r,
                                  long c) {
    std::vector<double> v;
    for (const auto* img : images)
        for (int b = 0; b < img->bands; ++b) v.push_back(img->at(b, r, c));
    return v;
}

std::vector<int> classify(const ClassRules& rules,
                          const std::vector<const geo::GeoRaster*>& images) {
    if (images.empty()) throw std::invalid_argument("classify: no image");
    const long rows = images[0]->rows, columns = images[0]->columns;
    int bands = 0;
    for (const auto* img : images) {
        if (img->rows != rows || img->columns != columns)
            throw DataError({rules.path, 0}, "the images differ in size");
        bands += img->bands;
    }
    if (rules.highest_band() > bands)
        throw DataError({rules.path, 0}, "a rule reads band " +
                                             std::to_string(rules.highest_band()) +
                                             ", the images have " + std::to_string(bands));
    std::vector<int> out(static_cast<std::size_t>(rows) * columns, 0);
    for (long r = 0; r < rows; ++r)
        for (long c = 0; c < columns; ++c) {
            const auto px = stacked_pixel(images, r, c);
            for (const auto& rule : rules.rules)
                if (std::all_of(rule.terms.begin(), rule.terms.end(),
                                [&](const Term& t) { return t.holds(px); })) {
                    out[r * columns + c] = rule.id;
                    break;
                }
        }
    return out;
}

void fill_unclassified(std::vector<int>& classes, long rows, long columns) {
    if (std::none_of(classes.begin(), classes.end(), [](int k) { return k > 0; })) return;
    for (bool any = true; any;) {
        any = false;
        std::vector<int> next = classes;
        for (long r = 0; r < rows; ++r)
            for (long c = 0; c < columns; ++c) {
                if (classes[r * columns + c] != 0) continue;
                std::array<int, 256> votes{};
                for (long dr = -1; dr <= 1; ++dr)
                    for (long dc = -1; dc <= 1; ++dc) {
                        const long rr = r + dr, cc = c + dc;
                        if (rr < 0 || cc < 0 || rr >= rows || cc >= columns) continue;
                        const int k = classes[rr * columns + cc];
                        if (k > 0 && k < 256) ++votes[k];
                    }
                const auto best = std::max_element(votes.begin() + 1, votes.end());
                if (*best > 0) next[r * columns + c] = static_cast<int>(best - votes.begin());
                else any = true;
            }
        classes.swap(next);
    }
}

}  // namespace sigchain::landcover
