// .wth weather history (White (1996), fig. 4.32, section 4.2.3.6; man wth(5)): the weather at
// the scene, at equal time steps, that drives the thermal model.
//
// Two layouts: the whitespace (tab) separated one of White (1996), and a fixed-width one read
// by column, as DIRSIG's later files are, where a value may touch the one before it
// ("  0.31-20.00"). The reader detects the form per file; the writer writes the form
// that was read. Times are hours from midnight of the day before the simulation.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One weather record (one row).
struct WthRow {
    double time_h = 0;                       // from midnight of the day before
    double air_temperature_c = 0;            // >= -273.15
    double pressure_mb = 0;                  // > 0
    double relative_humidity_pct = 0;        // 0..100, or -1: use the dew point
    double dew_point_c = 0;                  // >= -273.15
    double wind_speed_m_s = 0;               // >= 0
    double direct_insolation_ly_h = 0;       // Langley/h (1 W/m2 = 0.086 Ly/h); 0 = compute
    double diffuse_insolation_ly_h = 0;      // Langley/h; 0 = compute
    double sky_exposure = 0;                 // 0 overcast .. 1 clear
    long cloud_type = 0;                     // >= 0
    long precipitation_type = 0;             // >= 0
    double precipitation_rate_cm_h = 0;      // >= 0
    double precipitation_temperature_c = 0;  // >= -273.15
    bool operator==(const WthRow&) const = default;
};

enum class WthForm { Whitespace, FixedWidth };

struct Wth {
    double increment_h = 0;    // header: time between rows, > 0
    std::vector<WthRow> rows;  // header: row count; times step by increment_h
    WthForm form = WthForm::Whitespace;
    bool operator==(const Wth&) const = default;
};

// The fixed-width form's 13 right-aligned fields: width and decimals (0: integer).
struct WthColumn {
    const char* name;
    int width;
    int decimals;
};
inline constexpr int kWthFields = 13;
extern const WthColumn kWthColumns[kWthFields];
inline constexpr int kWthFixedRecordWidth = 76;  // sum of the widths
inline constexpr double kWthTimeTolerance_h = 1e-6;

Wth parse_wth(const TextInput& in);
// Whitespace form: tab-separated, shortest round-trip numbers. Fixed-width form: the
// columns of kWthColumns (throws sigchain::Error if a value cannot fit its field).
void write_wth(std::ostream& out, const Wth& wth);
inline Wth read_wth_file(const std::string& path) { return parse_wth(TextInput::from_file(path)); }
FormatHandler wth_format();

}  // namespace sigchain::io
