// LOWTRAN 7 water-cloud models (CARD 2 ICLD 1-5): the liquid water content profile above
// the ground and the spectral extinction, absorption and asymmetry parameter, from
// data/atmosphere/lowtran7/cloud_models.txt and cloud_rain_profiles.txt.
// Units: altitude km (MSL unless stated), wavelength um, extinction km-1, LWC g m-3.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "atmos/aerosol.hpp"
#include "io/cdk.hpp"

namespace sigchain::atmos {

class CloudModel {
public:
    // The cloud models build_radiance models: ICLD 1 cumulus, 2 altostratus, 3 stratus,
    // 4 stratus/stratocumulus, 5 nimbostratus. Rain (ICLD 6-10, RAINRT), ICLD 11 and
    // cirrus (18-20) are not.
    static bool modelled(int icld) { return icld >= 1 && icld <= 5; }

    // LOWTRAN 7's cloud levels (km above the ground), the rows 0..11 of
    // cloud_rain_profiles.txt (subroutine FLAYZ's inserted levels).
    static const std::array<double, 12>& level_heights_km();

    // The deck's cloud: nullopt for ICLD 0. `ground_km` is the ground altitude (km MSL)
    // the cloud levels stand on. asymmetry_g, when given (IPH 0, CARD 3A2), replaces
    // the tabulated g as it does for the aerosols. Throws DataError for an ICLD that is
    // not modelled.
    static std::optional<CloudModel> from_deck(const io::CdkCard2& card2, double ground_km,
                                               const std::string& data_dir,
                                               std::optional<double> asymmetry_g = std::nullopt);

    // Liquid water content (g m-3) at altitude z (km MSL).
    double lwc_g_m3(double z_km) const;
    // Extinction coefficient (km-1) at altitude z (km MSL) and wavelength (um).
    double extinction_km1(double z_km, double wavelength_um) const;
    // {normalised extinction, normalised absorption, g} at a wavelength (ext 1 at 0.55 um).
    std::array<double, 3> optics(double wavelength_um) const;
    // Liquid water content (g m-3) giving 1 km-1 at 0.55 um.
    double equivalent_lwc_g_m3() const { return m_eq_lwc; }
    // The cloud levels (km MSL).
    const std::vector<double>& levels_km() const { return m_z_km; }

    // The slab [z_lo_km, z_hi_km] (km MSL): optical depth, ssa, g.
    AerosolLayerOptics layer(double z_lo_km, double z_hi_km, double wavelength_um) const;

private:
    std::vector<double> m_wavelength_um, m_ext, m_abs, m_g;  // 47 wavelengths
    std::vector<double> m_z_km, m_lwc;                       // cloud levels
    double m_eq_lwc = 1;
    double column_lwc(double z_lo_km, double z_hi_km) const;  // g m-3 x km
};

// Two scatterers in one slab: optical depths add, ssa extinction-weighted, g
// scattering-weighted.
AerosolLayerOptics combine(const AerosolLayerOptics& a, const AerosolLayerOptics& b);

}  // namespace sigchain::atmos
