// .gdb geometric database (DIRSIG 3 layout; man gdb(5)): reader, writer, problem report.
#include "io/gdb.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"

namespace sigchain::io {

namespace {

constexpr std::string_view kEndWhat = "OBJECT, PART, FACE or END (a .gdb ends with END)";

bool is_keyword(std::string_view text) {
    return text == "OBJECT" || text == "PART" || text == "FACE" || text == "END";
}

// A whole line: names may contain spaces, but may not be a keyword (which would mean
// a field is missing and the parser would otherwise silently shift every field).
std::string read_text(LineCursor& c, std::string_view what) {
    const Line& line = c.next(what);
    if (is_keyword(line.text))
        throw DataError(c.where(line), "expected " + std::string(what) + ", found keyword " +
                                           sigchain::quoted(line.text));
    return std::string(line.text);
}

// "1-1-0": three non-negative integers joined by dashes.
bool is_id(std::string_view text) {
    int parts = 0;
    std::size_t i = 0;
    while (true) {
        std::size_t j = i;
        while (j < text.size() && text[j] >= '0' && text[j] <= '9') ++j;
        if (j == i) return false;
        ++parts;
        if (j == text.size()) return parts == 3;
        if (text[j] != '-') return false;
        i = j + 1;
    }
}

std::string read_id(LineCursor& c, std::string_view what) {
    const Line& line = c.next(what);
    if (!is_id(line.text))
        throw DataError(c.where(line),
                        "expected " + std::string(what) +
                            " (three dash-separated integers such as 1-1-0), found " +
                            sigchain::quoted(line.text));
    return std::string(line.text);
}

// parse_double's acceptance (an optional '+', then the whole token one finite number
// by std::from_chars) without building its SourceLocation (a copy of the file name):
// the fast path of the .gdb's many vertex lines. False when parse_double would throw.
bool parse_finite(std::string_view t, double& value) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    if (t.empty()) return false;
    auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    return ec == std::errc() && ptr == t.data() + t.size() && std::isfinite(value);
}

// The next line's number, not consumed, when the line is one field (no space, tab, CR
// or LF in it, as split_fields splits) that parse_finite reads: the fast path of the
// one-number lines (as read_vec3's).
bool peek_number(const LineCursor& c, std::string_view what, double& v) {
    if (c.at_end()) return false;
    const std::string_view text = c.peek(what).text;
    return text.find_first_of(" \t\r\n") == std::string_view::npos && parse_finite(text, v);
}

double read_number(LineCursor& c, std::string_view what) {
    double v = 0;
    if (peek_number(c, what, v)) {
        c.next(what);
        return v;
    }
    auto f = c.fields(1, what);
    return parse_double(f[0], c.where(), what);
}

// A number in [lo, hi] (parse_in_range), by the fast path when it applies.
double read_in_range(LineCursor& c, std::string_view what, double lo, double hi) {
    double v = 0;
    if (peek_number(c, what, v) && v >= lo && v <= hi) {
        c.next(what);
        return v;
    }
    auto f = c.fields(1, what);
    return parse_in_range(f[0], c.where(), what, lo, hi);
}

// The fields of `text` split as split_fields(text, true) splits them, into `out`
// without allocating; false unless there are exactly three.
bool three_fields(std::string_view text, std::array<std::string_view, 3>& out) {
    auto is_sep = [](char ch) {
        return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == ',';
    };
    std::size_t n = 0, i = 0;
    while (i < text.size()) {
        while (i < text.size() && is_sep(text[i])) ++i;
        std::size_t j = i;
        while (j < text.size() && !is_sep(text[j])) ++j;
        if (j > i) {
            if (n == 3) return false;
            out[n++] = text.substr(i, j - i);
        }
        i = j;
    }
    return n == 3;
}

Vec3 read_vec3(LineCursor& c, std::string_view what) {
    // The fast path: three finite numbers, read as below would read them.
    std::array<std::string_view, 3> fast;
    if (!c.at_end() && three_fields(c.peek(what).text, fast)) {
        Vec3 v{};
        if (parse_finite(fast[0], v[0]) && parse_finite(fast[1], v[1]) &&
            parse_finite(fast[2], v[2])) {
            c.next(what);
            return v;
        }
    }
    // The checked path, whose errors name the line, the field and what was found.
    auto f = c.fields(3, what, true);
    Vec3 v{};
    for (int i = 0; i < 3; ++i) v[i] = parse_double(f[i], c.where(), what);
    return v;
}

// A vertex: finite (parse_double) and within kGdbMaxCoordinate on each axis (gdb(5)).
Vec3 read_vertex(LineCursor& c) {
    Vec3 v = read_vec3(c, "vertex x y z");
    for (int i = 0; i < 3; ++i)
        if (std::abs(v[i]) > kGdbMaxCoordinate)
            throw DataError(c.where(), "expected vertex coordinates within +-" +
                                           format_number(kGdbMaxCoordinate) + ", found " +
                                           format_number(v[i]));
    return v;
}

void read_facet_attributes(LineCursor& c, GdbFacet& f) {
    f.material_name = read_text(c, "material name");
    auto id = c.fields(1, "material id");
    f.material_id = parse_count(id[0], c.where(), "material id");
    if (f.material_id > kMaxMaterialId)
        throw DataError(c.where(), "expected material id from 0 to " +
                                       std::to_string(kMaxMaterialId) + ", found " +
                                       sigchain::quoted(id[0]));
    f.legacy_name = read_text(c, "legacy name");
    f.temperature_c = read_number(c, "temperature (C, -1 = from therm)");
    if (f.temperature_c != -1 && f.temperature_c < -273.15)
        throw DataError(c.where(), "expected temperature (C) -1 or at least -273.15, found " +
                                       format_number(f.temperature_c));
    f.thickness_cm = read_number(c, "thickness (cm)");
    if (f.thickness_cm != -1 && f.thickness_cm < 0)
        throw DataError(c.where(), "expected thickness (cm) 0 or more, or -1, found " +
                                       format_number(f.thickness_cm));
    f.power = read_number(c, "self-generated power");
    f.exposed_area = read_number(c, "exposed area");
    for (auto& spare : f.spares) spare = read_text(c, "spare field (null)");
}

void read_facet_geometry(LineCursor& c, GdbFacet& f) {
    auto n = c.fields(1, "vertex count (3 or 4)");
    long count = parse_long(n[0], c.where(), "vertex count (3 or 4)");
    if (count != 3 && count != 4)
        throw DataError(c.where(), "expected vertex count 3 or 4, found " + sigchain::quoted(n[0]));
    for (long i = 0; i < count; ++i) f.vertices.push_back(read_vertex(c));
    f.normal = read_vec3(c, "normal nx ny nz");
    if (f.normal[0] == 0 && f.normal[1] == 0 && f.normal[2] == 0)
        throw DataError(c.where(), "expected a non-zero normal, found 0 0 0");
    f.slope_zenith_deg = read_in_range(c, "slope zenith (deg)", 0, 180);
    f.slope_azimuth_deg = read_in_range(c, "slope azimuth (deg)", -360, 360);
    f.spare = read_text(c, "facet spare field");
}

// `ids`: facet id -> the line it was first read on (a key of .shd, .tmp and trace must
// name one facet); null: not checked here (parse_gdb's pieces check them when joined).
GdbFacet read_facet(LineCursor& c, int keyword_line, std::unordered_map<std::string, int>* ids) {
    GdbFacet f;
    f.line = keyword_line;
    f.name = read_text(c, "facet name");
    f.id = read_id(c, "facet id");
    if (ids) {
        auto [it, fresh] = ids->emplace(f.id, c.where().line);
        if (!fresh)
            throw DataError(c.where(), "facet id " + f.id + " already used at line " +
                                           std::to_string(it->second));
    }
    read_facet_attributes(c, f);
    read_facet_geometry(c, f);
    return f;
}

// An OBJECT or PART record (T: GdbObject or GdbPart) after its keyword line: its name
// and id, read as "<kind> name" and "<kind> id".
template <class T>
T read_named(LineCursor& c, int keyword_line, std::string_view name_what,
             std::string_view id_what) {
    T t;
    t.line = keyword_line;
    t.name = read_text(c, name_what);
    t.id = read_id(c, id_what);
    return t;
}

GdbObject read_object(LineCursor& c, int keyword_line) {
    return read_named<GdbObject>(c, keyword_line, "object name", "object id");
}

GdbPart read_part(LineCursor& c, int keyword_line) {
    return read_named<GdbPart>(c, keyword_line, "part name", "part id");
}

}  // namespace

