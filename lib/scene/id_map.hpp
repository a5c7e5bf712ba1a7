// Map files (odb(5) MAP FILES): OBJ material names or land-use classes to .mat ids.
#pragma once

#include <string>
#include <unordered_map>

namespace sigchain::scene {

// One text file of "KEY ID" lines: the ID (an integer >= 0, a mat(5) MATERIAL_ID) is
// the last field; the KEY is everything before it, trimmed (it may contain spaces).
// `#` starts a comment; blank lines are ignored. Each KEY at most once.
struct IdMap {
    std::string file;
    struct Entry {
        long id = 0;
        int line = 0;
    };
    std::unordered_map<std::string, Entry> entries;

    // The entry for `key`, or null.
    const Entry* find(const std::string& key) const {
        auto it = entries.find(key);
        return it == entries.end() ? nullptr : &it->second;
    }
};

// Reads a map file; throws IoError if it cannot be read, DataError "FILE:LINE: ..."
// for a line without a key and an id, a bad id, a repeated key or an empty map.
IdMap read_id_map(const std::string& path);
IdMap parse_id_map(const std::string& text, const std::string& name);

}  // namespace sigchain::scene
