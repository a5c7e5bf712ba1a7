// The image loop over one process or the ranks of an MPI farm (distributed.hpp).
#include "trace/distributed.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "core/farm.hpp"

namespace sigchain::trace {

namespace {

// render()'s note when no primary sample left the scene (render.cpp): a farm knows it
// only from the sum over its tiles.
constexpr const char* kNoWorldNote = "the world beyond the scene for primary rays (none left it)";

// A tile's ray counts, sent ahead of its floats.
struct TileCounts {
    std::uint64_t primary = 0, secondary = 0, shadow = 0, hits = 0, sky = 0, background = 0;
};

// A worker's tile: the counts, then the radiance floats and the truth floats.
FarmBytes pack(const RenderResult& r) {
    const RenderStats& s = r.stats;
    const TileCounts k{s.primary_rays, s.secondary_rays, s.shadow_rays,
                       s.hits,         s.sky_samples,    s.background_samples};
    FarmBytes out(sizeof k + 4 * (r.radiance.data.size() + r.truth.data.size()));
    unsigned char* p = out.data();
    std::memcpy(p, &k, sizeof k);
    p += sizeof k;
    std::memcpy(p, r.radiance.data.data(), 4 * r.radiance.data.size());
    p += 4 * r.radiance.data.size();
    std::memcpy(p, r.truth.data.data(), 4 * r.truth.data.size());
    return out;
}

// Tile rows [begin, end) of `whole` (image rows 0.. of the render) from its bytes.
void unpack(long begin, long end, const FarmBytes& bytes, RenderResult& whole) {
    const long n = end - begin;
    const std::size_t floats =
        static_cast<std::size_t>(n) * (static_cast<std::size_t>(whole.radiance.channels) *
                                           whole.radiance.columns +
                                       static_cast<std::size_t>(whole.truth.channels) *
                                           whole.truth.columns);
    TileCounts k;
    if (bytes.size() != sizeof k + 4 * floats)
        throw IoError("MPI: tile " + std::to_string(begin) + ":" + std::to_string(end) +
                      " does not fit the image");
    const unsigned char* p = bytes.data();
    std::memcpy(&k, p, sizeof k);
    p += sizeof k;
    for (image::Image* img : {&whole.radiance, &whole.truth}) {
        const std::size_t plane = static_cast<std::size_t>(n) * img->columns;
        for (int c = 0; c < img->channels; ++c, p += 4 * plane)
            std::memcpy(&img->at(c, begin, 0), p, 4 * plane);
    }
    RenderStats& s = whole.stats;
    s.primary_rays += k.primary;
    s.secondary_rays += k.secondary;
    s.shadow_rays += k.shadow;
    s.hits += k.hits;
    s.sky_samples += k.sky;
    s.background_samples += k.background;
}

// An image of no rows (render()'s empty cube) grown to `rows` rows of zeros.
void grow(image::Image& image, long rows) {
    image.rows = rows;
    image.data.assign(static_cast<std::size_t>(image.channels) * image.plane_size(), 0.0f);
}

}  // namespace

bool distributed_worker() { return farm_worker(); }

bool render_rows(const RenderInputs& inputs, const RenderOptions& options, long ring_rows,
                 const RowSink& sink, const Reporter& reporter, RenderResult& result) {
    if (!farm_available()) {
        ProgressScope bar(reporter, "rendering");
        result = render_streamed(inputs, options, ring_rows, sink, bar.callback());
        return true;
    }
    const auto start = std::chrono::steady_clock::now();
    const long first = options.row_begin;
    const long rows = (options.row_end < 0 ? inputs.sensor->rows() : options.row_end) - first;
    const auto& grid = inputs.atmosphere->grid();
    const double bytes_per_row =
        4.0 * static_cast<double>(inputs.sensor->columns()) *
        static_cast<double>(grid.size() + (options.truth ? truth_layer_names(grid).size() : 0));
    FarmJob job;
    job.items = rows;
    job.parts = farm_parts(rows, farm_workers(), bytes_per_row);
    job.compute = [&](long begin, long end) {
        RenderOptions o = options;
        o.row_begin = first + begin;
        o.row_end = first + end;
        return pack(render(inputs, o));
    };
    // Rank 0, while the workers start: the empty cubes and the render's notes (strategy,
    // bounces, background) from a render of no rows.
    job.meanwhile = [&] {
        RenderOptions none = options;
        none.row_end = none.row_begin;
        result = render(inputs, none);
        grow(result.radiance, rows);
        if (options.truth) grow(result.truth, rows);
    };
    reporter.info("MPI: " + std::to_string(farm_workers()) + " worker(s), " +
                  std::to_string(job.parts) + " tiles of about " +
                  std::to_string(rows / job.parts) + " rows");
    ProgressScope bar(reporter, "rendering");
    const auto progress = bar.callback();
    long done = 0;
    job.gather = [&](long begin, long end, const FarmBytes& bytes) {
        unpack(begin, end, bytes, result);
        done += end - begin;
        if (progress) progress(done, rows);
    };
    if (run_farm(job) == FarmRole::Worker) return false;
    if (sink && rows > 0) sink(RenderedRows{result.radiance, result.truth, 0, 0, rows});
    std::vector<std::string>& skipped = result.stats.skipped;
    skipped.erase(std::remove(skipped.begin(), skipped.end(), kNoWorldNote), skipped.end());
    if (result.stats.sky_samples + result.stats.background_samples == 0)
        skipped.emplace_back(kNoWorldNote);
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

}  // namespace sigchain::trace
