// Tests for the .gdb reader's parse in pieces (lib/io/gdb, parse_gdb with
// ParallelOptions): parse_gdb_serial's facets, order, numbers and lines, and its first
// error, for 1, 2 and 4 threads on files beyond kGdbParallelBytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "data_error.hpp"
#include "io/gdb.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

// A number with all 17 significant digits, from a fixed pseudo-random sequence.
class Numbers {
public:
    double next(double scale) {
        m_state = m_state * 6364136223846793005ULL + 1442695040888963407ULL;
        const double unit = static_cast<double>(m_state >> 11) / 9007199254740992.0;
        return (unit - 0.5) * scale;
    }

private:
    std::uint64_t m_state = 88172645463325252ULL;
};

std::string g17(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// About `bytes` of .gdb: two objects, five parts, triangles and quads with 17-digit
// coordinates, comments (also after FACE) and blank lines; `eol` ends every line.
std::string big_gdb(std::size_t bytes, const std::string& eol = "\n") {
    std::ostringstream s;
    Numbers n;
    long facet = 0;
    auto line = [&](const std::string& text) { s << text << eol; };
    line("# a generated scene");
    for (int obj = 1; obj <= 2; ++obj) {
        line("OBJECT");
        line("object " + std::to_string(obj));
        line(std::to_string(obj) + "-0-0");
        for (int part = 1; part <= (obj == 1 ? 2 : 3); ++part) {
            line("PART");
            line("part " + std::to_string(part));
            line(std::to_string(obj) + "-" + std::to_string(part) + "-0");
            const std::size_t until = bytes * static_cast<std::size_t>(obj * 3 + part - 3) / 6;
            while (static_cast<std::size_t>(s.tellp()) < until) {
                ++facet;
                line(facet % 7 == 0 ? "FACE   # with a comment" : "FACE");
                line("facet " + std::to_string(facet));
                line(std::to_string(obj) + "-" + std::to_string(part) + "-" +
                     std::to_string(facet));
                line(facet % 3 ? "grass" : "asphalt");
                line(std::to_string(facet % 5));
                line("legacy");
                line(facet % 2 ? "-1" : g17(20 + n.next(10)));
                line("-1");
                line("-1");
                line(g17(n.next(2) + 1));
                line("null");
                line("null");
                line("null");
                if (facet % 11 == 0) line("");
                const int count = facet % 4 == 0 ? 4 : 3;
                line(std::to_string(count));
                for (int v = 0; v < count; ++v)
                    line(g17(n.next(1000)) + " " + g17(n.next(1000)) + "  " + g17(n.next(50)));
                line(g17(n.next(1)) + " " + g17(n.next(1)) + " 1");
                line(g17(std::abs(n.next(90))));
                line(g17(n.next(360)));
                line("null");
            }
        }
    }
    line("END");
    return s.str();
}

void put(std::ostringstream& out, double v) { out << ' ' << std::bit_cast<std::uint64_t>(v); }

// Everything parse_gdb returns, the doubles as their bits.
std::string dump(const Gdb& g) {
    std::ostringstream out;
    out << g.file << '\n';
    for (const auto& obj : g.objects) {
        out << "O " << obj.line << ' ' << obj.name << '|' << obj.id << '\n';
        for (const auto& part : obj.parts) {
            out << "P " << part.line << ' ' << part.name << '|' << part.id << '\n';
            for (const auto& f : part.facets) {
                out << "F " << f.line << ' ' << f.name << '|' << f.id << '|' << f.material_name
                    << '|' << f.material_id << '|' << f.legacy_name << '|' << f.spares[0] << '|'
                    << f.spares[1] << '|' << f.spares[2] << '|' << f.spare;
                for (double v : {f.temperature_c, f.thickness_cm, f.power, f.exposed_area,
                                 f.slope_zenith_deg, f.slope_azimuth_deg})
                    put(out, v);
                for (const auto& v : f.vertices)
                    for (double x : v) put(out, x);
                for (double x : f.normal) put(out, x);
                out << '\n';
            }
        }
    }
    return out.str();
}

Gdb parsed(const std::string& text, unsigned threads) {
    ParallelOptions o;
    o.threads = threads;
    return parse_gdb(TextInput::from_string(text, "big.gdb"), o);
}

Gdb serial(const std::string& text) {
    return parse_gdb_serial(TextInput::from_string(text, "big.gdb"));
}

std::string error_of(const std::string& text, unsigned threads) {
    return test::data_error_of([&] { parsed(text, threads); });
}

// The error of each thread count, which must be the serial parse's and `want`.
void expect_error(const std::string& text, const std::string& want) {
    EXPECT_EQ(test::data_error_of([&] { serial(text); }), want);
    for (unsigned threads : {1u, 2u, 4u}) EXPECT_EQ(error_of(text, threads), want) << threads;
}

// The line number of byte `at`.
int line_at(const std::string& text, std::size_t at) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// The start of the first line `line` (a whole line) at or after byte `from`.
std::size_t find_line(const std::string& text, const std::string& line, std::size_t from) {
    std::size_t at = text.find("\n" + line + "\n", from);
    if (at == std::string::npos) throw std::logic_error("no line " + line);
    return at + 1;
}

// The start of the `n`th non-blank line after the one starting at `at`.
std::size_t lines_on(const std::string& text, std::size_t at, int n) {
    while (n > 0) {
        at = text.find('\n', at) + 1;
        if (text[at] != '\n') --n;
    }
    return at;
}

// The text of the line starting at `at`.
std::string line_of(const std::string& text, std::size_t at) {
    return text.substr(at, text.find('\n', at) - at);
}

// A byte at `fraction` of the text.
std::size_t at_fraction(const std::string& text, double fraction) {
    return static_cast<std::size_t>(static_cast<double>(text.size()) * fraction);
}

}  // namespace

