// Parse throughput of the largest text formats (.gdb geometry, .ems curves):
// prints facets or values per second. Scenes of ~10^5 facets must load in well
// under a second. BM_ParseGdb/N/T: N facets on T threads (0: parse_gdb_serial, the
// reference; files from kGdbParallelBytes on are parsed in pieces).
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
    sigchain::ParallelOptions parallel;
    parallel.threads = static_cast<unsigned>(state.range(1));
    std::string text = make_gdb(facets);
    for (auto _ : state) {
        auto in = sigchain::TextInput::from_string(text, "bench.gdb");
        auto gdb = parallel.threads ? sigchain::io::parse_gdb(in, parallel)
                                    : sigchain::io::parse_gdb_serial(in);
        benchmark::DoNotOptimize(gdb);
    }
    state.SetItemsProcessed(state.iterations() * facets);
    state.SetBytesProcessed(state.iterations() * static_cast<long>(text.size()));
}
BENCHMARK(BM_ParseGdb)
    ->Args({10000, 0})
    ->Args({100000, 0})
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond);

}  // namespace
