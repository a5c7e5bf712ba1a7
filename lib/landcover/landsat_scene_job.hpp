// landsat_scene(1)'s Job: its command line (a command, its arguments and the options)
// mapped onto the steps of landcover/landsat_scene.hpp.
// Thread-safety: free function.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace sigchain::landcover {

struct LandsatSceneOptions {
    std::vector<std::string> masks;  // --mask FILE (repeatable): pixels not scored
    std::string points;              // --points CPT: score at these points too
    int bands = 0;                   // --bands N: bands scored (0: all)
    std::string cloud = "b1 > 110";  // --cloud TERMS
    std::string dark = "b4 < 60";    // --dark TERMS
    std::string sun;                 // --sun ELEVATION,AZIMUTH (deg)
    std::string heights = "500,3000";  // --heights MIN,MAX (m)
    int buffer = 2;                  // --buffer N (pixels)
    double pixel_m = 30;             // --pixel M
};

// Runs one command ("classify", "mask", "terrain", "points", "fit", "ems", "score",
// "side-by-side", "difference", "pairs", "stats", "crosstab"); data to `out`, reports to `report`. Throws
// UsageError for a bad command line, DataError or IoError for bad files.
int run_landsat_scene(const std::vector<std::string>& args, const LandsatSceneOptions& options,
                      std::ostream& out, std::ostream& report);

}  // namespace sigchain::landcover