TEST(GdbParallel, SameResultForAnyThreadCount) {
    const std::string text = big_gdb(3 << 20);
    ASSERT_GT(text.size(), kGdbParallelBytes);
    const Gdb g = serial(text);
    EXPECT_GT(gdb_facet_count(g), 8000u);
    const std::string want = dump(g);
    for (unsigned threads : {1u, 2u, 4u, 0u})
        EXPECT_EQ(dump(parsed(text, threads)), want) << threads;
}

TEST(GdbParallel, CrlfLinesToo) {
    const std::string text = big_gdb(2 << 20, "\r\n");
    const std::string want = dump(serial(text));
    for (unsigned threads : {1u, 2u, 4u}) EXPECT_EQ(dump(parsed(text, threads)), want) << threads;
}

TEST(GdbParallel, AnErrorDeepInALatePieceNamesItsLine) {
    std::string text = big_gdb(3 << 20);
    // The third vertex line of a facet at 90% of the file: a field that is not a number.
    const std::size_t at = lines_on(text, find_line(text, "FACE", at_fraction(text, 0.9)), 16);
    text.replace(at, line_of(text, at).size(), "1 2 x");
    const std::string want =
        "big.gdb:" + std::to_string(line_at(text, at)) + ": expected vertex x y z (a number), "
                                                         "found 'x'";
    expect_error(text, want);
}

TEST(GdbParallel, TheFirstErrorInFileOrderWins) {
    std::string text = big_gdb(3 << 20);
    // A bad thickness at 85%, then a facet missing its last line (its spare) at 30%.
    const std::size_t late = lines_on(text, find_line(text, "FACE", at_fraction(text, 0.85)), 7);
    text.replace(late, line_of(text, late).size(), "-2");
    const std::size_t next = find_line(text, "FACE", at_fraction(text, 0.3));
    const std::size_t spare = text.rfind("null\n", next - 1);
    text.erase(spare, 5);
    const std::string want = "big.gdb:" + std::to_string(line_at(text, spare)) +
                             ": expected facet spare field, found keyword 'FACE'";
    expect_error(text, want);
}

