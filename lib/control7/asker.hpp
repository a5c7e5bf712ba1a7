// How control7 asks one question (internal to lib/control7): an --answer override
// first, else the answer source; the answer parsed and range-checked, a bad one
// re-asked on a terminal and an error ("WHERE: expected ...") anywhere else.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "control7/answers.hpp"
#include "control7/control7_questions.hpp"
#include "core/error.hpp"

namespace sigchain::control7 {

// A bad answer: the message after "WHERE: ".
struct BadAnswer : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "[lo, hi]", or "(lo, hi]" with open_lo.
std::string range_text(double lo, double hi, bool open_lo = false);

// Asks one question at a time: overrides first, then the source; a parser turns the
// text into a value or throws BadAnswer.
class Asker {
public:
    Asker(AnswerSource& src, const std::map<std::string, std::string>& overrides)
        : m_src(src), m_overrides(overrides) {}

    template <class T>
    T ask(const std::string& key, const std::function<T(const std::string&)>& parse);

    // An integer in [lo, hi], not among `unsupported` (`note` says why in the message).
    int integer(const std::string& key, const std::string& what, int lo, int hi,
                const std::set<int>& unsupported = {}, const std::string& note = "");
    double real(const std::string& key, const std::string& what, double lo, double hi,
                bool open_lo = false);
    bool yes_no(const std::string& key, const std::string& what);

    void inform(const std::string& text) { m_src.inform(text); }
    const std::set<std::string>& used() const { return m_used; }
    AnswerSource& source() { return m_src; }

    static double number(const std::string& t, const std::string& what);
    static bool parse_yes_no(const std::string& t, const std::string& what);

private:
    AnswerSource& m_src;
    const std::map<std::string, std::string>& m_overrides;
    std::set<std::string> m_used;
};

template <class T>
T Asker::ask(const std::string& key, const std::function<T(const std::string&)>& parse) {
    const std::string prompt = control7_prompt(key);
    auto ov = m_overrides.find(key);
    if (ov != m_overrides.end()) {
        m_used.insert(key);
        if (!m_src.interactive()) m_src.next(prompt);  // its line is replaced
        try {
            return parse(ov->second);
        } catch (const BadAnswer& e) {
            // An --answer comes from the command line: no file, no line.
            throw DataError({"--answer " + key, 0}, e.what());
        }
    }
    for (;;) {
        auto text = m_src.next(prompt);
        if (!text)
            throw DataError(m_src.where(),
                            "unexpected end of the answers, expected the "
                            "answer to '" +
                                key + "'");
        try {
            return parse(*text);
        } catch (const BadAnswer& e) {
            if (!m_src.interactive()) throw DataError(m_src.where(), e.what());
            m_src.complain(e.what());
        }
    }
}

}  // namespace sigchain::control7
