// The trace job: read the inputs, check that they agree, render, write the cubes.
#include "trace/trace_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <tuple>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/process.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "geo/georef.hpp"
#include "geo/solar_position.hpp"
#include "image/geolocation.hpp"
#include "image/image.hpp"
#include "imaging/georef.hpp"
#include "imaging/ground_layers.hpp"
#include "imaging/like_grid.hpp"
#include "imaging/view_angle.hpp"
#include "io/adv.hpp"
#include "io/mat.hpp"
#include "io/odb.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/load.hpp"
#include "trace/black_cube.hpp"
#include "trace/distributed.hpp"
#include "trace/part.hpp"
#include "trace/trace_temperatures.hpp"
#include "trace/trace_output.hpp"
#include "trace/uncertainty.hpp"

namespace sigchain::trace {

namespace {

// ENVI's `sensor type` of trace's cubes (cube(5)): the sensor model that made them,
// "sigchain " and Sensor::kind() ("sigchain frame camera").
std::string sensor_type(const Sensor& sensor) { return "sigchain " + sensor.kind(); }

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

// The view angles over the image border and centre against the .rad's table (the
// extremes of the view angle over a frame lie on its border unless nadir is inside,
// which the border's signs then show): outside the table the path terms are clamped
// (Atmosphere::path), which trace reports. The border is sampled where
// find_min_max_view_angle(1) samples it, at the border pixels' centres and the four
// outer corners, so that tables made from its range raise no warning.
void check_view_angles(const Sensor& camera, const radiometry::Atmosphere& atm,
                       const Reporter& reporter) {
    double lo = 1e9, hi = -1e9;
    const double r = static_cast<double>(camera.rows()), c = static_cast<double>(camera.columns());
    auto sample = [&](double row, double column) {
        geo::Vec3 origin{}, direction{};
        camera.ray(row, column, origin, direction);
        // Above the horizon a ray takes the path terms of its mirrored line of sight,
        // and within 1 deg of the horizon those of 89 deg (imaging::world_view_angle_deg,
        // as find_min_max_view_angle makes the tables for the world beyond the scene).
        const double va = imaging::world_view_angle_deg(camera.view_angle_deg(direction));
        lo = std::min(lo, va);
        hi = std::max(hi, va);
    };
    sample(r / 2, c / 2);
    for (double row : {0.0, r})
        for (double column : {0.0, c}) sample(row, column);
    const long steps = 256;  // per side: at most 1024 rays, a fraction of a degree apart
    for (long k = 0; k <= steps; ++k) {
        const double f = static_cast<double>(k) / steps;
        const double row = 0.5 + f * std::max(0.0, r - 1), column = 0.5 + f * std::max(0.0, c - 1);
        sample(0.5, column);
        sample(r - 0.5, column);
        sample(row, 0.5);
        sample(row, c - 0.5);
    }
    // 0.01 deg: below the precision the .rad's view-angle grid is written with.
    if (lo < atm.min_view_angle_deg() - 0.01 || hi > atm.max_view_angle_deg() + 0.01)
        reporter.warn(
            "the image spans view angles " + format("%.2f", lo) + " to " + format("%.2f", hi) +
            " deg but the .rad files cover " + format("%.2f", atm.min_view_angle_deg()) + " to " +
            format("%.2f", atm.max_view_angle_deg()) + " deg: path terms are clamped at the ends");
}

// The .adv (a frame camera) and the .snd, and the rows to render: [begin, end).
struct Setup {
    io::Adv adv;
    io::Snd snd;
    long row_begin = 0, row_end = 0;
    std::optional<imaging::LikeGrid> like;  // --like: the raster's grid, whose size the image takes
};

Setup read_setup(const TraceJob& job) {
    Setup st;
    st.adv = io::read_adv_file(job.adv_path);
    st.snd = io::read_snd_file(job.snd_path);
    if (st.snd.bands.size() != job.rad_paths.size())
        throw UsageError(job.snd_path + " has " + std::to_string(st.snd.bands.size()) +
                         " band(s) but " + std::to_string(job.rad_paths.size()) +
                         " .rad file(s) were given (one per band, in band order)");
    if (!job.like_path.empty()) {
        if (!job.crs.empty()) throw UsageError("--like takes the raster's CRS: not with --crs");
        st.like = imaging::read_like_grid(job.like_path);
        st.adv.rows = st.like->rows;
        st.adv.columns = st.like->columns;
    }
    st.row_end = st.adv.rows;
    if (job.rows) {
        if (job.rows->second > st.adv.rows)
            throw UsageError("--rows " + std::to_string(job.rows->first) + ":" +
                             std::to_string(job.rows->second) + ": the image has " +
                             std::to_string(st.adv.rows) + " rows (" + job.adv_path + ")");
        st.row_begin = job.rows->first;
        st.row_end = job.rows->second;
    }
    if (job.tile) {
        std::tie(st.row_begin, st.row_end) = job.tile->range(st.adv.rows);
        if (st.row_end == st.row_begin)
            throw UsageError("--tile " + job.tile->text() + ": the image has only " +
                             std::to_string(st.adv.rows) + " rows (" + job.adv_path +
                             "), fewer than the tiles");
    }
    return st;
}

// Refuses, before anything is read or allocated, a radiance cube (4-byte floats, one
// band per spectral sample) larger than the memory this process may use, when it is
// to be held whole: by rank 0 of an MPI farm, which gathers it (trace(1), MPI). One
// process writes the rows as they complete and holds a ring of them (trace_output.hpp).
void check_cube_size(const TraceJob& job, const Setup& st, std::size_t samples) {
    if (!farm_available()) return;
    double bytes = 4.0 * static_cast<double>(st.row_end - st.row_begin) *
                   static_cast<double>(st.adv.columns) * static_cast<double>(samples);
    double usable = usable_memory_bytes();
    if (bytes <= usable) return;
    constexpr double kMiB = 1024.0 * 1024.0;
    throw DataError({job.adv_path, st.adv.lines.size},
                    "a " + std::to_string(st.row_end - st.row_begin) + " x " +
                        std::to_string(st.adv.columns) + " image of " + std::to_string(samples) +
                        " spectral samples needs a " + format("%.0f", bytes / kMiB) +
                        " MiB radiance cube, more than the " + format("%.0f", usable / kMiB) +
                        " MiB of memory this process may use");
}

// One sigchain .rad per band, merged on one spectral grid.
radiometry::Atmosphere read_atmosphere(const TraceJob& job, const io::Snd& snd,
                                       const Reporter& reporter) {
    std::vector<io::Rad> rads;
    rads.reserve(job.rad_paths.size());
    for (std::size_t b = 0; b < job.rad_paths.size(); ++b) {
        const std::string& path = job.rad_paths[b];
        rads.push_back(io::read_rad_file(path));
        const long want = snd.bands[b].sample_count();
        if (static_cast<long>(rads.back().samples.size()) != want)
            reporter.warn(path + ": " + std::to_string(rads.back().samples.size()) +
                          " spectral samples, but band " + std::to_string(b + 1) + " of " +
                          job.snd_path + " has " + std::to_string(want));
    }
    radiometry::Atmosphere atmosphere = radiometry::Atmosphere::from_rads(rads, job.rad_paths);
    if (!atmosphere.has_sky()) {
        // A DIRSIG .rad (White (1996), fig. 4.33) has no SIGCHAIN_RAD block: no sun position and
        // no downwelled sky. The sun is placed from the .snd's date, GMT time and place
        // (NREL SPA, lib/atmos); the sky is left dark, which the user is told.
        geo::SolarPosition sun = geo::solar_position(io::scene_site(snd));
        atmosphere.set_sun(sun.zenith_deg, sun.azimuth_deg);
        reporter.warn(job.rad_paths.front() +
                      ": a DIRSIG .rad (no SIGCHAIN_RAD block): the sun is placed from " +
                      job.snd_path + " (zenith " + format("%.3f", sun.zenith_deg) +
                      " deg, azimuth " + format("%.3f", sun.azimuth_deg) +
                      " deg) and the downwelled sky is zero");
    }
    const auto& grid = atmosphere.grid();
    reporter.info("spectral grid: " + std::to_string(grid.size()) + " samples in " +
                  std::to_string(grid.band_count()) + " band(s)");
    if (!atmosphere.sun_up())
        reporter.info("the sun is below the horizon (zenith " +
                      format("%.2f", atmosphere.sun_zenith_deg()) + " deg)");
    return atmosphere;
}

// The scene in scene units (the .adv's) about the .snd's geodetic origin, checked
// against the materials.
scene::Scene read_scene(const TraceJob& job, const Setup& st,
                        const radiometry::MaterialLibrary& materials, TraceReport& report,
                        const Reporter& reporter) {
    scene::LoadOptions load;
    load.scene_meters_per_unit = io::meters_per_unit(st.adv.units);
    load.origin = scene::GeoOrigin{st.snd.latitude_deg, st.snd.longitude_east_deg, 0.0};
    load.allow_degenerate = job.allow_degenerate;
    load.input = job.scene_input;
    load.threads = job.threads;
    scene::Scene scene = scene::load_scene(job.scene_path, load, &report.load);
    for (const auto& w : report.load.warnings) reporter.warn(w);
    // No line to name: an empty scene is a property of the whole file (or of every
    // object its .odb lists), not of one record.
    if (scene.triangle_count() == 0)
        throw DataError({job.scene_path, 0}, "the scene has no facets");
    validate_scene(scene, materials);
    reporter.info("scene: " + std::to_string(report.load.meshes) + " mesh(es), " +
                  std::to_string(report.load.placements) + " placement(s), " +
                  std::to_string(report.load.facets) + " facets, " +
                  std::to_string(report.load.triangles) + " triangles; " +
                  std::to_string(report.materials) + " material(s)");
    return scene;
}

// The samples per pixel and the strategy, for -v: what was named, or what trace chose.
std::string sampling_report(const TraceJob& job, const RenderOptions& o) {
    const std::string count =
        o.convergence_min > 0 ? std::to_string(o.convergence_min) + " to " +
                                    std::to_string(o.convergence_max) + " sample(s) per pixel"
                              : std::to_string(o.samples_per_pixel) + " sample(s) per pixel";
    if (!sampling_by_accuracy(job))
        return (job.convergence ? "--convergence " : "") + count + ", " +
               sampling_name(o.sampling) + " sampling";
    char bound[32];
    std::snprintf(bound, sizeof bound, "%g", 100 * kAccuracySampling.pixel_bound());
    return count + ", montecarlo sampling with 1 hemisphere ray per sample" +
           (o.open_sky_integrated ? " and the open sky integrated" : "") + ", chosen by "
           "accuracy (--sampling auto, the default): samples where they lower the image's "
           "error most, each pixel's standard error under " + std::string(bound) +
           " % of a 20 % grey ground's radiance in every band";
}

RenderOptions render_options(const TraceJob& job, const Setup& st) {
    RenderOptions options;
    options.sampling = job.sampling;
    options.samples_per_pixel = job.samples_per_pixel.value_or(st.adv.samples_per_pixel);
    if (job.hemisphere_samples) options.hemisphere_samples = *job.hemisphere_samples;
    const bool by_accuracy = sampling_by_accuracy(job);
    if (by_accuracy) {
        options.sampling = Sampling::MonteCarlo;
        options.hemisphere_samples = 1;
    }
    if (job.max_transmissions) options.max_transmissions = *job.max_transmissions;
    if (job.bounces) options.bounces = *job.bounces;
    if (job.sun_image_planes) options.sun_image_planes = *job.sun_image_planes;
    parse_background(job.background, options);
    options.sky_table_side = job.sky_table_side;
    options.open_sky_integrated =
        job.open_sky_integrated.value_or(by_accuracy && kAccuracySampling.open_sky_integrated);
    options.golfball_jitter = job.golfball_jitter;
    options.seed = job.seed;
    options.threads = job.threads;
    options.row_begin = st.row_begin;
    options.row_end = st.row_end;
    options.truth = !job.truth_path.empty();
    options.sampling_layers = options.truth && (job.standard_error || job.convergence);
    options.uncertainty_layers = options.truth && !job.uncertainty_path.empty();
    if (job.convergence || by_accuracy) {
        const Convergence& c = by_accuracy ? kAccuracySampling.convergence : *job.convergence;
        options.convergence_min = c.min;
        options.convergence_max = c.max;
        options.convergence_threshold = c.threshold;
        options.convergence_error = c.error;
    }
    options.meters_per_unit = io::meters_per_unit(st.adv.units);
    options.adjacency = job.adjacency;
    if (job.adjacency_radius_m) options.adjacency_radius_m = *job.adjacency_radius_m;
    return options;
}

void report_stats(const RenderStats& s, long pixels, const Reporter& reporter) {
    const std::uint64_t rays = s.primary_rays + s.secondary_rays + s.shadow_rays;
    const double mrays = s.seconds > 0 ? static_cast<double>(rays) / s.seconds / 1e6 : 0.0;
    reporter.info(std::to_string(rays) + " rays (" + std::to_string(s.primary_rays) + " primary, " +
                  std::to_string(s.secondary_rays) + " secondary, " +
                  std::to_string(s.shadow_rays) + " shadow), " + std::to_string(s.hits) +
                  " hits, " + format("%.3f", s.seconds) + " s, " + format("%.2f", mrays) +
                  " Mrays/s");
    if (!s.background.empty()) reporter.info(s.background);
    if (!s.bounces.empty()) reporter.info(s.bounces);
    if (!s.sky_lookup.empty()) reporter.info(s.sky_lookup);
    if (!s.open_sky.empty()) reporter.info(s.open_sky);
    if (!s.convergence_scale.empty()) reporter.info(s.convergence_scale);
    if (pixels > 0)
        reporter.info(
            format("%.2f", static_cast<double>(s.pixel_samples) / static_cast<double>(pixels)) +
            " primary sample(s) per pixel on average, at most " +
            std::to_string(s.max_pixel_samples));
    reporter.info(std::to_string(s.sky_samples) + " primary sample(s) saw the sky, " +
                  std::to_string(s.background_samples) + " the background world");
    for (const auto& skipped : s.skipped) reporter.info("not modelled: " + skipped);
    if (s.hits == 0) reporter.warn("no primary ray hit the scene: check the look angles");
}

// Wall seconds of trace's phases (-v): what the set-up takes beside the rendering.
struct PhaseTimes {
    using Clock = std::chrono::steady_clock;
    Clock::time_point mark = Clock::now();
    double adv_snd = 0, rads = 0, materials = 0, scene_files = 0, build = 0, tmp = 0, other = 0;
    // The seconds since the last lap (or construction); starts the next lap.
    double lap() {
        const Clock::time_point now = Clock::now();
        const double s = std::chrono::duration<double>(now - mark).count();
        mark = now;
        return s;
    }
    double setup() const { return adv_snd + rads + materials + scene_files + build + tmp + other; }
};

void report_phases(const PhaseTimes& t, double render_seconds, const Reporter& reporter) {
    reporter.info("set-up " + format("%.3f", t.setup()) + " s: .adv/.snd " +
                  format("%.3f", t.adv_snd) + " s, .rad tables " + format("%.3f", t.rads) +
                  " s, materials " + format("%.3f", t.materials) + " s, scene files " +
                  format("%.3f", t.scene_files) + " s, Embree build " + format("%.3f", t.build) +
                  " s, .tmp " + format("%.3f", t.tmp) + " s, other " + format("%.3f", t.other) +
                  " s; render " + format("%.3f", render_seconds) + " s");
}

// Where the image lies on the map: the --like raster's placement, or the one --crs (or
// the scene's DEM) names; none with --crs none. Which CRS was taken is told with -v.
std::optional<imaging::GeoPlacement> map_placement(const TraceJob& job, const Setup& st,
                                                   const Reporter& reporter) {
    std::string crs_note = "map CRS: the --like raster's";
    const geo::LatLon origin{st.snd.latitude_deg, st.snd.longitude_east_deg};
    const double mpu = io::meters_per_unit(st.adv.units);
    const std::optional<imaging::GeoPlacement> place =
        st.like
            ? imaging::GeoPlacement{origin.latitude_deg, origin.longitude_deg, mpu, st.like->crs}
            : imaging::geo_placement(job.crs, job.scene_path, origin, mpu, job.snd_path,
                                     crs_note);
    if (!crs_note.empty()) reporter.info(crs_note);
    return place;
}

// The .adv's camera, or with --like a frame camera on the raster's grid.
std::unique_ptr<Sensor> make_camera(const TraceJob& job, const Setup& st,
                                    const scene::Scene& scene,
                                    const std::optional<imaging::GeoPlacement>& place,
                                    const Reporter& reporter) {
    std::unique_ptr<Sensor> sensor = imaging::make_sensor(
        st.adv, job.adv_path,
        imaging::SceneOrigin{st.snd.latitude_deg, st.snd.longitude_east_deg});
    if (st.like)
        sensor = imaging::make_grid_sensor(std::move(sensor), *st.like, *place, scene,
                                           scene.bounds().lower[2]);
    reporter.info("sensor: " + sensor->summary());
    return sensor;
}

// What the georeferencing of the outputs is made from: the camera, the scene, its place
// on the map and the plane under it (none with --background none).
struct ViewGeometry {
    const Sensor& camera;
    const scene::Scene& scene;
    const std::optional<imaging::GeoPlacement>& place;
    std::optional<double> plane;
};

// The cubes, georeferenced (by the --like raster, or by the render's geometry), open for
// the rows as they complete.
std::unique_ptr<TraceOutputs> open_outputs(const TraceJob& job, const Setup& st,
                                           const radiometry::SpectralGrid& grid,
                                           const RenderOptions& options, const ViewGeometry& v,
                                           const HeldReports& georef_reports) {
    image::Georeference georef;
    if (st.like)
        georef = imaging::like_georeference(*st.like, st.row_begin);
    else if (v.place)
        georef = imaging::georeference_render(
            v.camera, v.scene, *v.place, !job.crs.empty(), v.plane, st.row_begin, st.row_end,
            st.adv.rows, image::geolocation_name(job.output_path), georef_reports);
    return std::make_unique<TraceOutputs>(
        job, part_write_options(job, st.row_begin, st.row_end, st.adv.rows), grid, options, georef,
        sensor_type(v.camera), st.row_end - st.row_begin, v.camera.columns());
}

// --igm and --glt: each pixel's ground position and the map grid's source pixels.
void write_ground_layers(const TraceJob& job, const Setup& st, const RenderOptions& options,
                         const ViewGeometry& v, const Reporter& reporter) {
    if (job.igm_path.empty() && job.glt_path.empty()) return;
    std::string note;
    imaging::write_ground_layers(v.camera, v.scene, v.place, options.meters_per_unit, v.plane,
                                 st.row_begin, st.row_end, job.igm_path, job.glt_path, note);
    reporter.info(note);
}

// Renders the rows, each written to `outputs` (none on an MPI worker) as it completes,
// through a ring of rows; false on an MPI worker. The ring is released after the render.
bool render_into(const RenderInputs& inputs, const RenderOptions& options,
                 const radiometry::SpectralGrid& grid, long rows, long columns,
                 TraceOutputs* outputs, const Reporter& reporter, RenderResult& result) {
    const std::size_t floats =
        grid.size() + (options.truth ? truth_layer_names(grid, options).size() : 0);
    RowSink sink;
    if (outputs) sink = [outputs](const RenderedRows& r) { outputs->write(r); };
    if (!render_rows(inputs, options, ring_rows(rows, columns, floats, options.threads), sink,
                     reporter, result))
        return false;
    result.radiance = {};  // the ring: its rows are written
    result.truth = {};
    return true;
}

// What is rendered, for -v: the rows, the columns and the sampling.
std::string rendering_note(const TraceJob& job, const Setup& st, const RenderOptions& options) {
    return "rendering rows " + std::to_string(st.row_begin) + " to " +
           std::to_string(st.row_end) + " of " + std::to_string(st.adv.rows) + ", " +
           std::to_string(st.adv.columns) + " columns, " + sampling_report(job, options);
}

// After the render (-v): with --convergence what the pixels took, and the phases' times.
void report_render(const TraceReport& report, const RenderOptions& options,
                   const PhaseTimes& times, double render_seconds, const Reporter& reporter) {
    const long pixels = options.convergence_min > 0 ? report.rows * report.columns : 0;
    report_stats(report.stats, pixels, reporter);
    report_phases(times, render_seconds, reporter);
}

}  // namespace

TraceReport run_trace(const TraceJob& job, const Reporter& job_reporter) {
    check_job(job);
    // MPI ranks other than 0 read the same inputs: only rank 0 reports on them.
    const Reporter silent;
    const Reporter& reporter = distributed_worker() ? silent : job_reporter;
    TraceReport report;
    PhaseTimes times;
    const Setup st = read_setup(job);
    times.adv_snd = times.lap();
    const radiometry::Atmosphere atmosphere = read_atmosphere(job, st.snd, reporter);
    times.rads = times.lap();
    const radiometry::SpectralGrid& grid = atmosphere.grid();
    report.spectral_samples = grid.size();
    report.bands = grid.band_count();
    check_cube_size(job, st, grid.size());
    const radiometry::MaterialLibrary materials =
        radiometry::MaterialLibrary::load(io::read_mat_file(job.mat_path), job.mat_path, grid);
    report.materials = materials.materials().size();
    times.materials = times.lap();
    const scene::Scene scene = read_scene(job, st, materials, report, reporter);
    times.build = report.load.build_seconds;
    // The scene's lap less the build: reading the files, assembling and validating.
    times.scene_files = times.lap() - times.build;
    const Temperatures temperatures = read_temperatures(job, grid, scene, reporter);
    times.tmp = times.lap();
    const std::optional<imaging::GeoPlacement> place = map_placement(job, st, reporter);
    const std::unique_ptr<Sensor> sensor = make_camera(job, st, scene, place, reporter);
    const Sensor& camera = *sensor;
    check_view_angles(camera, atmosphere, reporter);
    const RenderOptions options = render_options(job, st);
    const InputUncertainty uncertainty = read_input_uncertainty(job.uncertainty_path, materials);
    const RenderInputs inputs{&scene, &atmosphere, &materials, &camera,
                              job.tmp_path.empty() ? nullptr : &temperatures, &uncertainty};
    const ViewGeometry view{camera, scene, place,
                            options.background == BackgroundChoice::None
                                ? std::nullopt
                                : std::optional<double>(scene.bounds().lower[2])};
    const long rows = st.row_end - st.row_begin, columns = camera.columns();
    // The cubes are written as their rows complete (rank 0 alone writes under MPI), so
    // their georeferencing is made before the render; what it reports is told after
    // the render, where -v has always told it.
    const HeldReports georef_reports(reporter);
    const std::unique_ptr<TraceOutputs> outputs =
        distributed_worker() ? nullptr : open_outputs(job, st, grid, options, view, georef_reports);
    reporter.info(rendering_note(job, st, options));
    RenderResult result;
    times.other = times.lap();
    if (!render_into(inputs, options, grid, rows, columns, outputs.get(), reporter, result))
        return report;  // an MPI worker
    const double render_seconds = times.lap();
    report.stats = result.stats;
    report.rows = rows;
    report.columns = columns;
    report_render(report, options, times, render_seconds, reporter);
    write_ground_layers(job, st, options, view, reporter);
    georef_reports.release();
    outputs->commit();
    alarm_if_black(outputs->largest_radiance(), outputs->values(), job.output_path, reporter);
    return report;
}

}  // namespace sigchain::trace
