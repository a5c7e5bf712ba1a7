// The .rad reader's fast lines (internal to lib/io: rad.cpp, rad_sky.cpp).
//
// A .rad holds tens of thousands of numbers, one table per band, and a trace of 200
// bands reads 200 of them. Each line is read twice over at most: first by
// `numbers_on`, which splits and parses it without an allocation or a message; a
// line whose numbers parse and pass the reader's checks is taken as it is. Any other
// line goes to the checked reader of that line, which builds the message and throws
// (or, when the fast check was only stricter, returns the same values). So what the
// reader accepts, and every message it gives, are the checked reader's alone.
#pragma once

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

#include "core/text.hpp"

namespace sigchain::io::rad_lines {

// True when `text` (a significant line: trimmed, comment removed) holds exactly
// out.size() fields separated by spaces or tabs, each a finite number as
// try_parse_double reads it; the numbers are then in `out`.
bool numbers_on(std::string_view text, std::span<double> out);

// The next line of `c` without consuming it, or nullptr at the end of the input.
inline const Line* next_line(const LineCursor& c) { return c.at_end() ? nullptr : &c.peek(""); }

// Reads the next line as `n` numbers >= 0 into `out`, consuming it, when it is one;
// otherwise leaves the cursor where it was and returns false.
bool spectrum_on(LineCursor& c, std::size_t n, std::vector<double>& out);

// How many entries to reserve for counts read from a file (rows x columns): their
// product, but at most 65536, so that a bad header cannot make the reader ask for
// gigabytes before the file runs out of lines.
inline std::size_t reservable(long rows, long columns = 1) {
    constexpr long kMost = 1L << 16;
    if (rows <= 0 || columns <= 0) return 0;
    if (rows >= kMost || columns >= kMost) return kMost;
    return static_cast<std::size_t>(std::min(rows * columns, kMost));
}

}  // namespace sigchain::io::rad_lines
