// Fortran fixed-column fields (Iw, Fw.d, Ew.d, Aw) as LOWTRAN 7 reads and writes them.
#include "io/fortran_columns.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/text.hpp"

namespace sigchain::io::fortran {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::size_t skip_digits(std::string_view s, std::size_t i) {
    while (i < s.size() && is_digit(s[i])) ++i;
    return i;
}

// The parts of a Fortran real: sign, digits before and after the point, exponent.
struct RealParts {
    bool negative = false;
    std::string_view whole, fraction;
    bool point = false;
    long exponent = 0;
};

// Splits `s` (trimmed, no blanks) into its parts; false if it is not a Fortran real.
bool split_real(std::string_view s, RealParts& p) {
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) p.negative = s[i++] == '-';
    std::size_t j = skip_digits(s, i);
    p.whole = s.substr(i, j - i);
    i = j;
    if (i < s.size() && s[i] == '.') {
        p.point = true;
        j = skip_digits(s, ++i);
        p.fraction = s.substr(i, j - i);
        i = j;
    }
    if (p.whole.empty() && p.fraction.empty()) return false;
    if (i == s.size()) return true;
    if (s[i] == 'E' || s[i] == 'e' || s[i] == 'D' || s[i] == 'd') ++i;
    bool exp_negative = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) exp_negative = s[i++] == '-';
    j = skip_digits(s, i);
    if (j == i || j != s.size() || j - i > 4) return false;
    p.exponent = std::strtol(std::string(s.substr(i, j - i)).c_str(), nullptr, 10);
    if (exp_negative) p.exponent = -p.exponent;
    return true;
}

std::string pad_left(const std::string& s, int width) {
    return s.size() >= static_cast<std::size_t>(width)
               ? s
               : std::string(static_cast<std::size_t>(width) - s.size(), ' ') + s;
}

}  // namespace

Card::Card(std::string_view text, SourceLocation where, std::string name)
    : m_text(text), m_where(std::move(where)), m_name(std::move(name)) {
    for (std::size_t i = 0; i < m_text.size(); ++i) {
        auto u = static_cast<unsigned char>(m_text[i]);
        if (u < 0x20 || u == 0x7f)
            throw DataError(m_where, m_name +
                                         ": expected a fixed-column card of printable "
                                         "characters, found " +
                                         quoted(m_text.substr(i, 1)) + " in column " +
                                         std::to_string(i + 1) +
                                         (u == '\t' ? " (a tab; use spaces)" : ""));
    }
}

std::string_view Card::slice(int column, int width) const {
    auto start = static_cast<std::size_t>(column - 1);
    if (start >= m_text.size()) return {};
    return m_text.substr(start, static_cast<std::size_t>(width));
}

void Card::fail(std::string_view field, int column, int width, const std::string& message) const {
    throw DataError(m_where, m_name + " " + std::string(field) + " (columns " +
                                 std::to_string(column) + "-" + std::to_string(column + width - 1) +
                                 "): " + message);
}

long Card::integer(int column, int width, std::string_view field) const {
    std::string_view raw = slice(column, width);
    std::string_view s = trim_blanks(raw);
    if (s.empty()) return 0;
    if (s.find(' ') != std::string_view::npos)
        fail(field, column, width,
             "expected an integer, found " + quoted(raw) + " (a blank inside the number)");
    std::size_t i = (s[0] == '+' || s[0] == '-') ? 1 : 0;
    long value = 0;
    std::string_view digits = s.substr(i);
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || ec != std::errc() || ptr != digits.data() + digits.size())
        fail(field, column, width, "expected an integer, found " + quoted(raw));
    return s[0] == '-' ? -value : value;
}

