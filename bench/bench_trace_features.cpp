// What trace's additions cost a render: the world beyond the scene (misses), the
// ground-sky coupling and adjacency, and multiple bounces, each measured side by side
// with the same render without it.
//
// Scene: bench_trace's generated terrain and instanced trees (trace_bench_scene.hpp),
// smaller by default; an oblique frame camera from a corner of the terrain, looking
// across it, so that the image holds sky (top), the background plane beyond the
// terrain's far edge, and terrain; golfball sampling; 3 bands x 7 spectral samples of
// an atmosphere with sky, COUPLING terms and an UPWELLED grid, as build_radiance
// writes. For each feature the render is run without it (off) and with it (on),
// alternately (off on, on off, ...) for ROUNDS rounds. Printed: the best CPU seconds
// (all threads) of each, their ratio on/off - 1 (the cost), and the median and range
// of the rounds' ratios, each of two renders run next to each other (the machine may
// be shared; CPU seconds vary less than wall seconds there, which are printed too).
//
//   misses      --background mean (the world) against --background none: the
//               background's setup (64 x 64 vertical rays) and the rays that meet it.
//   adjacency   adjacency and coupling against --no-adjacency.
//   bounces N   --bounces N against --bounces 1 (the default), N = 0, 2, 3.
//   uncertainty --truth --uncertainty (every input of unc(5) uncertain) against the
//               plain render (no truth) and against --truth alone: the partials
//               accumulated alongside the radiance (trace(1) UNCERTAINTY); the ratio
//               on/off is 1 + cost (target <= 1.5 against the plain render).
//
// The sky seen by rays that leave the scene upward (sky interpolation for secondary
// rays, the effective sky for primary rays) cannot be switched off: RenderOptions has
// no field for it. Its cost is estimated instead: each call is timed in a loop (one
// thread) and multiplied by the number of such misses in the render (from its ray
// counters), over the render's CPU seconds; the cell lookup it replaced for secondary
// rays (Atmosphere::add_sky_radiance) is timed beside it. What the world beyond the
// scene added is the interpolation over that lookup and the primary misses' effective
// sky (before it, a primary miss was 0).
//
// A plain program (not Google Benchmark), like bench_trace.
// Usage: bench_trace_features [VERTICES_PER_SIDE [TREES [IMAGE_SIDE [ROUNDS]]]]
// (default 501 1000 192 5: about 45 CPU seconds, a minute or two on 2 shared cores).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bench_timing.hpp"
#include "imaging/camera.hpp"
#include "imaging/sensor.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "trace/render.hpp"
#include "trace/tracer.hpp"
#include "trace/uncertainty.hpp"
#include "trace/world.hpp"
#include "trace_bench_scene.hpp"

