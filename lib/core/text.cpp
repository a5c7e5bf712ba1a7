// Text input with locations, strict number parsing and round-trip number output.
#include "core/text.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sigchain {

TextInput::TextInput(std::string text, std::string name)
    : m_name(std::move(name)), m_text(std::move(text)) {
    auto nul = m_text.find('\0');
    if (nul != std::string::npos) {
        int line = 1 + static_cast<int>(std::count(m_text.begin(), m_text.begin() + nul, '\n'));
        throw DataError({m_name, line}, "binary data (NUL byte); expected a text file");
    }
}

namespace {

// Accumulates a text file chunk by chunk and refuses it at the first NUL byte, the first
// over-long line or the first byte past the size limit, before reading any further.
class TextAccumulator {
public:
    TextAccumulator(const std::string& name, const TextLimits& limits)
        : m_name(name), m_limits(limits) {}

    void add(const char* data, std::size_t size) {
        if (m_text.size() + size > m_limits.max_bytes)
            throw DataError({m_name, m_line},
                            "file larger than " + std::to_string(m_limits.max_bytes) +
                                " bytes (the limit of a text file, sigchain(7)); expected a "
                                "text file");
        const char* end = data + size;
        const char* p = data;
        while (p < end) {
            const void* nul = std::memchr(p, '\0', static_cast<std::size_t>(end - p));
            const char* stop = nul ? static_cast<const char*>(nul) : end;
            scan_lines(p, stop);
            if (nul)
                throw DataError({m_name, m_line}, "binary data (NUL byte); expected a text file");
            p = stop;
        }
        m_text.append(data, size);
    }

    std::string take() { return std::move(m_text); }

private:
    // Counts lines and measures the current one over [p, end) (no NUL inside).
    void scan_lines(const char* p, const char* end) {
        while (p < end) {
            const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
            const char* stop = nl ? static_cast<const char*>(nl) : end;
            m_line_length += static_cast<std::size_t>(stop - p);
            if (m_line_length > m_limits.max_line)
                throw DataError({m_name, m_line},
                                "line longer than " + std::to_string(m_limits.max_line) +
                                    " bytes (the limit of a text line, sigchain(7)); expected "
                                    "a text file");
            if (!nl) return;
            ++m_line;
            m_line_length = 0;
            p = stop + 1;
        }
    }

    const std::string& m_name;
    const TextLimits& m_limits;
    std::string m_text;
    int m_line = 1;
    std::size_t m_line_length = 0;
};

constexpr std::size_t kChunk = 1 << 16;

// Reads `fd` to its end through `acc`.
void read_fd(int fd, const std::string& name, TextAccumulator& acc) {
    const std::unique_ptr<char[]> buffer(new char[kChunk]);  // not zeroed: read() fills it
    while (true) {
        ssize_t n = ::read(fd, buffer.get(), kChunk);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0)
            throw IoError(SourceLocation{name, 0}.str() + ": read error: " + std::strerror(errno));
        if (n == 0) return;
        acc.add(buffer.get(), static_cast<std::size_t>(n));
    }
}

// Closes a file descriptor on every path out.
struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
};

}  // namespace

TextInput TextInput::from_file(const std::string& path, const TextLimits& limits) {
    if (path == "-") {
        std::string name = "-";
        TextAccumulator acc(name, limits);
        read_fd(STDIN_FILENO, name, acc);
        return TextInput(acc.take(), name);
    }
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw IoError(path + ": cannot open: " + std::strerror(errno));
    FdCloser closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw IoError(path + ": cannot open: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw IoError(path + ": is a directory; expected a file");
    if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > limits.max_bytes)
        throw DataError({path, 0}, "file of " + std::to_string(st.st_size) +
                                       " bytes, larger than " + std::to_string(limits.max_bytes) +
                                       " (the limit of a text file, sigchain(7))");
    TextAccumulator acc(path, limits);
    read_fd(fd, path, acc);
    return TextInput(acc.take(), path);
}

TextInput TextInput::from_string(std::string text, std::string name) {
    return TextInput(std::move(text), std::move(name));
}

TextInput TextInput::from_stream(std::istream& in, std::string name, const TextLimits& limits) {
    TextAccumulator acc(name, limits);
    std::vector<char> buffer(kChunk);
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        auto n = in.gcount();
        if (n > 0) acc.add(buffer.data(), static_cast<std::size_t>(n));
    }
    if (in.bad()) throw IoError(SourceLocation{name, 0}.str() + ": read error");
    return TextInput(acc.take(), std::move(name));
}

std::string_view trim(std::string_view text) {
    const char* ws = " \t\r\n\f\v";
    auto b = text.find_first_not_of(ws);
    if (b == std::string_view::npos) return {};
    auto e = text.find_last_not_of(ws);
    return text.substr(b, e - b + 1);
}

std::vector<std::string_view> split_fields(std::string_view text, bool commas_too) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    auto is_sep = [&](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || (commas_too && c == ',');
    };
    while (i < text.size()) {
        while (i < text.size() && is_sep(text[i])) ++i;
        std::size_t j = i;
        while (j < text.size() && !is_sep(text[j])) ++j;
        if (j > i) out.push_back(text.substr(i, j - i));
        i = j;
    }
    return out;
}

