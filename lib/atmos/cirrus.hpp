// LOWTRAN 7 cirrus (CARD 2 ICLD 18 standard, 19 sub-visual, with CARD 2A): a slab of ice
// cloud of thickness CTHIK from base CALT with 0.55-um extinction CEXT, and its spectral
// optics from data/atmosphere/lowtran7/cloud_models.txt. Units: km MSL, um, km-1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "atmos/aerosol.hpp"
#include "io/cdk.hpp"

namespace sigchain::atmos {

class CirrusModel {
public:
    static bool modelled(int icld) { return icld == 18 || icld == 19; }

    // The deck's cirrus: nullopt unless ICLD is 18 or 19. Defaults as LOWTRAN 7's CIRR18
    // (man build_radiance(1), CIRRUS): CTHIK 0 is 1 km (18) or 0.2 km (19); CALT 0 the
    // mean base of the deck's MODEL (1-5: 11, 10, 8, 7, 5 km; others 10 km); CEXT 0 is
    // 0.14 CTHIK km-1. ISEED does not matter for 18 and 19 (LOWTRAN 7 draws the
    // thickness and base at random for the NOAA cirrus, ICLD 20, only). asymmetry_g,
    // when given (IPH 0, CARD 3A2), replaces the tabulated g as for the water clouds.
    static std::optional<CirrusModel> from_deck(const io::CdkRun& run, const std::string& data_dir,
                                                std::optional<double> asymmetry_g = std::nullopt);

    double thickness_km() const { return m_thickness_km; }
    double base_km() const { return m_base_km; }
    double extinction055_km1() const { return m_ext055_km1; }
    // FLAYZ's four levels (km MSL): zero extinction at the first and last, CEXT at the
    // middle two; their spacing at each end is a tenth of CTHIK, centred on CALT below.
    const std::vector<double>& levels_km() const { return m_z_km; }

    // Extinction (km-1) at altitude z (km MSL) and wavelength (um).
    double extinction_km1(double z_km, double wavelength_um) const;
    // {normalised extinction (1 at 0.55 um), normalised absorption, g} at a wavelength.
    std::array<double, 3> optics(double wavelength_um) const;
    // The slab [z_lo_km, z_hi_km] (km MSL): optical depth, ssa, g.
    AerosolLayerOptics layer(double z_lo_km, double z_hi_km, double wavelength_um) const;

private:
    std::vector<double> m_wavelength_um, m_ext, m_abs, m_g;  // 47 wavelengths
    std::vector<double> m_z_km, m_ext055;                    // the four levels
    double m_thickness_km = 0, m_base_km = 0, m_ext055_km1 = 0;
};

}  // namespace sigchain::atmos
