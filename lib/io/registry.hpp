// Registry of sigchain's file formats, by file extension, for sigchain-check,
// the fuzz harness and the man-page example test.
//
// Each format X provides `FormatHandler X_format()` in io/X.hpp; the list of all of
// them is in registry.cpp (one line per format).
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/text.hpp"

namespace sigchain::io {

struct FormatHandler {
    std::string extension;    // without the dot: "adv"
    std::string description;  // "look angle (White (1996), fig. 4.27)"
    // Parses the input (throws DataError on bad input); returns a one-line summary.
    std::function<std::string(const TextInput&)> check;
    // Parses the input and writes it back in canonical form.
    std::function<void(const TextInput&, std::ostream&)> rewrite;
};

// All known formats, sorted by extension.
const std::vector<FormatHandler>& formats();
// The handler for an extension (without the dot), or nullptr.
const FormatHandler* find_format(std::string_view extension);

}  // namespace sigchain::io
