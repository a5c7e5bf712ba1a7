// Validating and canonicalising any sigchain file by its format (sigchain-check).
#pragma once

#include <optional>
#include <ostream>
#include <string>

namespace sigchain::io {

// The format extension of a path: "scene.adv" -> "adv"; DIRSIG's numbered radiance
// files "scene.rad2" -> "rad". Empty if there is none.
std::string format_of_path(const std::string& path);

// Parses `path` ("-" is stdin) as `format` (or by its extension when empty) and
// returns a one-line summary; with `rewrite`, also writes the canonical form.
// Throws UsageError for an unknown format, DataError/IoError for bad files.
std::string check_file(const std::string& path, const std::string& format, std::ostream* rewrite);

}  // namespace sigchain::io