double Card::real(int column, int width, int decimals, std::string_view field) const {
    std::string_view raw = slice(column, width);
    std::string_view s = trim_blanks(raw);
    if (s.empty()) return 0;
    std::string expected = "expected a number (Fortran F" + std::to_string(width) + "." +
                           std::to_string(decimals) + "), found " + quoted(raw);
    if (s.find(' ') != std::string_view::npos)
        fail(field, column, width, expected + " (a blank inside the number)");
    RealParts p;
    if (!split_real(s, p)) fail(field, column, width, expected);
    // Without a point, the last `decimals` digits are the fraction (implied decimal).
    long exponent = p.exponent - (p.point ? 0 : decimals);
    std::string text = std::string(p.negative ? "-" : "") +
                       std::string(p.whole.empty() ? "0" : p.whole) + "." +
                       std::string(p.fraction) + "0e" + std::to_string(exponent);
    double value = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value))
        fail(field, column, width, expected + " (out of range)");
    return value;
}

std::string Card::characters(int column, int width) const {
    std::string s(slice(column, width));
    s.resize(static_cast<std::size_t>(width), ' ');
    return s;
}

void Card::require_blank_from(int column) const {
    auto start = static_cast<std::size_t>(column - 1);
    if (start >= m_text.size()) return;
    std::string_view rest = m_text.substr(start);
    auto first = rest.find_first_not_of(' ');
    if (first == std::string_view::npos) return;
    throw DataError(m_where, m_name + ": expected blanks from column " + std::to_string(column) +
                                 " on (the card ends at column " + std::to_string(column - 1) +
                                 "), found " + quoted(trim_blanks(rest)) + " in column " +
                                 std::to_string(column + static_cast<int>(first)));
}

bool Card::blank() const { return m_text.find_first_not_of(' ') == std::string_view::npos; }

std::string format_integer(long value, int width) {
    std::string s = std::to_string(value);
    if (s.size() > static_cast<std::size_t>(width))
        throw Error("integer " + s + " does not fit in a Fortran I" + std::to_string(width) +
                    " field");
    return pad_left(s, width);
}

std::string format_exponent(double value, int width, int decimals) {
    if (!std::isfinite(value)) throw Error("cannot write a non-finite number in a Fortran field");
    std::string mantissa(static_cast<std::size_t>(decimals), '0');
    int exponent = 0;
    if (value != 0) {
        char buf[64];
        // d.ddd...e+xx with `decimals` significant digits: the rounding is done here.
        std::snprintf(buf, sizeof buf, "%.*e", decimals - 1, std::fabs(value));
        std::string_view t = buf;
        auto e = t.find('e');
        mantissa = std::string(t.substr(0, 1)) + std::string(t.substr(2, e - 2));
        mantissa.resize(static_cast<std::size_t>(decimals), '0');
        exponent = std::atoi(buf + e + 1) + 1;
    }
    char exp_text[16];
    int magnitude = std::abs(exponent);
    if (magnitude <= 99)
        std::snprintf(exp_text, sizeof exp_text, "E%c%02d", exponent < 0 ? '-' : '+', magnitude);
    else
        std::snprintf(exp_text, sizeof exp_text, "%c%03d", exponent < 0 ? '-' : '+', magnitude);
    std::string s = std::string(value < 0 ? "-" : "") + "0." + mantissa + exp_text;
    if (s.size() > static_cast<std::size_t>(width))
        throw Error("number " + format_number(value) + " does not fit in a Fortran E" +
                    std::to_string(width) + "." + std::to_string(decimals) + " field");
    return pad_left(s, width);
}

std::string format_fixed(double value, int width, int decimals) {
    if (!std::isfinite(value)) throw Error("cannot write a non-finite number in a Fortran field");
    if (std::round(value * std::pow(10.0, decimals)) == 0) value = 0;
    char buf[400];
    std::snprintf(buf, sizeof buf, "%*.*f", width, decimals, value);
    std::string s = buf;
    if (s.size() <= static_cast<std::size_t>(width)) return s;
    for (int digits = width - 6; digits >= 1; --digits) {
        try {
            return format_exponent(value, width, digits);
        } catch (const Error&) {
        }
    }
    throw Error("number " + format_number(value) + " does not fit in a Fortran F" +
                std::to_string(width) + "." + std::to_string(decimals) + " field");
}

}  // namespace sigchain::io::fortran
