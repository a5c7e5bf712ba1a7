// control7: the questions of DIRSIG's CONTROL7 (White (1996), section 4.2.3.5, fig. 4.30) and
// the LOWTRAN 7 card deck (.cdk, fig. 4.31) built from their answers, with the
// radiosonde handling of White (1996), section 4.2.3.4. man control7(1) lists every question.
#pragma once

#include <istream>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "atmos/radiosonde.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "io/cdk.hpp"
#include "io/rsd.hpp"

namespace sigchain::atmos {

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

// One question of the list (for --help-questions, the man page and the unit tests).
struct QuestionInfo {
    std::string key;   // name for --answer KEY=VALUE
    std::string text;  // the question as asked (first line)
};
// Every question control7 can ask, in order of first appearance.
const std::vector<QuestionInfo>& control7_questions();
// The question `key` as printed on a terminal: its menu of codes (fig. 4.30), if it has
// one, then the question.
std::string control7_prompt(const std::string& key);

struct Control7Result {
    io::Cdk cdk;
    std::string deck_path;                      // the answer to "FILE NAME FOR PRODUCED CARD DECK"
    std::vector<std::string> unused_overrides;  // --answer keys whose question was not asked
};

// Asks the questions and builds the deck. `overrides` (KEY -> answer text) replace single
// answers: the question is not asked on a terminal, and a line-answer source still
// consumes its line for it, so one answers file serves with and without overrides. A bad
// answer throws DataError "WHERE: expected WHAT in [a, b], found X" (WHERE is the
// answers file and line, or "--answer KEY"); an interactive source re-asks instead.
// Relative radiosonde paths are opened from the current directory.
Control7Result run_control7(AnswerSource& answers,
                            const std::map<std::string, std::string>& overrides = {});

// Wavelength range to LOWTRAN wavenumbers: V1 = 1e4/end_um, V2 = 1e4/start_um (cm-1),
// DV = (V2 - V1)/intervals rounded to a multiple of 5 cm-1, at least 5 (LOWTRAN 7 steps
// its 20 cm-1 band model in 5 cm-1 increments).
io::CdkSpectral wavelength_to_card4(double start_um, double end_um, int intervals);

// A time answer: decimal hours in [0, 24], or HHMM (100 to 2400, minutes below 60) as
// White's (1996) "1400.0" (written 14.000 in its deck). Throws std::invalid_argument.
double time_answer_hours(double value);

}  // namespace sigchain::atmos
