// LOWTRAN 7 rain (CARD 2 ICLD 6-10 and RAINRT): the rain rate on LOWTRAN's levels and
// its extinction from the Marshall-Palmer drop-size distribution, with LOWTRAN 7's drop
// optics. Units: altitude km MSL, rain rate mm h-1, extinction km-1.
#pragma once

#include <optional>
#include <vector>

#include "atmos/aerosol.hpp"
#include "io/cdk.hpp"

namespace sigchain::atmos {

// Marshall & Palmer (1948), J. Meteor. 5, 165: N(D) = N0 exp(-Lambda D) drops per m3
// per mm of diameter D (mm), N0 = 8000 m-3 mm-1, Lambda = 4.1 R^-0.21 mm-1 (R mm h-1).
inline constexpr double kMarshallPalmerN0_m3_mm1 = 8000;
double marshall_palmer_slope_mm1(double rain_rate_mm_h);

// Extinction (km-1) of Marshall-Palmer rain in geometric optics (Q_ext = 2, drops much
// larger than the wavelength): beta = integral 2 (pi D^2 / 4) N(D) dD = pi N0 / Lambda^3
// (mm2 m-3 = 1e-3 km-1), i.e. 0.3647 R^0.63 km-1: LOWTRAN 7's TNRAIN for nu >= 350
// cm-1 (lambda <= 28.6 um). 0 for R <= 0.
double rain_extinction_km1(double rain_rate_mm_h);

class RainModel {
public:
    // LOWTRAN 7's drop optics above 250 cm-1 (subroutine RNSCAT's constants for its
    // extrapolation past 231 GHz, used for every nu >= 250 cm-1): absorption half the
    // extinction, so single-scattering albedo 0.5, and asymmetry 0.85, whatever IPH.
    static constexpr double kSingleScatteringAlbedo = 0.5;
    static constexpr double kAsymmetry = 0.85;

    // The deck's rain: nullopt when ICLD is not 6-10 and RAINRT is 0. `ground_km` is
    // GNDALT (km MSL). Levels and rates as LOWTRAN 7's FLAYZ, LAYCLD and AERNSM set
    // them (man build_radiance(1), RAIN): ICLD 6-10 the rate profile RR1..RR5 of
    // cloud_rain_profiles.txt on the cloud levels (ground + 0 .. 6 km, then 7 km), zero
    // above the model's cloud top; RAINRT > 0 replaces it by RAINRT from the ground up
    // to the cloud top (ICLD 1-10) or, without a water cloud, on every level up to 6 km
    // MSL (the levels then those of the aerosol grid, with the cirrus levels `cirrus_km`
    // of ICLD 18-19 inserted).
    static std::optional<RainModel> from_deck(const io::CdkCard2& card2, double ground_km,
                                              const std::string& data_dir,
                                              const std::vector<double>& cirrus_km = {});

    // Rain rate (mm h-1) on the levels; at other altitudes the extinction interpolates
    // (LOWTRAN integrates R^0.63 along the path like its other level densities).
    const std::vector<double>& levels_km() const { return m_z_km; }
    const std::vector<double>& rates_mm_h() const { return m_rate; }
    // Extinction (km-1) at altitude z (km MSL), any wavelength (geometric optics).
    double extinction_km1(double z_km) const;
    // The slab [z_lo_km, z_hi_km] (km MSL): optical depth, ssa, g.
    AerosolLayerOptics layer(double z_lo_km, double z_hi_km) const;

private:
    std::vector<double> m_z_km, m_rate, m_ext_km1;
};

}  // namespace sigchain::atmos
