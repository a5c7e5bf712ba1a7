// Benchmark of the thermal chain (its run time on trace's benchmark scene): the scene
// of bench_trace (trace_bench_scene.hpp: a 1001 x 1001-vertex terrain in 100 block
// facets and 3000 instanced trees of 2 facets, 6100 facets) gets a 24 h shadow history
// at 15 min (trace --shadow-history's library call) under the Hawkeye scene node of
// White (1996), then therm's facet model on every facet with the 30 Sep 1995 weather
// of White (1996). Each stage is timed on 1 thread and on all cores.
//
// A plain program (not Google Benchmark): one long run, not repeated timings.
// Usage: bench_therm [VERTICES_PER_SIDE [TREES [THERM_FACETS_ON_1_THREAD [POINTS]]]]
// (default 1001 3000, every facet, 1 point per facet as trace --shadow-history).
// Times are wall clock and CPU (all threads): on a shared machine the CPU time per
// facet is the steadier figure.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bench_timing.hpp"
#include "core/parallel.hpp"
#include "io/snd.hpp"
#include "io/wth.hpp"
#include "radiometry/material.hpp"
#include "thermal/environment.hpp"
#include "thermal/facet_model.hpp"
#include "thermal/slab.hpp"
#include "thermal/therm_job.hpp"
#include "trace/shadow_history.hpp"
#include "trace_bench_scene.hpp"

