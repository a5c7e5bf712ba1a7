// LOWTRAN 7 aerosol models (CARD 2: IHAZE, ISEASN, IVULCN, VIS, GNDALT): extinction,
// single-scattering albedo and asymmetry parameter against altitude and wavelength,
// from the tables in data/atmosphere/lowtran7/ (aerosol_*.txt, aerosol_vertical_profiles.txt).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "atmos/profile.hpp"
#include "io/cdk.hpp"

namespace sigchain::atmos {

// Optical properties of a slab of aerosol.
struct AerosolLayerOptics {
    double tau_ext = 0;  // extinction optical depth of the slab (vertical), >= 0
    double ssa = 0;      // single-scattering albedo, [0, 1]
    double g = 0;        // Henyey-Greenstein asymmetry parameter, (-1, 1)
    // Per region (AerosolModel's four, boundary layer first): scattering optical depth
    // and asymmetry parameter, for the regions' own phase functions (IPH 2).
    std::array<double, 4> tau_scat_region{};
    std::array<double, 4> g_region{};
};

class AerosolModel {
public:
    // CARD 2 of the deck and the profile (its relative humidity drives the
    // humidity-dependent models). IHAZE 0 gives no aerosol. Throws DataError naming
    // the card and field for a model that is not supported.
    // asymmetry_g, when given (the deck's G with IPH 0, CARD 3A2), replaces every
    // model's tabulated asymmetry parameter. `user` (CARD 2D, needed by IHAZE 7) gives
    // the regions with IREG 1 the deck's coefficients, in AerosolModel's region order.
    static AerosolModel from_deck(const io::CdkCard2& card2, const Profile& profile,
                                  const std::string& data_dir,
                                  std::optional<double> asymmetry_g = std::nullopt,
                                  const io::CdkUserOptics* user = nullptr);

    // Extinction coefficient (km-1) at altitude z (km MSL) and wavelength (um).
    double extinction_km1(double z_km, double wavelength_um) const;

    // The slab [z_lo_km, z_hi_km] at a wavelength: optical depth integrated over
    // altitude; ssa and g extinction- and scattering-weighted over the slab.
    AerosolLayerOptics layer(double z_lo_km, double z_hi_km, double wavelength_um) const;
    // The same from the slab's slab_columns055 (which do not depend on the wavelength:
    // a caller with fixed slabs integrates them once).
    AerosolLayerOptics layer(const std::array<double, 4>& columns055, double wavelength_um) const;
    // Each region's 0.55-um optical depth of the slab [z_lo_km, z_hi_km] (0 when empty).
    std::array<double, 4> slab_columns055(double z_lo_km, double z_hi_km) const;

    // Surface meteorological range (km) the model was built for (VIS, or the model's
    // default when the deck's VIS is 0).
    double visibility_km() const;

    // (implementation-defined members follow)

    // The four altitude regions of LOWTRAN 7, each with its own 0.55-um profile and
    // optical type: boundary layer (IHAZE model), troposphere (tropospheric model at
    // RH 70 %), stratosphere (IVULCN type), upper atmosphere (meteoric dust).
    static constexpr int kRegions = 4;

    // The boundary layer's effective relative humidity (percent) the optics were
    // interpolated at (LOWTRAN's aerosol-weighted mean of ln(100 - RH)).
    double boundary_layer_rh_percent() const { return m_rh_eff; }

private:
    // Normalised optics of one region on the 47-wavelength grid (ext = 1 at 0.55 um).
    struct Optics {
        std::vector<double> ext, abs, g;
    };
    std::vector<double> m_wavelength_um;  // the tables' 47 wavelengths
    std::array<Optics, kRegions> m_optics;
    std::vector<double> m_z_km;                               // profile nodes (km MSL)
    std::array<std::vector<double>, kRegions> m_beta055_km1;  // per region at the nodes
    double m_vis_km = 0;
    double m_rh_eff = 0;

    double region_extinction055(int region, double z_km) const;
    double effective_rh(const Profile& profile) const;
    double region_column055(int region, double z_lo_km, double z_hi_km) const;
    std::array<double, 3> region_optics(int region, double wavelength_um) const;
};

}  // namespace sigchain::atmos
