// LOWTRAN 7 aerosol models: 0.55-um extinction profiles by region and spectral optics.
//
// Follows the rules stated in data/atmosphere/lowtran7/aerosol_vertical_profiles.txt
// and aerosol_*.txt (LOWTRAN 7 subroutines AERPRF, AERNSM, EXABIN, AEREXT, DESATT):
//  * four regions (boundary layer z' <= 2 km, troposphere <= 10, stratosphere <= 30,
//    upper atmosphere above), each with its own 0.55-um profile on the table's levels
//    (0-25 km every km, 30, 35, 40, 45, 50, 70, 100 km) and its own optical type;
//  * between two levels a region's extinction is exponential in altitude when both
//    ends are positive, else linear (so a region falls linearly to zero across its
//    boundary); the slab integral is the exact integral of that piecewise function,
//    which is what LOWTRAN's layer integration gives on those levels;
//  * elevated ground: below 6 km the table is read at z' = 6 (z - GNDALT)/(6 - GNDALT);
//  * boundary-layer optics at one effective RH (aerosol-weighted mean of ln(100 - RH)
//    over the boundary layer of the profile), ln-ln interpolated in (100 - RH); the
//    troposphere at RH 70 %; all optics linear in wavelength.
#include "atmos/aerosol.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

using Table = std::vector<std::vector<double>>;

const SourceLocation kCard2{"card deck", 0};
constexpr double kRayleighKoschmieder_km1 = 0.01159;  // LOWTRAN's visibility convention
constexpr double kKoschmieder = 3.912;                // -ln(0.02)
constexpr double kGroundScale_km = 6.0;               // GNDALT compression height
constexpr std::size_t k055 = 3;                       // row of 0.55 um in every table

Table read_table(const std::string& path, std::size_t columns, std::size_t rows) {
    const TextInput in = TextInput::from_file(path);
    FieldReader cur(in);
    cur.require_not_empty("a table row");
    Table t = read_number_rows(
        cur, columns, "a row of " + std::to_string(columns) + " numbers", "a table value");
    if (rows && t.size() != rows)
        throw DataError(in.at(0), "expected " + std::to_string(rows) + " rows, found " +
                                      std::to_string(t.size()));
    return t;
}

std::string table_path(const std::string& data_dir, const std::string& name) {
    return data_dir + "/atmosphere/lowtran7/" + name;
}

// Interpolates between two values in x: of ln(value) when both are positive.
double log_or_linear(double a, double b, double f) {
    if (a > 0 && b > 0) return a * std::pow(b / a, f);
    return a + f * (b - a);
}

// ext/abs/g of a humidity-dependent model (columns: lambda, ext x4, abs x4, g x4 at
// RH 0, 70, 80, 99 %) at one RH: ln(value) linear in x = ln(100 - RH) (EXABIN).
std::array<std::vector<double>, 3> humid_optics(const Table& t, double rh) {
    const double x_nodes[4] = {std::log(100.0), std::log(30.0), std::log(20.0), 0.0};
    const double x = std::log(100.0 - std::clamp(rh, 0.0, 99.0));
    int k = 0;
    while (k < 2 && x < x_nodes[k + 1]) ++k;
    const double f = (x - x_nodes[k]) / (x_nodes[k + 1] - x_nodes[k]);
    std::array<std::vector<double>, 3> out;
    for (const auto& row : t)
        for (int q = 0; q < 3; ++q)
            out[q].push_back(log_or_linear(row[1 + 4 * q + k], row[2 + 4 * q + k], f));
    return out;
}

// ext/abs/g from three columns starting at `col` (fog and stratospheric tables).
std::array<std::vector<double>, 3> fixed_optics(const Table& t, int col) {
    std::array<std::vector<double>, 3> out;
    for (const auto& row : t)
        for (int q = 0; q < 3; ++q) out[q].push_back(row[col + q]);
    return out;
}

