// Exoatmospheric solar spectral irradiance at 1 AU (data/atmosphere/), and its value
// for a date (Earth-Sun distance).
#pragma once

#include <string>
#include <vector>

namespace sigchain::atmos {

class SolarSpectrum {
public:
    // Reads DATA_DIR/atmosphere/solar_lowtran7_extraterrestrial.txt (LOWTRAN 7's solar
    // source, 0.28-28 um and beyond). Throws DataError naming file and line.
    static SolarSpectrum load(const std::string& data_dir);

    // Irradiance at 1 AU, W cm-2 um-1, at a wavenumber (cm-1), interpolated as LOWTRAN
    // does (documented in the implementation).
    double irradiance_w_cm2_um(double wavenumber_cm1) const;

    // The integral over the whole table, W m-2 (the source's solar constant).
    double total_w_m2() const;

    // (implementation-defined members follow)
};

}  // namespace sigchain::atmos
