// Parse throughput of the largest text formats (.gdb geometry, .ems curves):
// prints facets or values per second. Scenes of ~10^5 facets must load in well
// under a second.
#include <benchmark/benchmark.h>

#include <sstream>
#include <string>

#include "core/text.hpp"
#include "io/gdb.hpp"

namespace {

// A .gdb with `n` quads in one part of one object (DIRSIG 3 layout).
std::string make_gdb(int n) {
    std::ostringstream s;
    s << "OBJECT\nterrain\n1-0-0\nPART\ncells\n1-1-0\n";
    for (int i = 0; i < n; ++i) {
        double x = i % 1000, y = i / 1000;
        s << "FACE\ncell " << i << "\n1-1-" << i + 1 << "\ngrass\n1\nlawn\n-1\n5\n-1\n-1\n"
          << "null\nnull\nnull\n4\n"
          << x << " " << y << " 0\n"
          << x + 1 << " " << y << " 0\n"
          << x + 1 << " " << y + 1 << " 0\n"
          << x << " " << y + 1 << " 0\n"
          << "0 0 1\n0\n0\nnull\n";
    }
    s << "END\n";
    return s.str();
}

void BM_ParseGdb(benchmark::State& state) {
    auto facets = static_cast<int>(state.range(0));
    std::string text = make_gdb(facets);
    for (auto _ : state) {
        auto in = sigchain::TextInput::from_string(text, "bench.gdb");
        auto gdb = sigchain::io::parse_gdb(in);
        benchmark::DoNotOptimize(gdb);
    }
    state.SetItemsProcessed(state.iterations() * facets);
    state.SetBytesProcessed(state.iterations() * static_cast<long>(text.size()));
}
BENCHMARK(BM_ParseGdb)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
