// trace --shadow-history: per facet, the sunlit fraction and the sun's transmittance
// through transmissive facets at each time step of the hours before the scene time,
// and the facet's sky-view factor; written as a .shd (shd(5)) for therm (the thermal
// chain).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "geo/vec3.hpp"
#include "io/shd.hpp"
#include "io/snd.hpp"
#include "radiometry/material.hpp"
#include "trace/shadow_scene.hpp"

namespace sigchain::trace {

// The sky-view factor's ray count per sample point (cosine-weighted, stratified).
inline constexpr long kDefaultSkyRays = 256;

struct ShadowOptions {
    double history_hours = 24;  // > 0: the grid spans [scene - history, scene]
    double step_minutes = 15;   // > 0, dividing history_hours * 60
    long points_per_facet = 1;  // 1: the facet's area centroid; N: stratified by area
    long sky_rays = kDefaultSkyRays;
    int max_transmissions = 8;  // transmissive facets crossed per sun ray, as trace renders
    std::uint64_t seed = 1;     // sample-point and sky-ray jitter; results depend on it only
    unsigned threads = 0;       // over facets; 0: all cores; results do not depend on it
};

// One time step: its time (hours of the .wth clock, shd(5)) and the sun there.
struct SunStep {
    double time_hours = 0;
    double zenith_deg = 0;   // topocentric, with refraction (NREL SPA)
    double azimuth_deg = 0;  // clockwise from north
    geo::Vec3 direction{};   // unit, toward the sun, scene frame (x east, y north, z up)
    bool up = false;         // zenith < 90 deg, as trace's Atmosphere::sun_up
};

// The number of steps of a history: history / step + 1 (both ends). UsageError
// naming the option when a value is not positive or the step does not divide it.
long history_steps(double history_hours, double step_minutes);

// The scene time of the .snd in the .wth's clock (shd(5), therm(1)): hours from
// midnight of the day before the scene's day, local time = GMT time - GMT offset.
double scene_time_hours(const io::Snd& snd);

// The sun (NREL SPA, lib/atmos, as build_radiance) at `steps` times ending at the
// scene time, `step_hours` apart. The UT of a grid time t is therm's (environment.hpp
// ut_of_wth_hours): the .snd's date - 1 day + (t + GMT offset) hours.
std::vector<SunStep> sun_history(const io::Snd& snd, long steps, double step_hours);

// The history of every facet (scene order: placements, then facets) over `sun`, whose
// last step is the scene time. `materials` gives transmissive facets their slab
// transmittance exp(-k d/|cos|) (ext(5)), averaged over its grid's samples as trace's
// shadow truth layer; opaque facets block the sun. DataError (validate_scene) when a
// facet's material is not in `materials`.
// Facets are spread over options.threads (sigchain::parallel_for): `progress(done,
// total)` is called now and then, never by two threads at once but from any of them
// (may be empty). Error for an empty `sun`, UsageError for options out of range.
struct ShadowStats {
    std::uint64_t rays = 0;  // sun rays (each facet crossing counts one) and sky rays
    double seconds = 0;      // wall-clock time of the computation
};
io::Shd shadow_history(const ShadowScene& scene, const radiometry::MaterialLibrary& materials,
                       const std::vector<SunStep>& sun, double step_hours,
                       const ShadowOptions& options,
                       const std::function<void(long, long)>& progress = {},
                       ShadowStats* stats = nullptr, long facet_begin = 0, long facet_end = -1);
// (facet_begin, facet_end: only the scene's facets [begin, end), -1 to the last; each
// facet's record depends on the facet alone, so parts join into the whole .shd.)

// trace --shadow-history as a job: .snd + scene + .mat -> .shd.
struct ShadowJob {
    std::string snd_path, scene_path, mat_path;
    scene::SceneInput scene_input;  // a lone mesh's or DEM's materials
    std::string output_path;  // .shd; "-" is standard output
    ShadowOptions options;
    bool allow_degenerate = false;
};

// Checks the options (UsageError), reads the inputs, computes and writes the .shd
// atomically; under mpirun (SIGCHAIN_MPI builds) the facets are farmed out to the
// ranks (core/farm.hpp) and rank 0 alone writes (the others return an empty .shd). DataError/IoError name the file and line of a bad input. Warnings and
// the -v details go to `reporter`, the progress as "shadow history".
io::Shd run_shadow_history(const ShadowJob& job, const Reporter& reporter);

}  // namespace sigchain::trace
