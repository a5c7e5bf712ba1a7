// Map files: "KEY ID" lines (OBJ material names, land-use classes).
#include "scene/id_map.hpp"

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::scene {

namespace {

IdMap parse(const TextInput& in) {
    IdMap map;
    map.file = in.name();
    LineCursor cur(in);
    cur.require_not_empty("a map line (KEY ID)");
    while (!cur.at_end()) {
        const Line& line = cur.next("a map line");
        SourceLocation at = cur.where(line);
        auto fields = split_fields(line.text);
        if (fields.size() < 2)
            throw DataError(at, "expected KEY ID (a name or class, then a material id), found " +
                                    quoted(line.text));
        std::string_view last = fields.back();
        long id = parse_count(last, at, "a material id (an integer >= 0)");
        std::string key(trim(line.text.substr(0, line.text.size() - last.size())));
        auto [it, fresh] = map.entries.emplace(key, IdMap::Entry{id, line.number});
        if (!fresh)
            throw DataError(at, "expected each key once, found " + quoted(key) +
                                    " again (first on line " + std::to_string(it->second.line) +
                                    ")");
    }
    return map;
}

}  // namespace

IdMap read_id_map(const std::string& path) { return parse(TextInput::from_file(path)); }

IdMap parse_id_map(const std::string& text, const std::string& name) {
    return parse(TextInput::from_string(text, name));
}

}  // namespace sigchain::scene
