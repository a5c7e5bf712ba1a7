// Atmospheric profile: pressure, temperature and gas amounts on altitude levels, from a
// LOWTRAN 7 card deck (a standard AFGL model, or radiosonde layers merged with a model).
// Used by build_radiance for Rayleigh, aerosol, gas absorption and thermal emission.
//
// Units: altitude km above mean sea level, pressure mb (hPa), temperature K, water
// vapour density g m-3, mixing ratios ppmv, relative humidity percent.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "io/cdk.hpp"

namespace sigchain::atmos {

// The absorbers of LOWTRAN 7, in its order (WMOL 1-12).
enum class Gas : int { H2O, CO2, O3, N2O, CO, CH4, O2, NO, SO2, NO2, NH3, HNO3 };
inline constexpr int kGasCount = 12;

struct Profile {
    std::vector<double> z_km;        // levels, strictly increasing
    std::vector<double> p_mb;        // > 0, decreasing with altitude
    std::vector<double> t_k;         // > 0
    std::vector<double> h2o_g_m3;    // water vapour density, >= 0
    std::vector<double> rh_percent;  // relative humidity over water, [0, 100]
    // Volume mixing ratio of every gas at every level, ppmv (index by int(Gas)); H2O
    // too, consistent with h2o_g_m3.
    std::array<std::vector<double>, kGasCount> vmr_ppmv;
    // The deck's MODEL (1-7) the profile was built for, 0 when unknown; the aerosol
    // models take their default season from it (ISEASN 0).
    int model = 0;

    std::size_t size() const { return z_km.size(); }
    double bottom_km() const { return z_km.front(); }
    double top_km() const { return z_km.back(); }
};

// Air number density (cm-3) of an ideal gas at p (mb) and T (K): n = p / (k T).
double air_number_density_cm3(double p_mb, double t_k);

// Saturation water vapour density over water (g m-3) at T (K), by the formula
// LOWTRAN 7 uses (data/atmosphere/lowtran7/formulas_and_constants.txt).
double saturation_vapour_density_g_m3(double t_k);

// One of the six AFGL model atmospheres (MODEL 1-6), 0-120 km, read from
// DATA_DIR/atmosphere/afgl_atmosphere_<model>_*.txt. The minor gases NO, SO2, NO2,
// NH3, HNO3 come from DATA_DIR/atmosphere/lowtran7/trace_gas_profiles.txt.
// Throws DataError naming the file and line on a bad table.
Profile afgl_profile(int model, const std::string& data_dir);

// The deck's atmosphere: MODEL 1-6, or MODEL 7 (radiosonde, CARD 2C/2C1 layers with
// their JCHAR units) merged above the sonde's top with the model chosen by M1..M6 /
// MDEF (documented in the implementation). Gases the deck does not give come from
// the model. Throws DataError (with the card named) for what cannot be modelled.
Profile profile_from_deck(const io::CdkRun& run, const std::string& data_dir);

// The profile restricted to [z_lo_km, z_hi_km] with levels added at both ends and at
// every altitude in `extra_z_km` inside that range (temperature interpolated linearly
// in altitude; pressure and every density exponentially, as LOWTRAN does).
Profile resample(const Profile& p, double z_lo_km, double z_hi_km,
                 const std::vector<double>& extra_z_km = {});

}  // namespace sigchain::atmos
