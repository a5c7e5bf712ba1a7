// Reading sigchain's text formats: lines with locations, comments, strict numbers.
//
// Every text format (sigchain(7), CONVENTIONS): `#` starts a comment, blank lines are
// ignored, numbers are C-locale floats. Parsers reject bad input with
// "FILE:LINE: expected X, found Y" (a DataError) and never guess.
#pragma once

#include <cstddef>
#include <istream>
#include <span>
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

// Reads the significant lines of a TextInput as LineCursor (Mode::Significant) does, for
// long tables: one line at a time, without a list of every line or an allocation per
// line, and with the messages of LineCursor and parse_double.
class FieldReader {
public:
    explicit FieldReader(const TextInput& input);

    bool at_end() const { return m_next_line == 0; }
    // Fails with "empty file, expected WHAT" if the input has no significant line.
    void require_not_empty(std::string_view what) const;
    // The next line split into exactly `count` fields, as LineCursor::fields (same
    // message); valid until the next call.
    std::span<const std::string_view> fields(std::size_t count, std::string_view what);
    // Number of the line last returned by fields(), and its location.
    int line() const { return m_line; }
    SourceLocation where() const { return m_input.at(m_line); }
    // parse_double(token, where(), what), building the location only for a message.
    double number(std::string_view token, std::string_view what) const;

private:
    void advance();  // finds the next significant line after m_rest

    const TextInput& m_input;
    std::string_view m_rest;       // the text after the next significant line
    std::string_view m_next_text;  // the next significant line (comment-stripped, trimmed)
    int m_next_line = 0;           // its number, 0 at the end
    int m_physical = 0;            // number of the last physical line scanned
    int m_line = 0;
    std::vector<std::string_view> m_fields;
};

// Every remaining line of `reader` as a row of exactly `columns` numbers:
// reader.fields(columns, row_what), then reader.number(field, value_what) for each.
std::vector<std::vector<double>> read_number_rows(FieldReader& reader, std::size_t columns,
                                                  std::string_view row_what,
                                                  std::string_view value_what);

// Strict number parsing: the whole token must be a finite number in C-locale syntax.
// `what` names the field in the message: "expected WHAT (a number), found 'abc'".
double parse_double(std::string_view token, const SourceLocation& where, std::string_view what);
// The value parse_double would return, or false where parse_double would throw.
bool try_parse_double(std::string_view token, double& value);
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
