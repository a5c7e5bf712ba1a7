// .rsd radiosonde file (White (1996), fig. 4.29; man rsd(5)): the atmosphere's profile of
// pressure, temperature and dew point with altitude.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One sounding level. A value written as -999 in the file is missing: std::nullopt
// here (allowed for temperature and dew point only).
struct RsdLevel {
    double altitude_km = 0;  // above mean sea level
    double pressure_mb = 0;  // > 0
    std::optional<double> temperature_c;
    std::optional<double> dew_point_c;

    bool operator==(const RsdLevel&) const = default;
};

// Levels in file order: altitude strictly increasing, pressure strictly decreasing.
struct Rsd {
    std::vector<RsdLevel> levels;  // at least 2

    bool operator==(const Rsd&) const = default;
};

inline constexpr double kRsdMissing = -999;
// Rounding allowance when checking dew point <= temperature (deg C).
inline constexpr double kRsdDewPointSlack_c = 0.05;

Rsd parse_rsd(const TextInput& in);
// One tab-separated row per level, -999 for a missing value, no comments (as White's
// (1996) spreadsheet export).
void write_rsd(std::ostream& out, const Rsd& rsd);
inline Rsd read_rsd_file(const std::string& path) { return parse_rsd(TextInput::from_file(path)); }
FormatHandler rsd_format();

}  // namespace sigchain::io
