// Where control7's answers come from: a file or a pipe of answers, one per line, or a
// terminal, where each question is shown first and a bad answer is asked again.
#pragma once

#include <istream>
#include <optional>
#include <ostream>
#include <string>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::control7 {

// Where the answers come from, one per question in the order asked.
class AnswerSource {
public:
    virtual ~AnswerSource() = default;
    // The next answer to `prompt` (the full question, menus included), or nullopt at the
    // end of the answers. A terminal source prints the prompt first.
    virtual std::optional<std::string> next(const std::string& prompt) = 0;
    // Where the last answer came from (or the end of the answers).
    virtual SourceLocation where() const = 0;
    // A terminal source re-asks after a bad answer; the others stop with the error.
    virtual bool interactive() const = 0;
    // Called after a bad answer on an interactive source.
    virtual void complain(const std::string& /*message*/) {}
    // Text shown between questions (the "ENTERING DATA FOR LAYER" lines); terminal only.
    virtual void inform(const std::string& /*text*/) {}
};

// Answers from a file or a pipe: one per line; '#' starts a comment and blank lines
// are skipped (text.hpp's significant lines).
class LineAnswers : public AnswerSource {
public:
    explicit LineAnswers(TextInput input);
    std::optional<std::string> next(const std::string& prompt) override;
    SourceLocation where() const override;
    bool interactive() const override { return false; }
    // The first answer not consumed, if any (trailing answers are an error).
    std::optional<std::string> leftover();

private:
    TextInput m_input;
    LineCursor m_cursor;
};

// Answers typed on a terminal: prompts and complaints go to `prompts`, answers are read
// from `in` one line at a time.
class TerminalAnswers : public AnswerSource {
public:
    TerminalAnswers(std::istream& in, std::ostream& prompts) : m_in(in), m_out(prompts) {}
    std::optional<std::string> next(const std::string& prompt) override;
    SourceLocation where() const override { return {"<stdin>", m_line}; }
    bool interactive() const override { return true; }
    void complain(const std::string& message) override;
    void inform(const std::string& text) override;

private:
    std::istream& m_in;
    std::ostream& m_out;
    int m_line = 0;
};

}  // namespace sigchain::control7
