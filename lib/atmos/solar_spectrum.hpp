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
private:
    // One evenly spaced table: E_lambda (W m-2 um-1) at nu = nu0 + i * dnu (cm-1).
    struct Grid {
        double nu0_cm1 = 0, dnu_cm1 = 0;
        std::vector<double> e_w_m2_um;
        double nu_end() const { return nu0_cm1 + dnu_cm1 * double(e_w_m2_um.size() - 1); }
    };
    Grid m_coarse;  // 0-28720 cm-1 every 20 cm-1 (LOWTRAN's SOLARA)
    Grid m_fine;    // 28400-57490 cm-1 every 10 cm-1 (SOLARB)
    double m_total_w_m2 = 0;
    static double lagrange4(const Grid& g, double nu_cm1);
    double irradiance_w_m2_um(double nu_cm1) const;
};

}  // namespace sigchain::atmos
