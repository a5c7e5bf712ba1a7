// What a pushbroom costs beside a frame camera: render() of a 1000-line pushbroom image
// (1000 x 64 pixels) and of a frame image of the same pixels (1000 x 64), both nadir
// over bench_trace's generated terrain (trace_bench_scene.hpp, no trees) from 1500 m,
// each covering the same 400 x 25.6 m strip in 0.4 m pixels, golfball sampling, 3 bands
// x 7 samples.
// The two renders are run alternately (frame pushbroom, pushbroom frame, ...) for
// ROUNDS rounds; printed: the best CPU seconds (all threads) of each and their ratio,
// the median of the rounds' ratios, and the same for ray generation alone (every
// pixel centre's Sensor::ray, one thread, 20 passes). The pushbroom's rays each take
// the platform's pose at their own time (Hermite position, slerped attitude); the
// target is pushbroom <= frame + 10 %.
//
// A plain program (not Google Benchmark), like bench_trace_features: a render is one
// long run, and the ratio must come from renders run next to each other.
// Usage: bench_scanners [VERTICES_PER_SIDE [ROUNDS]] (default 401 3).
#include <algorithm>
#include <cmath>
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
#include "trace_bench_scene.hpp"

namespace {

using namespace sigchain;
using namespace sigchain::bench;

radiometry::Atmosphere bench_atmosphere() {
    std::vector<io::Rad> rads;
    std::vector<std::string> names;
    std::vector<double> views;
    for (int v = -17; v <= 17; ++v) views.push_back(5.0 * v);
    for (double start : {0.45, 0.53, 0.62}) {
        std::vector<double> wl;
        for (int k = 0; k < 7; ++k) wl.push_back(start + 0.01 * k);
        rads.push_back(radiometry::uniform_rad(wl, 35, 150, 0.15, 0.004, 0.9, 0.002, views));
        names.push_back("band" + std::to_string(rads.size()));
    }
    return radiometry::Atmosphere::from_rads(rads, names);
}

// 1000 x 64 pixels of 9 um behind 33.75 mm: 0.4 m on the ground from 1500 m.
imaging::FrameCamera frame_camera() {
    imaging::FrameCamera cam;
    cam.position = {0, 0, 1500};
    cam.forward = {0, 0, -1};
    cam.right = {1, 0, 0};
    cam.down = geo::cross(cam.forward, cam.right);
    cam.focal_length_mm = 33.75;
    cam.pixel_pitch_mm = 0.009;
    cam.rows = 1000;
    cam.columns = 64;
    return cam;
}

// 64 detectors of 9 um behind 33.75 mm (0.4 m from 1500 m), 1000 lines 0.4 m apart
// (100 m/s, 4 ms), flying north from y = -200 m, along a .trj-style trajectory of 11
// records with a gentle roll so that the interpolation is exercised.
imaging::PushbroomSensor pushbroom() {
    io::Trj trj;
    for (int k = 0; k <= 10; ++k) {
        const double t = 0.4 * k;
        trj.records.push_back(
            {t, io::ScenePosition{{0, -200 + 100 * t, 1500}}, 0.2 * std::sin(t), 0, 0,
             geo::Vec3{0, 100, 0}, k + 2});
    }
    imaging::PushbroomGeometry g;
    g.lines = 1000;
    g.detectors = 64;
    g.focal_length_mm = 33.75;
    g.pitch_mm = 0.009;
    g.line_period_s = 0.004;
    g.integration_time_s = 0.004;
    return imaging::PushbroomSensor(imaging::Trajectory(trj, "bench.trj"), g);
}

double render_cpu(const trace::RenderInputs& in, const trace::RenderOptions& opt) {
    const double c0 = cpu_seconds();
    trace::render(in, opt);
    return cpu_seconds() - c0;
}

double rays_cpu(const imaging::Sensor& s) {
    const double c0 = cpu_seconds();
    double sink = 0;
    for (int pass = 0; pass < 20; ++pass)
        for (long r = 0; r < s.rows(); ++r)
            for (long c = 0; c < s.columns(); ++c) {
                geo::Vec3 o{}, d{};
                s.ray(r + 0.5, c + 0.5, o, d);
                sink += d[2];
            }
    const double t = cpu_seconds() - c0;
    if (sink == 12345.678) std::printf(" ");  // keeps the loop
    return t;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void print_row(const char* what, const std::vector<double>& frame,
               const std::vector<double>& push) {
    std::vector<double> ratios;
    for (std::size_t k = 0; k < frame.size(); ++k) ratios.push_back(push[k] / frame[k]);
    const double f = *std::min_element(frame.begin(), frame.end());
    const double p = *std::min_element(push.begin(), push.end());
    std::printf(
        "%-16s frame %.3f CPU s, pushbroom %.3f CPU s: pushbroom/frame %.3f (best), "
        "%.3f (median of rounds)\n",
        what, f, p, p / f, median(ratios));
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 401;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
    if (n < 3 || rounds < 1) {
        std::fprintf(stderr, "usage: bench_scanners [VERTICES_PER_SIDE [ROUNDS]]\n");
        return 2;
    }
    scene::Scene sc;
    sc.place(sc.add_mesh(terrain_mesh(n)), scene::identity_affine());
    sc.commit();
    const radiometry::Atmosphere atmosphere = bench_atmosphere();
    const std::size_t samples = atmosphere.grid().size();
    const auto materials = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.12, samples), radiometry::grey_material(2, 0.2, samples)});
    const imaging::FrameSensor frame(frame_camera());
    const imaging::PushbroomSensor push = pushbroom();
    const trace::RenderInputs in_frame{&sc, &atmosphere, &materials, &frame, nullptr};
    const trace::RenderInputs in_push{&sc, &atmosphere, &materials, &push, nullptr};
    trace::RenderOptions opt;
    opt.sampling = trace::Sampling::Golfball;
    opt.threads = std::max(1u, std::thread::hardware_concurrency());
    std::printf(
        "bench_scanners: terrain %d x %d vertices, frame 1000 x 64 vs pushbroom "
        "1000 x 64 pixels, golfball, 3 bands x 7 samples, %u threads, %d rounds\n",
        n, n, opt.threads, rounds);
    render_cpu(in_frame, opt);  // warm-up (page faults, caches)
    std::vector<double> rf, rp, gf, gp;
    for (int k = 0; k < rounds; ++k) {
        const bool frame_first = k % 2 == 0;
        if (frame_first) rf.push_back(render_cpu(in_frame, opt));
        rp.push_back(render_cpu(in_push, opt));
        if (!frame_first) rf.push_back(render_cpu(in_frame, opt));
        gf.push_back(rays_cpu(frame));
        gp.push_back(rays_cpu(push));
    }
    print_row("render:", rf, rp);
    print_row("rays alone:", gf, gp);
    return 0;
}