LineCursor::LineCursor(const TextInput& input, Mode mode)
    : LineCursor(input, input.text(), 1, mode) {}

LineCursor::LineCursor(const TextInput& input, std::string_view all, int first_line, Mode mode)
    : m_input(input) {
    m_lines.reserve(static_cast<std::size_t>(std::count(all.begin(), all.end(), '\n')) + 1);
    int number = first_line - 1;
    std::size_t start = 0;
    while (start < all.size()) {
        auto end = all.find('\n', start);
        if (end == std::string_view::npos) end = all.size();
        std::string_view raw = all.substr(start, end - start);
        ++number;
        start = end + 1;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        if (mode == Mode::Raw) {
            m_lines.push_back({number, raw});
            continue;
        }
        auto hash = raw.find('#');
        if (hash != std::string_view::npos) raw = raw.substr(0, hash);
        raw = trim(raw);
        if (!raw.empty()) m_lines.push_back({number, raw});
    }
}

const Line& LineCursor::peek(std::string_view what) const {
    if (at_end()) {
        int last = m_lines.empty() ? 0 : m_lines.back().number;
        throw DataError(m_input.at(last), "unexpected end of file, expected " + std::string(what));
    }
    return m_lines[m_pos];
}

const Line& LineCursor::next(std::string_view what) {
    const Line& line = peek(what);
    ++m_pos;
    return line;
}

SourceLocation LineCursor::where() const {
    if (m_lines.empty()) return m_input.at(0);
    std::size_t i = m_pos == 0 ? 0 : m_pos - 1;
    if (i >= m_lines.size()) i = m_lines.size() - 1;
    return m_input.at(m_lines[i].number);
}

void LineCursor::require_not_empty(std::string_view what) const {
    if (m_lines.empty())
        throw DataError(m_input.at(0), "empty file, expected " + std::string(what));
}

void LineCursor::require_end(std::string_view after) const {
    if (at_end()) return;
    const Line& line = m_lines[m_pos];
    throw DataError(m_input.at(line.number), "unexpected content after " + std::string(after) +
                                                 ", found " + quoted(line.text));
}

std::string quoted(std::string_view token) {
    std::string out = "'";
    std::size_t n = 0;
    for (char c : token) {
        if (++n > 40) {
            out += "...";
            break;
        }
        auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "'";
}

double parse_double(std::string_view token, const SourceLocation& where, std::string_view what) {
    double value = 0;
    if (try_parse_double(token, value)) return value;
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    bool whole = ec == std::errc() && ptr == t.data() + t.size() && !t.empty();
    if (!whole && ec == std::errc::result_out_of_range)
        throw DataError(where, "expected " + std::string(what) + " (a number), found " +
                                   quoted(token) + " (out of range)");
    if (!whole)
        throw DataError(where,
                        "expected " + std::string(what) + " (a number), found " + quoted(token));
    if (!std::isfinite(value))
        throw DataError(
            where, "expected " + std::string(what) + " (a finite number), found " + quoted(token));
    return value;
}

long parse_long(std::string_view token, const SourceLocation& where, std::string_view what) {
    long value = 0;
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || ptr != t.data() + t.size() || t.empty())
        throw DataError(where,
                        "expected " + std::string(what) + " (an integer), found " + quoted(token));
    return value;
}

long parse_count(std::string_view token, const SourceLocation& where, std::string_view what) {
    long value = parse_long(token, where, what);
    if (value < 0)
        throw DataError(where, "expected " + std::string(what) + " (a count, 0 or more), found " +
                                   quoted(token));
    return value;
}

double parse_in_range(std::string_view token, const SourceLocation& where, std::string_view what,
                      double lo, double hi) {
    double v = parse_double(token, where, what);
    if (v < lo || v > hi)
        throw DataError(where, "expected " + std::string(what) + " in [" + format_number(lo) +
                                   ", " + format_number(hi) + "], found " + quoted(token));
    return v;
}

std::string ascii_lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string file_extension(std::string_view path) {
    auto slash = path.find_last_of('/');
    auto dot = path.find_last_of('.');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
        return {};
    return ascii_lower(path.substr(dot + 1));
}

std::string format_number(double value) {
    char buf[64];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, ec == std::errc() ? ptr : buf);
}

void require_monotonic(const std::vector<double>& values, const SourceLocation& where,
                       std::string_view what) {
    if (values.size() < 2) return;
    bool increasing = values[1] > values[0];
    for (std::size_t i = 1; i < values.size(); ++i) {
        bool ok = increasing ? values[i] > values[i - 1] : values[i] < values[i - 1];
        if (!ok)
            throw DataError(where, std::string(what) + " is not monotonic: value " +
                                       std::to_string(i + 1) + " (" + format_number(values[i]) +
                                       ") after " + format_number(values[i - 1]));
    }
}

}  // namespace sigchain
