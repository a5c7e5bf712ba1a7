// Validating and canonicalising any sigchain file by its format.
#include "io/check.hpp"

#include <cctype>

#include "core/error.hpp"
#include "io/registry.hpp"

namespace sigchain::io {

std::string format_of_path(const std::string& path) {
    std::string ext = file_extension(path);
    // DIRSIG names one radiance file per band "NAME.rad1", "NAME.rad2", ...
    if (ext.size() > 3 && ext.compare(0, 3, "rad") == 0 &&
        ext.find_first_not_of("0123456789", 3) == std::string::npos)
        ext = "rad";
    return ext;
}

std::string check_file(const std::string& path, const std::string& format, std::ostream* rewrite) {
    std::string ext = format.empty() ? format_of_path(path) : format;
    if (ext.empty())
        throw UsageError(path + ": cannot tell the format from the name; use --format");
    const FormatHandler* handler = find_format(ext);
    if (!handler) throw UsageError("unknown format '" + ext + "'");
    TextInput in = TextInput::from_file(path);
    std::string summary = handler->check(in);
    if (rewrite) handler->rewrite(in, *rewrite);
    return summary;
}

}  // namespace sigchain::io
