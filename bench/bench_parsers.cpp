// Parse throughput of the largest text formats (.gdb geometry, .rad tables): prints
// facets or values per second. Scenes of ~10^5 facets must load in well under a
// second. BM_ParseGdb/N/T: N facets on T threads (0: parse_gdb_serial, the reference;
// files from kGdbParallelBytes on are parsed in pieces). BM_ReadRad/N: one .rad of N
// spectral samples as build_radiance writes a band of the hawkeye scene (77 view
// angles, a 5 x 10 deg sky of 648 cells, 39 x 36 upwelled cells, coupling terms), so
// a trace of B bands spends about B times its time reading tables.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/text.hpp"
#include "io/gdb.hpp"
#include "io/rad.hpp"

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

// Values of round-trip length (17 digits, as build_radiance prints them) in [lo, hi):
// a fixed sequence, so every run parses the same text.
class Values {
public:
    double next(double lo, double hi) {
        m_state = m_state * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * static_cast<double>(m_state >> 11) * 0x1.0p-53;
    }
    std::vector<double> spectrum(std::size_t n, double lo, double hi) {
        std::vector<double> v(n);
        for (auto& x : v) x = next(lo, hi);
        return v;
    }

private:
    std::uint64_t m_state = 42;
};

// A band of `n` samples at 10 nm steps from 0.6 um, with the hawkeye tables' grids.
sigchain::io::Rad make_rad(int n) {
    using namespace sigchain::io;
    Values val;
    Rad r;
    const double step = 250;  // cm-1
    r.sensor_altitude_km = 1;
    r.max_wavenumber_cm1 = 16800;
    r.min_wavenumber_cm1 = r.max_wavenumber_cm1 - step * (n - 1);
    r.wavenumber_increment_cm1 = step;
    r.min_wavelength_um = 1e4 / r.max_wavenumber_cm1;
    r.max_wavelength_um = 1e4 / r.min_wavenumber_cm1;
    r.min_view_angle_deg = -38;
    r.max_view_angle_deg = 38;
    r.view_angle_increment_deg = 1;
    for (int i = 0; i < n; ++i) {
        double k = r.max_wavenumber_cm1 - step * i;
        r.samples.push_back({1e4 / k, k, val.next(0.1, 0.2), val.next(0.4, 0.7)});
    }
    for (int a = -38; a <= 38; ++a) {
        RadView v{double(a), 1 / std::cos(a * 0.0174532925199432957), {}};
        for (int i = 0; i < n; ++i) v.path.push_back({val.next(0.8, 0.9), 0, val.next(1e-4, 3e-4)});
        r.views.push_back(v);
    }
    RadSky sky;
    sky.version_minor = 2;
    sky.sun_zenith_deg = 52.3;
    sky.sun_azimuth_deg = 221.7;
    sky.zenith_count = 18;
    sky.azimuth_count = 36;
    for (int z = 0; z < 18; ++z)
        for (int a = 0; a < 36; ++a) {
            double mu0 = std::cos(z * 5 * 0.0174532925199432957);
            double mu1 = std::cos((z + 1) * 5 * 0.0174532925199432957);
            sky.cells.push_back({z * 5 + 2.5, a * 10 + 5.0,
                                 (mu0 - mu1) * 10 * 0.0174532925199432957,
                                 val.spectrum(n, 1e-4, 1e-2), std::vector<double>(n, 0.0)});
        }
    RadUpwelled up;
    up.zenith_count = 39;
    up.azimuth_count = 36;
    for (int z = 0; z < 39; ++z)
        for (int a = 0; a < 36; ++a)
            up.cells.push_back(
                {double(z), a * 10.0, val.spectrum(n, 1e-4, 3e-4), std::vector<double>(n, 0.0)});
    sky.upwelled = up;
    RadCoupling k;
    k.spherical_albedo = val.spectrum(n, 0.1, 0.2);
    k.diffuse_down = val.spectrum(n, 0.1, 0.2);
    for (std::size_t v = 0; v < r.views.size(); ++v)
        k.diffuse_up.push_back(val.spectrum(n, 0.05, 0.1));
    sky.coupling = k;
    r.sky = sky;
    return r;
}

void BM_ReadRad(benchmark::State& state) {
    const int samples = static_cast<int>(state.range(0));
    std::ostringstream out;
    sigchain::io::write_rad(out, make_rad(samples));
    const std::string text = out.str();
    for (auto _ : state) {
        auto rad = sigchain::io::parse_rad(sigchain::TextInput::from_string(text, "bench.rad"));
        benchmark::DoNotOptimize(rad);
    }
    state.SetItemsProcessed(state.iterations());  // tables per second
    state.SetBytesProcessed(state.iterations() * static_cast<long>(text.size()));
}
BENCHMARK(BM_ReadRad)->Arg(1)->Arg(5)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
