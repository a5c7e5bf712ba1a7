// LOWTRAN 7 water-cloud models (see cloud.hpp).
//
// Follows the rules stated in data/atmosphere/lowtran7/cloud_models.txt and
// cloud_rain_profiles.txt (LOWTRAN 7 BLOCK DATA MDTA and EXTDTA, subroutines FLAYZ,
// AEREXT; Kneizys et al., AFGL-TR-88-0177, 1988):
//  * the liquid water content CLD1..CLD5 (g m-3) is given on 12 cloud levels, 0, .16,
//    .33, .66, 1, 1.5, 2, 2.4, 2.7, 3, 3.5 and 4 km above the ground (the file's z
//    column holds the level numbers 0..11); zero above;
//  * the 0.55-um extinction is LWC / LWC_eq (km-1), LWC_eq the model's liquid water
//    content giving 1 km-1 (EXABIN/AERNSM constants quoted in cloud_models.txt); at
//    other wavelengths times the normalised extinction, absorption likewise, both
//    linear in wavelength between the 47 tabulated ones (AEREXT);
//  * between two levels the LWC is exponential in altitude when both ends are positive,
//    else linear, as the aerosols (aerosol.cpp): LOWTRAN's layer integration of its
//    level densities; the slab integral is exact for that piecewise function;
//  * scattering by Henyey-Greenstein with the tabulated g.
#include "atmos/cloud.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

const SourceLocation kCard2{"card deck", 0};

// LWC (g m-3) giving 1 km-1 at 0.55 um, ICLD 1-5 (cloud_models.txt header).
constexpr double kEquivalentLwc[5] = {7.683e-3, 4.509e-3, 5.272e-3, 4.177e-3, 7.518e-3};

}  // namespace

std::vector<std::vector<double>> read_rows(const std::string& path, std::size_t columns,
                                           std::size_t rows) {
    const TextInput in = TextInput::from_file(path);
    FieldReader cur(in);
    cur.require_not_empty("a table row");
    auto t = read_number_rows(
        cur, columns, "a row of " + std::to_string(columns) + " numbers", "a table value");
    if (t.size() != rows)
        throw DataError(in.at(0), "expected " + std::to_string(rows) + " rows, found " +
                                      std::to_string(t.size()));
    return t;
}

const std::array<double, 12>& CloudModel::level_heights_km() {
    static const std::array<double, 12> z = {0,   0.16, 0.33, 0.66, 1,   1.5,
                                             2.0, 2.4,  2.7,  3.0,  3.5, 4.0};
    return z;
}

std::optional<CloudModel> CloudModel::from_deck(const io::CdkCard2& card2, double ground_km,
                                                const std::string& data_dir,
                                                std::optional<double> asymmetry_g,
                                                const io::CdkUserOptics* user) {
    if (card2.icld == 0 || card2.icld == 18 || card2.icld == 19) return std::nullopt;
    if (!modelled(card2.icld))
        throw DataError(kCard2, "CARD 2 ICLD: " + std::to_string(card2.icld) +
                                    " is not modelled (clouds and rain 1-11 and cirrus 18-19 "
                                    "are; 20 is not)");
    // CARD 2D IREG(2): with a cloud LOWTRAN 7's aerosol region 2 is the cloud, whose
    // coefficients EXABIN then leaves as the deck gave them; without them ICLD 11 takes
    // the cumulus's (EXABIN's cloud table for IC 11).
    const io::CdkUserRegion* u = user && user->regions[1] ? &*user->regions[1] : nullptr;
    const int m = cloud_of(card2.icld) - 1;
    const std::string dir = data_dir + "/atmosphere/lowtran7/";
    CloudModel c;
    for (const auto& row : read_rows(dir + "cloud_models.txt", 22, 47)) {
        const std::size_t i = c.m_wavelength_um.size();
        c.m_wavelength_um.push_back(row[0]);
        // CARD 2D2's coefficients on the same 47 wavelengths (LOWTRAN 7 RDEXA, EXABIN;
        // VX is not used), times LWC / the model's equivalent LWC as they stand (HAZEC).
        c.m_ext.push_back(u ? u->extinction[i] : row[1 + 3 * m]);
        c.m_abs.push_back(u ? u->absorption[i] : row[2 + 3 * m]);
        c.m_g.push_back(asymmetry_g ? *asymmetry_g : u ? u->asymmetry[i] : row[3 + 3 * m]);
    }
    const auto prof = read_rows(dir + "cloud_rain_profiles.txt", 11, 12);
    for (std::size_t i = 0; i < prof.size(); ++i) {
        if (prof[i][0] != double(i))
            throw DataError({dir + "cloud_rain_profiles.txt", 0},
                            "expected the cloud level numbers 0..11 in the z column");
        c.m_z_km.push_back(ground_km + level_heights_km()[i]);
        c.m_lwc.push_back(prof[i][1 + m]);
    }
    c.m_eq_lwc = kEquivalentLwc[m];
    return c;
}

