// The open sky integrated (trace --open-sky integrated, radiometry/sky_irradiance.hpp):
// what its table costs beside the sky lookup it saves. A .rad sky of 18 x 36 cells and
// 144 spectral samples (a Landsat scene's six bands of 24), as build_radiance writes.
//   BM_SkyIrradianceSetUp   the quadrature grid's 64 800 stencils, once per render
//   BM_SkyIrradianceNode    one node of the table (W_c(n) over the grid, then the
//                           cells' spectra): paid once per node a render touches
//   BM_SkyIrradianceNodeFallOff  the same with a material's incoming fall-off F(theta)
//                           (linear between whole degrees) weighting the integrand
//   BM_SkyIrradianceRead    a hit's E(n) from four warm nodes
//   BM_SkyInterpolatorAdd   one interpolated sky lookup: what each hemisphere ray that
//                           escapes upward no longer needs
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "radiometry/sky_interpolation.hpp"
#include "radiometry/sky_irradiance.hpp"

namespace {

using namespace sigchain;

const radiometry::Atmosphere& landsat_like() {
    static const radiometry::Atmosphere atm = [] {
        std::vector<double> wl;
        for (int k = 0; k < 144; ++k) wl.push_back(0.45 + 0.012 * k);
        io::Rad rad = radiometry::uniform_rad(wl, 35, 140, 0.15, 0.004, 0.9, 0.001, {-60, 0, 60});
        for (auto& cell : rad.sky->cells)
            for (std::size_t k = 0; k < cell.scattered_radiance.size(); ++k)
                cell.scattered_radiance[k] *= 1 + 0.01 * cell.zenith_deg + 0.001 * (k % 7);
        return radiometry::Atmosphere::from_rads({rad}, {"bench.rad"});
    }();
    return atm;
}

std::vector<geo::Vec3> normals(int n) {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> g;
    std::vector<geo::Vec3> v;
    for (int i = 0; i < n; ++i) {
        geo::Vec3 d{0.2 * g(rng), 0.2 * g(rng), 1};
        v.push_back(geo::unit(d));
    }
    return v;
}

void BM_SkyIrradianceSetUp(benchmark::State& state) {
    for (auto _ : state) {
        radiometry::SkyIrradiance e(landsat_like(), false);
        benchmark::DoNotOptimize(&e);
    }
}
BENCHMARK(BM_SkyIrradianceSetUp)->Unit(benchmark::kMillisecond);

// One node after another, at 64 normals near the zenith.
void time_nodes(benchmark::State& state, const radiometry::SkyIrradiance& e) {
    const auto n = normals(64);
    std::vector<double> out(144);
    std::size_t i = 0;
    for (auto _ : state) {
        e.integrate(n[i++ % n.size()], out);
        benchmark::DoNotOptimize(out.data());
    }
}

void BM_SkyIrradianceNode(benchmark::State& state) {
    time_nodes(state, radiometry::SkyIrradiance(landsat_like(), false));
}
BENCHMARK(BM_SkyIrradianceNode)->Unit(benchmark::kMicrosecond);

void BM_SkyIrradianceNodeFallOff(benchmark::State& state) {
    // A grass-like fall-off: 1 to 45 deg, then linear to 0.2 at 80 and 0.1 at 90 deg.
    radiometry::MaterialOptics m = radiometry::grey_material(1, 0.1, 1);
    for (int d = 0; d <= 90; ++d)
        m.fall_off[d] = d <= 45 ? 1.0 : d <= 80 ? 1.0 - 0.8 * (d - 45) / 35.0 : 0.2 - 0.01 * (d - 80);
    const auto lib = radiometry::MaterialLibrary::from_optics({m});
    const radiometry::MaterialOptics& mm = *lib.find(1);
    time_nodes(state, radiometry::SkyIrradiance(landsat_like(), false,
                                                [&mm](double c) { return mm.fall_off_cos(c); }));
}
BENCHMARK(BM_SkyIrradianceNodeFallOff)->Unit(benchmark::kMicrosecond);

void BM_SkyIrradianceRead(benchmark::State& state) {
    const radiometry::SkyIrradiance e(landsat_like(), false);
    const auto n = normals(1024);
    std::vector<double> out(144, 0.0);
    for (const auto& d : n) e.add(d, 1.0, out);  // warm the nodes
    std::size_t i = 0;
    for (auto _ : state) {
        e.add(n[i++ % n.size()], 1.0, out);
        benchmark::DoNotOptimize(out.data());
    }
}
BENCHMARK(BM_SkyIrradianceRead)->Unit(benchmark::kNanosecond);

void BM_SkyInterpolatorAdd(benchmark::State& state) {
    const radiometry::SkyInterpolator sky(landsat_like());
    const auto n = normals(1024);
    std::vector<double> out(144, 0.0);
    std::size_t i = 0;
    for (auto _ : state) {
        sky.add(n[i++ % n.size()], 1.0, out, false);
        benchmark::DoNotOptimize(out.data());
    }
}
BENCHMARK(BM_SkyInterpolatorAdd)->Unit(benchmark::kNanosecond);

}  // namespace
