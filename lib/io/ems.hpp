// .ems emissivity files (White (1996), fig. 4.35 and proposed fig. 5.22; man ems(5)): angular
// fall-off, optional specular lobe, and spectral emissivity curves.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// How the curves are written in the file; kept so a rewrite keeps the file's layout.
enum class EmsLayout {
    Wavenumber,  // DIRSIG 3 (White (1996), fig. 4.35): curve index line, then "wavenumber emissivity"
    Wavelength,  // DIRSIG "CURVE_BEGIN" block: "wavelength emissivity", increasing wavelength
};

// One spectral emissivity curve (hemispherical emissivity without the specular lobe).
struct EmsCurve {
    std::vector<double> wavelength_um;  // strictly increasing, > 0
    std::vector<double> emissivity;     // in [0, 1], one per wavelength
    // Wavenumber layout only: the file's wavenumbers (cm-1), parallel to wavelength_um
    // (so decreasing), kept so a rewrite reproduces them exactly. Empty otherwise.
    std::vector<double> wavenumber_cm1;
    bool operator==(const EmsCurve&) const = default;
};

// One row of the proposed specular-lobe table (White (1996), fig. 5.22), for one specular angle.
struct EmsLobeRow {
    double depth = 0;            // lobe depth below the diffuse value, emissivity units [0, 1],
                                 // or kLobeDepthUnused in every row
    double base_radius_deg = 0;  // cone base radius, >= 0
    double spare1 = -999;        // unused (-999)
    double spare2 = -999;        // unused (-999)
    bool operator==(const EmsLobeRow&) const = default;
};

inline constexpr int kFallOffCount = 91;  // 0..90 deg in 1 deg steps
inline constexpr int kLobeRowCount = 7;   // 0..90 deg in 15 deg steps
// A depth column of -999 (DIRSIG's "not used") leaves the lobe's energy to SPECULARITY.
inline constexpr double kLobeDepthUnused = -999;

struct Ems {
    EmsLayout layout = EmsLayout::Wavenumber;  // one layout for all curves of a file
    // fall_off[i] for the angle i degrees from the facet normal; each in [0, 1].
    std::array<double, kFallOffCount> fall_off{};
    // Empty, or kLobeRowCount rows for specular angles 0, 15, ..., 90 deg.
    std::vector<EmsLobeRow> specular_lobe;
    std::vector<EmsCurve> curves;  // at least one; curve k is the k-th in the file
    bool operator==(const Ems&) const = default;
};

Ems parse_ems(const TextInput& in);
void write_ems(std::ostream& out, const Ems& ems);
inline Ems read_ems_file(const std::string& path) { return parse_ems(TextInput::from_file(path)); }
FormatHandler ems_format();

// True when the file has a lobe table whose depth column is not -999 (ems(5), SPECULAR
// LOBE): the cone's depth then sets the lobe's energy in trace.
bool lobe_depth_used(const Ems& ems);

// Emissivity of curve `curve` at `wavelength_um`: linear in wavelength between the
// curve's rows; outside its range, the value of the nearest end (clamped, never
// extrapolated). Throws std::out_of_range for a curve index outside the file's curves.
double emissivity(const Ems& ems, int curve, double wavelength_um);

// Fall-off at `angle_deg` from the facet normal: linear between the 91 tabulated
// values; angles are clamped to [0, 90] deg (a NaN angle gives NaN).
double fall_off(const Ems& ems, double angle_deg);

}  // namespace sigchain::io
