// The text of control7's questions and of the menus before them (White (1996), fig.
// 4.30): the list --help-questions prints, man control7(1) documents and --answer KEY
// names.
#pragma once

#include <string>
#include <vector>

namespace sigchain::control7 {

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

}  // namespace sigchain::control7
