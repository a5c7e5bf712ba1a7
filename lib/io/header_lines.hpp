// Header lines shared by sigchain's own text formats: the `# sigchain-NAME MAJOR[.MINOR]`
// magic line and `key = value` lines (man tmp(5), cpt(5)).
#pragma once

#include <optional>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/text.hpp"

namespace sigchain::io {

// Checks that the first physical line of `in` is `# sigchain-NAME MAJOR[.MINOR]` with
// MAJOR == `major` (any minor version is accepted: minor versions only add optional
// content). Returns the minor version (0 when absent). Throws DataError at line 1 for a
// missing or malformed magic line or another major version, and at line 0 for an empty
// file.
int require_magic_line(const TextInput& in, std::string_view name, int major);

// Version MAJOR.1 of sigchain's row formats (tmp(5), cpt(5)) ends with a comment line
// "# sigchain-end N", N the number of data rows, so that a truncated file is refused;
// a version MAJOR.0 reader skips it as a comment.
inline constexpr int kEndMarkerMinor = 1;
std::string end_marker_line(std::size_t rows);  // "# sigchain-end N\n"
// For a file of minor version >= kEndMarkerMinor: the last non-blank line of `in` must
// be "# sigchain-end N" with N == `rows`. Throws DataError at that line otherwise;
// does nothing for older minor versions.
void require_end_marker(const TextInput& in, std::string_view name, int minor, std::size_t rows);

// A `key = value` line split at its first `=`, both sides trimmed.
struct KeyValue {
    std::string_view key;
    std::string_view value;
};

// The key and value of `text`, or nothing when it has no `=`. Throws DataError at
// `where` when the key or the value is empty or the key contains white space.
std::optional<KeyValue> split_key_value(std::string_view text, const SourceLocation& where);

}  // namespace sigchain::io