namespace {

using namespace sigchain;
using namespace sigchain::bench;

constexpr double kSunZenithDeg = 35, kSunAzimuthDeg = 150;
constexpr double kDegToRad = M_PI / 180;

// One band's .rad: 7 samples from `start_um`, view angles -85..85 deg, the coupling
// terms of a clear visible atmosphere and an UPWELLED grid (view zenith 0..85 deg by 5,
// azimuth by 10 deg) whose path radiance grows with view zenith.
io::Rad band_rad(double start_um) {
    std::vector<double> wl, views;
    for (int k = 0; k < 7; ++k) wl.push_back(start_um + 0.01 * k);
    for (int v = -17; v <= 17; ++v) views.push_back(5.0 * v);
    io::Rad rad =
        radiometry::uniform_rad(wl, kSunZenithDeg, kSunAzimuthDeg, 0.15, 0.004, 0.9, 0.002, views);
    rad.sky->version_minor = 2;
    io::RadCoupling coupling;
    coupling.spherical_albedo.assign(wl.size(), 0.15);
    coupling.diffuse_down.assign(wl.size(), 0.12);
    coupling.diffuse_up.assign(rad.views.size(), std::vector<double>(wl.size(), 0.07));
    rad.sky->coupling = coupling;
    io::RadUpwelled up;
    up.zenith_count = 18;
    up.azimuth_count = 36;
    for (int r = 0; r < up.zenith_count; ++r)
        for (int a = 0; a < up.azimuth_count; ++a) {
            io::RadUpwelledCell cell;
            cell.view_zenith_deg = 5.0 * r;
            cell.azimuth_deg = 10.0 * a;
            cell.scattered_radiance.assign(wl.size(), 0.002 * (1 + r / 18.0));
            cell.emitted_radiance.assign(wl.size(), 0.0);
            up.cells.push_back(cell);
        }
    rad.sky->upwelled = up;
    return rad;
}

radiometry::Atmosphere bench_atmosphere() {
    std::vector<io::Rad> rads;
    std::vector<std::string> names;
    for (double start : {0.45, 0.53, 0.62}) {
        rads.push_back(band_rad(start));
        names.push_back("band" + std::to_string(rads.size()));
    }
    return radiometry::Atmosphere::from_rads(rads, names);
}

// IMAGE_SIDE^2 camera 100 m above the terrain's south-west corner, looking north-east
// 8 deg below the horizon with a 40 deg field of view: sky above the horizon, the
// background plane beyond the terrain's far corner (about 4 deg below), then terrain.
imaging::FrameCamera oblique_camera(long side) {
    const double depression = 8 * kDegToRad, h = std::sqrt(0.5);
    imaging::FrameCamera cam;
    cam.position = {-480, -480, 100};
    cam.forward = {h * std::cos(depression), h * std::cos(depression), -std::sin(depression)};
    cam.right = {h, -h, 0};
    cam.down = geo::cross(cam.forward, cam.right);
    cam.pixel_pitch_mm = 0.009;
    cam.focal_length_mm =
        0.5 * cam.pixel_pitch_mm * static_cast<double>(side) / std::tan(20 * kDegToRad);
    cam.rows = cam.columns = side;
    return cam;
}

struct Timing {
    double wall = 0, cpu = 0;  // seconds
};

Timing timed_render(const trace::RenderInputs& in, const trace::RenderOptions& opt,
                    trace::RenderStats* stats = nullptr) {
    const auto t0 = Clock::now();
    const double c0 = cpu_seconds();
    trace::RenderResult r = trace::render(in, opt);
    Timing t{seconds_since(t0), cpu_seconds() - c0};
    if (stats) *stats = r.stats;
    return t;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// One feature, off against on: ROUNDS pairs, alternating which runs first.
struct Comparison {
    std::string feature;
    std::vector<double> off_cpu, on_cpu, ratio_cpu, ratio_wall;
};

Comparison compare(const std::string& feature, const trace::RenderInputs& in,
                   const trace::RenderOptions& off, const trace::RenderOptions& on, int rounds) {
    Comparison c{feature, {}, {}, {}, {}};
    for (int r = 0; r < rounds; ++r) {
        Timing a, b;
        if (r % 2 == 0) {
            a = timed_render(in, off);
            b = timed_render(in, on);
        } else {
            b = timed_render(in, on);
            a = timed_render(in, off);
        }
        c.off_cpu.push_back(a.cpu);
        c.on_cpu.push_back(b.cpu);
        c.ratio_cpu.push_back(b.cpu / a.cpu);
        c.ratio_wall.push_back(b.wall / a.wall);
    }
    return c;
}

void print_comparison(const Comparison& c) {
    const double off = *std::min_element(c.off_cpu.begin(), c.off_cpu.end());
    const double on = *std::min_element(c.on_cpu.begin(), c.on_cpu.end());
    const auto [lo, hi] = std::minmax_element(c.ratio_cpu.begin(), c.ratio_cpu.end());
    std::printf("%-26s %7.3f %7.3f %+7.1f %+7.1f (%+.1f .. %+.1f) %+7.1f\n", c.feature.c_str(), off,
                on, 100 * (on / off - 1), 100 * (median(c.ratio_cpu) - 1), 100 * (*lo - 1),
                100 * (*hi - 1), 100 * (median(c.ratio_wall) - 1));
}

// Nanoseconds per call of `call(dir)` over `dirs`, best of 3 passes; `sink` keeps the
// results alive.
template <class F>
double ns_per_call(const std::vector<geo::Vec3>& dirs, F call) {
    double best = 1e300;
    for (int pass = 0; pass < 3; ++pass) {
        const auto t0 = Clock::now();
        for (const auto& d : dirs) call(d);
        best = std::min(best, seconds_since(t0));
    }
    return 1e9 * best / static_cast<double>(dirs.size());
}

// Upward unit directions: `count` uniform on the hemisphere, fixed seed.
std::vector<geo::Vec3> upward_directions(std::size_t count) {
    std::vector<geo::Vec3> dirs;
    std::uint64_t state = 0x5EED;
    for (std::size_t i = 0; i < count; ++i) {
        const double z = std::max(1e-3, unit_random(state)), phi = 2 * M_PI * unit_random(state);
        const double s = std::sqrt(1 - z * z);
        dirs.push_back({s * std::cos(phi), s * std::sin(phi), z});
    }
    return dirs;
}

struct MissCalls {
    double effective_sky_ns = 0, interpolated_ns = 0, cell_ns = 0, background_ns = 0;
    double checksum = 0;  // of every result, printed so that no call is optimised away
};

// Per-call cost of what a miss does (world.hpp, tracer.cpp: add_world), one thread,
// on the render's own context (coupled atmosphere, background).
MissCalls time_miss_calls(const trace::RenderInputs& in, const trace::RenderOptions& opt) {
    const trace::TraceContext c = trace::make_context(in, opt);
    const std::size_t n = c.n;
    std::vector<double> out(n), tau2(n), lus(n), lue(n);
    const std::vector<geo::Vec3> up = upward_directions(200000);
    std::vector<geo::Vec3> down = up;
    for (auto& d : down) d[2] = -d[2];
    MissCalls m;
    auto keep = [&] { m.checksum += out[n / 2]; };
    m.effective_sky_ns = ns_per_call(up, [&](const geo::Vec3& d) {
        trace::effective_sky(c, *in.sensor, d, out.data(), tau2.data(), lus.data(), lue.data());
        keep();
    });
    m.interpolated_ns = ns_per_call(up, [&](const geo::Vec3& d) {
        c.sky->add(d, 1.0, out, c.emission);
        keep();
    });
    m.cell_ns = ns_per_call(up, [&](const geo::Vec3& d) {
        c.in.atmosphere->add_sky_radiance(d, 1.0, out, c.emission);
        keep();
    });
    m.background_ns = ns_per_call(down, [&](const geo::Vec3& d) {
        if (trace::background_distance(c.background, {0, 0, 50}, d) >= 0)
            for (std::size_t k = 0; k < n; ++k) out[k] += c.background.radiance[k];
        keep();
    });
    return m;
}

// The sky-path estimate (header): misses counted from the base render's counters.
void print_sky_estimate(const MissCalls& m, const trace::RenderStats& s, double render_cpu) {
    const double primary_hits =
        static_cast<double>(s.primary_rays - s.sky_samples - s.background_samples);
    const double secondary_misses =
        static_cast<double>(s.secondary_rays) - (static_cast<double>(s.hits) - primary_hits);
    const double sky_cpu = 1e-9 * (static_cast<double>(s.sky_samples) * m.effective_sky_ns +
                                   secondary_misses * m.interpolated_ns);
    const double interp_extra = 1e-9 * secondary_misses * (m.interpolated_ns - m.cell_ns);
    // What the world beyond the scene added to the sky path: escaping secondary rays
    // saw a cell's sky before it, primary misses saw nothing.
    const double added = interp_extra + 1e-9 * static_cast<double>(s.sky_samples) * m.effective_sky_ns;
    std::printf(
        "\nsky for rays that leave the scene upward (estimate: per-call time x count):\n"
        "  per call: effective sky (primary) %.0f ns, sky interpolation (secondary) %.0f ns,\n"
        "            cell lookup it replaced %.0f ns, background plane %.0f ns\n"
        "  misses: %llu primary to the sky, %llu primary to the background, %.0f secondary\n"
        "          (%.0f %% of %llu secondary rays; all priced as sky interpolations)\n"
        "  sky path %.3f CPU s of the render's %.2f CPU s: %.2f %%, of which added by the\n"
        "  world beyond the scene (interpolation over the cell lookup %.2f %%, effective\n"
        "  sky of primary misses %.2f %%): %.2f %% (target for misses, with the background\n"
        "  plane above: < 5 %%)  [checksum %g]\n",
        m.effective_sky_ns, m.interpolated_ns, m.cell_ns, m.background_ns,
        static_cast<unsigned long long>(s.sky_samples),
        static_cast<unsigned long long>(s.background_samples), secondary_misses,
        100 * secondary_misses / static_cast<double>(s.secondary_rays),
        static_cast<unsigned long long>(s.secondary_rays), sky_cpu, render_cpu,
        100 * sky_cpu / render_cpu, 100 * interp_extra / render_cpu,
        100 * (added - interp_extra) / render_cpu, 100 * added / render_cpu, m.checksum);
}

struct Args {
    int n = 501, trees = 1000, rounds = 5;
    long side = 192;
};

bool parse(int argc, char** argv, Args& a) {
    if (argc > 1) a.n = std::atoi(argv[1]);
    if (argc > 2) a.trees = std::atoi(argv[2]);
    if (argc > 3) a.side = std::atol(argv[3]);
    if (argc > 4) a.rounds = std::atoi(argv[4]);
    return argc <= 5 && a.n >= 2 && a.trees >= 0 && a.side >= 1 && a.rounds >= 1;
}

scene::Scene bench_scene(const Args& a) {
    scene::Scene sc;
    sc.place(sc.add_mesh(terrain_mesh(a.n)), scene::identity_affine());
    const std::size_t tree = sc.add_mesh(tree_mesh());
    int t = 0;
    for (const auto& x : tree_transforms(a.trees))
        sc.place(tree, x, "2." + std::to_string(++t) + "/");
    sc.commit();
    return sc;
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    if (!parse(argc, argv, a)) {
        std::fprintf(stderr,
                     "usage: bench_trace_features [VERTICES_PER_SIDE [TREES [IMAGE_SIDE "
                     "[ROUNDS]]]]\n");
        return 2;
    }
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::printf(
        "bench_trace_features: terrain %d x %d vertices, %d trees, %ld x %ld pixels, "
        "oblique, golfball, 3 bands x 7 samples, %u threads, %d rounds\n",
        a.n, a.n, a.trees, a.side, a.side, threads, a.rounds);
    const scene::Scene sc = bench_scene(a);
    const radiometry::Atmosphere atmosphere = bench_atmosphere();
    const std::size_t samples = atmosphere.grid().size();
    const auto materials = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.12, samples), radiometry::grey_material(2, 0.2, samples),
         radiometry::grey_material(3, 0.08, samples), radiometry::grey_material(4, 0.3, samples)});
    const imaging::FrameSensor sensor(oblique_camera(a.side));
    const trace::RenderInputs in{&sc, &atmosphere, &materials, &sensor, nullptr};

    trace::RenderOptions base;  // trace's defaults: world, adjacency, 1 bounce
    base.sampling = trace::Sampling::Golfball;
    base.threads = threads;
    trace::RenderStats stats;
    timed_render(in, base);  // warm-up (page faults, caches)
    const Timing t_base = timed_render(in, base, &stats);
    const double px = static_cast<double>(stats.primary_rays);
    std::printf(
        "base render: %.2f s, %.2f CPU s; primary samples: %.1f %% sky, %.1f %% "
        "background, %.1f %% scene\n",
        t_base.wall, t_base.cpu, 100 * stats.sky_samples / px, 100 * stats.background_samples / px,
        100 * (px - stats.sky_samples - stats.background_samples) / px);

    trace::RenderOptions no_world = base, no_adjacency = base;
    no_world.background = trace::BackgroundChoice::None;
    no_adjacency.adjacency = false;
    std::vector<Comparison> rows;
    rows.push_back(compare("misses: background plane", in, no_world, base, a.rounds));
    rows.push_back(compare("adjacency and coupling", in, no_adjacency, base, a.rounds));
    for (int b : {0, 2, 3}) {
        trace::RenderOptions deeper = base;
        deeper.bounces = b;
        rows.push_back(
            compare("bounces " + std::to_string(b) + " (off: 1)", in, base, deeper, a.rounds));
    }
    // Every input uncertain (unc(5)): the most work the layers can do.
    trace::InputUncertainty u;
    u.es = u.tau1 = u.lus = u.lds = {0.02, true};
    u.tau2 = {0.01, false};
    u.sun_zenith_deg = 0.5;
    u.reflectance.assign(materials.materials().size(), {0.02, false});
    u.specularity.assign(materials.materials().size(), {0.05, false});
    trace::RenderInputs in_u = in;
    in_u.uncertainty = &u;
    trace::RenderOptions truth = base, uncertain = base;
    truth.truth = uncertain.truth = uncertain.uncertainty_layers = true;
    rows.push_back(compare("uncertainty (off: plain)", in_u, base, uncertain, a.rounds));
    rows.push_back(compare("uncertainty (off: truth)", in_u, truth, uncertain, a.rounds));
    std::printf("\n%-26s %7s %7s %7s %7s %-17s %7s\n", "feature", "off", "on", "cost %", "paired",
                "(range)", "wall %");
    for (const auto& c : rows) print_comparison(c);
    std::printf(
        "off, on: best CPU seconds of %d renders; cost %%: on/off - 1 of those;\n"
        "paired: median (range) over the %d rounds of on/off - 1, CPU seconds of renders\n"
        "run next to each other; wall %%: the same of wall seconds (noisier on a shared\n"
        "machine)\n",
        a.rounds, a.rounds);
    print_sky_estimate(time_miss_calls(in, base), stats, t_base.cpu);
    return 0;
}
