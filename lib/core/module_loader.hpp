// Opening sigchain's shared modules: libraries built on their own (CMake MODULE targets,
// installed in LIBDIR/sigchain/) that a static library opens with dlopen on first use,
// so that a process that does not need them does not load them and what they link (the
// OpenImageIO back end, lib/image/oiio_module.hpp; the MPI transport,
// lib/core/mpi_module.hpp). Each module exports one extern "C" function that returns a
// struct of function pointers starting with its size and its interface version.
#pragma once

#include <cstdint>
#include <string>

namespace sigchain {

namespace detail {

struct ModuleEntry {
    void* entry = nullptr;  // the entry point's address; null on failure
    std::string failed;     // "cannot load the WHAT module PATH: "
    std::string error;      // failed + the reason, when entry is null
};

// dlopens the module file `file_name` and looks up `symbol` in it (ModuleEntry).
ModuleEntry open_module(const std::string& file_name, const char* symbol,
                        const std::string& what);

}  // namespace detail

template <typename Api>
struct LoadedModule {
    const Api* api = nullptr;
    std::string error;  // why api is null: "cannot load the WHAT module PATH: REASON"
};

// Opens the module `file_name` from its candidate paths, in order: LIBDIR/sigchain
// beside the running program's bin folder (an installed copy, and the build tree's
// bin/), then the build tree's folder (unit tests and benchmarks, whose programs live
// elsewhere in the build tree); both are fixed when sigchain is configured
// (CMakeLists.txt). The first candidate that exists is opened (the first one when none
// does, for dlerror's message), its extern "C" function `symbol` is called, and the
// Api it returns must have this sizeof(Api) and `version`. Not thread-safe: callers
// load once, under std::call_once.
template <typename Api>
LoadedModule<Api> load_module(const std::string& file_name, const char* symbol,
                              const std::string& what, std::uint32_t version) {
    const detail::ModuleEntry opened = detail::open_module(file_name, symbol, what);
    if (!opened.entry) return {nullptr, opened.error};
    using Entry = const Api* (*)();
    const Api* api = reinterpret_cast<Entry>(opened.entry)();
    if (!api || api->size != sizeof(Api) || api->version != version)
        return {nullptr, opened.failed + "built for another interface (version " +
                             std::to_string(api ? api->version : 0) + ", expected " +
                             std::to_string(version) + ")"};
    return {api, {}};
}

}  // namespace sigchain
