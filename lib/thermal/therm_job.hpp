// therm: facet temperatures (.tmp) at the scene time from the sun/shadow history (.shd),
// weather (.wth), materials (.mat), scene (.gdb/.odb) and scene node (.snd); White (1996), section 3.4.
// The library behind tools/therm (GDAL-apps style: options struct in, work done here).
#pragma once

#include <string>
#include <vector>

#include "core/report.hpp"
#include "io/mat.hpp"
#include "io/shd.hpp"
#include "io/snd.hpp"
#include "io/tmp.hpp"
#include "io/wth.hpp"
#include "thermal/facet_model.hpp"
#include "thermal/scene_facets.hpp"

namespace sigchain::thermal {

struct ThermJob {
    std::string shd_path, wth_path, mat_path, scene_path, snd_path;
    scene::SceneInput scene_input;  // a lone mesh's or DEM's materials
    std::string output_path = "-";
    double time_step_s = 60;  // backward-Euler step, (0, 3600]
    unsigned threads = 0;     // facets solved in parallel; 0: all cores
};

// One facet's thermal description resolved from the .gdb and the .mat. Throws
// DataError naming the .gdb FACE line (missing material, missing thickness,
// non-physical override) or the .mat entry line (non-physical property).
FacetThermal resolve_facet(const SceneFacet& facet, const io::Mat& mat);

// Per env step: sunlit fraction x transmittance from the .shd facet, linearly
// interpolated between its steps; a time outside the .shd window takes the value at the
// same time of day inside it when the window spans 24 h, else 1 (unshadowed).
std::vector<double> sun_factors(const io::Shd& shd, const io::ShdFacet& facet,
                                const std::vector<EnvironmentStep>& env);

struct ThermResult {
    io::Tmp tmp;
    double spinup_residual_k = 0;  // max over facets of |last run - run before| at the scene time
    std::string spinup_facet;      // where it is largest
    int spinup_runs_max = 0;       // most runs any facet needed
    long facets_solved = 0, facets_fixed = 0;
    bool worker = false;  // an MPI worker's (farm_worker): rank 0 holds the result
};

// Spin-up: runs over the whole weather window, each from the previous run's profile
// 24 h after the start, until the scene-time answers of two runs agree within this.
inline constexpr double kSpinUpToleranceK = 0.01;
inline constexpr int kSpinUpMaxRuns = 8;

// Reads the inputs and computes. Every run starts at the .wth's first row (which must
// be at least 24 h before the scene time): the first with every node at the air
// temperature, each next one from the previous run's profile 24 h after the start
// (the same time of day), until two runs' answers at the scene time agree within
// kSpinUpToleranceK (or kSpinUpMaxRuns runs). The last run is the answer. Warnings
// ("FILE:LINE: ..." or plain) and what was assumed (info) go to `reporter`.
ThermResult compute_temperatures(const ThermJob& job, const Reporter& reporter);

// compute_temperatures, then writes the .tmp atomically.
void run_therm(const ThermJob& job, const Reporter& reporter);

}  // namespace sigchain::thermal
