// .shd sun/shadow history (sigchain format; man shd(5)): per facet, the sky view factor
// and, per time step, the sunlit fraction and the sun's transmittance to the facet.
// Written by trace --shadow-history, read by therm.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One facet's history, sampled at `points` points of the facet (1 unless trace ran with
// --points-per-facet). Values are stored step-major: index step * points + point.
struct ShdFacet {
    std::string id;                       // the facet as trace names it (one token, unique)
    double sky_view_factor = 0;           // fraction of the sky hemisphere seen, 0..1
    long points = 1;                      // 1 or more
    std::vector<double> sunlit_fraction;  // 0..1, steps * points values
    std::vector<double> transmittance;    // sun transmittance through transmissive facets, 0..1
    int line = 0;                         // line of the FACET keyword

    double sunlit(long step, long point = 0) const {
        return sunlit_fraction[step * points + point];
    }
    double sun_transmittance(long step, long point = 0) const {
        return transmittance[step * points + point];
    }
};

// The time grid ends at the scene time: step k (0-based) is at
// scene_time_hours - (steps - 1 - k) * step_hours. Hours count from midnight of the
// day before the scene's date, as in the .wth.
struct Shd {
    double scene_time_hours = 0;
    long steps = 1;         // K, 1 or more
    double step_hours = 1;  // > 0
    std::vector<ShdFacet> facets;

    double time_hours(long step) const {
        return scene_time_hours - static_cast<double>(steps - 1 - step) * step_hours;
    }
};

// The first line of every .shd; the reader accepts major version 1 (and 1.N).
inline constexpr std::string_view kShdMagic = "# sigchain-shd 1";

Shd parse_shd(const TextInput& in);
void write_shd(std::ostream& out, const Shd& shd);
inline Shd read_shd_file(const std::string& path) { return parse_shd(TextInput::from_file(path)); }

FormatHandler shd_format();

}  // namespace sigchain::io
