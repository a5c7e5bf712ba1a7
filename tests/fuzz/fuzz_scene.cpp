// libFuzzer harness for a whole tool's input path: a scene as trace, therm and the
// shadow history read it (lib/scene's load_scene on an .odb naming a .gdb, and the .mat
// beside them), from files written to a temporary folder (run by `make fuzz` and,
// briefly, by `make test`).
//
// Input layout: three texts separated by a line "%%": the .odb (scene.odb), the .gdb
// (a.gdb) and the .mat (scene.mat). A missing part is an empty file. The .odb may
// name only files of that folder: an input with '/' in its .odb is skipped, so the
// fuzzer cannot make the harness read /dev/stdin or a FIFO elsewhere.
//
// Expected for bad input: a sigchain::Error, which is caught. Everything else (any
// other exception, a crash, a sanitizer report, a timeout, an out-of-memory) is a
// finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/text.hpp"
#include "io/mat.hpp"
#include "scene/load.hpp"

namespace {

std::string g_dir;  // the temporary folder, made once

void write(const std::string& name, std::string_view text) {
    std::ofstream out(g_dir + "/" + name, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    char pattern[] = "/tmp/sigchain-fuzz-scene-XXXXXX";
    if (!mkdtemp(pattern)) std::abort();
    g_dir = pattern;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view all(reinterpret_cast<const char*>(data), size);
    std::string_view part[3];
    for (int i = 0; i < 3; ++i) {
        auto sep = all.find("\n%%\n");
        part[i] = all.substr(0, sep);
        all = sep == std::string_view::npos ? std::string_view() : all.substr(sep + 4);
    }
    if (part[0].find('/') != std::string_view::npos) return 0;
    write("scene.odb", part[0]);
    write("a.gdb", part[1]);
    write("scene.mat", part[2]);
    try {
        sigchain::io::read_mat_file(g_dir + "/scene.mat");
    } catch (const sigchain::Error&) {
    }
    try {
        sigchain::scene::LoadReport report;
        sigchain::scene::load_scene(g_dir + "/scene.odb", sigchain::scene::LoadOptions{}, &report);
    } catch (const sigchain::Error&) {
    }
    return 0;
}