// Desert model at wind speed ws (m/s): ln(ext), ln(abs) and g linear in ws between the
// 0/10/20/30 m/s columns (extrapolated above 30), normalised by ext(0.55) (DESATT).
// Returns the optics and the absolute ext(0.55) in km-1.
std::pair<std::array<std::vector<double>, 3>, double> desert_optics(const Table& t, double ws) {
    const int k = std::clamp(int(ws / 10.0), 0, 2);
    const double f = (ws - 10.0 * k) / 10.0;
    std::array<std::vector<double>, 3> out;
    for (const auto& row : t) {
        out[0].push_back(log_or_linear(row[1 + k], row[2 + k], f));
        out[1].push_back(log_or_linear(row[5 + k], row[6 + k], f));
        out[2].push_back(row[9 + k] + f * (row[10 + k] - row[9 + k]));
    }
    const double e055 = out[0][k055];
    for (int q = 0; q < 2; ++q)
        for (double& v : out[q]) v /= e055;
    return {out, e055};
}

// Navy maritime model (IHAZE 3; Gathman 1983, Opt. Eng. 22, 57; LOWTRAN 7's MARINE, as
// data/atmosphere/lowtran7/aerosol_navy_maritime_modes.txt states it): three lognormal
// modes with amplitudes A1 = 2000 ICSTL^2 (air-mass character; outside 1-10 LOWTRAN's
// default 3), A2 = max(5.866 (WHH - 2.2), 0.5), A3 = 10^(0.06 WSS - 2.8) (winds in m/s,
// at most 20; WHH 0: the model atmosphere's default, WSS 0: WHH); each mode's log10
// Q-integral linear in RH between 50, 85, 95 and 98 % (RH clamped there); ext(0.55 um)
// = pi/1000 sum A_i 10^T_i / F km-1 with the growth factor
// F = ((2 - RH/100) / (6 (1 - RH/100)))^(1/3), the spectrum normalised at 0.55 um. The
// 40 wavelengths are the first 40 of the other tables' 47; beyond 40 um the 40-um values
// hold. The tables give no asymmetry parameter: LOWTRAN 7 scatters IHAZE 3 with the
// maritime model's phase functions (PHASEF: IHAZE 3 and 4 use models 5-8,
// aerosol_phase_function_index.txt), whose first moment is the maritime model's
// tabulated g, so g is the maritime table's at the same RH. Returns the optics on the
// 47 wavelengths and the absolute ext(0.55) in km-1.
std::pair<std::array<std::vector<double>, 3>, double> navy_optics(const Table& modes,
                                                                  const Table& maritime,
                                                                  const io::CdkCard2& c, int model,
                                                                  double rh) {
    // Default 24-hour winds by MODEL 0-7 (MARINE).
    const double wind[8] = {6.9, 4.1, 4.1, 10.29, 6.69, 12.35, 7.2, 6.9};
    const double wh = std::min(
        c.wind_speed_24h_m_s > 0 ? c.wind_speed_24h_m_s : wind[std::clamp(model, 0, 7)], 20.0);
    const double ws = c.wind_speed_m_s > 0 ? std::min(c.wind_speed_m_s, 20.0) : wh;
    const double icstl = c.icstl >= 1 && c.icstl <= 10 ? c.icstl : 3;
    const double amp[3] = {2000 * icstl * icstl, std::max(5.866 * (wh - 2.2), 0.5),
                           std::pow(10.0, 0.06 * ws - 2.8)};
    const double arel[4] = {50, 85, 95, 98};
    const double r = std::clamp(rh, 50.0, 98.0);
    int k = 0;
    while (k < 2 && r > arel[k + 1]) ++k;
    const double f = (r - arel[k]) / (arel[k + 1] - arel[k]);
    std::array<std::vector<double>, 3> out;
    for (const auto& row : modes) {
        double ext = 0, abs = 0;
        for (int m = 0; m < 3; ++m) {
            const int e = 1 + 4 * m + k, a = 13 + 4 * m + k;
            ext += amp[m] * std::pow(10.0, row[e] + f * (row[e + 1] - row[e]));
            abs += amp[m] * std::pow(10.0, row[a] + f * (row[a + 1] - row[a]));
        }
        out[0].push_back(ext);
        out[1].push_back(abs);
    }
    const double total055 = out[0][k055];
    for (int q = 0; q < 2; ++q) {
        for (double& v : out[q]) v /= total055;
        while (out[q].size() < maritime.size()) out[q].push_back(out[q].back());
    }
    out[2] = humid_optics(maritime, rh)[2];
    const double growth = std::cbrt((2 - r / 100) / (6 * (1 - r / 100)));
    return {out, std::numbers::pi / 1000 * total055 / growth};
}

