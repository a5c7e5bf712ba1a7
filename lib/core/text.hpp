// Reading sigchain's text formats: lines with locations, comments, strict numbers.
//
// Every text format (sigchain(7), CONVENTIONS): `#` starts a comment, blank lines are
// ignored, numbers are C-locale floats. Parsers reject bad input with
// "FILE:LINE: expected X, found Y" (a DataError) and never guess.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace sigchain {

// One physical line of a file. `text` has its comment (from `#`) and trailing CR
// removed and is trimmed of surrounding white space, unless the cursor was created
// in raw mode (fixed-column formats), where only the trailing CR/LF is removed.
struct Line {
    int number = 0;         // 1-based line number in the file
    std::string_view text;  // view into the owning TextInput
};

// What any text file may hold (sigchain(7), Text files). Reading stops at the first
// byte past a limit, so an endless or huge input (/dev/zero, a runaway pipe) is
// refused without being read whole.
struct TextLimits {
    std::size_t max_bytes = std::size_t{1} << 30;  // 1 GiB: the whole file
    std::size_t max_line = std::size_t{1} << 20;   // 1 MiB: one line, without its '\n'
};

// A whole text file held in memory. Construction checks for binary content (NUL
// bytes) and reports it as a DataError. Not thread-safe for mutation; const use is.
class TextInput {
public:
    // Reads a file; "-" reads standard input. Reads incrementally and throws a
    // DataError at the first NUL byte, the first line longer than limits.max_line or
    // past limits.max_bytes ("FILE:LINE: ..."); an IoError ("FILE: is a directory",
    // "FILE: cannot open: ...") for what is not a readable file. A FIFO or pipe is read
    // to its end, like standard input (it waits for its writer, as cat(1) does).
    static TextInput from_file(const std::string& path, const TextLimits& limits = {});
    // Wraps text already in memory; `name` is used in messages.
    static TextInput from_string(std::string text, std::string name);
    // Reads a stream to its end with the same checks as from_file.
    static TextInput from_stream(std::istream& in, std::string name,
                                 const TextLimits& limits = {});

    const std::string& name() const { return m_name; }
    const std::string& text() const { return m_text; }
    SourceLocation at(int line) const { return {m_name, line}; }

private:
    TextInput(std::string text, std::string name);
    std::string m_name;
    std::string m_text;
};

// Splits on spaces, tabs and (optionally) commas; empty tokens are dropped.
std::vector<std::string_view> split_fields(std::string_view text, bool commas_too = false);

// Trims spaces, tabs, CR and LF from both ends.
std::string_view trim(std::string_view text);

// Iterates over the significant lines of a TextInput: comment-stripped, trimmed,
// non-blank (Mode::Significant), or every physical line untouched (Mode::Raw, for
// fixed-column formats such as the LOWTRAN card deck).
class LineCursor {
public:
    enum class Mode { Significant, Raw };
    explicit LineCursor(const TextInput& input, Mode mode = Mode::Significant);
    // The lines of `part` only: a view into input.text() that begins a line, numbered
    // from `first_line` (the file's number of that line), for a file parsed in pieces
    // (io::parse_gdb). at_end() and "unexpected end of file" refer to the end of `part`.
    LineCursor(const TextInput& input, std::string_view part, int first_line,
               Mode mode = Mode::Significant);

    bool at_end() const { return m_pos >= m_lines.size(); }
    // The next line without consuming it; throws "unexpected end of file, expected
    // WHAT" at the end.
    const Line& peek(std::string_view what) const;
    const Line& next(std::string_view what);
    // The next line split into exactly `count` fields (throws naming `what` otherwise).
    std::vector<std::string_view> fields(std::size_t count, std::string_view what,
                                         bool commas_too = false);
    // Location of the last line returned (or of the end of the file).
    SourceLocation where() const;
    SourceLocation where(const Line& line) const { return m_input.at(line.number); }
    const TextInput& input() const { return m_input; }
    // Fails with "empty file, expected WHAT" if the input has no significant line.
    void require_not_empty(std::string_view what) const;
    // Fails with "unexpected content after ..., found '...'" if lines remain.
    void require_end(std::string_view after) const;

private:
    const TextInput& m_input;
    std::vector<Line> m_lines;
    std::size_t m_pos = 0;
};

// Strict number parsing: the whole token must be a finite number in C-locale syntax.
// `what` names the field in the message: "expected WHAT (a number), found 'abc'".
double parse_double(std::string_view token, const SourceLocation& where, std::string_view what);
long parse_long(std::string_view token, const SourceLocation& where, std::string_view what);
// A non-negative integer count.
long parse_count(std::string_view token, const SourceLocation& where, std::string_view what);
// A number that must lie in [lo, hi].
double parse_in_range(std::string_view token, const SourceLocation& where, std::string_view what,
                      double lo, double hi);

// Quote a found token for messages, shortened and with control characters escaped.
std::string quoted(std::string_view token);

// ASCII lower case (file extensions, keywords, unit names).
std::string ascii_lower(std::string_view text);
// The extension of a file name in lower case, without the dot ("a/b.TIF" -> "tif"; ""
// when there is none; a dot in a directory name does not count).
std::string file_extension(std::string_view path);

// Shortest decimal text that round-trips to the same double (C locale).
std::string format_number(double value);

// Checks that values are strictly increasing or strictly decreasing; throws naming
// `what` and the first offending index (0-based) at `where`.
void require_monotonic(const std::vector<double>& values, const SourceLocation& where,
                       std::string_view what);

}  // namespace sigchain
