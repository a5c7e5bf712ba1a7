// LOWTRAN 7 cirrus (see cirrus.hpp).
//
// Follows LOWTRAN 7's subroutines CIRR18 (the defaults), FLAYZ (the levels) and AERNSM
// (the 0.55-um extinction on them), as the user's guide describes CARD 2A (Kneizys et
// al., AFGL-TR-88-0177, 1988): the levels CLD0 = CALT - CTHIK / 20 (not below 0),
// CLD1 = CLD0 + CTHIK / 10, CLD2 = CLD1 + 0.9 CTHIK, CLD3 = CLD2 + CTHIK / 10 carry the
// extinction 0, CEXT, CEXT, 0 km-1, linear between a zero and CEXT (LOWTRAN's level
// integration), so the column is CEXT x CTHIK. At other wavelengths the extinction is
// CEXT times the cirrus model's normalised extinction of cloud_models.txt (ice spheres
// of 64 um mode radius for 18, 4 um for 19; within 2 % of 1 from 0.2 to 3 um for 18),
// absorption likewise, g tabulated: all linear in wavelength (AEREXT), scattering by
// Henyey-Greenstein.
#include "atmos/cirrus.hpp"

#include <algorithm>
#include <cmath>

#include "atmos/cloud.hpp"
#include "core/error.hpp"

namespace sigchain::atmos {

namespace {

// Mean cirrus base (km) of MODEL 1-5 (CIRR18's CAMEAN); other models use MODEL 2's.
constexpr double kMeanBase_km[5] = {11, 10, 8, 7, 5};

}  // namespace

std::optional<CirrusModel> CirrusModel::from_deck(const io::CdkRun& run,
                                                  const std::string& data_dir,
                                                  std::optional<double> asymmetry_g) {
    const int icld = run.card2.icld;
    if (!modelled(icld)) return std::nullopt;
    const io::CdkCirrus card = run.cirrus.value_or(io::CdkCirrus{});
    CirrusModel c;
    c.m_thickness_km = card.thickness_km > 0 ? card.thickness_km : icld == 18 ? 1.0 : 0.2;
    c.m_ext055_km1 = card.extinction_km1 > 0 ? card.extinction_km1 : 0.14 * c.m_thickness_km;
    const int model = run.card1.model >= 1 && run.card1.model <= 5 ? run.card1.model : 2;
    c.m_base_km = card.base_altitude_km > 0 ? card.base_altitude_km : kMeanBase_km[model - 1];
    const double ramp = 0.1 * c.m_thickness_km;
    const double cld0 = std::max(0.0, c.m_base_km - 0.5 * ramp);
    const double cld1 = cld0 + ramp, cld2 = cld1 + c.m_thickness_km - ramp, cld3 = cld2 + ramp;
    c.m_z_km = {cld0, cld1, cld2, cld3};
    c.m_ext055 = {0, c.m_ext055_km1, c.m_ext055_km1, 0};
    const std::size_t m = icld == 18 ? 5 : 6;  // the model's columns in cloud_models.txt
    for (const auto& row : read_rows(data_dir + "/atmosphere/lowtran7/cloud_models.txt", 22, 47)) {
        c.m_wavelength_um.push_back(row[0]);
        c.m_ext.push_back(row[1 + 3 * m]);
        c.m_abs.push_back(row[2 + 3 * m]);
        c.m_g.push_back(asymmetry_g ? *asymmetry_g : row[3 + 3 * m]);
    }
    return c;
}

std::array<double, 3> CirrusModel::optics(double wavelength_um) const {
    return table_optics(m_wavelength_um, m_ext, m_abs, m_g, wavelength_um);
}

double CirrusModel::extinction_km1(double z_km, double wavelength_um) const {
    return level_value(m_z_km, m_ext055, z_km) * optics(wavelength_um)[0];
}

AerosolLayerOptics CirrusModel::layer(double z_lo_km, double z_hi_km, double wavelength_um) const {
    if (!(z_hi_km > z_lo_km)) return {};
    const double column055 = level_integral(m_z_km, m_ext055, z_lo_km, z_hi_km);
    return column055 > 0 ? slab_optics(column055, optics(wavelength_um)) : AerosolLayerOptics{};
}

}  // namespace sigchain::atmos