Gdb parse_gdb_serial(const TextInput& in) {
    Gdb gdb;
    gdb.file = in.name();
    LineCursor c(in);
    c.require_not_empty("OBJECT or END");
    std::unordered_map<std::string, int> facet_ids;
    while (true) {
        const Line& line = c.next(kEndWhat);
        if (line.text == "END") break;
        if (line.text == "OBJECT") {
            gdb.objects.push_back(read_object(c, line.number));
        } else if (line.text == "PART") {
            if (gdb.objects.empty())
                throw DataError(c.where(line),
                                "expected OBJECT before PART, found PART outside an OBJECT");
            gdb.objects.back().parts.push_back(read_part(c, line.number));
        } else if (line.text == "FACE") {
            if (gdb.objects.empty() || gdb.objects.back().parts.empty())
                throw DataError(c.where(line),
                                "expected PART before FACE, found FACE outside a PART");
            int number = line.number;
            gdb.objects.back().parts.back().facets.push_back(read_facet(c, number, &facet_ids));
        } else {
            throw DataError(c.where(line), "expected " + std::string(kEndWhat) + ", found " +
                                               sigchain::quoted(line.text));
        }
    }
    c.require_end("END");
    return gdb;
}

namespace {

// --- A large file in pieces ---
//
// The file is cut at lines "FACE" into pieces of about kPieceBytes, each parsed on its
// own (its records: those whose keyword line is in it). Joined in order they are the
// serial parse's result when every piece parsed whole (its last record ends where the
// next piece begins), each piece's leading facets and parts have a part and an object
// to join, facet ids are unique and END ends the file. Anything else (an error of the
// file, or a cut the serial parse would not read as a record's start) is left to
// parse_gdb_serial, which then names the first error in file order with its line (a
// file with an error is read twice). Even on one thread the pieces are faster than the
// serial parse (bench_parsers, 100000 facets: ~225 against ~340 ms): their line tables are
// small and reused, and a part's facets are moved into memory reserved once.

constexpr std::size_t kPieceBytes = std::size_t{1} << 18;

struct Piece {
    std::vector<GdbFacet> facets;  // before its first PART or OBJECT: the open part's
    std::vector<GdbPart> parts;    // before its first OBJECT: the open object's
    std::vector<GdbObject> objects;
    bool has_lines = false;  // it has significant lines
    bool ends = false;       // it holds END, with nothing after it
    bool ok = false;         // parsed whole
};

// Where the pieces begin: 0, then the first line "FACE" from every kPieceBytes on.
std::vector<std::size_t> piece_starts(std::string_view text) {
    std::vector<std::size_t> starts{0};
    std::size_t from = kPieceBytes;
    while (from < text.size()) {
        std::size_t k = text.find("\nFACE", from - 1);
        while (k != std::string_view::npos) {
            std::string_view rest = text.substr(k + 5, 2);
            if (rest.empty() || rest[0] == '\n' || rest == "\r\n") break;
            k = text.find("\nFACE", k + 1);
        }
        if (k == std::string_view::npos) break;
        starts.push_back(k + 1);
        from = k + 1 + kPieceBytes;
    }
    return starts;
}

void parse_piece(const TextInput& in, std::string_view text, int first_line, Piece& p) {
    LineCursor c(in, text, first_line);
    p.has_lines = !c.at_end();
    try {
        while (!c.at_end()) {
            const Line& line = c.next(kEndWhat);
            if (line.text == "END") {
                p.ends = true;
                p.ok = c.at_end();
                return;
            }
            if (line.text == "OBJECT") {
                p.objects.push_back(read_object(c, line.number));
            } else if (line.text == "PART") {
                (p.objects.empty() ? p.parts : p.objects.back().parts)
                    .push_back(read_part(c, line.number));
            } else if (line.text == "FACE") {
                if (!p.objects.empty() && p.objects.back().parts.empty()) return;
                auto& to = !p.objects.empty() ? p.objects.back().parts.back().facets
                           : !p.parts.empty() ? p.parts.back().facets
                                              : p.facets;
                to.push_back(read_facet(c, line.number, nullptr));
            } else {
                return;
            }
        }
        p.ok = true;
    } catch (const DataError&) {
        // parse_gdb_serial names it
    }
}

template <class T>
void append(std::vector<T>& to, std::vector<T>& from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// The leading facets of pieces[i] and of the pieces after it that go to the same part.
std::size_t leading_facets(const std::vector<Piece>& pieces, std::size_t i) {
    std::size_t n = 0;
    for (; i < pieces.size(); ++i) {
        n += pieces[i].facets.size();
        if (!pieces[i].parts.empty() || !pieces[i].objects.empty()) break;
    }
    return n;
}

// Joins pieces[i] to `gdb`; false where the serial parse would fail.
bool join_piece(Gdb& gdb, std::vector<Piece>& pieces, std::size_t i, bool& ended) {
    Piece& p = pieces[i];
    if (ended) return !p.has_lines;
    if (!p.ok) return false;
    if (!p.facets.empty()) {
        if (gdb.objects.empty() || gdb.objects.back().parts.empty()) return false;
        auto& to = gdb.objects.back().parts.back().facets;
        // Once for the part (not doubling as it grows): new memory costs page faults.
        if (to.capacity() < to.size() + p.facets.size())
            to.reserve(to.size() + leading_facets(pieces, i));
        append(to, p.facets);
    }
    if (!p.parts.empty()) {
        if (gdb.objects.empty()) return false;
        append(gdb.objects.back().parts, p.parts);
    }
    append(gdb.objects, p.objects);
    ended = p.ends;
    return true;
}

bool unique_facet_ids(const Gdb& gdb) {
    std::unordered_set<std::string_view> ids;
    ids.reserve(gdb_facet_count(gdb));
    for (const auto& obj : gdb.objects)
        for (const auto& part : obj.parts)
            for (const auto& f : part.facets)
                if (!ids.insert(f.id).second) return false;
    return true;
}

}  // namespace

Gdb parse_gdb(const TextInput& in, const ParallelOptions& parallel) {
    const std::string_view text = in.text();
    if (text.size() < kGdbParallelBytes) return parse_gdb_serial(in);
    const std::vector<std::size_t> starts = piece_starts(text);
    const long n = static_cast<long>(starts.size());
    if (n < 2) return parse_gdb_serial(in);
    auto piece_text = [&](long i) {
        const std::size_t end = i + 1 < n ? starts[i + 1] : text.size();
        return text.substr(starts[i], end - starts[i]);
    };
    ParallelOptions opt;
    opt.threads = parallel.threads;
    std::vector<int> first_line(starts.size() + 1, 1);  // then each piece's line count
    parallel_for(n, opt, [&](long i, unsigned) {
        const std::string_view t = piece_text(i);
        first_line[i + 1] = static_cast<int>(std::count(t.begin(), t.end(), '\n'));
    });
    for (long i = 0; i < n; ++i) first_line[i + 1] += first_line[i];
    std::vector<Piece> pieces(starts.size());
    parallel_for(n, opt, [&](long i, unsigned) {
        parse_piece(in, piece_text(i), first_line[i], pieces[i]);
    });
    Gdb gdb;
    gdb.file = in.name();
    bool ended = false;
    for (std::size_t i = 0; i < pieces.size(); ++i)
        if (!join_piece(gdb, pieces, i, ended)) return parse_gdb_serial(in);
    if (!ended || !unique_facet_ids(gdb)) return parse_gdb_serial(in);
    return gdb;
}

namespace {

void write_facet(std::ostream& out, const GdbFacet& f) {
    out << "FACE\n" << f.name << '\n' << f.id << '\n';
    out << f.material_name << '\n' << f.material_id << '\n' << f.legacy_name << '\n';
    out << format_number(f.temperature_c) << '\n' << format_number(f.thickness_cm) << '\n';
    out << format_number(f.power) << '\n' << format_number(f.exposed_area) << '\n';
    for (const auto& spare : f.spares) out << spare << '\n';
    out << f.vertices.size() << '\n';
    auto vec = [&](const Vec3& v) {
        out << format_number(v[0]) << ' ' << format_number(v[1]) << ' ' << format_number(v[2])
            << '\n';
    };
    for (const auto& v : f.vertices) vec(v);
    vec(f.normal);
    out << format_number(f.slope_zenith_deg) << '\n' << format_number(f.slope_azimuth_deg) << '\n';
    out << f.spare << '\n';
}

}  // namespace

void write_gdb(std::ostream& out, const Gdb& gdb) {
    for (const auto& obj : gdb.objects) {
        out << "OBJECT\n" << obj.name << '\n' << obj.id << '\n';
        for (const auto& part : obj.parts) {
            out << "PART\n" << part.name << '\n' << part.id << '\n';
            for (const auto& f : part.facets) write_facet(out, f);
        }
    }
    out << "END\n";
}

std::size_t gdb_facet_count(const Gdb& gdb) {
    std::size_t n = 0;
    for (const auto& obj : gdb.objects)
        for (const auto& part : obj.parts) n += part.facets.size();
    return n;
}

namespace {

// "1 facet", "2 facets" (for summaries).
std::string plural(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

FormatHandler gdb_format() {
    return {"gdb", "geometric database (DIRSIG 3 layout)",
            [](const TextInput& in) {
                Gdb g = parse_gdb(in);
                std::size_t parts = 0;
                for (const auto& obj : g.objects) parts += obj.parts.size();
                std::ostringstream s;
                s << plural(g.objects.size(), "object") << ", " << plural(parts, "part") << ", "
                  << plural(gdb_facet_count(g), "facet");
                auto problems = gdb_problems(g);
                if (!problems.empty()) s << ", " << plural(problems.size(), "geometry problem");
                return s.str();
            },
            [](const TextInput& in, std::ostream& out) { write_gdb(out, parse_gdb(in)); }};
}

}  // namespace sigchain::io
