// bench_rt: the discrete-ordinate solver on build_radiance's typical call: 35 layers,
// 16 streams, Rayleigh + Henyey-Greenstein moments (64), 110 user cosines, 2 depths,
// 40 azimuths, beam on. The target is a few ms per call (about 125 calls per scene).
// CPU time on the development machine (AMD EPYC, x86-64 baseline, no -march): 3.1 / 10.8 /
// 68 ms for 8 / 16 / 32 streams before the solver's speed work, 2.1 / 8.0 / 52 ms after.
#include <benchmark/benchmark.h>

#include <cmath>

#include "rt/discrete_ordinates.hpp"

namespace {

sigchain::rt::Problem typical(int streams) {
    using sigchain::rt::Layer;
    sigchain::rt::Problem p;
    p.streams = streams;
    for (int n = 0; n < 35; ++n) {
        Layer l;
        const double tr = 0.05 * std::exp(-n / 8.0), ta = 0.02 * std::exp(-(35 - n) / 6.0);
        l.tau = tr + ta + 0.01;
        l.ssa = (tr + 0.9 * ta) / l.tau;
        for (int k = 0; k < 64; ++k) {
            const double rayleigh = k == 0 ? 1 : (k == 2 ? 0.1 : 0);
            l.pmom.push_back((tr * rayleigh + 0.9 * ta * std::pow(0.7, k)) / (tr + 0.9 * ta));
        }
        p.layers.push_back(l);
    }
    p.beam_flux = 1;
    p.beam_mu0 = 0.6;
    p.albedo = 0.2;
    double total = 0;
    for (const Layer& l : p.layers) total += l.tau;
    p.utau = {0, total};
    for (int i = 0; i < 110; ++i) p.umu.push_back(-1 + 2.0 * (i + 0.5) / 110);
    for (int i = 0; i < 40; ++i) p.phi_deg.push_back(i * 180.0 / 39);
    return p;
}

void BM_SolveTypical(benchmark::State& state) {
    const auto p = typical(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(sigchain::rt::solve(p));
}
BENCHMARK(BM_SolveTypical)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
