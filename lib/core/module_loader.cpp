// dlopen of sigchain's shared modules (module_loader.hpp).
#include "core/module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace sigchain::detail {

namespace {

// The candidate paths of module `file_name`, in order (load_module says which).
std::vector<std::string> module_paths(const std::string& file_name) {
    std::vector<std::string> paths;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec)
        paths.push_back((exe.parent_path() / SIGCHAIN_MODULE_FROM_BINDIR / file_name)
                            .lexically_normal()
                            .string());
    paths.push_back(SIGCHAIN_MODULE_BUILD_DIR "/" + file_name);
    return paths;
}

}  // namespace

ModuleEntry open_module(const std::string& file_name, const char* symbol,
                        const std::string& what) {
    const std::vector<std::string> paths = module_paths(file_name);
    std::string path = paths.front();
    std::error_code ec;
    for (const std::string& p : paths)
        if (std::filesystem::exists(p, ec)) {
            path = p;
            break;
        }
    ModuleEntry opened;
    opened.failed = "cannot load the " + what + " module " + path + ": ";
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle) opened.entry = dlsym(handle, symbol);
    if (!opened.entry) {
        const char* reason = dlerror();
        opened.error = opened.failed + (reason ? reason : "no entry point " + std::string(symbol));
    }
    return opened;
}

}  // namespace sigchain::detail
