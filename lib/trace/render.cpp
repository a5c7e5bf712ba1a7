// The renderer's image loop: primary rays per pixel from the sensor, the radiance
// leaving each hit toward it (tracer.hpp), and the atmosphere's path terms to the
// sensor (White (1996), sections 3.4, 3.6.5, 5.2.1-5.2.3); rows spread over threads by
// parallel_for.
#include "trace/render.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/parallel.hpp"
#include "trace/adjacency.hpp"
#include "trace/material_fraction.hpp"
#include "trace/render_stream.hpp"
#include "trace/sample_stats.hpp"
#include "trace/sampling.hpp"
#include "trace/tracer.hpp"
#include "trace/uncertainty.hpp"
#include "trace/world.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;

// Pixel accumulation of the truth layers (truth_layer_names order).
enum TruthLayer {
    kHit,
    kMaterial,
    kObject,
    kFacet,
    kShadow,
    kSkyView,
    kViewAngle,
    kRange,
    kTemperature,
    kSky,
    kBackground,
    kFixedLayers
};
constexpr int kPerBand = 5;  // reflectance, solar, downwelled, upwelled, transmission

// One worker's state: its tracer and pixel accumulators.
struct RowWorker {
    RowWorker(const TraceContext& c, std::size_t truth_layers)
        : tracer(c),
          pixel(c.n),
          sample(c.n),
          truth_acc(truth_layers),
          uncertainty(c.opt.uncertainty_layers ? c.in.uncertainty : nullptr,
                      c.in.atmosphere->grid().band_count()) {}
    Tracer tracer;
    std::vector<double> pixel;
    std::vector<double> sample;  // the last primary sample's radiance at the sensor
    std::vector<double> truth_acc;
    std::uint64_t sky = 0, background = 0;  // primary samples that left the scene
    std::uint64_t samples = 0;  // primary samples of the worker's pixels
    long max_samples = 0;
    MaterialTally materials;  // material_fraction layers
    PixelUncertainty uncertainty;  // uncertainty layers (uncertainty.hpp)
};

// The spectral buffers of one primary sample: radiance leaving the hit and the path
// terms (tau2, L_us, L_ue) at its view angle.
struct SampleBuffers {
    double* leave;
    double* tau2;
    double* lus;
    double* lue;
};

// A primary sample that left the scene (world.hpp): the effective sky above the
// horizon, the background plane through the path terms below it, else 0. Adds to the
// pixel and the truth's sky and background fractions.
void add_miss(const TraceContext& c, RowWorker& w, const SampleBuffers& b, const Vec3& o,
              const Vec3& d) {
    const std::size_t n = c.n;
    if (d[2] > 0) {
        effective_sky(c, *c.in.sensor, d, b.leave, b.tau2, b.lus, b.lue);
        for (std::size_t k = 0; k < n; ++k) w.pixel[k] += (w.sample[k] = b.leave[k]);
        ++w.sky;
        if (c.opt.truth) w.truth_acc[kSky] += 1;
        return;
    }
    if (background_distance(c.background, o, d) < 0) {
        std::fill(w.sample.begin(), w.sample.end(), 0.0);
        return;
    }
    c.in.atmosphere->path(d, c.in.sensor->view_angle_deg(d), {b.tau2, n}, {b.lus, n}, {b.lue, n});
    const auto& l = c.background.radiance;
    for (std::size_t k = 0; k < n; ++k)
        w.pixel[k] += (w.sample[k] = b.tau2[k] * l[k] + b.lus[k] + (c.emission ? b.lue[k] : 0.0));
    ++w.background;
    if (c.opt.truth) w.truth_acc[kBackground] += 1;
}

