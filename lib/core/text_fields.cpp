// FieldReader and the fields of a line (text.hpp): tables read one line at a time, and
// numbers parsed exactly without from_chars where a decimal token allows it.
#include <charconv>
#include <cmath>
#include <cstdint>

#include "core/text.hpp"

namespace sigchain {

namespace {

// "expected COUNT fields (WHAT), found FOUND: 'TEXT'" (LineCursor and FieldReader).
[[noreturn]] void throw_field_count(const SourceLocation& where, std::size_t count,
                                    std::string_view what, std::size_t found,
                                    std::string_view text) {
    throw DataError(where, "expected " + std::to_string(count) +
                               (count == 1 ? " field (" : " fields (") + std::string(what) +
                               "), found " + std::to_string(found) + ": " + quoted(text));
}

}  // namespace

std::vector<std::string_view> LineCursor::fields(std::size_t count, std::string_view what,
                                                 bool commas_too) {
    const Line& line = next(what);
    auto f = split_fields(line.text, commas_too);
    if (f.size() != count) throw_field_count(where(line), count, what, f.size(), line.text);
    return f;
}

FieldReader::FieldReader(const TextInput& input) : m_input(input), m_rest(input.text()) {
    advance();
}

void FieldReader::advance() {
    // As LineCursor's constructor: the trailing CR, then the comment, then white space
    // (trim's) are removed, and blank lines skipped.
    auto space = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
    };
    while (!m_rest.empty()) {
        const auto end = m_rest.find('\n');
        std::string_view raw = m_rest.substr(0, end);
        m_rest = end == std::string_view::npos ? std::string_view{} : m_rest.substr(end + 1);
        ++m_physical;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        const auto hash = raw.find('#');
        if (hash != std::string_view::npos) raw = raw.substr(0, hash);
        std::size_t b = 0, e = raw.size();
        while (b < e && space(raw[b])) ++b;
        while (e > b && space(raw[e - 1])) --e;
        if (b < e) {
            m_next_text = raw.substr(b, e - b);
            m_next_line = m_physical;
            return;
        }
    }
    m_next_text = {};
    m_next_line = 0;
}

void FieldReader::require_not_empty(std::string_view what) const {
    if (m_line == 0 && at_end())
        throw DataError(m_input.at(0), "empty file, expected " + std::string(what));
}

std::span<const std::string_view> FieldReader::fields(std::size_t count, std::string_view what) {
    if (at_end())
        throw DataError(m_input.at(m_line),
                        "unexpected end of file, expected " + std::string(what));
    const std::string_view text = m_next_text;
    m_line = m_next_line;
    advance();
    // split_fields (without commas); a byte above ' ' is never a separator.
    auto sep = [](char c) {
        return static_cast<unsigned char>(c) <= ' ' &&
               (c == ' ' || c == '\t' || c == '\r' || c == '\n');
    };
    m_fields.clear();
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p < end) {
        if (sep(*p)) {
            ++p;
            continue;
        }
        const char* const first = p;
        while (p < end && !sep(*p)) ++p;
        m_fields.emplace_back(first, static_cast<std::size_t>(p - first));
    }
    if (m_fields.size() != count) throw_field_count(where(), count, what, m_fields.size(), text);
    return m_fields;
}

double FieldReader::number(std::string_view token, std::string_view what) const {
    double value = 0;
    if (try_parse_double(token, value)) return value;
    return parse_double(token, where(), what);
}

std::vector<std::vector<double>> read_number_rows(FieldReader& reader, std::size_t columns,
                                                  std::string_view row_what,
                                                  std::string_view value_what) {
    std::vector<std::vector<double>> rows;
    while (!reader.at_end()) {
        const auto f = reader.fields(columns, row_what);
        std::vector<double> row;
        row.reserve(columns);
        for (const auto x : f) row.push_back(reader.number(x, value_what));
        rows.push_back(std::move(row));
    }
    return rows;
}

namespace {

// 10^0 .. 10^22, every one a double exactly.
constexpr double kExactPowersOf10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// A decimal token [-]digits[.digits][(e|E)[+|-]digits] whose value is m 10^k with an
// integer m <= 2^53 and |k| <= 22: m and 10^|k| are doubles exactly, so the one product
// or quotient m * 10^k, m / 10^-k is the correctly rounded value, the double from_chars
// gives (Clinger 1990, "How to read floating point numbers accurately"; fast_float's
// fast path). False for every other token (from_chars then decides).
bool exact_decimal(std::string_view t, double& value) {
    const char* p = t.data();
    const char* const end = p + t.size();
    const bool negative = p < end && *p == '-';
    if (negative) ++p;
    auto digit = [](char c) { return static_cast<unsigned char>(c - '0') < 10; };
    // m gathers the digits after the leading zeros; more than 19 of them (m may then
    // have wrapped) are refused below.
    std::uint64_t m = 0;
    const char* const integer = p;
    while (p < end && *p == '0') ++p;
    const char* const first = p;
    for (; p < end && digit(*p); ++p) m = m * 10 + static_cast<unsigned char>(*p - '0');
    std::ptrdiff_t significant = p - first, k = 0;
    bool any = p > integer;
    if (p < end && *p == '.') {
        const char* const fraction = ++p;
        if (m == 0)
            while (p < end && *p == '0') ++p;
        const char* const counted = p;
        for (; p < end && digit(*p); ++p) m = m * 10 + static_cast<unsigned char>(*p - '0');
        significant += p - counted;
        k = -(p - fraction);
        any = any || p > fraction;
    }
    if (!any || significant > 19) return false;
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        const bool minus = p < end && *p == '-';
        if (p < end && (*p == '-' || *p == '+')) ++p;
        if (p == end || !digit(*p)) return false;
        std::ptrdiff_t e = 0;
        for (; p < end && digit(*p); ++p) {
            e = e * 10 + (*p - '0');
            if (e > 1000) return false;
        }
        k += minus ? -e : e;
    }
    if (p != end || m > (std::uint64_t{1} << 53) || k < -22 || k > 22) return false;
    const double v = static_cast<double>(m);
    const double magnitude = k < 0 ? v / kExactPowersOf10[-k] : v * kExactPowersOf10[k];
    value = negative ? -magnitude : magnitude;
    return true;
}

}  // namespace

bool try_parse_double(std::string_view token, double& value) {
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    if (t.empty()) return false;
    if (exact_decimal(t, value)) return true;
    double v = 0;
    auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v)) return false;
    value = v;
    return true;
}

}  // namespace sigchain
