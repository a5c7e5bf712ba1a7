// Facet temperatures for trace: the .tmp read and its keys checked against the scene's
// facets (trace(1), TEMPERATURES).
#include "trace/trace_temperatures.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

#include "core/error.hpp"
#include "io/tmp.hpp"

namespace sigchain::trace {
namespace {

std::string format_g4(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// From this wavelength on, thermal emission of scene-temperature facets is no longer
// negligible beside reflected sunlight (B(300 K) is ~1e-4 of the solar-reflected
// radiance at 1 um but comparable near 3-4 um): trace warns when it is left out.
constexpr double kEmissiveFromUm = 2.5;

// How the .tmp's keys meet the scene's facets (trace(1) TEMPERATURES): keys that name
// no facet, or facets without a key, are a warning naming the counts, and with --strict
// an error at the first unmatched key (or at the file when every key matched).
void check_temperature_keys(const TraceJob& job, const scene::Scene& scene, const io::Tmp& tmp,
                            const Reporter& reporter) {
    std::set<std::string> tmp_keys, facet_keys;
    for (const auto& t : tmp.facets) tmp_keys.insert(t.facet_id);
    long without = 0, from_gdb = 0;
    for (std::size_t object = 0; object < scene.placement_count(); ++object) {
        const std::size_t mesh = scene.mesh_of_placement(object);
        for (std::uint32_t f = 0; f < scene.facet_count(mesh); ++f) {
            scene::Hit h;
            h.object = static_cast<std::uint32_t>(object);
            h.facet = f;
            const std::string key = scene.facet_key(h);
            facet_keys.insert(key);
            if (!tmp_keys.count(key)) {
                ++without;
                if (scene.attributes(mesh, f).temperature_c != -1) ++from_gdb;
            }
        }
    }
    long matched = 0;
    const io::FacetTemperature* first_unmatched = nullptr;
    for (const auto& t : tmp.facets) {
        if (facet_keys.count(t.facet_id))
            ++matched;
        else if (!first_unmatched)
            first_unmatched = &t;
    }
    const long unmatched = static_cast<long>(tmp.facets.size()) - matched;
    if (unmatched == 0 && without == 0) return;
    const std::string message =
        std::to_string(matched) + " of " + std::to_string(tmp.facets.size()) +
        " facet key(s) match a facet of the scene, " + std::to_string(unmatched) + " match none" +
        (first_unmatched ? " (the first: " + first_unmatched->facet_id + ")" : "") + "; " +
        std::to_string(without) + " of " + std::to_string(facet_keys.size()) +
        " facet(s) have no temperature (" + std::to_string(from_gdb) +
        " take the .gdb TEMPERATURE, " + std::to_string(without - from_gdb) + " emit nothing)";
    if (job.strict)
        throw DataError({job.tmp_path, first_unmatched ? first_unmatched->line : 0},
                        message + " (--strict)");
    reporter.warn(job.tmp_path + ": " + message);
}

}  // namespace

// Facet temperatures by key from the .tmp, when one is given.
Temperatures read_temperatures(const TraceJob& job, const radiometry::SpectralGrid& grid,
                               const scene::Scene& scene, const Reporter& reporter) {
    Temperatures temperatures;
    if (job.tmp_path.empty()) {
        const auto longest = std::max_element(grid.wavelength_um.begin(), grid.wavelength_um.end());
        if (longest != grid.wavelength_um.end() && *longest >= kEmissiveFromUm)
            reporter.warn("the spectral grid reaches " + format_g4(*longest) +
                          " um but no facet temperatures (--tmp) were given: facet "
                          "emission is left out");
        else
            reporter.info("no temperature file (--tmp): emission is left out");
        return temperatures;
    }
    const io::Tmp tmp = io::read_tmp_file(job.tmp_path);
    for (const auto& f : tmp.facets) temperatures[f.facet_id] = f.temperature_k;
    reporter.info("temperatures of " + std::to_string(temperatures.size()) + " facet(s) from " +
                  job.tmp_path);
    check_temperature_keys(job, scene, tmp, reporter);
    return temperatures;
}

}  // namespace sigchain::trace