TEST(GdbParallel, AFacetIdUsedInAnEarlierPiece) {
    std::string text = big_gdb(3 << 20);
    const std::size_t first = find_line(text, "FACE", at_fraction(text, 0.05));
    const std::size_t first_id = lines_on(text, first, 2);
    const std::string id = line_of(text, first_id);
    const std::size_t again_id = lines_on(text, find_line(text, "FACE", at_fraction(text, 0.8)), 2);
    text.replace(again_id, line_of(text, again_id).size(), id);
    const std::string want = "big.gdb:" + std::to_string(line_at(text, again_id)) +
                             ": facet id " + id + " already used at line " +
                             std::to_string(line_at(text, first_id));
    expect_error(text, want);
}

TEST(GdbParallel, EndAndWhatFollowsItAsInSerial) {
    const std::string text = big_gdb(2 << 20);
    const std::string no_end = text.substr(0, text.size() - 4);
    const std::string after = text + "FACE\n";
    const std::size_t half = find_line(text, "FACE", at_fraction(text, 0.5));
    const std::string early = text.substr(0, half) + "END\n" + text.substr(half);
    expect_error(no_end, "big.gdb:" + std::to_string(line_at(no_end, no_end.size() - 1)) +
                             ": unexpected end of file, expected OBJECT, PART, FACE or END (a "
                             ".gdb ends with END)");
    expect_error(after, "big.gdb:" + std::to_string(line_at(after, after.size() - 1)) +
                            ": unexpected content after END, found 'FACE'");
    expect_error(early, "big.gdb:" + std::to_string(line_at(early, half + 4)) +
                            ": unexpected content after END, found 'FACE'");
}

namespace {

// The result's dump, or its error's message.
std::string outcome(const std::function<Gdb()>& parse) {
    try {
        return dump(parse());
    } catch (const DataError& e) {
        return std::string("error: ") + e.what();
    }
}

}  // namespace

TEST(GdbParallel, RandomEditsGiveTheSerialOutcome) {
    const std::string base = big_gdb(5 << 18);
    Numbers n;
    // Before a facet: valid records and lines (the first three), and invalid ones.
    const char* inserts[] = {"PART\nextra\n1-9-0\n",
                             "OBJECT\nextra\n9-0-0\nPART\nextra\n9-1-0\n",
                             "\n# FACE\n\n",
                             "END\n",
                             "OBJECT\nextra\n8-0-0\n",
                             "FACE\n",
                             "1-1-1\n"};
    int valid = 0;
    for (int k = 0; k < 24; ++k) {
        std::string text = base;
        // One to three edits: a line deleted, doubled or replaced by FACE, or a record or
        // line inserted before a facet (only valid ones in every other file).
        for (int e = 0; e <= k % 3; ++e) {
            const auto at_byte = static_cast<std::size_t>((n.next(1) + 0.5) * double(text.size()));
            const std::size_t at = text.rfind('\n', at_byte) + 1;
            const std::size_t len = text.find('\n', at) + 1 - at;
            const std::string line = text.substr(at, len);
            const int kind = k % 2 ? 3 : (k / 2 + e) % 7;
            switch (kind) {
                case 0: text.erase(at, len); break;
                case 1: text.insert(at, line); break;
                case 2: text.replace(at, len, "FACE\n"); break;
                default:
                    const char* what = inserts[(k / 2 + e) % (k % 2 ? 3 : 7)];
                    text.insert(find_line(text, "FACE", at), what);
            }
        }
        const std::string want = outcome([&] { return serial(text); });
        valid += want.rfind("error: ", 0) != 0;
        for (unsigned threads : {1u, 2u, 4u})
            EXPECT_EQ(outcome([&] { return parsed(text, threads); }), want) << k << " " << threads;
    }
    EXPECT_GE(valid, 12);
}