// The partials of a primary hit's radiance at the sensor at each band centre
// (uncertainty.hpp), into the worker's pixel uncertainty.
void add_uncertainty(const TraceContext& c, RowWorker& w, const SampleBuffers& b,
                     const std::vector<std::size_t>& centre, const scene::Hit& hit,
                     const HitTruth& ht) {
    const auto& a = c.in.scene->attributes(hit);
    const radiometry::MaterialOptics* m = c.in.materials->find(a.material_id);
    const auto& all = c.in.materials->materials();
    for (std::size_t band = 0; band < centre.size() && ht.rho; ++band) {
        const std::size_t k = centre[band];
        HitTerms t;
        t.tau2 = b.tau2[k];
        t.lus = b.lus[k];
        t.leave = b.leave[k];
        t.solar = ht.solar[k];
        t.downwelled = ht.downwelled[k];
        t.solar_per_zenith_deg = ht.solar_per_zenith ? ht.solar_per_zenith[k] : 0.0;
        t.solar_per_specularity = ht.solar_per_specularity ? ht.solar_per_specularity[k] : 0.0;
        t.tau1 = c.tau1[k];
        if (m) {
            t.material = m - all.data();
            t.r = 1 - m->emissivity[a.texture_curve][k];
            t.specularity = m->specularity;
        }
        w.uncertainty.add_hit(band, t);
    }
}

// Adds primary sample i of pixel (row, col), at offset `off` in [0, 1)^2 over the
// pixel, to the worker's accumulators (its radiance at the sensor also in w.sample);
// true on a hit.
bool add_sample(const TraceContext& c, RowWorker& w, const SampleBuffers& b,
                const std::vector<std::size_t>& centre, long row, long col, long i,
                const std::array<double, 2>& off) {
    const Sensor& cam = *c.in.sensor;
    const std::size_t n = c.n;
    Vec3 o, d;
    cam.ray(static_cast<double>(row) + off[0], static_cast<double>(col) + off[1], o, d);
    HitTruth ht;
    auto hit = w.tracer.primary(o, d, row, col, i, b.leave, c.opt.truth ? &ht : nullptr);
    if (c.opt.truth)
        w.materials.add(hit ? c.in.scene->attributes(*hit).material_id : kMissMaterial);
    if (!hit) {
        add_miss(c, w, b, o, d);
        return false;
    }
    double va = cam.view_angle_deg(d);
    c.in.atmosphere->path(d, va, {b.tau2, n}, {b.lus, n}, {b.lue, n});
    c.adjacency->add_path(va, b.lus);  // the environment's light scattered toward the sensor
    for (std::size_t k = 0; k < n; ++k) {
        double l = b.tau2[k] * b.leave[k] + b.lus[k] + (c.emission ? b.lue[k] : 0.0);
        w.pixel[k] += (w.sample[k] = l);
    }
    if (!c.opt.truth) return true;
    std::vector<double>& t_acc = w.truth_acc;
    t_acc[kShadow] += 1 - ht.sun_visibility;
    t_acc[kSkyView] += ht.sky_view;
    t_acc[kViewAngle] += va;
    t_acc[kRange] += hit->distance * c.opt.meters_per_unit;
    t_acc[kTemperature] += ht.temperature_k;
    for (std::size_t band = 0; band < centre.size() && ht.rho; ++band) {
        std::size_t k = centre[band];
        double* t = &t_acc[kFixedLayers + kPerBand * band];
        t[0] += ht.rho[k];
        // At the sensor: pixel = solar + downwelled + upwelled (+ emission).
        t[1] += b.tau2[k] * ht.solar[k];
        t[2] += b.tau2[k] * ht.downwelled[k];
        t[3] += b.lus[k];
        t[4] += b.tau2[k];
    }
    if (w.uncertainty.active()) add_uncertainty(c, w, b, centre, *hit, ht);
    return true;
}

// The truth layers of pixel (row, col) from the accumulated samples (`hits` of spp).
void put_truth(const TraceContext& c, const std::vector<double>& truth_acc, long hits, long spp,
               long row, long col, long out_row, image::Image& truth) {
    const Sensor& cam = *c.in.sensor;
    auto put = [&](int layer, double v) { truth.at(layer, out_row, col) = static_cast<float>(v); };
    put(kHit, static_cast<double>(hits) / static_cast<double>(spp));
    // Categorical layers from the ray through the pixel centre.
    Vec3 o, d;
    cam.ray(row + 0.5, col + 0.5, o, d);
    auto centre_hit = c.in.scene->intersect(o, d);
    put(kMaterial, centre_hit ? c.in.scene->attributes(*centre_hit).material_id : -1);
    put(kObject, centre_hit ? static_cast<double>(centre_hit->object) : -1);
    put(kFacet, centre_hit ? static_cast<double>(centre_hit->facet) : -1);
    double h = static_cast<double>(hits);
    put(kSky, truth_acc[kSky] / static_cast<double>(spp));
    put(kBackground, truth_acc[kBackground] / static_cast<double>(spp));
    for (int layer = kShadow; layer < static_cast<int>(truth_acc.size()); ++layer) {
        if (layer == kMaterial || layer == kObject || layer == kFacet || layer == kSky ||
            layer == kBackground)
            continue;
        double v = hits ? truth_acc[static_cast<std::size_t>(layer)] / h : 0.0;
        if (layer == kTemperature && (!hits || v < 0)) v = -1;
        put(layer, v);
    }
    if (hits == 0) put(kViewAngle, cam.view_angle_deg(d));
}

