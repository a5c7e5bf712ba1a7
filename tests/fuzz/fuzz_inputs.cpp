// libFuzzer harness for the inputs outside the format registry: LOWTRAN 7 / MODTRAN
// TAPE7 files (io::parse_tape7), meshes through Assimp (PLY, OBJ, STL), DEMs (an Esri
// ASCII grid) and a DEM's .prj, each as trace reads it (run by `make fuzz` and, briefly,
// by `make test`).
//
// Input layout: the first byte picks the input (modulo 6): 0 a TAPE7; 1 a PLY, 2 an
// OBJ, 3 an STL, each loaded as the scene with material id 1 (scene::load_scene); 4 an
// ASCII grid beside a fixed WGS84 .prj, 5 a .prj beside a fixed 2 x 2 grid, loaded as
// the scene with material id 1 at the grid's origin. The rest is the file.
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
#include "io/tape7.hpp"
#include "scene/load.hpp"

namespace {

std::string g_dir;  // the temporary folder, made once

const char kWgs84[] =
    "GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137.0,"
    "298.257223563]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]]\n";
const char kGrid[] =
    "ncols 2\nnrows 2\nxllcorner -77.66677\nyllcorner 43.08323\ncellsize 0.0001\n1 2\n3 4\n";

std::string write(const std::string& name, std::string_view text) {
    const std::string path = g_dir + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    return path;
}

void load(const std::string& path, bool dem) {
    sigchain::scene::LoadOptions options;
    options.input.material_id = 1;
    if (dem) options.origin = sigchain::scene::GeoOrigin{43.0834, -77.6667, 0};
    sigchain::scene::load_scene(path, options);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    char pattern[] = "/tmp/sigchain-fuzz-inputs-XXXXXX";
    if (!mkdtemp(pattern)) std::abort();
    g_dir = pattern;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        switch (data[0] % 6) {
        case 0:
            sigchain::io::parse_tape7(
                sigchain::TextInput::from_string(std::string(text), "fuzz.tp7"));
            break;
        case 1: load(write("m.ply", text), false); break;
        case 2: load(write("m.obj", text), false); break;
        case 3: load(write("m.stl", text), false); break;
        case 4:
            write("g.prj", kWgs84);
            load(write("g.asc", text), true);
            break;
        default:
            write("g.prj", text);
            load(write("g.asc", kGrid), true);
            break;
        }
    } catch (const sigchain::Error&) {
    }
    return 0;
}
