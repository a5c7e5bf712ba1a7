// The .rad reader's fast lines (rad_lines.hpp): numbers split and parsed in one pass.
#include "io/rad_lines.hpp"

#include <charconv>
#include <cmath>

namespace sigchain::io::rad_lines {

namespace {

// split_fields' separators (a LineCursor line holds no '\n').
bool separator(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n'; }

}  // namespace

// Each field is read where it starts, and must end where the number does: the whole
// token read as try_parse_double reads it (a leading '+' dropped, the correctly
// rounded double, finite), in one pass instead of a split and a parse.
bool numbers_on(std::string_view text, std::span<double> out) {
    const char* p = text.data();
    const char* const end = p + text.size();
    std::size_t i = 0;
    while (p < end) {
        if (separator(*p)) {
            ++p;
            continue;
        }
        if (i == out.size()) return false;
        if (*p == '+') ++p;
        if (p == end) return false;
        if (*p == '0' && (p + 1 == end || separator(p[1]))) {  // half a table's numbers
            out[i++] = 0;
            ++p;
            continue;
        }
        auto [stop, ec] = std::from_chars(p, end, out[i]);
        if (ec != std::errc() || stop == p || (stop < end && !separator(*stop)) ||
            !std::isfinite(out[i]))
            return false;
        p = stop;
        ++i;
    }
    return i == out.size();
}

bool spectrum_on(LineCursor& c, std::size_t n, std::vector<double>& out) {
    const Line* line = next_line(c);
    out.resize(n);
    if (!line || !numbers_on(line->text, out)) return false;
    for (double v : out)
        if (!(v >= 0)) return false;
    c.next("");
    return true;
}

}  // namespace sigchain::io::rad_lines