// Primary samples of pixel (row, col): samples_per_pixel stratified over the pixel, or
// with --convergence batches of MIN at the points of the pixel's (0,2)-sequence (so
// the samples so far stay stratified as batches are added; their other random numbers
// those of the sample's index) until the error --convergence-error names (render.hpp
// ConvergenceError; from the spread of block means) is under the threshold or MAX
// samples are taken. Returns (samples, hits).
std::pair<long, long> sample_pixel(const TraceContext& c, RowWorker& w, const SampleBuffers& b,
                                   const std::vector<std::size_t>& centre, SampleStats& stats,
                                   long row, long col) {
    const RenderOptions& o = c.opt;
    const bool converge = o.convergence_min > 0, track = o.sampling_layers || converge;
    stats.reset(centre.size(), converge);
    long hits = 0;
    auto take = [&](long i, const std::array<double, 2>& off) {
        if (add_sample(c, w, b, centre, row, col, i, off)) ++hits;
        if (track) stats.add(w.sample, centre);
    };
    if (!converge) {
        const long spp = std::max(1L, o.samples_per_pixel);
        for (long i = 0; i < spp; ++i)
            take(i, stratified_offset(i, spp, uniform01(o.seed, row, col, i, ~0ULL),
                                      uniform01(o.seed, row, col, i, ~1ULL)));
        return {spp, hits};
    }
    // The pixel's digital shift of its (0,2)-sequence, 32 bits per axis.
    const auto shift = [&](std::uint64_t k) {
        return static_cast<std::uint32_t>(uniform01(o.seed, row, col, ~0ULL, k) * 0x1.0p32);
    };
    const std::uint32_t shift_row = shift(~2ULL), shift_col = shift(~3ULL);
    long n = 0;
    while (true) {
        const long batch = std::min(o.convergence_min, o.convergence_max - n);
        for (long i = n; i < n + batch; ++i)
            take(i, sobol02_offset(static_cast<std::uint32_t>(i), shift_row, shift_col));
        n += batch;
        double error = 0;
        switch (o.convergence_error) {
        case ConvergenceError::Relative: error = stats.relative_error(); break;
        case ConvergenceError::Absolute: error = stats.absolute_error(); break;
        case ConvergenceError::Rms:
            error = stats.absolute_error() * std::sqrt(static_cast<double>(o.convergence_min) /
                                                       static_cast<double>(n));
            break;
        case ConvergenceError::Scene:
            error = stats.scaled_error(c.grey_radiance) *
                    std::sqrt(static_cast<double>(o.convergence_min) / static_cast<double>(n));
            break;
        }
        if (n >= o.convergence_max || error < o.convergence_threshold) break;
    }
    return {n, hits};
}

