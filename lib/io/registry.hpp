// Registry of sigchain's file formats, by file extension, for sigchain-check,
// the fuzz harness and the man-page example test.
//
// Each format X provides `FormatHandler X_format()` (io/format_handler.hpp) in
// io/X.hpp; the list of all of them is in registry.cpp (one line per format), the only
// file of lib/io that includes every format.
#pragma once

#include <string_view>
#include <vector>

#include "io/format_handler.hpp"

namespace sigchain::io {

// All known formats, sorted by extension.
const std::vector<FormatHandler>& formats();
// The handler for an extension (without the dot), or nullptr.
const FormatHandler* find_format(std::string_view extension);

}  // namespace sigchain::io
