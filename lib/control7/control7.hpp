// control7: the questions of DIRSIG's CONTROL7 (White (1996), section 4.2.3.5, fig. 4.30) and
// the LOWTRAN 7 card deck (.cdk, fig. 4.31) built from their answers, with the
// radiosonde handling of White (1996), section 4.2.3.4. man control7(1) lists every question.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "control7/answers.hpp"
#include "control7/control7_questions.hpp"
#include "control7/radiosonde.hpp"
#include "io/cdk.hpp"

namespace sigchain::control7 {

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

}  // namespace sigchain::control7
