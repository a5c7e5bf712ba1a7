// trace --shadow-history: sun rays from points on every facet at each step of the
// history, sky rays for the sky-view factor (shadow_history.hpp; shd(5)).
//
// Conventions: a facet faces the side its .gdb FACE normal points to (gdb(5): the
// normal, not the winding, says which way it faces; the winding's normal when the
// FACE gives a zero one), placed as therm places it; the sun behind it (n.s <= 0) or
// below the horizon gives 0. Rays leave from the point offset along that normal by the scene's
// ray epsilon (1e-6 of its largest coordinate or extent, as render.cpp). A sky ray
// counts as sky when it escapes the scene above the horizon; one that escapes below
// it meets the ground beyond the scene (not sky), as trace renders it.
#include "trace/shadow_history.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/numeric.hpp"
#include "core/output.hpp"
#include "core/parallel.hpp"
#include "geo/scene_clock.hpp"
#include "geo/solar_position.hpp"
#include "io/mat.hpp"
#include "trace/render.hpp"
#include "trace/sampling.hpp"
#include "trace/transmission.hpp"

namespace sigchain::trace {
namespace {

constexpr double kPi = 3.14159265358979323846;

using geo::Vec3;

// An orthonormal basis (x, y, z = n) about a unit normal.
struct Basis {
    Vec3 x, y, z;
    explicit Basis(const Vec3& n) : z(n) {
        Vec3 a = std::abs(n[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
        x = geo::unit(geo::cross(a, n));
        y = geo::cross(z, x);
    }
    Vec3 world(double lx, double ly, double lz) const {
        return {lx * x[0] + ly * y[0] + lz * z[0], lx * x[1] + ly * y[1] + lz * z[1],
                lx * x[2] + ly * y[2] + lz * z[2]};
    }
};

// Sample points of a facet: its area centroid for one point; else point j of n in
// the j-th of n equal slices of its cumulative area (triangles in order), jittered,
// mapped into the triangle by the square-root warp (uniform by area).
std::vector<Vec3> sample_points(const ShadowFacet& f, long n, std::uint64_t seed,
                                std::uint64_t facet_index) {
    std::vector<double> area;
    double total = 0;
    for (const auto& t : f.triangles) {
        const Vec3 c = geo::cross(geo::sub(t[1], t[0]), geo::sub(t[2], t[0]));
        area.push_back(0.5 * geo::norm(c));
        total += area.back();
    }
    std::vector<Vec3> points;
    if (n == 1 || total <= 0) {
        Vec3 c{0, 0, 0};
        for (std::size_t i = 0; i < f.triangles.size(); ++i) {
            const double w = total > 0 ? area[i] / total : 1.0 / f.triangles.size();
            for (const Vec3& v : f.triangles[i]) c = geo::add(c, geo::scale(v, w / 3));
        }
        points.assign(static_cast<std::size_t>(n), c);
        return points;
    }
    for (long j = 0; j < n; ++j) {
        const double u = (static_cast<double>(j) + uniform01(seed, facet_index, 1, j, 0)) /
                         static_cast<double>(n) * total;
        const double v = uniform01(seed, facet_index, 1, j, 1);
        std::size_t i = 0;
        double below = 0;
        while (i + 1 < area.size() && below + area[i] < u) below += area[i++];
        const double s = std::sqrt(std::clamp((u - below) / area[i], 0.0, 1.0));
        const auto& t = f.triangles[i];
        Vec3 p{};
        for (int k = 0; k < 3; ++k)
            p[k] = (1 - s) * t[0][k] + s * (1 - v) * t[1][k] + s * v * t[2][k];
        points.push_back(p);
    }
    return points;
}

// Per-thread scratch for the spectral transmittance of a sun ray.
struct SunRay {
    const scene::Scene& scene;
    const radiometry::MaterialLibrary& materials;
    int max_transmissions;
    double eps;
    std::vector<double> vis, t;
    std::uint64_t rays = 0;  // cast by this thread, sun and sky

    // Whether the sun reaches p (no opaque facet on the way, at most
    // max_transmissions transmissive ones) and the mean over the grid of the product of
    // the transmissive facets' slab transmittances (as render.cpp's sun_visibility).
    bool reaches(const Vec3& p, const Vec3& sun, double& transmittance) {
        transmittance = 1;
        std::fill(vis.begin(), vis.end(), 1.0);
        std::uint64_t crossed = 0;
        ++rays;
        // validate_scene() has checked that every facet's material exists.
        auto material = [this](const scene::Hit& hit) -> const radiometry::MaterialOptics& {
            return *materials.find(scene.attributes(hit).material_id);
        };
        if (!transmit_through(scene, material, p, sun, eps, max_transmissions, vis.data(), t.data(),
                              vis.size(), crossed)) {
            rays += crossed;
            return false;
        }
        rays += crossed;
        if (crossed > 0 && !vis.empty()) {
            double mean = 0;
            for (double v : vis) mean += v;
            transmittance = std::clamp(mean / static_cast<double>(vis.size()), 0.0, 1.0);
        }
        return true;
    }
};

// Cosine-weighted fraction of the hemisphere above the facet at p that is open sky:
// sky_rays directions, the first m^2 (m = floor(sqrt(sky_rays))) jittered in an m x m
// grid of (r^2, phi) strata (Malley's method), the rest at random.
double sky_fraction(const scene::Scene& scene, const Vec3& p, const Basis& b, long rays,
                    std::uint64_t seed, std::uint64_t facet_index, long point) {
    const long m = static_cast<long>(std::floor(std::sqrt(static_cast<double>(rays))));
    long sky = 0;
    for (long i = 0; i < rays; ++i) {
        double u1 = uniform01(seed, facet_index, 2 + point, i, 0);
        double u2 = uniform01(seed, facet_index, 2 + point, i, 1);
        if (i < m * m) {
            u1 = (static_cast<double>(i / m) + u1) / static_cast<double>(m);
            u2 = (static_cast<double>(i % m) + u2) / static_cast<double>(m);
        }
        const double r = std::sqrt(u1), phi = 2 * kPi * u2;
        const Vec3 d = b.world(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u1));
        if (d[2] > 0 && !scene.occluded(p, d, 0.0, INFINITY)) ++sky;
    }
    return static_cast<double>(sky) / static_cast<double>(rays);
}

io::ShdFacet facet_history(const ShadowFacet& f, std::uint64_t index,
                           const std::vector<SunStep>& sun, const ShadowOptions& o, SunRay& ray) {
    io::ShdFacet out;
    out.id = f.key;
    out.points = o.points_per_facet;
    const auto points = sample_points(f, o.points_per_facet, o.seed, index);
    const Basis basis(f.normal);
    std::vector<Vec3> lifted;
    double svf = 0;
    for (std::size_t j = 0; j < points.size(); ++j) {
        lifted.push_back(geo::add(points[j], geo::scale(f.normal, ray.eps)));
        ray.rays += static_cast<std::uint64_t>(o.sky_rays);
        svf += sky_fraction(ray.scene, lifted.back(), basis, o.sky_rays, o.seed, index,
                            static_cast<long>(j));
    }
    out.sky_view_factor = std::clamp(svf / static_cast<double>(points.size()), 0.0, 1.0);
    out.sunlit_fraction.reserve(sun.size() * points.size());
    out.transmittance.reserve(sun.size() * points.size());
    for (const SunStep& s : sun) {
        const bool facing = s.up && geo::dot(f.normal, s.direction) > 0;
        for (const Vec3& p : lifted) {
            double t = 1;
            const bool lit = facing && ray.reaches(p, s.direction, t);
            out.sunlit_fraction.push_back(lit ? 1.0 : 0.0);
            out.transmittance.push_back(lit ? t : 1.0);
        }
    }
    return out;
}

double scene_epsilon(const scene::Scene& sc) {
    const scene::Bounds b = sc.bounds();
    double scale = 1;
    if (!b.empty())
        for (int i = 0; i < 3; ++i)
            scale = std::max(
                {scale, std::abs(b.lower[i]), std::abs(b.upper[i]), b.upper[i] - b.lower[i]});
    return 1e-6 * scale;  // render.cpp make_context: 17 float ulps at the largest coordinate
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

long history_steps(double history_hours, double step_minutes) {
    if (!(history_hours > 0) || !std::isfinite(history_hours))
        throw UsageError("--history-hours: expected a positive number of hours");
    if (!(step_minutes > 0) || !std::isfinite(step_minutes))
        throw UsageError("--history-step-minutes: expected a positive number of minutes");
    const double n = history_hours * 60 / step_minutes;
    const double whole = std::round(n);
    if (whole < 1 || std::abs(n - whole) > 1e-9 * std::max(1.0, n))
        throw UsageError("--history-step-minutes: " + number(step_minutes) +
                         " min does not divide --history-hours " + number(history_hours) +
                         " h into whole steps");
    if (whole > 1e6) throw UsageError("--history-step-minutes: more than 1000000 steps");
    return static_cast<long>(whole) + 1;
}

double scene_time_hours(const io::Snd& snd) { return geo::scene_wth_hours(io::scene_site(snd)); }

std::vector<SunStep> sun_history(const io::Snd& snd, long steps, double step_hours) {
    const double scene = scene_time_hours(snd);
    std::vector<SunStep> out;
    out.reserve(static_cast<std::size_t>(steps));
    for (long k = 0; k < steps; ++k) {
        SunStep s;
        s.time_hours = scene - static_cast<double>(steps - 1 - k) * step_hours;
        const geo::SolarPosition sp = geo::sun_at_wth_hours(io::scene_site(snd), s.time_hours);
        s.zenith_deg = sp.zenith_deg;
        s.azimuth_deg = sp.azimuth_deg;
        s.direction =
            geo::direction_from_angles(sp.zenith_deg * kRadPerDeg, sp.azimuth_deg * kRadPerDeg);
        s.up = sp.zenith_deg < 90;
        out.push_back(s);
    }
    return out;
}

io::Shd shadow_history(const ShadowScene& sc, const radiometry::MaterialLibrary& materials,
                       const std::vector<SunStep>& sun, double step_hours, const ShadowOptions& o,
                       const std::function<void(long, long)>& progress, ShadowStats* stats,
                       long facet_begin, long facet_end) {
    const auto start = std::chrono::steady_clock::now();
    if (sun.empty()) throw Error("shadow_history: no time steps");
    if (o.points_per_facet < 1 || o.sky_rays < 1 || o.max_transmissions < 0)
        throw UsageError(
            "shadow history: --points-per-facet and --sky-rays must be at least 1, "
            "--max-transmissions at least 0");
    validate_scene(sc.scene(), materials);  // as trace: every facet's material exists
    io::Shd shd;
    shd.scene_time_hours = sun.back().time_hours;
    shd.steps = static_cast<long>(sun.size());
    shd.step_hours = step_hours;
    const auto& facets = sc.facets();
    const long first = std::clamp(facet_begin, 0L, static_cast<long>(facets.size()));
    const long end = facet_end < 0 ? static_cast<long>(facets.size())
                                   : std::clamp(facet_end, first, static_cast<long>(facets.size()));
    shd.facets.resize(static_cast<std::size_t>(end - first));
    std::size_t samples = 0;
    for (const auto& m : materials.materials())
        samples = std::max(samples, m.extinction_per_km.size());
    const double eps = scene_epsilon(sc.scene());
    const long total = end - first;

    const ParallelOptions parallel{o.threads, progress};
    WorkerStates<SunRay> rays(parallel_workers(total, parallel));
    parallel_for(total, parallel, [&](long i, unsigned worker) {
        SunRay& ray = rays.get(worker, [&] {
            return SunRay{sc.scene(),
                          materials,
                          o.max_transmissions,
                          eps,
                          std::vector<double>(samples),
                          std::vector<double>(samples)};
        });
        const auto u = static_cast<std::size_t>(first + i);
        shd.facets[static_cast<std::size_t>(i)] = facet_history(facets[u], u, sun, o, ray);
    });
    if (stats) {
        stats->rays = 0;
        rays.each([&](const SunRay& ray) { stats->rays += ray.rays; });
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return shd;
}

namespace {

// The .snd's bands as a spectral grid (the grid trace renders on with matching .rad
// files), on which the .mat's .ext curves are sampled.
radiometry::SpectralGrid snd_grid(const io::Snd& snd) {
    radiometry::SpectralGrid g;
    for (std::size_t b = 0; b < snd.bands.size(); ++b) {
        const io::SndBand& band = snd.bands[b];
        std::vector<double> wl;
        for (long k = 0; k < band.sample_count(); ++k)
            wl.push_back(um_from_cm1(band.wavenumber_cm1(k)));
        std::sort(wl.begin(), wl.end());
        for (double w : wl) {
            g.wavelength_um.push_back(w);
            g.band_of_sample.push_back(static_cast<int>(b));
        }
        g.band_names.push_back("band" + std::to_string(b + 1));
    }
    return g;
}

// A part of the facets' records as bytes (the farm's message): the rays, then per
// facet its id, sky view factor, points, line and the two series.
struct Packer {
    FarmBytes bytes;
    template <class T>
    void put(const T& v) {
        const auto* p = reinterpret_cast<const unsigned char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof v);
    }
    void put(const std::vector<double>& v) {
        put(static_cast<std::uint64_t>(v.size()));
        const auto* p = reinterpret_cast<const unsigned char*>(v.data());
        bytes.insert(bytes.end(), p, p + 8 * v.size());
    }
};
struct Unpacker {
    const FarmBytes& bytes;
    std::size_t at = 0;
    void take(void* to, std::size_t n) {
        if (at + n > bytes.size()) throw IoError("MPI: a malformed shadow-history part");
        std::memcpy(to, bytes.data() + at, n);
        at += n;
    }
    template <class T>
    T get() {
        T v{};
        take(&v, sizeof v);
        return v;
    }
    std::vector<double> series() {
        std::vector<double> v(static_cast<std::size_t>(get<std::uint64_t>()));
        take(v.data(), 8 * v.size());
        return v;
    }
};

FarmBytes pack(const io::Shd& part, std::uint64_t rays) {
    Packer p;
    p.put(rays);
    for (const io::ShdFacet& f : part.facets) {
        p.put(static_cast<std::uint64_t>(f.id.size()));
        p.bytes.insert(p.bytes.end(), f.id.begin(), f.id.end());
        p.put(f.sky_view_factor);
        p.put(static_cast<std::int64_t>(f.points));
        p.put(static_cast<std::int32_t>(f.line));
        p.put(f.sunlit_fraction);
        p.put(f.transmittance);
    }
    return p.bytes;
}

std::uint64_t unpack(const FarmBytes& bytes, io::ShdFacet* facets, long count) {
    Unpacker u{bytes};
    const auto rays = u.get<std::uint64_t>();
    for (long i = 0; i < count; ++i) {
        io::ShdFacet& f = facets[i];
        f.id.resize(static_cast<std::size_t>(u.get<std::uint64_t>()));
        u.take(f.id.data(), f.id.size());
        f.sky_view_factor = u.get<double>();
        f.points = static_cast<long>(u.get<std::int64_t>());
        f.line = u.get<std::int32_t>();
        f.sunlit_fraction = u.series();
        f.transmittance = u.series();
    }
    if (u.at != bytes.size()) throw IoError("MPI: a malformed shadow-history part");
    return rays;
}

// The history over the farm's ranks (core/farm.hpp); false on a worker.
bool farm_history(const ShadowScene& sc, const radiometry::MaterialLibrary& materials,
                  const std::vector<SunStep>& sun, double step_hours, const ShadowOptions& o,
                  io::Shd& shd, ShadowStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    const long n = static_cast<long>(sc.facets().size());
    FarmJob job;
    job.items = n;
    job.parts = farm_parts(n, farm_workers(),
                           16.0 * static_cast<double>(sun.size() * o.points_per_facet) + 64);
    job.compute = [&](long begin, long end) {
        ShadowStats part_stats;
        const io::Shd part =
            shadow_history(sc, materials, sun, step_hours, o, {}, &part_stats, begin, end);
        return pack(part, part_stats.rays);
    };
    job.meanwhile = [&] {
        shd = shadow_history(sc, materials, sun, step_hours, o, {}, nullptr, 0, 0);
        shd.facets.resize(static_cast<std::size_t>(n));
    };
    job.gather = [&](long begin, long end, const FarmBytes& bytes) {
        stats.rays += unpack(bytes, shd.facets.data() + begin, end - begin);
    };
    if (run_farm(job) == FarmRole::Worker) return false;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

void check_options(const ShadowJob& job) {
    if (job.output_path.empty()) throw UsageError("no output: give -o FILE.shd");
    require_outputs_distinct({job.output_path}, {job.snd_path, job.scene_path, job.mat_path});
    history_steps(job.options.history_hours, job.options.step_minutes);
    if (job.options.points_per_facet < 1 || job.options.points_per_facet > 1000000)
        throw UsageError("--points-per-facet: expected 1 to 1000000");
    if (job.options.sky_rays < 1 || job.options.sky_rays > 1000000)
        throw UsageError("--sky-rays: expected 1 to 1000000");
    if (job.options.max_transmissions < 0)
        throw UsageError("--max-transmissions: expected 0 or more");
}

}  // namespace

io::Shd run_shadow_history(const ShadowJob& job, const Reporter& job_reporter) {
    check_options(job);
    // MPI ranks other than 0 read the same inputs: only rank 0 reports and writes.
    const Reporter silent;
    const Reporter& reporter = farm_worker() ? silent : job_reporter;
    const long steps = history_steps(job.options.history_hours, job.options.step_minutes);
    const double step_hours = job.options.step_minutes / 60;
    const io::Snd snd = io::read_snd_file(job.snd_path);
    const radiometry::MaterialLibrary materials = radiometry::MaterialLibrary::load(
        io::read_mat_file(job.mat_path), job.mat_path, snd_grid(snd));
    scene::LoadReport load;
    // DEMs are placed about the .snd's point, as trace and therm place them.
    const scene::GeoOrigin origin{snd.latitude_deg, snd.longitude_east_deg, 0.0};
    const ShadowScene sc = load_shadow_scene(job.scene_path, 1.0, job.allow_degenerate, &load,
                                             job.scene_input, origin, job.options.threads);
    for (const auto& w : load.warnings) reporter.warn(w);
    // No line to name: an empty scene is a property of the whole file (or of every
    // object its .odb lists), not of one record.
    if (sc.facets().empty()) throw DataError({job.scene_path, 0}, "the scene has no facets");
    const std::vector<SunStep> sun = sun_history(snd, steps, step_hours);
    const long up = std::count_if(sun.begin(), sun.end(), [](const SunStep& s) { return s.up; });
    reporter.info("history: " + std::to_string(steps) + " steps of " +
                  number(job.options.step_minutes) + " min ending at " +
                  number(sun.back().time_hours) + " h (.wth clock), sun up at " +
                  std::to_string(up) + "; " + std::to_string(sc.facets().size()) + " facets x " +
                  std::to_string(job.options.points_per_facet) + " point(s), " +
                  std::to_string(job.options.sky_rays) + " sky rays per point");
    ShadowStats stats;
    io::Shd shd;
    if (farm_available()) {
        if (!farm_history(sc, materials, sun, step_hours, job.options, shd, stats)) return {};
    } else {
        ProgressScope bar(reporter, "shadow history");
        shd = shadow_history(sc, materials, sun, step_hours, job.options, bar.callback(), &stats);
    }
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.3f s, %.2f Mrays/s", stats.seconds,
                  stats.seconds > 0 ? static_cast<double>(stats.rays) / stats.seconds / 1e6 : 0.0);
    reporter.info(std::to_string(stats.rays) + " rays (sun and sky), " + buf);
    write_atomically(job.output_path, [&](std::ostream& out) { io::write_shd(out, shd); });
    return shd;
}

}  // namespace sigchain::trace