// Boundary-layer 0.55-um extinction for VIS, linear in 1/VIS between the bracketing
// tabulated visibilities 50, 23, 10, 5, 2 km (extrapolated outside; AERPRF).
double boundary_layer_beta(const std::vector<double>& row, double vis_km) {
    const double v[5] = {50, 23, 10, 5, 2};
    int j = 1;
    while (j < 4 && vis_km < v[j]) ++j;
    const double a = row[j], b = row[1 + j];  // columns of v[j-1], v[j]
    const double f = (1 / vis_km - 1 / v[j - 1]) / (1 / v[j] - 1 / v[j - 1]);
    return std::max(0.0, a + f * (b - a));
}

// Free-troposphere extinction (AERPRF): VIS <= 23 km the 23-km profile; above, below
// 4 km linear in 1/VIS between the 23- and 50-km profiles, above 4 km the 50-km one.
double troposphere_beta(const std::vector<double>& row, bool fall_winter, double vis_km) {
    const double b50 = row[fall_winter ? 6 : 8], b23 = row[fall_winter ? 7 : 9];
    if (vis_km <= 23) return b23;
    if (row[0] > 4) return b50;
    const double f = (1 / vis_km - 1 / 23.0) / (1 / 50.0 - 1 / 23.0);
    return std::max(0.0, b23 + f * (b50 - b23));
}

// Stratospheric profile column and optical-type column (in aerosol_stratospheric.txt)
// for IVULCN 0-8 (aerosol_stratospheric.txt header).
int strat_profile_column(int ivulcn, bool fall_winter) {
    // 0 background, 1 moderate, 2 high, 3 extreme volcanic profile
    const int profile[9] = {0, 0, 1, 2, 2, 1, 1, 2, 3};
    return (fall_winter ? 10 : 14) + profile[ivulcn];
}
int strat_optics_column(int ivulcn) {
    // 1 background stratospheric, 4 aged volcanic, 7 fresh volcanic
    const int type[9] = {1, 1, 4, 7, 4, 7, 1, 1, 7};
    return type[ivulcn];
}

[[noreturn]] void reject(const std::string& field, const std::string& why) {
    throw DataError(kCard2, "CARD 2 " + field + ": " + why);
}

void check_card2(const io::CdkCard2& c) {
    if (c.ihaze < 0 || c.ihaze > 10) reject("IHAZE", "expected 0-10");
    if (c.iseasn < 0 || c.iseasn > 2) reject("ISEASN", "expected 0-2");
    if (c.ivulcn < 0 || c.ivulcn > 8) reject("IVULCN", "expected 0-8");
    if (c.icld != 0) reject("ICLD", "clouds and rain are not modelled (use ICLD 0)");
    if (c.ivsa != 0) reject("IVSA", "the army vertical structure algorithm is not supported");
    if (c.visibility_km < 0) reject("VIS", "a negative VIS (optical depth) is not supported");
    if (c.ground_altitude_km < 0 || c.ground_altitude_km >= kGroundScale_km)
        reject("GNDALT", "expected 0 <= GNDALT < 6 km");
}

// The model's default visibility (km) for VIS 0 (BLOCK DATA TITLE, VSB).
double default_visibility(int ihaze) {
    switch (ihaze) {
        case 1:
            return 23;
        case 2:
            return 5;
        case 4:
            return 23;
        case 5:
            return 5;
        case 6:
            return 50;
        case 8:
            return 0.2;
        case 9:
            return 0.5;
        default:
            return 23;
    }
}

// Relative humidity (percent) of the profile at z, linear in altitude, clamped.
double profile_rh(const Profile& p, double z) {
    if (p.size() == 0) return 70;
    return interpolate_clamped(p.z_km, p.rh_percent, z);
}