void render_row(const TraceContext& c, RowWorker& w, long row, long out_row, RenderResult& res) {
    Arena& arena = w.tracer.arena();
    ArenaScope scope(arena);
    const SampleBuffers buffers{arena.take(), arena.take(), arena.take(), arena.take()};
    const auto& grid = c.in.atmosphere->grid();
    std::vector<std::size_t> centre;  // per band; small, once per row
    for (int b = 0; b < static_cast<int>(grid.band_count()); ++b)
        centre.push_back(grid.band_centre_sample(b));
    // The sampling layers follow the material fractions (truth_layer_names).
    const int sampling_first = static_cast<int>(truth_layer_names(grid).size());
    SampleStats stats;
    for (long col = 0; col < c.in.sensor->columns(); ++col) {
        std::fill(w.pixel.begin(), w.pixel.end(), 0.0);
        std::fill(w.truth_acc.begin(), w.truth_acc.end(), 0.0);
        w.materials.clear();
        if (w.uncertainty.active()) w.uncertainty.clear();
        const auto [spp, hits] = sample_pixel(c, w, buffers, centre, stats, row, col);
        w.samples += static_cast<std::uint64_t>(spp);
        w.max_samples = std::max(w.max_samples, spp);
        for (std::size_t k = 0; k < c.n; ++k)
            res.radiance.at(static_cast<int>(k), out_row, col) =
                static_cast<float>(w.pixel[k] / static_cast<double>(spp));
        if (!c.opt.truth) continue;
        put_truth(c, w.truth_acc, hits, spp, row, col, out_row, res.truth);
        w.materials.put(spp, sampling_first - 2 * kMaterialFractionSlots, out_row, col,
                        res.truth);
        if (w.uncertainty.active()) {
            const int first = static_cast<int>(res.truth.channel_names.size() - centre.size());
            for (std::size_t b = 0; b < centre.size(); ++b)
                res.truth.at(first + static_cast<int>(b), out_row, col) =
                    static_cast<float>(w.uncertainty.sigma(b, spp));
        }
        if (!c.opt.sampling_layers) continue;
        res.truth.at(sampling_first, out_row, col) = static_cast<float>(spp);
        for (std::size_t b = 0; b < centre.size(); ++b)
            res.truth.at(sampling_first + 1 + static_cast<int>(b), out_row, col) =
                static_cast<float>(stats.standard_error(b));
    }
}

// What the render did not model, for --verbose.
std::vector<std::string> skipped(const TraceContext& c) {
    std::vector<std::string> out;
    if (!c.emission) out.push_back("emission (no facet temperatures given)");
    if (c.missing_temperature) out.push_back("emission of facets without a temperature");
    if (!c.any_transmissive) out.push_back("transmission (no transmissive material)");
    bool lobes = false;
    for (const auto& m : c.in.materials->materials())
        lobes |= specularity_of(m) > 0 || m.brdf.has_depth();
    if (!lobes) out.push_back("specular lobes (every specularity is 0)");
    if (!c.in.atmosphere->has_sky()) out.push_back("downwelled sky (no sky in the .rad)");
    if (c.bounces >= 1)
        out.push_back("bounces beyond " + std::to_string(c.bounces) +
                      " (the last is closed with the sun and an unobstructed sky)");
    if (c.bounces == 0) out.push_back("light from neighbouring facets (bounces 0)");
    if (!c.adjacency->active()) out.push_back(c.adjacency->skipped());
    if (!c.sun_images_skipped.empty()) out.push_back(c.sun_images_skipped);
    return out;
}

// The bounce depth and why, for --verbose.
std::string bounce_report(const TraceContext& c) {
    const BounceEstimate& e = c.bounce_estimate;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "bounces %d%s: by estimate, paths of more facet reflections carry %.2g %% of "
                  "the reflected radiance (facet albedo %.3g over %ld sensor-seen points; "
                  "--bounces auto keeps it under %.2g %%%s)",
                  c.bounces, c.opt.bounces == kAutoBounces ? " (auto)" : "",
                  100 * e.tail(c.bounces), e.facet_albedo, e.points, 100 * kBounceTolerance,
                  c.opt.bounces == kAutoBounces ? ""
                  : (" with " + std::to_string(e.bounces)).c_str());
    return buf;
}

// --convergence-error scene's scale per band, for --verbose ("" in another mode).
std::string convergence_scale_report(const TraceContext& c) {
    if (c.grey_radiance.empty()) return "";
    std::string out = "convergence scale (radiance of a 20 % grey ground at nadir, "
                      "W cm-2 sr-1 um-1, per band):";
    char buf[32];
    for (double l : c.grey_radiance) {
        std::snprintf(buf, sizeof buf, " %.4g", l);
        out += buf;
    }
    return out;
}

// The empty cubes of `rows` rows.
RenderResult empty_result(const RenderInputs& inputs, const RenderOptions& options, long rows) {
    const Sensor& cam = *inputs.sensor;
    const auto& grid = inputs.atmosphere->grid();
    RenderResult res;
    res.radiance = image::Image(rows, cam.columns(), static_cast<int>(grid.size()));
    res.radiance.wavelength_um = grid.wavelength_um;
    res.radiance.units = "W cm-2 sr-1 um-1";
    if (options.truth) {
        std::vector<std::string> names = truth_layer_names(grid, options);
        res.truth = image::Image(rows, cam.columns(), static_cast<int>(names.size()));
        res.truth.channel_names = names;
    }
    return res;
}

}  // namespace

