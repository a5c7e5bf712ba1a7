// Where control7's answers come from (see answers.hpp).
#include "control7/answers.hpp"

#include <string>
#include <utility>

namespace sigchain::control7 {

LineAnswers::LineAnswers(TextInput input) : m_input(std::move(input)), m_cursor(m_input) {}

std::optional<std::string> LineAnswers::next(const std::string&) {
    if (m_cursor.at_end()) return std::nullopt;
    return std::string(m_cursor.next("an answer").text);
}

SourceLocation LineAnswers::where() const { return m_cursor.where(); }

std::optional<std::string> LineAnswers::leftover() {
    if (m_cursor.at_end()) return std::nullopt;
    return std::string(m_cursor.next("an answer").text);
}

std::optional<std::string> TerminalAnswers::next(const std::string& prompt) {
    m_out << prompt << ' ' << std::flush;
    std::string line;
    if (!std::getline(m_in, line)) return std::nullopt;
    ++m_line;
    return std::string(trim(line));
}

void TerminalAnswers::complain(const std::string& message) {
    m_out << "control7: " << message << "; please answer again\n";
}

void TerminalAnswers::inform(const std::string& text) { m_out << text << '\n'; }

}  // namespace sigchain::control7