// The deck's visibility (km), its model's default for VIS 0; for the desert model
// (IHAZE 10) and the Navy maritime model (IHAZE 3, at the ground's RH and the profile's
// model for its default winds) also their wind-dependent boundary-layer optics
// (`own_bl`), whose 0.55-um extinction sets the visibility when VIS is 0.
double deck_visibility(const io::CdkCard2& card2, const Profile& profile,
                       const std::string& data_dir, std::array<std::vector<double>, 3>& own_bl) {
    double vis = card2.visibility_km;
    double e055 = 0;
    if (card2.ihaze == 10) {
        const Table desert = read_table(table_path(data_dir, "aerosol_desert.txt"), 13, 47);
        std::tie(own_bl, e055) = desert_optics(desert, card2.wind_speed_m_s);
    } else if (card2.ihaze == 3) {
        const Table modes =
            read_table(table_path(data_dir, "aerosol_navy_maritime_modes.txt"), 25, 40);
        const Table maritime = read_table(table_path(data_dir, "aerosol_maritime.txt"), 13, 47);
        // The ground's RH; without one MARINE's default for the model atmosphere.
        const double rh_default[8] = {80, 75.63, 76.2, 77.13, 75.24, 80.53, 45.89, 80};
        const double rh = profile.size() && profile.rh_percent.front() > 0
                              ? profile.rh_percent.front()
                              : rh_default[std::clamp(profile.model, 0, 7)];
        std::tie(own_bl, e055) = navy_optics(modes, maritime, card2, profile.model, rh);
    }
    if (vis == 0 && e055 > 0) vis = kKoschmieder / (e055 + kRayleighKoschmieder_km1);
    if (vis == 0) vis = default_visibility(card2.ihaze);
    return vis;
}

// The regions' 0.55-um extinction (km-1) on the profile table's levels, the levels
// moved up for elevated ground (AERPRF).
struct RegionProfiles {
    std::vector<double> z_km;
    std::array<std::vector<double>, AerosolModel::kRegions> beta055_km1;
};

RegionProfiles region_profiles(const io::CdkCard2& card2, bool fall_winter, double vis_km,
                               const std::string& data_dir) {
    RegionProfiles out;
    const Table prof = read_table(table_path(data_dir, "aerosol_vertical_profiles.txt"), 22, 34);
    const double g_km = card2.ground_altitude_km;
    for (const auto& row : prof) {
        const double zt = row[0];
        if (zt > 1000) continue;  // the 99999 sentinel
        out.z_km.push_back(
            zt < kGroundScale_km ? g_km + zt * (kGroundScale_km - g_km) / kGroundScale_km : zt);
        const double bl = zt <= 2 ? boundary_layer_beta(row, vis_km) : 0;
        const double trop = zt > 2 && zt <= 10 ? troposphere_beta(row, fall_winter, vis_km) : 0;
        const double strat =
            zt > 10 && zt <= 30 ? row[strat_profile_column(card2.ivulcn, fall_winter)] : 0;
        const double upper = zt > 30 ? row[card2.ivulcn <= 1 ? 18 : 19] : 0;
        out.beta055_km1[0].push_back(bl);
        out.beta055_km1[1].push_back(trop);
        out.beta055_km1[2].push_back(strat);
        out.beta055_km1[3].push_back(upper);
    }
    return out;
}

// The boundary layer's optics for the deck's IHAZE at effective humidity rh_eff.
std::array<std::vector<double>, 3> boundary_layer_optics(
    const io::CdkCard2& card2, const Table& rural, const Table& trop_table,
    const std::array<std::vector<double>, 3>& own_bl, double rh_eff, const std::string& data_dir) {
    switch (card2.ihaze) {
        case 1:
        case 2:
            return humid_optics(rural, rh_eff);
        case 4:
            return humid_optics(read_table(table_path(data_dir, "aerosol_maritime.txt"), 13, 47),
                                rh_eff);
        case 5:
            return humid_optics(read_table(table_path(data_dir, "aerosol_urban.txt"), 13, 47),
                                rh_eff);
        case 6:
            return humid_optics(trop_table, rh_eff);
        case 7:  // CARD 2D with IREG(1) 0: LOWTRAN's EXABIN leaves the coefficients 0
            return {std::vector<double>(47, 0), std::vector<double>(47, 0),
                    std::vector<double>(47, 0)};
        case 8:
        case 9:
            return fixed_optics(read_table(table_path(data_dir, "aerosol_fog.txt"), 7, 47),
                                card2.ihaze == 8 ? 1 : 4);
        default:  // 3 Navy maritime and 10 desert; check_card2 admits no other value here
            return own_bl;
    }
}

}  // namespace