double level_value(const std::vector<double>& z, const std::vector<double>& v, double z_km) {
    if (z_km < z.front() || z_km > z.back()) return 0;
    if (!(z_km < z.back())) return v.back();  // the top level (or NaN)
    const Bracket at = bracket(z, z_km);
    const double f = at.t;
    const double a = v[at.k], b = v[at.k + 1];
    return a > 0 && b > 0 ? a * std::pow(b / a, f) : a + f * (b - a);
}

double level_integral(const std::vector<double>& z, const std::vector<double>& v, double z_lo_km,
                      double z_hi_km) {
    double sum = 0;
    for (std::size_t i = 1; i < z.size(); ++i) {
        const double lo = std::max(z_lo_km, z[i - 1]), hi = std::min(z_hi_km, z[i]);
        if (hi <= lo) continue;
        const double h = z[i] - z[i - 1];
        const double f0 = (lo - z[i - 1]) / h, f1 = (hi - z[i - 1]) / h;
        const double b0 = v[i - 1], b1 = v[i];
        const double k = b0 > 0 && b1 > 0 ? std::log(b1 / b0) : 0.0;
        if (std::abs(k) > 1e-12) {
            sum += b0 * h / k * (std::exp(k * f1) - std::exp(k * f0));  // exponential
        } else {
            const double v0 = b0 + f0 * (b1 - b0), v1 = b0 + f1 * (b1 - b0);
            sum += 0.5 * (v0 + v1) * (hi - lo);  // linear (or constant)
        }
    }
    return sum;
}

std::array<double, 3> table_optics(const std::vector<double>& wl, const std::vector<double>& ext,
                                   const std::vector<double>& abs, const std::vector<double>& g,
                                   double wavelength_um) {
    const Bracket b = bracket(wl, wavelength_um);
    const std::size_t hi = b.k + 1;
    const double f = b.t;
    auto lerp = [&](const std::vector<double>& v) { return v[hi - 1] + f * (v[hi] - v[hi - 1]); };
    return {lerp(ext), lerp(abs), lerp(g)};
}

double CloudModel::lwc_g_m3(double z_km) const { return level_value(m_z_km, m_lwc, z_km); }

std::array<double, 3> CloudModel::optics(double wavelength_um) const {
    return table_optics(m_wavelength_um, m_ext, m_abs, m_g, wavelength_um);
}

double CloudModel::extinction_km1(double z_km, double wavelength_um) const {
    return lwc_g_m3(z_km) / m_eq_lwc * optics(wavelength_um)[0];
}

AerosolLayerOptics CloudModel::layer(double z_lo_km, double z_hi_km, double wavelength_um) const {
    if (!(z_hi_km > z_lo_km)) return {};
    const double column055 = level_integral(m_z_km, m_lwc, z_lo_km, z_hi_km) / m_eq_lwc;
    return column055 > 0 ? slab_optics(column055, optics(wavelength_um)) : AerosolLayerOptics{};
}

AerosolLayerOptics slab_optics(double column055, const std::array<double, 3>& optics) {
    AerosolLayerOptics out;
    const auto [ext, abs, g] = optics;
    out.tau_ext = column055 * ext;
    if (ext > 0) out.ssa = std::clamp(1 - abs / ext, 0.0, 1.0);
    out.g = g;
    return out;
}

AerosolLayerOptics combine(const AerosolLayerOptics& a, const AerosolLayerOptics& b) {
    AerosolLayerOptics out;
    out.tau_ext = a.tau_ext + b.tau_ext;
    const double sa = a.tau_ext * a.ssa, sb = b.tau_ext * b.ssa;
    if (out.tau_ext > 0) out.ssa = std::clamp((sa + sb) / out.tau_ext, 0.0, 1.0);
    if (sa + sb > 0) out.g = (sa * a.g + sb * b.g) / (sa + sb);
    for (std::size_t r = 0; r < out.tau_scat_region.size(); ++r) {  // b (the cloud) has none
        out.tau_scat_region[r] = a.tau_scat_region[r] + b.tau_scat_region[r];
        out.g_region[r] = a.tau_scat_region[r] > 0 ? a.g_region[r] : b.g_region[r];
    }
    return out;
}

}  // namespace sigchain::atmos
