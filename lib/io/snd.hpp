// .snd scene-node file (White (1996), fig. 4.28; man snd(5)): sensor altitude, spectral bands,
// view-angle grid, date, time and place of the simulation.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "geo/scene_site.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One spectral band: samples at min + k * increment (cm-1), k = 0 .. sample_count()-1.
struct SndBand {
    double min_wavenumber_cm1 = 0;
    double max_wavenumber_cm1 = 0;
    double increment_cm1 = 0;

    // floor((max - min) / increment + 1e-6) + 1: max is included when the span is a
    // whole number of increments (snd(5)).
    long sample_count() const;
    // Sample k's wavenumber (cm-1): min + k * increment.
    double wavenumber_cm1(long k) const {
        return min_wavenumber_cm1 + static_cast<double>(k) * increment_cm1;
    }
    bool operator==(const SndBand&) const = default;
};

// How the latitude or longitude was written, so a rewrite keeps a legacy file legacy.
// Plain: a signed number (latitude north positive; longitude WEST positive, the legacy
// convention of White (1996)). Hemisphere: a non-negative number with an N/S or E/W suffix.
enum class CoordinateStyle { Plain, Hemisphere };

struct Snd {
    double sensor_altitude_km = 0;  // above mean sea level
    std::vector<SndBand> bands;     // in file order
    double view_min_deg = 0;        // view angles (deg from nadir), min <= max
    double view_max_deg = 0;
    double view_increment_deg = 0;
    int month = 1;                  // 1-12
    int day = 1;                    // 1-31, valid for the month
    int year = 2000;                // full year: a two-digit 95 is stored as 1995
    bool year_two_digits = false;   // written with two digits
    double time_gmt_hours = 0;      // decimal hours GMT, [0, 24)
    double gmt_offset_hours = 0;    // GMT = local time + offset (5 for US Eastern standard)
    double latitude_deg = 0;        // of the target, north positive
    double longitude_east_deg = 0;  // of the target, EAST positive (the file's legacy
                                    // plain form is west positive)
    CoordinateStyle latitude_style = CoordinateStyle::Plain;
    CoordinateStyle longitude_style = CoordinateStyle::Plain;

    // Number of view angles: floor((max - min) / increment + 1e-6) + 1.
    long view_angle_count() const;
    bool operator==(const Snd&) const = default;
};

// Limit on the samples of one band and on the view angles (snd(5) ERRORS).
inline constexpr long kSndMaxSamples = 1000000;

Snd parse_snd(const TextInput& in);
// Writes the legacy layout (no comments); a year, latitude or longitude is written the
// way it was read (two-digit year, west-positive plain longitude, or N/S/E/W suffix).
void write_snd(std::ostream& out, const Snd& snd);
inline Snd read_snd_file(const std::string& path) { return parse_snd(TextInput::from_file(path)); }
FormatHandler snd_format();
// The scene's date, GMT time, GMT offset and place, for the sun (geo/scene_site.hpp)
// and the .wth clock (geo/scene_clock.hpp).
geo::SceneSite scene_site(const Snd& snd);

}  // namespace sigchain::io
