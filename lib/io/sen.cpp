// Reading and writing the .sen sensor band file (White (1996), fig. 4.42; man sen(5)).
#include "io/sen.hpp"

#include <limits>

namespace sigchain::io {

namespace {

// A line holding one number, which must be at least `floor` (or above it when `strict`).
double parse_single(LineCursor& cur, const std::string& what, double floor, bool strict) {
    auto f = cur.fields(1, what);
    double v = parse_double(f[0], cur.where(), what);
    if (strict ? v <= floor : v < floor)
        throw DataError(cur.where(), "expected " + what +
                                         (strict ? " greater than " : " at or above ") +
                                         format_number(floor) + ", found " + quoted(f[0]));
    return v;
}

}  // namespace

Sen parse_sen(const TextInput& in) {
    LineCursor cur(in);
    cur.require_not_empty("a .sen sensor file (number of spectral samples)");
    auto f = cur.fields(1, "number of spectral samples");
    long count = parse_count(f[0], cur.where(), "number of spectral samples");
    if (count < 1 || count > kSenMaxSamples)
        throw DataError(cur.where(), "expected number of spectral samples (1 to " +
                                         std::to_string(kSenMaxSamples) + "), found " +
                                         quoted(f[0]));
    int count_line = cur.where().line;
    Sen sen;
    sen.gain = parse_single(cur, "gain", 0, true);
    sen.bias = parse_single(cur, "bias", std::numeric_limits<double>::lowest(), false);
    for (long i = 1; i <= count; ++i) {
        std::string what = "relative response " + std::to_string(i) + " of " +
                           std::to_string(count) + " (the count on line " +
                           std::to_string(count_line) + ")";
        sen.response.push_back(parse_single(cur, what, 0, false));
    }
    cur.require_end(std::to_string(count) + " relative responses (the count on line " +
                    std::to_string(count_line) + ")");
    return sen;
}

void write_sen(std::ostream& out, const Sen& sen) {
    out << sen.response.size() << '\n'
        << format_number(sen.gain) << '\n'
        << format_number(sen.bias) << '\n';
    for (double r : sen.response) out << format_number(r) << '\n';
}

FormatHandler sen_format() {
    return {"sen", "sensor band response (White (1996), fig. 4.42)",
            [](const TextInput& in) {
                Sen s = parse_sen(in);
                return std::to_string(s.response.size()) + " spectral samples, gain " +
                       format_number(s.gain) + ", bias " + format_number(s.bias);
            },
            [](const TextInput& in, std::ostream& out) { write_sen(out, parse_sen(in)); }};
}

}  // namespace sigchain::io
