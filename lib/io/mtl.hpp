// Landsat MTL metadata files (man mtl(5)): the ODL text USGS ships with every Level-1
// product, read into the date, time, place, sun and per-band calibration of a scene.
// Collection 1, Collection 2 and the older (pre-2012) key names are read.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One `KEY = VALUE` statement of the ODL text, with the groups that hold it.
struct OdlEntry {
    std::string group;  // innermost group ("" at the top level)
    std::string key;
    std::string value;  // without its quotes
    bool quoted = false;
    int line = 0;
    int depth = 0;  // number of enclosing groups
};

// An ODL statement of its own: GROUP, END_GROUP or a KEY = VALUE (kept in file order so a
// canonical rewrite keeps the file's structure).
struct OdlStatement {
    enum class Kind { Group, EndGroup, Value };
    Kind kind = Kind::Value;
    OdlEntry entry;  // Group/EndGroup: key "GROUP"/"END_GROUP", value the group's name
};

struct Odl {
    std::vector<OdlStatement> statements;
    int end_line = 0;  // the line of END
};

// Reads the ODL layout: GROUP = NAME / END_GROUP = NAME (matching), KEY = VALUE, and a
// final END; values are quoted strings or bare tokens; /* ... */ comments (also over
// several lines) and blank lines are ignored. DataError "FILE:LINE: expected ..." else.
Odl parse_odl(const TextInput& in);

enum class MtlFormat { PreCollection, Collection1, Collection2 };

// The calibration of one band as the file gives it. Radiance units: W m-2 sr-1 um-1.
struct MtlBand {
    std::string name;  // "1", "6_VCID_1" (the older format's "61"), "10"
    char gain_state = 0;  // 'H', 'L' (ETM+), 0 when the file gives none
    int gain_line = 0;
    // L = mult * QCAL + add: RADIANCE_MULT/ADD_BAND_N, or for the older format
    // (LMAX - LMIN) / (QCALMAX - QCALMIN) and LMIN - mult * QCALMIN.
    std::optional<double> radiance_mult;
    std::optional<double> radiance_add;
    int rescaling_line = 0;  // of RADIANCE_MULT (or LMAX in the older format)
    std::optional<double> radiance_max;  // RADIANCE_MAXIMUM_BAND_N / LMAX_BANDN
    std::optional<double> radiance_min;  // RADIANCE_MINIMUM_BAND_N / LMIN_BANDN
    std::optional<double> qcal_min;      // QUANTIZE_CAL_MIN_BAND_N / QCALMIN_BANDN
    std::optional<double> qcal_max;
    std::optional<double> k1;  // K1_CONSTANT_BAND_N, W m-2 sr-1 um-1
    std::optional<double> k2;  // K2_CONSTANT_BAND_N, K
    bool operator==(const MtlBand&) const = default;
};

struct MtlCorner {
    double latitude_deg = 0;        // north positive
    double longitude_east_deg = 0;  // east positive
    bool operator==(const MtlCorner&) const = default;
};

struct Mtl {
    MtlFormat format = MtlFormat::Collection1;
    std::string spacecraft;  // normalised: "LANDSAT_7" (the older "Landsat7" too)
    std::string sensor;      // normalised: "ETM" (the older "ETM+"), "OLI_TIRS", "TM"
    std::string product_id;  // LANDSAT_PRODUCT_ID, or "" when absent
    int year = 2000, month = 1, day = 1;  // DATE_ACQUIRED (GMT)
    double time_gmt_hours = 0;            // SCENE_CENTER_TIME, decimal hours GMT
    std::array<MtlCorner, 4> corners;     // UL, UR, LL, LR of the product
    std::optional<double> sun_azimuth_deg;    // clockwise from north, at the scene centre
    std::optional<double> sun_elevation_deg;  // above the horizon (both informational)
    std::optional<double> earth_sun_distance_au;
    std::vector<MtlBand> bands;  // by band number ("1" < "2" < ... < "10")
    int end_line = 0;            // the line of END (missing values are reported there)
    bool operator==(const Mtl&) const = default;
};

// Reads an MTL file (mtl(5)). DataError at the value's line for a malformed value, at the
// END line for a required value that is missing (date, time, four corners, sun azimuth and
// elevation, spacecraft, sensor), and for a band with only half of a pair (mult without add,
// LMAX without LMIN, ...).
Mtl parse_mtl(const TextInput& in);
inline Mtl read_mtl_file(const std::string& path) { return parse_mtl(TextInput::from_file(path)); }
// The ODL statements back, indented two spaces per group, comments dropped.
void write_odl(std::ostream& out, const Odl& odl);
// The band named `name`, or nullptr.
const MtlBand* find_band(const Mtl& mtl, const std::string& name);
const char* format_name(MtlFormat format);
FormatHandler mtl_format();

}  // namespace sigchain::io