AerosolModel AerosolModel::from_deck(const io::CdkCard2& card2, const Profile& profile,
                                     const std::string& data_dir, std::optional<double> asymmetry_g,
                                     const io::CdkUserOptics* user) {
    check_card2(card2);
    if (card2.ihaze == 7 && !user) reject("IHAZE", "7 (user-defined aerosol) needs CARD 2D");
    AerosolModel m;
    const Table rural = read_table(table_path(data_dir, "aerosol_rural.txt"), 13, 47);
    for (const auto& row : rural) m.m_wavelength_um.push_back(row[0]);
    if (card2.ihaze == 0) {  // no aerosol at all: the Koschmieder range of clean air
        m.m_vis_km = kKoschmieder / kRayleighKoschmieder_km1;
        m.m_z_km = {0, 100};
        for (int r = 0; r < kRegions; ++r) {
            m.m_beta055_km1[r] = {0, 0};
            m.m_optics[r] = {std::vector<double>(47, 1), std::vector<double>(47, 0),
                             std::vector<double>(47, 0)};
        }
        return m;
    }
    std::array<std::vector<double>, 3> own_bl;
    m.m_vis_km = deck_visibility(card2, profile, data_dir, own_bl);

    const bool fall_winter =
        card2.iseasn == 2 || (card2.iseasn == 0 && (profile.model == 3 || profile.model == 5));
    RegionProfiles regions = region_profiles(card2, fall_winter, m.m_vis_km, data_dir);
    m.m_z_km = std::move(regions.z_km);
    m.m_beta055_km1 = std::move(regions.beta055_km1);
    m.m_rh_eff = m.effective_rh(profile);

    auto optics = [](const std::array<std::vector<double>, 3>& o) {
        return Optics{o[0], o[1], o[2]};
    };
    const Table trop_table = read_table(table_path(data_dir, "aerosol_tropospheric.txt"), 13, 47);
    m.m_optics[0] =
        optics(boundary_layer_optics(card2, rural, trop_table, own_bl, m.m_rh_eff, data_dir));
    m.m_optics[1] = optics(humid_optics(trop_table, 70.0));
    const Table strat = read_table(table_path(data_dir, "aerosol_stratospheric.txt"), 13, 47);
    m.m_optics[2] = optics(fixed_optics(strat, strat_optics_column(card2.ivulcn)));
    m.m_optics[3] = optics(fixed_optics(strat, 10));  // meteoric dust
    // CARD 2D: a region with IREG 1 takes the deck's coefficients on the tables' own 47
    // wavelengths, times the region's 0.55-um profile as they stand (LOWTRAN 7 EXABIN,
    // RDEXA, AEREXT: no renormalisation, VX unused).
    if (user)
        for (std::size_t r = 0; r < kRegions; ++r)
            if (const auto& u = user->regions[r]) {
                m.m_optics[r].ext.assign(u->extinction.begin(), u->extinction.end());
                m.m_optics[r].abs.assign(u->absorption.begin(), u->absorption.end());
                m.m_optics[r].g.assign(u->asymmetry.begin(), u->asymmetry.end());
            }
    if (asymmetry_g)  // IPH 0: Henyey-Greenstein with the deck's G for every aerosol
        for (Optics& o : m.m_optics) std::fill(o.g.begin(), o.g.end(), *asymmetry_g);
    return m;
}

// Effective boundary-layer RH: exp of the aerosol-weighted mean of ln(100 - RH)
// (RH capped at 99 %), trapezoid with 400 steps over the boundary layer's extent.
double AerosolModel::effective_rh(const Profile& profile) const {
    const double z0 = m_z_km.front();
    const double z1 = m_z_km[3];  // table level 3 km, where the boundary layer reaches 0
    double sw = 0, swx = 0;
    constexpr int kSteps = 400;
    for (int i = 0; i <= kSteps; ++i) {
        const double z = z0 + (z1 - z0) * i / kSteps;
        const double w = region_extinction055(0, z) * (i == 0 || i == kSteps ? 0.5 : 1.0);
        sw += w;
        swx += w * std::log(100.0 - std::min(profile_rh(profile, z), 99.0));
    }
    return sw > 0 ? 100.0 - std::exp(swx / sw) : profile_rh(profile, z0);
}

