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
    // The water clouds build_radiance models: ICLD 1 cumulus, 2 altostratus, 3 stratus,
    // 4 stratus/stratocumulus, 5 nimbostratus, and the clouds of the rain models 6-10
    // (stratus under the drizzle 6, nimbostratus under 7 and 8, cumulus under 9 and 10;
    // their rain is rain.hpp's) and 11, the user-defined cloud (CARD 2D). 20 (NOAA
    // cirrus) is not; cirrus 18 and 19 are cirrus.hpp's.
    static bool modelled(int icld) { return icld >= 1 && icld <= 11; }
    // The water cloud (1-5) whose liquid water profile a cloud or rain model (1-11) takes:
    // LOWTRAN 7's LAYCLD pairs the rain models with the clouds 3, 5, 5, 1, 1 and the
    // user-defined cloud 11 with the cumulus 1 (MC=1), whose LWC per km-1 (CULWC) its
    // HAZEC also divides by.
    static int cloud_of(int icld) {
        constexpr int kRainCloud[6] = {3, 5, 5, 1, 1, 1};
        return icld <= 5 ? icld : kRainCloud[icld - 6];
    }

    // LOWTRAN 7's cloud levels (km above the ground), the rows 0..11 of
    // cloud_rain_profiles.txt (subroutine FLAYZ's inserted levels).
    static const std::array<double, 12>& level_heights_km();

    // The deck's water cloud: nullopt for ICLD 0, 18 and 19. `ground_km` is the ground
    // altitude (km MSL) the cloud levels stand on. asymmetry_g, when given (IPH 0, CARD 3A2),
    // replaces the tabulated g as it does for the aerosols. Throws DataError for an ICLD that is
    // not modelled. With `user`'s region 2 (CARD 2D IREG(2) 1: LOWTRAN 7 makes the cloud
    // aerosol region 2) the cloud takes its extinction, absorption and asymmetry; ICLD 11
    // without them is the cumulus.
    static std::optional<CloudModel> from_deck(const io::CdkCard2& card2, double ground_km,
                                               const std::string& data_dir,
                                               std::optional<double> asymmetry_g = std::nullopt,
                                               const io::CdkUserOptics* user = nullptr);

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
};

// The numbers of a LOWTRAN 7 table of data/atmosphere/lowtran7/ ('#' lines skipped):
// `rows` rows of `columns` numbers, else DataError with the file and line.
std::vector<std::vector<double>> read_rows(const std::string& path, std::size_t columns,
                                           std::size_t rows);

// LOWTRAN 7's profiles on levels (clouds, rain): the value at z between two levels is
// exponential in altitude when both ends are positive, else linear, zero outside the
// levels; level_integral is the exact integral of that piecewise function over
// [z_lo, z_hi] (units of v times km). z ascending.
double level_value(const std::vector<double>& z_km, const std::vector<double>& v, double z);
double level_integral(const std::vector<double>& z_km, const std::vector<double>& v, double z_lo_km,
                      double z_hi_km);

// {extinction, absorption, g} of a table on wavelengths wl (um, increasing) at
// wavelength_um, linear between the table's wavelengths and held beyond its ends (the
// cloud and cirrus columns of LOWTRAN 7's cloud_models.txt).
std::array<double, 3> table_optics(const std::vector<double>& wl, const std::vector<double>& ext,
                                   const std::vector<double>& abs, const std::vector<double>& g,
                                   double wavelength_um);

// A slab of `column055` (its optical depth at 0.55 um, scaled so that the table's
// extinction there is 1) with a table's {extinction, absorption, g} at the sample's
// wavelength: tau = column055 ext, ssa = 1 - abs / ext, g. Empty for no column.
AerosolLayerOptics slab_optics(double column055, const std::array<double, 3>& optics);

// Two scatterers in one slab: optical depths add, ssa extinction-weighted, g
// scattering-weighted.
AerosolLayerOptics combine(const AerosolLayerOptics& a, const AerosolLayerOptics& b);

}  // namespace sigchain::atmos
