// Hot paths of sensorize and compare on a 512 x 512 image: band integration of a
// 30-sample cube (pixels per second), pixelwise comparison of 3-band images, and
// rank-order correlation of control points.
#include <benchmark/benchmark.h>

#include <numeric>
#include <random>

#include "compare/compare.hpp"
#include "sensor_response/band.hpp"
#include "stats/stats.hpp"

namespace {

using namespace sigchain;

image::Image random_image(long rows, long columns, int channels, unsigned seed) {
    image::Image img(rows, columns, channels);
    std::mt19937 gen(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float& v : img.data) v = u(gen);
    return img;
}

void BM_BandRadiance(benchmark::State& state) {
    auto cube = random_image(512, 512, 30, 1);
    for (int i = 0; i < 30; ++i) cube.wavelength_um.push_back(0.4 + 0.01 * i);
    std::vector<double> response(10, 0.5);
    auto widths =
        sensor_response::sample_widths_um({cube.wavelength_um.begin(), cube.wavelength_um.begin() + 10}, 10);
    for (auto _ : state) {
        auto band = sensor_response::band_radiance(cube, {0, 10}, response, widths, "bench.sen");
        benchmark::DoNotOptimize(band);
    }
    state.SetItemsProcessed(state.iterations() * 512 * 512);
}
BENCHMARK(BM_BandRadiance)->Unit(benchmark::kMillisecond);

void BM_ComparePixels(benchmark::State& state) {
    auto a = random_image(512, 512, 3, 2), b = random_image(512, 512, 3, 3);
    compare::NamedImage na{"a", &a}, nb{"b", &b};
    compare::BandMap map{1, 2, 3};
    for (auto _ : state) {
        auto cmp = compare::compare_pixels(na, nb, map);
        benchmark::DoNotOptimize(cmp);
    }
    state.SetItemsProcessed(state.iterations() * 512 * 512 * 3);
}
BENCHMARK(BM_ComparePixels)->Unit(benchmark::kMillisecond);

void BM_RankCorrelation(benchmark::State& state) {
    auto n = static_cast<std::size_t>(state.range(0));
    std::vector<double> a(n), b(n);
    std::mt19937 gen(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (std::size_t i = 0; i < n; ++i) a[i] = u(gen), b[i] = a[i] + 0.1 * u(gen);
    for (auto _ : state) benchmark::DoNotOptimize(stats::rank_order_correlation(a, b));
    state.SetItemsProcessed(state.iterations() * static_cast<long>(n));
}
BENCHMARK(BM_RankCorrelation)->Arg(11)->Arg(100000);

}  // namespace
