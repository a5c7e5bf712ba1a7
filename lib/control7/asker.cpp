// How control7 asks one question (see asker.hpp).
#include "control7/asker.hpp"

#include <cmath>
#include <string>

#include "core/text.hpp"

namespace sigchain::control7 {

std::string range_text(double lo, double hi, bool open_lo) {
    return std::string(open_lo ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + "]";
}

int Asker::integer(const std::string& key, const std::string& what, int lo, int hi,
                  const std::set<int>& unsupported, const std::string& note) {
    return ask<int>(key, [&](const std::string& t) {
        double v = number(t, what);
        if (v != std::floor(v) || v < lo || v > hi || unsupported.count(static_cast<int>(v)))
            throw BadAnswer("expected " + what + " in " + range_text(lo, hi) + note +
                            ", found " + quoted(t));
        return static_cast<int>(v);
    });
}

double Asker::real(const std::string& key, const std::string& what, double lo, double hi,
                  bool open_lo) {
    return ask<double>(key, [&](const std::string& t) {
        double v = number(t, what);
        if (v < lo || v > hi || (open_lo && v == lo))
            throw BadAnswer("expected " + what + " in " + range_text(lo, hi, open_lo) +
                            ", found " + quoted(t));
        return v;
    });
}

bool Asker::yes_no(const std::string& key, const std::string& what) {
    return ask<bool>(key, [&](const std::string& t) { return parse_yes_no(t, what); });
}

double Asker::number(const std::string& t, const std::string& what) {
    try {
        return parse_double(t, {}, what);
    } catch (const DataError& e) {
        throw BadAnswer(e.message());
    }
}

bool Asker::parse_yes_no(const std::string& t, const std::string& what) {
    std::string l = ascii_lower(t);
    if (l == "y" || l == "yes") return true;
    if (l == "n" || l == "no") return false;
    throw BadAnswer("expected " + what + " in [y, n], found " + quoted(t));
}

}  // namespace sigchain::control7
