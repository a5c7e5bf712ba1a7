// What a file format implements for sigchain-check, the fuzz harness and the man-page
// example test: each format X provides `FormatHandler X_format()` in io/X.hpp. Only
// io/registry.cpp knows the list of them (io/registry.hpp), so a format's header
// includes this one and not the registry.
#pragma once

#include <functional>
#include <ostream>
#include <string>

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

}  // namespace sigchain::io
