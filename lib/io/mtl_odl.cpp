// The ODL layer of Landsat MTL files (man mtl(5)): GROUP / END_GROUP / KEY = VALUE / END,
// with /* ... */ comments.
#include <cctype>
#include <vector>

#include "io/mtl.hpp"

namespace sigchain::io {

namespace {

// Removes /* ... */ comments from one line (quotes protect their contents); `in_comment`
// carries an open comment over to the next line.
std::string strip_comments(std::string_view line, bool& in_comment) {
    std::string out;
    bool in_quote = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (in_comment) {
            if (line.compare(i, 2, "*/") == 0) in_comment = false, ++i;
            continue;
        }
        if (!in_quote && line.compare(i, 2, "/*") == 0) {
            in_comment = true, ++i;
            out += ' ';
            continue;
        }
        if (line[i] == '"') in_quote = !in_quote;
        out += line[i];
    }
    return out;
}

bool valid_key(std::string_view key) {
    if (key.empty()) return false;
    for (char c : key)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

OdlEntry parse_statement(std::string_view text, const SourceLocation& where) {
    const auto eq = text.find('=');
    if (eq == std::string_view::npos)
        throw DataError(where, "expected KEY = VALUE, GROUP = NAME or END, found " + quoted(text));
    OdlEntry e;
    e.key = std::string(trim(text.substr(0, eq)));
    if (!valid_key(e.key))
        throw DataError(where, "expected a key (letters, digits, '_') before '=', found " +
                                   quoted(e.key));
    std::string_view value = trim(text.substr(eq + 1));
    if (value.empty()) throw DataError(where, "expected a value after '" + e.key + " ='");
    if (value.front() == '"') {
        if (value.size() < 2 || value.back() != '"' ||
            value.substr(1, value.size() - 2).find('"') != std::string_view::npos)
            throw DataError(where, "expected a quoted string on one line, found " + quoted(value));
        e.value = std::string(value.substr(1, value.size() - 2));
        e.quoted = true;
    } else {
        if (value.find_first_of(" \t\"") != std::string_view::npos)
            throw DataError(where, "expected one value after '" + e.key + " =', found " +
                                       quoted(value));
        e.value = std::string(value);
    }
    return e;
}

using OpenGroups = std::vector<std::pair<std::string, int>>;  // open groups and their lines

// END closes the file: every group must be closed before it.
void check_groups_closed(const OpenGroups& groups, const SourceLocation& where) {
    if (!groups.empty())
        throw DataError(where, "expected END_GROUP = " + groups.back().first +
                                   " (the GROUP on line " + std::to_string(groups.back().second) +
                                   ") before END");
}

// The statement of entry e: a value; a GROUP, pushed on `groups`; or an END_GROUP, which
// must close the innermost open group.
OdlStatement statement(const OdlEntry& e, OpenGroups& groups, const SourceLocation& where,
                       int number) {
    OdlStatement s{OdlStatement::Kind::Value, e};
    if (e.key == "GROUP" || e.key == "BEGIN_GROUP") {
        s.kind = OdlStatement::Kind::Group;
        groups.emplace_back(e.value, number);
    } else if (e.key == "END_GROUP") {
        if (groups.empty())
            throw DataError(where, "END_GROUP = " + e.value + " without an open GROUP");
        if (groups.back().first != e.value)
            throw DataError(where, "expected END_GROUP = " + groups.back().first +
                                       " (the GROUP on line " +
                                       std::to_string(groups.back().second) + "), found " +
                                       quoted(e.value));
        groups.pop_back();
        s.kind = OdlStatement::Kind::EndGroup;
        s.entry.depth = static_cast<int>(groups.size());
    }
    return s;
}

// At the end of the text: no comment left open, and an END seen.
void check_ending(const TextInput& in, const Odl& odl, const OpenGroups& groups, bool ended,
                  bool in_comment, int comment_line) {
    if (in_comment)
        throw DataError(in.at(comment_line), "a /* comment is not closed by */");
    if (!ended) {
        int last = odl.statements.empty() ? 0 : odl.statements.back().entry.line;
        if (odl.statements.empty()) throw DataError(in.at(0), "empty file, expected an MTL file");
        throw DataError(in.at(last), "unexpected end of file, expected END" +
                                         (groups.empty() ? std::string()
                                                         : " and END_GROUP = " + groups.back().first));
    }
}

}  // namespace

Odl parse_odl(const TextInput& in) {
    Odl odl;
    OpenGroups groups;
    bool in_comment = false, ended = false;
    int comment_line = 0;
    const std::string& text = in.text();
    std::size_t pos = 0;
    for (int number = 1; pos < text.size(); ++number) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        const bool was_in_comment = in_comment;
        const std::string line = strip_comments(std::string_view(text).substr(pos, end - pos),
                                                in_comment);
        if (!was_in_comment && in_comment) comment_line = number;
        pos = end + 1;
        const std::string_view body = trim(line);
        if (body.empty()) continue;
        const SourceLocation where = in.at(number);
        if (ended) throw DataError(where, "unexpected content after END, found " + quoted(body));
        if (body == "END") {
            check_groups_closed(groups, where);
            ended = true;
            odl.end_line = number;
            continue;
        }
        OdlEntry e = parse_statement(body, where);
        e.line = number;
        e.group = groups.empty() ? "" : groups.back().first;
        e.depth = static_cast<int>(groups.size());
        odl.statements.push_back(statement(e, groups, where, number));
    }
    check_ending(in, odl, groups, ended, in_comment, comment_line);
    return odl;
}

void write_odl(std::ostream& out, const Odl& odl) {
    for (const auto& s : odl.statements) {
        out << std::string(2 * static_cast<std::size_t>(s.entry.depth), ' ') << s.entry.key
            << " = ";
        if (s.entry.quoted)
            out << '"' << s.entry.value << '"';
        else
            out << s.entry.value;
        out << '\n';
    }
    out << "END\n";
}

}  // namespace sigchain::io
