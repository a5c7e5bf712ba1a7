// LOWTRAN 7 rain (see rain.hpp).
//
// The levels and rates follow LOWTRAN 7's subroutines FLAYZ (levels), LAYCLD and AERNSM
// (the rate on each level; Kneizys et al., AFGL-TR-88-0177, 1988, CARD 2 RAINRT: "used
// to top of cloud when cloud is present, when no clouds rain rate used to 6 km"):
//  * a cloud or rain model (ICLD 1-10): the cloud levels, ground + 0, .16, .33, .66, 1,
//    1.5, 2, 2.4, 2.7, 3, 3.5, 4, 4.5, 5, 5.5, 6 km. On each, the model's tabulated rate
//    (RR1..RR5 of cloud_rain_profiles.txt for ICLD 6-10, zero above its 12 rows; none
//    for 1-5); RAINRT > 0 replaces it below 6 km MSL; zero above the cloud top (CLDTOP:
//    3, 3, 1, 2, .66, 1, .66, .66, 3, 3 km above the ground for ICLD 1-10);
//  * otherwise (ICLD 0, 18, 19): the aerosol grid (0, 1, .. 7 km; with GNDALT > 0 six
//    levels evenly from GNDALT below 6 km), the cirrus levels inserted as FLAYZ does;
//    RAINRT on every level up to 6 km MSL;
//  * between levels the extinction (LOWTRAN's density R^0.63 times TNRAIN's constant)
//    is exponential in altitude when both ends are positive, else linear (cloud.hpp's
//    level_integral), so the rain tapers to zero between its top level and the next.
#include "atmos/rain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "atmos/cloud.hpp"
#include "core/error.hpp"

namespace sigchain::atmos {

namespace {

// LOWTRAN 7's cloud levels up to 6 km above the ground (LAYCLD's ZCLD).
constexpr double kCloudLevels_km[16] = {0,   0.16, 0.33, 0.66, 1.0, 1.5, 2.0, 2.4,
                                        2.7, 3.0,  3.5,  4.0,  4.5, 5.0, 5.5, 6.0};
// The cloud top (km above the ground) of ICLD 1-10 (LOWTRAN 7's CLDTOP).
constexpr double kCloudTop_km[10] = {3, 3, 1, 2, 0.66, 1, 0.66, 0.66, 3, 3};
// RAINRT without a water cloud reaches up to this altitude (km MSL).
constexpr double kRainTop_km = 6;

// The aerosol grid below 8 km (FLAYZ's ZAER, squeezed above GNDALT below 6 km), with
// the cirrus levels [cld0, cld3] replacing the grid's levels between them.
std::vector<double> aerosol_grid(double ground_km, const std::vector<double>& cirrus_km) {
    std::vector<double> z;
    for (int i = 0; i <= 8; ++i) z.push_back(i);
    if (ground_km > 0)
        for (int i = 0; i < 6; ++i) z[std::size_t(i)] = ground_km + i * (6 - ground_km) / 6;
    if (cirrus_km.size() == 4) {
        std::erase_if(z, [&](double h) { return h >= cirrus_km[0] && h < cirrus_km[3]; });
        z.insert(z.end(), cirrus_km.begin(), cirrus_km.end());
        std::sort(z.begin(), z.end());
    }
    return z;
}

// Drops the levels above the first zero rate after the last positive one.
void trim(std::vector<double>& z, std::vector<double>& rate) {
    std::size_t last = 0;
    for (std::size_t i = 0; i < rate.size(); ++i)
        if (rate[i] > 0) last = i;
    const std::size_t keep = std::min(rate.size(), last + 2);
    z.resize(keep);
    rate.resize(keep);
}

}  // namespace

double marshall_palmer_slope_mm1(double rain_rate_mm_h) {
    return 4.1 * std::pow(rain_rate_mm_h, -0.21);  // Marshall & Palmer (1948)
}

double rain_extinction_km1(double rain_rate_mm_h) {
    if (!(rain_rate_mm_h > 0)) return 0;
    const double lambda = marshall_palmer_slope_mm1(rain_rate_mm_h);
    // pi N0 / Lambda^3 in mm2 m-3; 1 mm2 m-3 = 1e-6 m-1 = 1e-3 km-1.
    return std::numbers::pi * kMarshallPalmerN0_m3_mm1 / (lambda * lambda * lambda) * 1e-3;
}

std::optional<RainModel> RainModel::from_deck(const io::CdkCard2& card2, double ground_km,
                                              const std::string& data_dir,
                                              const std::vector<double>& cirrus_km) {
    const bool rain_model = card2.icld >= 6 && card2.icld <= 10;
    const double rainrt = card2.rain_rate_mm_h;
    if (!rain_model && !(rainrt > 0)) return std::nullopt;
    RainModel r;
    if (card2.icld >= 1 && card2.icld <= 10) {
        std::vector<double> table(16, 0.0);
        if (rain_model) {
            const auto prof =
                read_rows(data_dir + "/atmosphere/lowtran7/cloud_rain_profiles.txt", 11, 12);
            for (std::size_t i = 0; i < prof.size(); ++i)
                table[i] = prof[i][std::size_t(card2.icld)];  // RR1..RR5: columns 6-10
        }
        for (std::size_t i = 0; i < 16; ++i) {
            const double h = kCloudLevels_km[i], z = ground_km + h;
            double rate = table[i];
            if (rainrt > 0 && z < kRainTop_km) rate = rainrt;
            if (h > kCloudTop_km[card2.icld - 1]) rate = 0;
            r.m_z_km.push_back(z);
            r.m_rate.push_back(rate);
        }
    } else {
        for (double z : aerosol_grid(ground_km, cirrus_km)) {
            r.m_z_km.push_back(z);
            r.m_rate.push_back(z <= kRainTop_km ? rainrt : 0.0);
        }
    }
    trim(r.m_z_km, r.m_rate);
    for (double rate : r.m_rate) r.m_ext_km1.push_back(rain_extinction_km1(rate));
    return r;
}

double RainModel::extinction_km1(double z_km) const { return level_value(m_z_km, m_ext_km1, z_km); }

AerosolLayerOptics RainModel::layer(double z_lo_km, double z_hi_km) const {
    AerosolLayerOptics out;
    if (!(z_hi_km > z_lo_km)) return out;
    out.tau_ext = level_integral(m_z_km, m_ext_km1, z_lo_km, z_hi_km);
    if (out.tau_ext <= 0) return {};
    out.ssa = kSingleScatteringAlbedo;
    out.g = kAsymmetry;
    return out;
}

}  // namespace sigchain::atmos
