// .ext extinction coefficients of transmissive materials (man ext(5)): curves of
// extinction coefficient against wavelength, and the transmittance of a facet.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One extinction curve (CURVE_BEGIN block).
struct ExtCurve {
    std::vector<double> wavelength_um;      // strictly increasing, > 0
    std::vector<double> extinction_per_km;  // >= 0, one per wavelength (1/km)
    bool operator==(const ExtCurve&) const = default;
};

// A whole .ext file: one or more curves, numbered from 0 in file order (as a texture
// index or a material's curve number selects them).
struct Ext {
    std::vector<ExtCurve> curves;
    bool operator==(const Ext&) const = default;
};

Ext parse_ext(const TextInput& in);
void write_ext(std::ostream& out, const Ext& ext);
inline Ext read_ext_file(const std::string& path) { return parse_ext(TextInput::from_file(path)); }
FormatHandler ext_format();

// Extinction coefficient (1/km) of curve `curve` at `wavelength_um`: linear in
// wavelength between rows, clamped to the first/last row outside the curve's range.
// Throws std::out_of_range for a curve index outside [0, curves.size()).
double extinction_per_km(const Ext& ext, int curve, double wavelength_um);

// Transmittance through a slab of thickness `thickness_km` with extinction
// coefficient `k_per_km`, entered at incidence angle theta (cos_incidence = cos theta,
// either sign: facets are crossed from either side). ext(5):
//     t = exp(-k d / |cos theta|)
// Guard: |cos theta| is clamped to [kMinCosIncidence, 1], so a grazing ray sees a
// long but finite path (t is then ~0 for any k d > 0) instead of a division by zero;
// k d = 0 gives exactly 1 at every angle.
inline constexpr double kMinCosIncidence = 1e-6;
double transmittance(double k_per_km, double thickness_km, double cos_incidence);

}  // namespace sigchain::io