std::vector<std::string> truth_layer_names(const radiometry::SpectralGrid& grid) {
    std::vector<std::string> names = {"hit",
                                      "material_id",
                                      "object",
                                      "facet",
                                      "shadow_fraction",
                                      "sky_view_factor",
                                      "view_angle_deg",
                                      "range_m",
                                      "temperature_k",
                                      "sky_fraction",
                                      "background_fraction"};
    for (const auto& band : grid.band_names)
        for (const char* q :
             {"reflectance_", "solar_", "downwelled_", "upwelled_", "transmission_"})
            names.push_back(q + band);
    for (const auto& name : material_fraction_layer_names()) names.push_back(name);
    return names;
}

std::vector<std::string> truth_layer_names(const radiometry::SpectralGrid& grid,
                                           const RenderOptions& options) {
    std::vector<std::string> names = truth_layer_names(grid);
    if (options.sampling_layers) {
        names.push_back("samples");
        for (const auto& band : grid.band_names) names.push_back("standard_error_" + band);
    }
    if (options.uncertainty_layers)
        for (const auto& band : grid.band_names) names.push_back("uncertainty_" + band);
    return names;
}

RenderResult render(const RenderInputs& inputs, const RenderOptions& options,
                    const std::function<void(long, long)>& progress) {
    return render_streamed(inputs, options, 0, {}, progress);
}

RenderResult render_streamed(const RenderInputs& inputs, const RenderOptions& options,
                             long ring_rows, const RowSink& sink,
                             const std::function<void(long, long)>& progress) {
    auto start = std::chrono::steady_clock::now();
    if (options.uncertainty_layers && (!options.truth || !inputs.uncertainty))
        throw std::invalid_argument("render: uncertainty layers need truth and uncertainties");
    const TraceContext c = make_context(inputs, options);
    const Sensor& cam = *inputs.sensor;
    long row_begin = std::clamp(options.row_begin, 0L, cam.rows());
    long row_end =
        options.row_end < 0 ? cam.rows() : std::clamp(options.row_end, row_begin, cam.rows());
    long rows = row_end - row_begin;
    // Row r is rendered into row r % ring of the ring, which the sink receives in order.
    const long ring = ring_rows <= 0 ? rows : std::min(ring_rows, rows);
    RenderResult res = empty_result(inputs, options, ring);
    const std::size_t truth_layers = options.truth ? res.truth.channel_names.size() : 0;

    const ParallelOptions parallel{options.threads, progress};
    WorkerStates<RowWorker> workers(parallel_workers(rows, parallel));
    parallel_for_ordered(
        rows, ring, parallel,
        [&](long r, unsigned worker) {
            RowWorker& w = workers.get(worker, [&] { return RowWorker(c, truth_layers); });
            render_row(c, w, row_begin + r, r % ring, res);
        },
        [&](long first, long n) {
            if (sink) sink(RenderedRows{res.radiance, res.truth, first, first % ring, n});
        });
    workers.each([&](const RowWorker& w) {
        const RayCounters& k = w.tracer.counters();
        res.stats.primary_rays += k.primary;
        res.stats.secondary_rays += k.secondary;
        res.stats.shadow_rays += k.shadow;
        res.stats.hits += k.hits;
        res.stats.sky_samples += w.sky;
        res.stats.background_samples += w.background;
        res.stats.pixel_samples += w.samples;
        res.stats.max_pixel_samples = std::max(res.stats.max_pixel_samples, w.max_samples);
    });
    res.stats.skipped = skipped(c);
    res.stats.background = c.background.description;
    res.stats.bounces = bounce_report(c);
    res.stats.sky_lookup = sky_lookup_description(c);
    res.stats.open_sky = open_sky_description(c);
    res.stats.convergence_scale = convergence_scale_report(c);
    if (res.stats.sky_samples + res.stats.background_samples == 0)
        res.stats.skipped.push_back("the world beyond the scene for primary rays (none left it)");
    res.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
}

}  // namespace sigchain::trace
