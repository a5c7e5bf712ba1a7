// The trace job (GDAL-apps style: an options struct and a run function, testable
// without a process): .adv + .snd + scene + .mat + one .rad per band -> a spectral
// radiance cube, optionally a truth cube (trace(1)).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/report.hpp"
#include "core/tile.hpp"
#include "image/image.hpp"
#include "scene/load.hpp"
#include "trace/render_options.hpp"

namespace sigchain::trace {

// --convergence MIN,MAX,THRESHOLD (RenderOptions::convergence_*).
struct Convergence {
    long min = 0, max = 0;
    double threshold = 0;  // in the unit of `error` (relative: 0.01 is one per cent)
    ConvergenceError error = ConvergenceError::Relative;  // --convergence-error
};

struct TraceJob {
    std::string adv_path;
    std::string snd_path;
    std::string scene_path;  // .gdb, .odb, a mesh or a DEM raster (scene::assemble_scene)
    scene::SceneInput scene_input;  // a lone mesh's or DEM's materials
    std::string mat_path;
    std::vector<std::string> rad_paths;  // one per .snd band, in band order
    std::string output_path;             // .img/.hdr (ENVI) or .tif (GeoTIFF)
    std::string truth_path;              // empty: no truth cube
    std::string tmp_path;                // empty: no emission
    bool strict = false;                 // --strict: .tmp keys that match no facet, or
                                         // facets without one, are an error
    Sampling sampling = Sampling::Golfball;
    // --sampling auto: the sampling chosen by accuracy (kAccuracySampling), not with a
    // strategy's own settings (samples per pixel, hemisphere samples, jitter, --convergence).
    bool accuracy_sampling = false;
    std::optional<long> samples_per_pixel;   // default: the .adv's samples_per_pixel
    std::optional<long> hemisphere_samples;  // default: RenderOptions's
    std::optional<int> max_transmissions;    // default: RenderOptions's
    bool golfball_jitter = false;            // golfball: each cell's ray at random inside the cell
    std::optional<int> bounces;              // 0 to kMaxBounces; default: RenderOptions's
    std::string background = "mean";        // "mean", "none" or a MATERIAL_ID (world.hpp)
    std::optional<int> sun_image_planes;     // --sun-images; default: RenderOptions's
    int sky_table_side = 0;                  // --sky-lookup table:N; 0: exact (RenderOptions)
    // --open-sky integrated (true) or sampled (false); unset: integrated with --sampling
    // auto, sampled otherwise (RenderOptions::open_sky_integrated).
    std::optional<bool> open_sky_integrated;
    std::uint64_t seed = 1;
    unsigned threads = 0;                       // 0: all cores
    std::optional<std::pair<long, long>> rows;  // [begin, end); default: every row
    std::optional<Tile> tile;  // --tile K/N: the rows Tile::range of the .adv's (not with rows)
    // A part's recorded options (cli::part_options; cube(5), Parts): what merge_tiles
    // compares between the parts of one render.
    std::string part_options;
    bool allow_degenerate = false;
    bool adjacency = true;                     // --no-adjacency turns it off
    std::optional<double> adjacency_radius_m;  // default: RenderOptions's (1000 m)
    image::WriteOptions write_options;         // --co and the provenance of the cubes
    // --crs: the map CRS of a geo-placed render: "" the CRS of the scene's first DEM
    // object (none: the render is not geo-placed), "none", "EPSG:N" or a WKT file.
    std::string crs;
    // --radiance-units W/m2/sr/um: radiance in W m-2 sr-1 um-1 (default W cm-2 sr-1 um-1).
    bool si_radiance_units = false;
    // --like: render on this raster's grid (its CRS, size and geotransform); "" none.
    std::string like_path;
    // --standard-error: the truth cube's sampling layers (samples, standard_error_BAND).
    bool standard_error = false;
    std::optional<Convergence> convergence;  // --convergence; implies the sampling layers
    // --uncertainty FILE (unc(5)): the truth cube's uncertainty_BAND layers; "" for none.
    std::string uncertainty_path;
    // --igm, --glt: the ground-position layers and the geometry lookup table (GeoTIFFs,
    // cube(5) GEOLOCATION LAYERS); "" for none.
    std::string igm_path;
    std::string glt_path;
};

// What happened, for -v: the scene's counts, the render's statistics.
struct TraceReport {
    scene::LoadReport load;
    RenderStats stats;
    long rows = 0, columns = 0;  // of the written cube (a --rows slice: its rows)
    std::size_t spectral_samples = 0, bands = 0;
    std::size_t materials = 0;
};

// "dirsig", "golfball", "montecarlo" or "proposed"; else UsageError.
Sampling parse_sampling(const std::string& name);
// relative, absolute or rms (--convergence-error); anything else is a UsageError.
ConvergenceError parse_convergence_error(const std::string& name);
std::string sampling_name(Sampling sampling);

// The sampling of --sampling auto, trace's default (trace(1) SAMPLING BY ACCURACY):
// montecarlo with one hemisphere ray per camera ray and the open sky integrated, camera
// rays added in batches of `convergence.min` at each pixel's (0,2)-sequence until one
// more would lower the pixel's variance by less than (threshold L_grey)^2 / min in every band (the scene
// rule: samples in proportion to each pixel's spread, the least image RMS per ray), or
// `convergence.max` rays; a pixel that stopped after n has a standard error under
// threshold sqrt(n / min) L_grey, at most 5 % of L_grey (n <= max = 64 min).
struct AccuracySampling {
    Convergence convergence{8, 512, 0.05 / 8, ConvergenceError::Scene};
    // The open sky integrated (--open-sky integrated) unless --open-sky sampled is given.
    bool open_sky_integrated = true;
    // The per-pixel bound the rule keeps: threshold sqrt(max / min), relative to L_grey.
    double pixel_bound() const {
        return convergence.threshold *
               std::sqrt(static_cast<double>(convergence.max) /
                         static_cast<double>(convergence.min));
    }
};
inline const AccuracySampling kAccuracySampling{};
// True when `job`'s sampling is kAccuracySampling's (--sampling auto).
bool sampling_by_accuracy(const TraceJob& job);
// "mean", "none" or a MATERIAL_ID (an integer) into options; else UsageError.
void parse_background(const std::string& text, RenderOptions& options);
// --sky-lookup: "exact" (0), "table" (kDefaultSkyTableSide) or "table:N" (N, an integer
// from SkyTable::kMinSide to kMaxSide) as RenderOptions::sky_table_side; else UsageError.
inline constexpr int kDefaultSkyTableSide = 64;
int parse_sky_lookup(const std::string& text);
// --open-sky: "integrated" (true) or "sampled" (false); else UsageError.
bool parse_open_sky(const std::string& text);
// "auto" (kAutoBounces) or an integer 0 to kMaxBounces; else UsageError.
int parse_bounces(const std::string& text);
// "A:B" with 0 <= A < B (integers) as [A, B); else UsageError naming `option`.
std::pair<long, long> parse_rows(const std::string& text, const std::string& option = "--rows");

// Checks what can be checked before any file is read (output names and formats,
// counts); throws UsageError.
void check_job(const TraceJob& job);

// Runs the job: reads every input, validates the scene against the materials,
// renders and writes the cube (and the truth cube) atomically; a part (--rows, --tile)
// records its rows, inputs and options (part.hpp). Under mpirun (SIGCHAIN_MPI builds)
// the rows are farmed out to the ranks (distributed.hpp) and rank 0 alone writes. Throws UsageError
// (a --rows range outside the image, a .rad count that is not the .snd's band count),
// DataError/IoError naming the file and line for bad inputs. Warnings and the -v
// details go to `reporter`, the render's progress as "rendering".
TraceReport run_trace(const TraceJob& job, const Reporter& reporter);

}  // namespace sigchain::trace
