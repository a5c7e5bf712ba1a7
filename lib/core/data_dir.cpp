#include "core/data_dir.hpp"

#include <cstdlib>
#include <filesystem>

#include "core/error.hpp"
#include "sigchain/version.hpp"

namespace sigchain {

namespace {

// The data an installed copy carries: PREFIX/share/sigchain/data beside the running
// program's PREFIX/bin (`make install`); empty when there is none (a build tree).
std::string installed_data_dir() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const std::filesystem::path dir = exe.parent_path().parent_path() / "share/sigchain/data";
    return std::filesystem::is_directory(dir, ec) ? dir.string() : std::string();
}

}  // namespace

std::string data_dir(const std::string& option) {
    std::string dir = option;
    std::string from = "--data-dir";
    if (dir.empty()) {
        const char* env = std::getenv("SIGCHAIN_DATA");
        if (env && *env) {
            dir = env;
            from = "SIGCHAIN_DATA";
        } else if (dir = installed_data_dir(); !dir.empty()) {
            from = "the installed data directory";
        } else {
            dir = kDefaultDataDir;
            from = "the build's data directory";
        }
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw IoError(dir + ": data directory (" + from + ") does not exist");
    return dir;
}

}  // namespace sigchain