namespace {

using namespace sigchain;
using namespace sigchain::bench;

constexpr double kHistoryHours = 24, kStepMinutes = 15;  // trace --shadow-history defaults
constexpr double kThermStepS = 60;                       // therm's default --time-step

// Slabs (back insulated). Room-temperature values of Incropera & DeWitt, Fundamentals
// of Heat and Mass Transfer, table A.3: softwood (fir, pine) across the grain, 510 kg
// m-3, 1380 J kg-1 K-1, 0.12 W m-1 K-1; soil, 2050 kg m-3, 1840 J kg-1 K-1, 0.52 W m-1 K-1.
thermal::SlabProperties wood_slab() { return {0.05, 510, 1380, 0.12, 0}; }   // 5 cm
thermal::SlabProperties soil_slab() { return {0.20, 2050, 1840, 0.52, 0}; }  // 20 cm

// One facet as therm resolves it: solar absorptivity 0.8, emissivity 0.9.
thermal::FacetThermal facet_thermal(const trace::ShadowFacet& f, const io::ShdFacet& h,
                                    bool terrain) {
    thermal::FacetThermal t;
    t.slab = terrain ? soil_slab() : wood_slab();
    t.solar_absorptivity = 0.8;
    t.thermal_emissivity = 0.9;
    t.back_exposure = 0;
    t.normal = {f.normal[0], f.normal[1], f.normal[2]};
    t.sky_view_factor = h.sky_view_factor;
    return t;
}

struct Answer {
    double temperature_k = 0;
    int runs = 0;
    double residual_k = 0;   // |last run - run before| at the scene time
    bool converged = false;  // the last two runs agree within kSpinUpToleranceK
};

// therm's spin-up for one facet, reproduced from therm_job.cpp's solve_facet (internal
// there): runs over the whole window, each from the previous run's profile 24 h after
// the start, the first from the air temperature, until two scene-time answers agree
// within kSpinUpToleranceK or kSpinUpMaxRuns runs; the same library calls
// (sun_factors, slab_nodes, Slab, run_facet) with the same constants.
Answer solve(const thermal::FacetThermal& f, const io::Shd& shd, const io::ShdFacet& h,
             const std::vector<thermal::EnvironmentStep>& env, std::size_t i24) {
    const auto sun = thermal::sun_factors(shd, h, env);
    thermal::Slab slab(
        f.slab, thermal::slab_nodes(f.slab.thickness_m, thermal::kSlabCells, thermal::kSlabGrowth),
        env.front().air_k);
    std::vector<double> start = slab.temperatures_k();
    Answer a;
    double previous = 0;
    for (int run = 1; run <= thermal::kSpinUpMaxRuns; ++run) {
        slab.set_temperatures_k(start);
        thermal::run_facet(f, env, sun, 0, i24, slab, nullptr);
        start = slab.temperatures_k();
        thermal::run_facet(f, env, sun, i24, env.size() - 1, slab, nullptr);
        a.temperature_k = slab.front_k();
        a.runs = run;
        if (run > 1) a.residual_k = std::abs(a.temperature_k - previous);
        if (run > 1 && a.residual_k < thermal::kSpinUpToleranceK) {
            a.converged = true;
            break;
        }
        previous = a.temperature_k;
    }
    return a;
}

// Solves facets [0, count) on `threads` threads (sigchain::parallel_for, as therm).
std::vector<Answer> solve_all(const std::vector<thermal::FacetThermal>& facets, const io::Shd& shd,
                              const std::vector<thermal::EnvironmentStep>& env, std::size_t i24,
                              std::size_t count, unsigned threads) {
    std::vector<Answer> out(count);
    parallel_for(static_cast<long>(count), ParallelOptions{threads, {}}, [&](long i, unsigned) {
        const auto k = static_cast<std::size_t>(i);
        out[k] = solve(facets[k], shd, shd.facets[k], env, i24);
    });
    return out;
}

void report_therm(const char* label, const std::vector<Answer>& a, std::size_t terrain_facets,
                  double seconds, double cpu, unsigned threads) {
    double lo_t = 1e300, hi_t = -1e300, lo_v = 1e300, hi_v = -1e300;
    int runs_max = 0;
    double runs_sum = 0;
    std::size_t at_limit = 0;
    double residual_max = 0;  // facets stopped by kSpinUpMaxRuns, not by the tolerance
    for (std::size_t i = 0; i < a.size(); ++i) {
        double t = a[i].temperature_k;
        if (i < terrain_facets)
            lo_t = std::min(lo_t, t), hi_t = std::max(hi_t, t);
        else
            lo_v = std::min(lo_v, t), hi_v = std::max(hi_v, t);
        runs_max = std::max(runs_max, a[i].runs);
        runs_sum += a[i].runs;
        residual_max = std::max(residual_max, a[i].residual_k);
        if (a[i].runs == thermal::kSpinUpMaxRuns && !a[i].converged) ++at_limit;
    }
    std::printf(
        "therm, %s, %u thread(s): %.2f s (%.2f CPU s), %zu facets, %.3f ms per facet "
        "(%.3f CPU ms)\n",
        label, threads, seconds, cpu, a.size(), 1e3 * seconds / static_cast<double>(a.size()),
        1e3 * cpu / static_cast<double>(a.size()));
    std::printf(
        "  spin-up runs: mean %.2f, max %d (%zu facets not within %.2f K after %d; largest "
        "residual %.3f K);\n  surface temperature",
        runs_sum / static_cast<double>(a.size()), runs_max, at_limit, thermal::kSpinUpToleranceK,
        thermal::kSpinUpMaxRuns, residual_max);
    if (lo_t <= hi_t) std::printf(" terrain %.2f .. %.2f K", lo_t, hi_t);
    if (lo_v <= hi_v) std::printf(" trees %.2f .. %.2f K", lo_v, hi_v);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 1001;
    const int trees = argc > 2 ? std::atoi(argv[2]) : 3000;
    const long subset = argc > 3 ? std::atol(argv[3]) : -1;
    const long points = argc > 4 ? std::atol(argv[4]) : 1;
    if (n < 2 || trees < 0 || points < 1) {
        std::fprintf(stderr,
                     "usage: bench_therm [VERTICES_PER_SIDE [TREES [THERM_FACETS [POINTS]]]]\n");
        return 2;
    }
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const std::string seed = SIGCHAIN_SOURCE_DIR "/tests/data/white1996/";
    const io::Snd snd = io::read_snd_file(seed + "hawkeye.snd");
    const io::Wth wth = io::read_wth_file(seed + "weather_30_Sep_95.wth");

    // The scene: placements "1.1/" (terrain) and "2.i/" (tree i). A crown is a closed
    // ellipsoid and a trunk an open cylinder, whose winding normals sum to ~0, so each
    // faces a given way: the crown up, the trunk horizontally (turned by its heading).
    auto t0 = Clock::now();
    trace::ShadowScene sc;
    const std::size_t terrain = sc.add_mesh(terrain_mesh(n));
    sc.place(terrain, scene::identity_affine(), "1.1/");
    const std::size_t tree = sc.add_mesh(tree_mesh(), {{0, 0, 1}, {1, 0, 0}});
    int t = 0;
    for (const auto& a : tree_transforms(trees))
        sc.place(tree, a, "2." + std::to_string(++t) + "/");
    sc.commit();
    const double t_scene = seconds_since(t0);
    const std::size_t facets = sc.facets().size();
    const std::size_t terrain_facets = terrain_mesh(n).facets.size();
    std::printf(
        "bench_therm: terrain %d x %d vertices (%ld triangles), %d trees, %zu facets, "
        "%u cores\n",
        n, n, 2L * (n - 1) * (n - 1), trees, facets, cores);
    std::printf("scene build (ShadowScene)      %8.2f s\n", t_scene);

    // Shadow history: 97 steps of 15 min ending at the scene time, opaque grey materials.
    const auto materials = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.12, 1), radiometry::grey_material(2, 0.2, 1),
         radiometry::grey_material(3, 0.08, 1), radiometry::grey_material(4, 0.3, 1)});
    const double step_h = kStepMinutes / 60;
    const auto sun =
        trace::sun_history(snd, trace::history_steps(kHistoryHours, kStepMinutes), step_h);
    io::Shd shd;
    double t_shadow = 0;
    for (unsigned threads : {1u, cores}) {
        trace::ShadowOptions options;
        options.threads = threads;
        options.points_per_facet = points;
        trace::ShadowStats stats;
        const double c0 = cpu_seconds();
        shd = trace::shadow_history(sc, materials, sun, step_h, options, {}, &stats);
        const double cpu = cpu_seconds() - c0;
        t_shadow = stats.seconds;
        std::printf(
            "shadow history, %u thread(s): %.2f s (%.2f CPU s), %llu rays (%.2f Mrays/s), "
            "%zu steps, %ld point(s) per facet\n",
            threads, stats.seconds, cpu, static_cast<unsigned long long>(stats.rays),
            static_cast<double>(stats.rays) / stats.seconds / 1e6, sun.size(), points);
        if (threads == cores) break;  // one core: nothing more to time
    }
    double svf_lo = 1, svf_hi = 0, lit_sum = 0;
    for (const auto& f : shd.facets) {
        svf_lo = std::min(svf_lo, f.sky_view_factor);
        svf_hi = std::max(svf_hi, f.sky_view_factor);
        for (long p = 0; p < f.points; ++p) lit_sum += f.sunlit(shd.steps - 1, p) / f.points;
    }
    std::printf(
        "  sky view %.3f .. %.3f; sunlit area at the scene time: %.1f facets' worth of "
        "%zu\n",
        svf_lo, svf_hi, lit_sum, shd.facets.size());
    for (std::size_t i = 0; i < facets; ++i)
        if (shd.facets[i].id != sc.facets()[i].key) {
            std::fprintf(stderr, "bench_therm: .shd facet %zu is %s, not %s\n", i,
                         shd.facets[i].id.c_str(), sc.facets()[i].key.c_str());
            return 1;
        }

    // therm's window: from the .wth's first row to the scene time, 60 s steps.
    const double start_h = wth.rows.front().time_h;
    const auto env = thermal::sample_environment(wth, seed + "weather_30_Sep_95.wth", snd, start_h,
                                                 shd.scene_time_hours, kThermStepS, nullptr);
    const std::size_t i24 =
        std::min(env.size() - 1, static_cast<std::size_t>(std::lround(86400 / kThermStepS)));
    std::printf("therm window %.2f .. %.2f h, %zu steps of %.0f s per run\n", start_h,
                shd.scene_time_hours, env.size() - 1, kThermStepS);
    std::vector<thermal::FacetThermal> ft;
    ft.reserve(facets);
    for (std::size_t i = 0; i < facets; ++i)
        ft.push_back(facet_thermal(sc.facets()[i], shd.facets[i], i < terrain_facets));

    const std::size_t one = subset >= 0 ? std::min<std::size_t>(facets, subset) : facets;
    t0 = Clock::now();
    double c0 = cpu_seconds();
    const auto a1 = solve_all(ft, shd, env, i24, one, 1);
    const double t_one = seconds_since(t0);
    report_therm(one == facets ? "every facet" : "first facets", a1, terrain_facets, t_one,
                 cpu_seconds() - c0, 1);
    double t_therm = t_one;
    if (cores > 1) {
        t0 = Clock::now();
        c0 = cpu_seconds();
        const auto an = solve_all(ft, shd, env, i24, facets, cores);
        t_therm = seconds_since(t0);
        report_therm("every facet", an, terrain_facets, t_therm, cpu_seconds() - c0, cores);
        for (std::size_t i = 0; i < one; ++i)
            if (an[i].temperature_k != a1[i].temperature_k) {
                std::fprintf(stderr, "bench_therm: facet %zu differs between 1 and %u threads\n", i,
                             cores);
                return 1;
            }
    }
    std::printf("shadow history %.2f s + therm %.2f s on %u threads for %zu facets\n", t_shadow,
                t_therm, cores, facets);
    return 0;
}
