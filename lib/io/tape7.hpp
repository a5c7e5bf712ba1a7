// TAPE7, the spectral output of one LOWTRAN 7 run (or one MODTRAN run, .tp7): a card
// echo, a column heading, one row per wavenumber, the " -9999." end marker (man
// tape7(5); LOWTRAN 7 rev 4.2 source, the TAPE7 WRITE statements of its MAIN and TRANS;
// Kneizys et al. 1988, AFGL-TR-88-0177).
//
// Values keep the file's units: wavenumber cm-1, radiance W cm-2 sr-1 (cm-1)-1,
// irradiance W cm-2 (cm-1)-1; per_micrometre converts. Altitudes km, angles degrees.
#pragma once

#include <optional>
#include <vector>

#include "core/text.hpp"

namespace sigchain::io {

enum class Tape7Program { Lowtran7, Modtran };

// What LOWTRAN 7 echoes of its cards before the table (absent from a MODTRAN file,
// whose echo is not read).
struct Tape7Echo {
    int model = 0, itype = 0, iemsct = 0, imult = 0;
    double boundary_temperature_k = 0;          // TBOUND as LOWTRAN used it (0 replaced by the
                                                // ground air temperature when the path ends there)
    double surface_albedo = 0;                  // SALB
    double ground_km = 0;                       // GNDALT (CARD 2)
    double h1_km = 0, h2_km = 0;                // CARD 3: observer, end of the path
    double zenith_angle_deg = 0;                // CARD 3 ANGLE at H1
    double v1_cm1 = 0, v2_cm1 = 0, dv_cm1 = 0;  // CARD 4
    int card1_line = 0, card3_line = 0;         // where they are, for messages
};

// One wavenumber of the table; a quantity the run's mode does not give is 0.
struct Tape7Row {
    double wavenumber_cm1 = 0;
    double transmittance = 0;      // total, along the path, [0, 1]
    double path_thermal = 0;       // path emission (+ thermal scattering): LOWTRAN 7's ATMOS
                                   // also holds the boundary's emission (Tape7::
                                   // thermal_includes_boundary); W cm-2 sr-1 (cm-1)-1
    double path_solar = 0;         // solar scattered into the path, single + multiple
    double solar_exo = 0;          // IEMSCT 3: solar irradiance above the atmosphere,
                                   // W cm-2 (cm-1)-1
    double solar_transmitted = 0;  // IEMSCT 3: that irradiance times transmittance
    int line = 0;
};

struct Tape7 {
    Tape7Program program = Tape7Program::Lowtran7;
    // 0 transmittance, 1 thermal radiance, 2 thermal and solar radiance, 3 solar irradiance
    int iemsct = 0;
    std::optional<Tape7Echo> echo;           // LOWTRAN 7 only
    bool thermal_includes_boundary = false;  // LOWTRAN 7 radiance: ATMOS adds
                                             // (1 - SALB) B(TBOUND) T when the path
                                             // ends at the ground
    std::vector<Tape7Row> rows;              // wavenumber increasing, at least 2
    int heading_line = 0;
};

// Reads a TAPE7 holding one run. LOWTRAN 7 files are read by their Fortran columns;
// MODTRAN files by the names of their heading (white-space separated values). Throws
// DataError at the line of the first problem.
Tape7 parse_tape7(const TextInput& in);
inline Tape7 read_tape7_file(const std::string& path) {
    return parse_tape7(TextInput::from_file(path));
}

// A spectral density per cm-1 at `wavenumber_cm1` as a density per um: the Jacobian
// |d nu / d lambda| = nu^2 / 10^4 (lambda = 10^4 / nu, lambda in um, nu in cm-1).
inline double per_micrometre(double per_cm1, double wavenumber_cm1) {
    return per_cm1 * wavenumber_cm1 * wavenumber_cm1 / 1e4;
}

}  // namespace sigchain::io
