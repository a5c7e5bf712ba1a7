// check_ply: the PLY header and a walk over the body (ply.hpp).
#include "scene/ply.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::scene {

namespace {

// A PLY scalar type's size in bytes, 0 for an unknown name.
int type_size(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

bool is_real(const std::string& t) {
    return t == "float" || t == "float32" || t == "double" || t == "float64";
}

bool is_signed(const std::string& t) {
    return t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" ||
           t == "int32";
}

struct Property {
    std::string name, type;  // the item type of a list
    std::string count_type;  // empty: a scalar
};

struct Element {
    std::string name;
    std::size_t count = 0;
    int line = 0;
    std::vector<Property> properties;
};

// The bytes of a binary scalar of `size` at `p` in the file's byte order, as a double.
double binary_value(const unsigned char* p, const std::string& type, int size, bool big) {
    unsigned char b[8];
    for (int i = 0; i < size; ++i) b[i] = big ? p[size - 1 - i] : p[i];
    if (is_real(type)) {
        if (size == 4) {
            float f;
            std::memcpy(&f, b, 4);
            return f;
        }
        double d;
        std::memcpy(&d, b, 8);
        return d;
    }
    std::uint64_t u = 0;
    for (int i = size - 1; i >= 0; --i) u = (u << 8) | b[i];
    if (is_signed(type) && size < 8 && (u >> (8 * size - 1)) & 1) u |= ~0ULL << (8 * size);
    return is_signed(type) ? static_cast<double>(static_cast<std::int64_t>(u))
                           : static_cast<double>(u);
}

class Body {
public:
    Body(const std::string& path, const std::string& text, std::size_t at, int line)
        : m_path(path), m_text(text), m_at(at), m_line(line) {}

    void ascii(const std::vector<Element>& elements) {
        for (const Element& e : elements)
            for (std::size_t k = 0; k < e.count; ++k) {
                std::string_view row;
                do {
                    if (m_at >= m_text.size())
                        throw DataError({m_path, m_line},
                                        "the file ends after " + std::to_string(k) + " of the " +
                                            std::to_string(e.count) + " " + e.name +
                                            " lines (a truncated file?)");
                    row = next_line();
                } while (trim(row).empty());
                ascii_row(e, split_fields(row), k);
            }
        while (m_at < m_text.size())
            if (!trim(next_line()).empty())
                throw DataError({m_path, m_line}, "data after the last element (the header "
                                                  "counts fewer elements than the file holds)");
    }

    void binary(const std::vector<Element>& elements, bool big) {
        m_line = 0;  // a binary body has no lines: its errors name the element instead
        const auto* data = reinterpret_cast<const unsigned char*>(m_text.data());
        for (const Element& e : elements)
            for (std::size_t k = 0; k < e.count; ++k)
                for (const Property& p : e.properties) {
                    std::size_t n = 1;
                    if (!p.count_type.empty()) {
                        const int cs = type_size(p.count_type);
                        need(cs, e, k);
                        const double c = binary_value(data + m_at, p.count_type, cs, big);
                        if (c < 0) bad(e, k, "a negative list length");
                        n = static_cast<std::size_t>(c);
                        m_at += cs;
                    }
                    const int size = type_size(p.type);
                    if (n > (m_text.size() - m_at) / size) need(m_text.size() - m_at + 1, e, k);
                    if (is_real(p.type))
                        for (std::size_t i = 0; i < n; ++i)
                            if (!std::isfinite(binary_value(data + m_at + i * size, p.type, size,
                                                            big)))
                                bad(e, k, "property " + p.name + " is not finite");
                    m_at += n * size;
                }
        if (m_at != m_text.size())
            throw DataError({m_path, 0}, std::to_string(m_text.size() - m_at) +
                                             " bytes after the last element (the header counts "
                                             "fewer elements than the file holds)");
    }

private:
    const std::string& m_path;
    const std::string& m_text;
    std::size_t m_at;
    int m_line;

    std::string_view next_line() {
        const std::size_t end = m_text.find('\n', m_at);
        const std::size_t stop = end == std::string::npos ? m_text.size() : end;
        std::string_view row(m_text.data() + m_at, stop - m_at);
        if (!row.empty() && row.back() == '\r') row.remove_suffix(1);  // CRLF lines
        m_at = stop + (end == std::string::npos ? 0 : 1);
        ++m_line;
        return row;
    }

    [[noreturn]] void bad(const Element& e, std::size_t k, const std::string& why) const {
        throw DataError({m_path, m_line}, e.name + " " + std::to_string(k) + ": " + why);
    }

    void need(std::size_t bytes, const Element& e, std::size_t k) const {
        if (m_text.size() - m_at < bytes)
            throw DataError({m_path, 0}, "the file ends inside " + e.name + " " +
                                             std::to_string(k) + " of " +
                                             std::to_string(e.count) + " (a truncated file?)");
    }

    void ascii_row(const Element& e, const std::vector<std::string_view>& f, std::size_t k) {
        std::size_t i = 0;
        const auto value = [&](const Property& p) {
            if (i >= f.size())
                bad(e, k, "too few values (property " + p.name + " is missing)");
            double v = 0;
            if (!try_parse_double(f[i], v))
                bad(e, k, "property " + p.name + ": '" + std::string(f[i]) +
                              "' is not a finite number");
            ++i;
            return v;
        };
        for (const Property& p : e.properties) {
            if (p.count_type.empty()) {
                value(p);
                continue;
            }
            const double n = value(p);
            if (n < 0 || n != std::floor(n)) bad(e, k, "the list length is not a count");
            for (double j = 0; j < n; ++j) value(p);
        }
        if (i != f.size()) bad(e, k, "more values than its properties");
    }
};

// The header's elements and format, and where the body starts (byte, and the number
// of the header's last line).
struct Header {
    std::vector<Element> elements;
    std::string format;
    std::size_t at = 0;
    int line = 0;
};

// A property line's fields: 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'.
Property parse_property(const std::vector<std::string_view>& f, const SourceLocation& where) {
    Property p;
    if (f.size() == 5 && f[1] == "list") {
        p = {std::string(f[4]), std::string(f[3]), std::string(f[2])};
        if (is_real(p.count_type) || type_size(p.count_type) == 0)
            throw DataError(where, "the list's length type '" + p.count_type +
                                       "' is not an integer type");
    } else if (f.size() == 3) {
        p = {std::string(f[2]), std::string(f[1]), ""};
    } else {
        throw DataError(where, "expected 'property TYPE NAME' or 'property list "
                               "COUNT_TYPE TYPE NAME'");
    }
    if (type_size(p.type) == 0) throw DataError(where, "unknown type '" + p.type + "'");
    return p;
}

// The header: lines up to end_header (at most 1 MiB of them).
Header read_header(const std::string& path, const std::string& text) {
    constexpr std::size_t kMaxHeader = 1 << 20;
    Header h;
    bool ended = false;
    while (!ended) {
        const std::size_t end = text.find('\n', h.at);
        if (end == std::string::npos || end > kMaxHeader)
            throw DataError({path, h.line},
                            "the header has no end_header line (a truncated file?)");
        std::string row = text.substr(h.at, end - h.at);
        if (!row.empty() && row.back() == '\r') row.pop_back();
        h.at = end + 1;
        ++h.line;
        const std::vector<std::string_view> f = split_fields(row);
        const std::string key = f.empty() ? "" : std::string(f[0]);
        const SourceLocation where{path, h.line};
        if (h.line == 1) {
            if (key != "ply") throw DataError(where, "not a PLY file (no 'ply' line)");
            continue;
        }
        if (key == "format") {
            if (f.size() != 3 || f[2] != "1.0" ||
                (f[1] != "ascii" && f[1] != "binary_little_endian" && f[1] != "binary_big_endian"))
                throw DataError(where, "expected 'format ascii|binary_little_endian|"
                                       "binary_big_endian 1.0'");
            h.format = f[1];
        } else if (key == "element") {
            if (f.size() != 3) throw DataError(where, "expected 'element NAME COUNT'");
            const long count = parse_count(f[2], where, "the element count");
            h.elements.push_back({std::string(f[1]), static_cast<std::size_t>(count), h.line, {}});
        } else if (key == "property") {
            if (h.elements.empty()) throw DataError(where, "a property before any element");
            h.elements.back().properties.push_back(parse_property(f, where));
        } else if (key == "end_header") {
            ended = true;
        } else if (key != "comment" && key != "obj_info" && !key.empty()) {
            throw DataError(where, "unknown header line '" + key + "'");
        }
    }
    if (h.format.empty()) throw DataError({path, h.line}, "the header has no format line");
    return h;
}

}  // namespace

PlyCounts check_ply(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path + ": cannot open the mesh file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw IoError(path + ": read error");
    const Header h = read_header(path, text);
    Body body(path, text, h.at, h.line);
    if (h.format == "ascii")
        body.ascii(h.elements);
    else
        body.binary(h.elements, h.format == "binary_big_endian");
    PlyCounts counts;
    for (const Element& e : h.elements) {
        if (e.name == "vertex") counts.vertices = e.count;
        if (e.name == "face") counts.faces = e.count;
    }
    return counts;
}

}  // namespace sigchain::scene
