// .unc input uncertainties (sigchain format; man unc(5)): one-sigma uncertainties of a
// render's inputs, absolute or relative, for trace --uncertainty's first-order
// propagation through the Big Equation (White (1996), section 5.1.2; Beers (1957)).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// The input a row of a .unc is about.
enum class UncTerm {
    SolarIrradiance,  // "Es": exoatmospheric solar irradiance (relative only)
    SunTransmission,  // "tau1": sun to ground transmittance
    PathTransmission,  // "tau2": ground to sensor transmittance
    UpwelledRadiance,  // "L_us": upwelled path radiance (absolute: W cm-2 sr-1 um-1)
    SkyRadiance,       // "L_ds": downwelled sky radiance (relative only)
    SunZenith,         // "sun_zenith": degrees (absolute only)
    Reflectance,       // "material M reflectance": 1 - eps of the material's curves
    Specularity,       // "material M specularity": the .mat's SPECULARITY
};

// One one-sigma uncertainty: `sigma` in the term's unit, or in per cent of the value
// when `relative`.
struct UncRow {
    UncTerm term = UncTerm::SolarIrradiance;
    std::string material;  // Reflectance, Specularity: a MATERIAL_ID or MATERIAL_NAME
    double sigma = 0;      // >= 0
    bool relative = false;
    int line = 0;  // line in the file it came from (not compared)

    friend bool operator==(const UncRow& a, const UncRow& b) {
        return a.term == b.term && a.material == b.material && a.sigma == b.sigma &&
               a.relative == b.relative;
    }
};

struct Unc {
    int minor_version = 0;     // read from the magic line; the writer writes version 1.1
    std::vector<UncRow> rows;  // each term (and material quantity) once, file order
    friend bool operator==(const Unc& a, const Unc& b) { return a.rows == b.rows; }
};

// The keyword of a term ("Es", "tau1", ..., "reflectance", "specularity").
std::string unc_term_name(UncTerm term);

// Reads version 1; a 1.1 file must end with "# sigchain-end N" (N rows). Throws
// DataError at the line of an unknown term, a bad or negative sigma, a relative sigma
// where only absolute ones are meaningful (sun_zenith) or the reverse (Es, L_ds), or a
// term given twice.
Unc parse_unc(const TextInput& in);
void write_unc(std::ostream& out, const Unc& unc);
inline Unc read_unc_file(const std::string& path) { return parse_unc(TextInput::from_file(path)); }
FormatHandler unc_format();

}  // namespace sigchain::io
