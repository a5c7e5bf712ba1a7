#include "core/data_dir.hpp"

#include <cstdlib>
#include <filesystem>

#include "core/error.hpp"
#include "sigchain/version.hpp"

namespace sigchain {

std::string data_dir(const std::string& option) {
    std::string dir = option;
    std::string from = "--data-dir";
    if (dir.empty()) {
        const char* env = std::getenv("SIGCHAIN_DATA");
        if (env && *env) {
            dir = env;
            from = "SIGCHAIN_DATA";
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
