// sensorize's blur on a 1024 x 1024 band, side by side: the MTF chain in the frequency
// domain (FFTW3 r2c/c2r on the 2048 x 2048 mirror-padded band) against the spatial
// convolution with a Gaussian PSF of the same width: σ = 2 px (a 13 x 13 kernel) and
// σ = 6 px (37 x 37). The FFT's cost does not depend on the width; the convolution's
// grows with the kernel's area.
#include <benchmark/benchmark.h>

#include <random>

#include "sensor_response/mtf.hpp"
#include "sensor_response/psf.hpp"

namespace {

using namespace sigchain;

constexpr long size = 1024;

std::vector<float> random_band() {
    std::vector<float> v(static_cast<std::size_t>(size * size));
    std::mt19937 gen(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float& x : v) x = u(gen);
    return v;
}

void BM_MtfFilterFftw(benchmark::State& state) {
    const auto band = random_band();
    sensor_response::MtfParams p;
    // The same Gaussian as the PSF below (plus the detector footprint).
    p.defocus_sigma_px = static_cast<double>(state.range(0));
    p.enabled = true;
    const sensor_response::MtfChain chain(p, 0);
    for (auto _ : state) {
        auto out = sensor_response::apply_mtf(band, size, size, chain);
        benchmark::DoNotOptimize(out);
    }
    state.SetItemsProcessed(state.iterations() * size * size);
}
BENCHMARK(BM_MtfFilterFftw)->Arg(2)->Arg(6)->Unit(benchmark::kMillisecond);

void BM_PsfConvolveSpatial(benchmark::State& state) {
    const auto band = random_band();
    const auto kernel = sensor_response::gaussian_kernel(static_cast<double>(state.range(0)));
    for (auto _ : state) {
        auto out = sensor_response::convolve(band, size, size, kernel);
        benchmark::DoNotOptimize(out);
    }
    state.SetItemsProcessed(state.iterations() * size * size);
}
BENCHMARK(BM_PsfConvolveSpatial)->Arg(2)->Arg(6)->Unit(benchmark::kMillisecond);

}  // namespace
