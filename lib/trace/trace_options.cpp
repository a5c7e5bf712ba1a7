// trace's options: the strategy, background, bounce and row names parsed, and the
// checks of a TraceJob that need no file (trace_job.hpp).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "core/error.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "image/image.hpp"
#include "io/adv.hpp"
#include "radiometry/sky_table.hpp"
#include "trace/trace_job.hpp"

namespace sigchain::trace {

namespace {

// A non-negative integer, the whole of `text`.
bool parse_count(std::string_view text, long& value) {
    if (text.empty()) return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && value >= 0;
}

// The ENVI data file a cube name stands for (NAME.hdr writes NAME.img), so that two
// outputs that would overwrite each other are caught.
std::string written_name(const std::string& path) {
    std::filesystem::path p(path);
    if (file_extension(path) == "hdr") p.replace_extension(".img");
    return std::filesystem::absolute(p).lexically_normal().string();
}

}  // namespace

Sampling parse_sampling(const std::string& name) {
    if (name == "dirsig") return Sampling::Dirsig;
    if (name == "golfball") return Sampling::Golfball;
    if (name == "montecarlo") return Sampling::MonteCarlo;
    if (name == "proposed") return Sampling::Proposed;
    throw UsageError("--sampling: unknown strategy '" + name +
                     "' (dirsig, golfball, montecarlo or proposed)");
}

ConvergenceError parse_convergence_error(const std::string& name) {
    if (name == "relative") return ConvergenceError::Relative;
    if (name == "absolute") return ConvergenceError::Absolute;
    if (name == "rms") return ConvergenceError::Rms;
    if (name == "scene") return ConvergenceError::Scene;
    throw UsageError("--convergence-error: unknown error '" + name +
                     "' (relative, absolute, rms or scene)");
}

void parse_background(const std::string& text, RenderOptions& options) {
    if (text == "mean") {
        options.background = BackgroundChoice::Mean;
        return;
    }
    if (text == "none") {
        options.background = BackgroundChoice::None;
        return;
    }
    char* end = nullptr;
    const long id = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0')
        throw UsageError("--background: expected mean, none or a MATERIAL_ID, not '" + text + "'");
    options.background = BackgroundChoice::Material;
    options.background_material = id;
}

int parse_sky_lookup(const std::string& text) {
    using radiometry::SkyTable;
    if (text == "exact") return 0;
    if (text == "table") return kDefaultSkyTableSide;
    long side = 0;
    if (text.rfind("table:", 0) == 0 && parse_count(std::string_view(text).substr(6), side) &&
        side >= SkyTable::kMinSide && side <= SkyTable::kMaxSide)
        return static_cast<int>(side);
    throw UsageError("--sky-lookup: expected exact, table or table:N (N cells a side, " +
                     std::to_string(SkyTable::kMinSide) + " to " +
                     std::to_string(SkyTable::kMaxSide) + "), not '" + text + "'");
}

bool parse_open_sky(const std::string& text) {
    if (text == "integrated") return true;
    if (text == "sampled") return false;
    throw UsageError("--open-sky: expected integrated or sampled, not '" + text + "'");
}

std::string sampling_name(Sampling sampling) {
    switch (sampling) {
        case Sampling::Dirsig:
            return "dirsig";
        case Sampling::Golfball:
            return "golfball";
        case Sampling::MonteCarlo:
            return "montecarlo";
        case Sampling::Proposed:
            return "proposed";
    }
    return "?";
}

bool sampling_by_accuracy(const TraceJob& job) { return job.accuracy_sampling; }

int parse_bounces(const std::string& text) {
    if (text == "auto") return kAutoBounces;
    long n = 0;
    if (!parse_count(text, n) || n > kMaxBounces)
        throw UsageError("--bounces: expected auto or 0 to " + std::to_string(kMaxBounces) +
                         ", found '" + text + "'");
    return static_cast<int>(n);
}

std::pair<long, long> parse_rows(const std::string& text, const std::string& option) {
    const auto colon = text.find(':');
    long a = 0, b = 0;
    if (colon == std::string::npos || !parse_count(std::string_view(text).substr(0, colon), a) ||
        !parse_count(std::string_view(text).substr(colon + 1), b))
        throw UsageError(option + ": expected A:B (first row, end row), found '" + text + "'");
    if (b <= a)
        throw UsageError(option + ": the end row must be greater than the first, found '" + text +
                         "'");
    return {a, b};
}

namespace {

// --convergence MIN,MAX,THRESHOLD: 2 <= MIN <= MAX <= the .adv's limit, 0 < THRESHOLD;
// not with --samples-per-pixel (MIN and MAX set the count).
void check_convergence(const Convergence& c, bool samples_per_pixel) {
    if (samples_per_pixel)
        throw UsageError("--convergence: not with --samples-per-pixel (MIN and MAX set the count)");
    if (c.min < 2 || c.max < c.min || c.max > io::kAdvMaxSamplesPerPixel)
        throw UsageError("--convergence: expected 2 <= MIN <= MAX <= " +
                         std::to_string(io::kAdvMaxSamplesPerPixel) + ", found " +
                         std::to_string(c.min) + "," + std::to_string(c.max));
    if (!(c.threshold > 0) || !std::isfinite(c.threshold))
        throw UsageError("--convergence: expected a THRESHOLD > 0");
}

// --truth (if given): a file of a known format, not the output.
void check_truth_path(const TraceJob& job) {
    if (job.truth_path.empty()) return;
    if (job.truth_path == "-")
        throw UsageError("--truth: a truth cube cannot be written to standard output");
    image::cube_format_of(job.truth_path);
    if (written_name(job.truth_path) == written_name(job.output_path))
        throw UsageError("--truth: " + job.truth_path + " would overwrite the output " +
                         job.output_path);
}

// No output overwrites an input or another output.
void check_outputs_distinct(const TraceJob& job) {
    // The cube and the truth, each with the ENVI header beside it, against the inputs.
    std::vector<std::string> outputs;
    for (const std::string& out : {job.output_path, job.truth_path}) {
        if (out.empty()) continue;
        outputs.push_back(written_name(out));
        outputs.push_back(std::filesystem::path(written_name(out)).replace_extension(".hdr"));
    }
    for (const auto& [option, layers] :
         {std::pair{"--igm", job.igm_path}, std::pair{"--glt", job.glt_path}}) {
        if (layers.empty()) continue;
        if (file_extension(layers) != "tif")
            throw UsageError(std::string(option) + ": expected a GeoTIFF FILE.tif, found '" +
                             layers + "'");
        if (std::count(outputs.begin(), outputs.end(), written_name(layers)))
            throw UsageError(std::string(option) + ": " + layers +
                             " would overwrite another output");
        outputs.push_back(written_name(layers));
    }
    std::vector<std::string> inputs{job.adv_path, job.snd_path, job.scene_path, job.mat_path,
                                    job.tmp_path, job.uncertainty_path};
    inputs.insert(inputs.end(), job.rad_paths.begin(), job.rad_paths.end());
    require_outputs_distinct(outputs, inputs);
}

// The sampling options: --samples-per-pixel, --convergence, --sampling auto (which
// chooses its own samples), --hemisphere-samples, --max-transmissions, and the options
// whose layers are in the truth cube.
void check_sampling(const TraceJob& job) {
    if (job.samples_per_pixel &&
        (*job.samples_per_pixel < 1 || *job.samples_per_pixel > io::kAdvMaxSamplesPerPixel))
        throw UsageError("--samples-per-pixel: expected 1 to " +
                         std::to_string(io::kAdvMaxSamplesPerPixel));
    if (job.standard_error && job.truth_path.empty())
        throw UsageError("--standard-error: its layers are in the truth cube: give --truth FILE");
    if (!job.uncertainty_path.empty() && job.truth_path.empty())
        throw UsageError("--uncertainty: its layers are in the truth cube: give --truth FILE");
    if (job.convergence) check_convergence(*job.convergence, job.samples_per_pixel.has_value());
    if (job.accuracy_sampling) {
        for (const auto& [given, option] :
             {std::pair{job.samples_per_pixel.has_value(), "--samples-per-pixel"},
              std::pair{job.hemisphere_samples.has_value(), "--hemisphere-samples"},
              std::pair{job.golfball_jitter, "--golfball-jitter"},
              std::pair{job.convergence.has_value(), "--convergence"}})
            if (given)
                throw UsageError(std::string("--sampling auto chooses its own samples: not with ") +
                                 option);
    }
    if (job.open_sky_integrated.value_or(false) && !job.accuracy_sampling &&
        job.sampling != Sampling::MonteCarlo)
        throw UsageError("--open-sky integrated: only with --sampling montecarlo or auto (" +
                         sampling_name(job.sampling) + " samples the sky in fixed directions)");
    if (job.hemisphere_samples && *job.hemisphere_samples < 1)
        throw UsageError("--hemisphere-samples: expected at least 1");
    if (job.max_transmissions && *job.max_transmissions < 0)
        throw UsageError("--max-transmissions: expected 0 or more");
}

}  // namespace

void check_job(const TraceJob& job) {
    if (job.rad_paths.empty()) throw UsageError("expected ADV SND SCENE MAT and at least one RAD");
    if (job.output_path.empty()) throw UsageError("no output cube: give -o CUBE");
    if (job.output_path == "-")
        throw UsageError("a radiance cube cannot be written to standard output: give -o CUBE");
    image::cube_format_of(job.output_path);  // UsageError for an unknown extension
    RenderOptions background;
    parse_background(job.background, background);  // UsageError for a bad --background
    check_truth_path(job);
    check_outputs_distinct(job);
    check_sampling(job);
    if (job.adjacency_radius_m && !(*job.adjacency_radius_m > 0))
        throw UsageError("--adjacency-radius: expected a positive number of metres");
    if (job.adjacency_radius_m && !job.adjacency)
        throw UsageError("--adjacency-radius does not apply with --no-adjacency");
    if (job.rows && (job.rows->first < 0 || job.rows->second <= job.rows->first))
        throw UsageError("--rows: expected 0 <= A < B");
    if (job.rows && job.tile) throw UsageError("--rows and --tile cannot be given together");
    if (job.tile && (job.tile->index < 1 || job.tile->index > job.tile->count))
        throw UsageError("--tile: expected K/N with 1 <= K <= N");
}

}  // namespace sigchain::trace
