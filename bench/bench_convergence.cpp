// trace --convergence against a fixed number of primary samples per pixel, side by side
// on one small scene: CPU seconds, mean samples per pixel and RMS error against a
// converged reference, for each setting, in one run.
//
// Scene: a 200 m plate (reflectance 0.1) with a 4 x 4 x 3 m box (0.6) in its middle,
// the sun at 30 deg, a uniform sky, montecarlo sampling with 8 hemisphere rays; a 32 x
// 64 orthographic nadir image of 0.25 m pixels over the box and its surroundings (flat
// plate, box top, the box's edges and its shadow). Reference: 1024 samples per pixel.
// Fixed counts 8, 16, 32, 64, 128; convergence 8,128 at thresholds 0.05, 0.02, 0.01,
// 0.005. Each setting runs ROUNDS times (best CPU seconds kept); errors are over all
// pixels and bands, relative to the reference's mean radiance.
//
// A plain program, like bench_trace_features.
// Usage: bench_convergence [ROUNDS] (default 3; about a minute of CPU).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "trace/render.hpp"

namespace {

using namespace sigchain;
using geo::Vec3;

// Parallel nadir rays: pixel (r, c) aims at (x0 + c pitch, y0 - r pitch, 0).
class Nadir final : public imaging::Sensor {
public:
    Nadir(long side, double pitch, double x0, double y0)
        : m_side(side), m_pitch(pitch), m_x0(x0), m_y0(y0) {}
    long rows() const override { return m_side; }
    long columns() const override { return m_side; }
    void ray(double row, double col, Vec3& o, Vec3& d) const override {
        o = {m_x0 + col * m_pitch, m_y0 - row * m_pitch, 100};
        d = {0, 0, -1};
    }
    double view_angle_deg(const Vec3&) const override { return 0; }

private:
    long m_side;
    double m_pitch, m_x0, m_y0;
};

void quad(scene::MeshData& m, const std::array<Vec3, 4>& v, long material) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size() / 3);
    for (const auto& p : v)
        for (double x : p) m.vertices.push_back(static_cast<float>(x));
    const auto facet = static_cast<std::uint32_t>(m.facets.size());
    m.triangles.insert(m.triangles.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    m.triangle_facet.insert(m.triangle_facet.end(), {facet, facet});
    scene::FacetAttributes a;
    a.material_id = material;
    m.facets.push_back(a);
    scene::FacetOrigin o;
    o.file = "bench";
    o.id = "1-1-" + std::to_string(facet + 1);
    m.origins.push_back(o);
}

scene::Scene plate_and_box() {
    scene::MeshData m;
    quad(m, {{{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}}}, 1);
    const double x0 = -2, y0 = -2, x1 = 2, y1 = 2, z1 = 3;
    quad(m, {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}}, 2);
    quad(m, {{{x0, y0, 0}, {x1, y0, 0}, {x1, y0, z1}, {x0, y0, z1}}}, 2);
    quad(m, {{{x1, y1, 0}, {x0, y1, 0}, {x0, y1, z1}, {x1, y1, z1}}}, 2);
    quad(m, {{{x1, y0, 0}, {x1, y1, 0}, {x1, y1, z1}, {x1, y0, z1}}}, 2);
    quad(m, {{{x0, y1, 0}, {x0, y0, 0}, {x0, y0, z1}, {x0, y1, z1}}}, 2);
    scene::Scene s;
    s.place(s.add_mesh(std::move(m)), scene::identity_affine());
    s.commit();
    return s;
}

struct Run {
    std::string name;
    double cpu_seconds = 1e300, mean_samples = 0, rms = 0, max_error = 0;
};

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const scene::Scene scene = plate_and_box();
    const std::vector<double> wl{0.45, 0.55, 0.65};
    const auto mats = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.1, wl.size()), radiometry::grey_material(2, 0.6, wl.size())});
    const auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(wl, 30, 120, 0.15, 0.005, 0.9, 0.001, {-60, 0, 60})}, {"b.rad"});
    constexpr long kSide = 64;
    const Nadir cam(kSide, 0.25, -8, 8);
    trace::RenderInputs in;
    in.scene = &scene;
    in.materials = &mats;
    in.atmosphere = &atm;
    in.sensor = &cam;
    trace::RenderOptions base;
    base.sampling = trace::Sampling::MonteCarlo;
    base.hemisphere_samples = 8;
    base.adjacency = false;
    base.bounces = 1;
    base.truth = true;
    base.sampling_layers = true;
    base.seed = 7;

    trace::RenderOptions ref_opt = base;
    ref_opt.samples_per_pixel = 1024;
    ref_opt.seed = 1234567;  // independent of the runs' seed
    const trace::RenderResult ref = trace::render(in, ref_opt);
    double ref_mean = 0;
    for (float v : ref.radiance.data) ref_mean += v / static_cast<double>(ref.radiance.data.size());
    const int samples_layer = static_cast<int>(trace::truth_layer_names(atm.grid()).size());

    std::vector<std::pair<std::string, trace::RenderOptions>> settings;
    for (long n : {8, 16, 32, 64, 128}) {
        trace::RenderOptions o = base;
        o.samples_per_pixel = n;
        settings.push_back({"fixed " + std::to_string(n), o});
    }
    for (double t : {0.05, 0.02, 0.01, 0.005}) {
        trace::RenderOptions o = base;
        o.convergence_min = 8;
        o.convergence_max = 128;
        o.convergence_threshold = t;
        char name[64];
        std::snprintf(name, sizeof name, "convergence 8,128,%g", t);
        settings.push_back({name, o});
    }
    std::vector<Run> runs;
    for (const auto& [name, o] : settings) {
        Run r;
        r.name = name;
        for (int k = 0; k < rounds; ++k) {
            const double t0 = bench::cpu_seconds();
            const trace::RenderResult res = trace::render(in, o);
            r.cpu_seconds = std::min(r.cpu_seconds, bench::cpu_seconds() - t0);
            if (k > 0) continue;
            double sq = 0, samples = 0;
            for (std::size_t i = 0; i < res.radiance.data.size(); ++i) {
                const double d = res.radiance.data[i] - ref.radiance.data[i];
                sq += d * d;
                r.max_error = std::max(r.max_error, std::abs(d) / ref_mean);
            }
            for (long row = 0; row < kSide; ++row)
                for (long col = 0; col < kSide; ++col)
                    samples += res.truth.at(samples_layer, row, col);
            r.rms = std::sqrt(sq / static_cast<double>(res.radiance.data.size())) / ref_mean;
            r.mean_samples = samples / static_cast<double>(kSide * kSide);
        }
        runs.push_back(r);
    }
    std::printf("bench_convergence: 64 x 64 pixels, montecarlo, 8 hemisphere rays, best of %d\n",
                rounds);
    std::printf("%-28s %10s %12s %14s %14s %14s\n", "setting", "cpu s", "samples/px",
                "rms err (rel)", "max err (rel)", "cpu / fixed 32");
    const double fixed32 = runs[2].cpu_seconds;
    for (const Run& r : runs)
        std::printf("%-28s %10.3f %12.1f %14.5f %14.5f %14.2f\n", r.name.c_str(), r.cpu_seconds,
                    r.mean_samples, r.rms, r.max_error, r.cpu_seconds / fixed32);
    return 0;
}