double AerosolModel::region_extinction055(int region, double z_km) const {
    const auto& b = m_beta055_km1[region];
    if (z_km <= m_z_km.front()) return b.front();
    if (z_km >= m_z_km.back()) return z_km == m_z_km.back() ? b.back() : 0.0;
    const Bracket at = bracket(m_z_km, z_km);
    return log_or_linear(b[at.k], b[at.k + 1], at.t);
}

// Exact integral (km-1 x km) of one region's 0.55-um extinction over [z_lo, z_hi].
double AerosolModel::region_column055(int region, double z_lo_km, double z_hi_km) const {
    const auto& b = m_beta055_km1[region];
    const auto& z = m_z_km;
    double sum = 0;
    if (z_lo_km < z.front()) sum += b.front() * (std::min(z_hi_km, z.front()) - z_lo_km);
    for (std::size_t i = 1; i < z.size(); ++i) {
        const double lo = std::max(z_lo_km, z[i - 1]), hi = std::min(z_hi_km, z[i]);
        if (hi <= lo) continue;
        const double h = z[i] - z[i - 1];
        const double f0 = (lo - z[i - 1]) / h, f1 = (hi - z[i - 1]) / h;
        const double b0 = b[i - 1], b1 = b[i];
        const double k = b0 > 0 && b1 > 0 ? std::log(b1 / b0) : 0.0;
        if (b0 > 0 && b1 > 0 && std::abs(k) > 1e-12) {
            sum += b0 * h / k * (std::exp(k * f1) - std::exp(k * f0));  // exponential
        } else {
            const double v0 = b0 + f0 * (b1 - b0), v1 = b0 + f1 * (b1 - b0);
            sum += 0.5 * (v0 + v1) * (hi - lo);  // linear (or constant)
        }
    }
    return sum;  // above the top level (100 km) there is no aerosol
}

// {ext, abs, g} of a region at a wavelength: linear in wavelength (AEREXT), clamped
// to the tables' 0.2-300 um.
std::array<double, 3> AerosolModel::region_optics(int region, double wavelength_um) const {
    const auto& w = m_wavelength_um;
    const Optics& o = m_optics[region];
    const Bracket b = bracket(w, wavelength_um);
    const std::size_t hi = b.k + 1;
    const double f = b.t;
    auto lerp = [&](const std::vector<double>& v) { return v[hi - 1] + f * (v[hi] - v[hi - 1]); };
    return {lerp(o.ext), lerp(o.abs), lerp(o.g)};
}

double AerosolModel::extinction_km1(double z_km, double wavelength_um) const {
    double sum = 0;
    for (int r = 0; r < kRegions; ++r) {
        const double b = region_extinction055(r, z_km);
        if (b > 0) sum += b * region_optics(r, wavelength_um)[0];
    }
    return sum;
}

std::array<double, 4> AerosolModel::slab_columns055(double z_lo_km, double z_hi_km) const {
    std::array<double, 4> out{};
    if (!(z_hi_km > z_lo_km)) return out;
    for (int r = 0; r < kRegions; ++r) out[r] = region_column055(r, z_lo_km, z_hi_km);
    return out;
}

AerosolLayerOptics AerosolModel::layer(double z_lo_km, double z_hi_km, double wavelength_um) const {
    return layer(slab_columns055(z_lo_km, z_hi_km), wavelength_um);
}

AerosolLayerOptics AerosolModel::layer(const std::array<double, 4>& columns055,
                                       double wavelength_um) const {
    AerosolLayerOptics out;
    double scat = 0, scat_g = 0;
    for (int r = 0; r < kRegions; ++r) {
        const double column = columns055[r];
        if (column <= 0) continue;
        const auto [ext, abs, g] = region_optics(r, wavelength_um);
        out.tau_ext += column * ext;
        scat += column * std::max(0.0, ext - abs);
        scat_g += column * std::max(0.0, ext - abs) * g;
        out.tau_scat_region[r] = column * std::max(0.0, ext - abs);
        out.g_region[r] = g;
    }
    if (out.tau_ext > 0) out.ssa = std::clamp(scat / out.tau_ext, 0.0, 1.0);
    if (scat > 0) out.g = scat_g / scat;
    return out;
}

double AerosolModel::visibility_km() const { return m_vis_km; }

}  // namespace sigchain::atmos
