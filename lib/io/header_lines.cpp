// Magic/version lines and `key = value` lines of sigchain's own text formats.
#include "io/header_lines.hpp"

#include <algorithm>
#include <string>

namespace sigchain::io {

namespace {

// "1" -> {1, 0}, "1.2" -> {1, 2}; nothing for anything else.
std::optional<std::pair<long, long>> parse_version(std::string_view token) {
    auto dot = token.find('.');
    std::string_view major = token.substr(0, dot);
    std::string_view minor = dot == std::string_view::npos ? "0" : token.substr(dot + 1);
    auto digits = [](std::string_view s) {
        return !s.empty() && s.size() <= 6 && s.find_first_not_of("0123456789") == s.npos;
    };
    if (!digits(major) || !digits(minor)) return std::nullopt;
    return std::pair{std::stol(std::string(major)), std::stol(std::string(minor))};
}

}  // namespace

int require_magic_line(const TextInput& in, std::string_view name, int major) {
    std::string magic = "sigchain-" + std::string(name);
    std::string expected = "'# " + magic + " " + std::to_string(major) + "'";
    std::string_view text = in.text();
    if (trim(text).empty()) throw DataError(in.at(0), "empty file, expected " + expected);
    std::string_view first = text.substr(0, text.find('\n'));
    if (!first.empty() && first.back() == '\r') first.remove_suffix(1);
    std::string_view body = trim(first);
    auto fields = split_fields(body.empty() ? body : body.substr(1));
    if (body.empty() || body.front() != '#' || fields.size() != 2 || fields[0] != magic)
        throw DataError(in.at(1),
                        "expected " + expected + " as the first line, found " + quoted(first));
    auto version = parse_version(fields[1]);
    if (!version || version->first != major)
        throw DataError(in.at(1), "expected " + magic + " version " + std::to_string(major) +
                                      " or " + std::to_string(major) + ".N, found " +
                                      quoted(fields[1]));
    return static_cast<int>(version->second);
}

std::string end_marker_line(std::size_t rows) {
    return "# sigchain-end " + std::to_string(rows) + "\n";
}

void require_end_marker(const TextInput& in, std::string_view name, int minor, std::size_t rows) {
    if (minor < kEndMarkerMinor) return;
    std::string_view text = in.text();
    // The last non-blank physical line and its number.
    std::size_t end = text.find_last_not_of(" \t\r\n");
    std::string_view last;
    int line = 0;
    if (end != std::string_view::npos) {
        std::size_t begin = text.rfind('\n', end);
        begin = begin == std::string_view::npos ? 0 : begin + 1;
        last = trim(text.substr(begin, end + 1 - begin));
        line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + begin, '\n'));
    }
    std::string expected = "'# sigchain-end " + std::to_string(rows) + "'";
    std::string version = "sigchain-" + std::string(name) + " 1." + std::to_string(minor);
    auto fields = split_fields(last.empty() ? last : last.substr(1));
    if (last.empty() || last.front() != '#' || fields.size() != 2 ||
        fields[0] != "sigchain-end")
        throw DataError(in.at(line), "expected " + expected + " as the last line of a " +
                                         version + " file (a truncated file?), found " +
                                         quoted(last));
    if (fields[1] != std::to_string(rows))
        throw DataError(in.at(line), "expected " + expected + " (" +
                                         std::to_string(rows) + " rows read; a truncated file?), found " +
                                         quoted(last));
}

std::optional<KeyValue> split_key_value(std::string_view text, const SourceLocation& where) {
    auto eq = text.find('=');
    if (eq == std::string_view::npos) return std::nullopt;
    KeyValue kv{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
    if (kv.key.empty() || kv.key.find_first_of(" \t") != std::string_view::npos)
        throw DataError(where, "expected 'key = value' with a one-word key, found " + quoted(text));
    if (kv.value.empty())
        throw DataError(
            where, "expected a value after '" + std::string(kv.key) + " =', found " + quoted(text));
    return kv;
}

}  // namespace sigchain::io
