// Atmospheric profiles: the AFGL model atmospheres and LOWTRAN 7 radiosonde decks.
#include "atmos/profile.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kBoltzmann_J_K = 1.380649e-23;       // CODATA 2018 (exact)
constexpr double kAvogadro_mol = 6.02214076e23;       // CODATA 2018 (exact)
constexpr double kGasConstant_J_mol_K = 8.314462618;  // CODATA 2018
constexpr double kMolarMassAir_g_mol = 28.964;        // dry air, US Standard Atmosphere 1976
constexpr double kAtm_mb = 1013.25;
constexpr double kZeroCelsius_K = 273.15;
constexpr int kUsStandard = 6;
// Molar masses (g/mol) of H2O, CO2 and O3, for the deck's mass units.
constexpr double kMolarMassH2O_g_mol = 18.015;
constexpr double kMolarMassCO2_g_mol = 44.010;
constexpr double kMolarMassO3_g_mol = 47.998;

const SourceLocation kDeck{"card deck", 0};

double air_number_density_m3(double p_mb, double t_k) {
    return p_mb * 100.0 / (kBoltzmann_J_K * t_k);
}

// Gas density g m-3 <-> volume mixing ratio ppmv in air at (p, T).
double ppmv_to_g_m3(double ppmv, double molar_mass, double p_mb, double t_k) {
    return ppmv * 1e-6 * air_number_density_m3(p_mb, t_k) * molar_mass / kAvogadro_mol;
}
double g_m3_to_ppmv(double rho, double molar_mass, double p_mb, double t_k) {
    return rho / molar_mass * kAvogadro_mol / air_number_density_m3(p_mb, t_k) * 1e6;
}

double relative_humidity(double h2o_g_m3, double t_k) {
    return std::clamp(100.0 * h2o_g_m3 / saturation_vapour_density_g_m3(t_k), 0.0, 100.0);
}

// Fills h2o_g_m3 and rh_percent from the H2O mixing ratio, p and T.
void derive_water(Profile& p) {
    const std::size_t n = p.size();
    p.h2o_g_m3.resize(n);
    p.rh_percent.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double ppmv = p.vmr_ppmv[int(Gas::H2O)][i];
        p.h2o_g_m3[i] = ppmv_to_g_m3(ppmv, kMolarMassH2O_g_mol, p.p_mb[i], p.t_k[i]);
        p.rh_percent[i] = relative_humidity(p.h2o_g_m3[i], p.t_k[i]);
    }
}

std::string find_model_file(int model, const std::string& data_dir) {
    const std::filesystem::path dir = std::filesystem::path(data_dir) / "atmosphere";
    const std::string prefix = "afgl_atmosphere_" + std::to_string(model) + "_";
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) == 0 && name.ends_with(".txt")) return entry.path().string();
    }
    throw IoError("no AFGL model atmosphere " + std::to_string(model) + " (" + prefix +
                  "*.txt) in " + dir.string());
}

// Rows of numbers of a '#'-commented table, each with exactly `columns` fields.
std::vector<std::vector<double>> read_rows(const TextInput& in, std::size_t columns,
                                           std::string_view what) {
    FieldReader cur(in);
    cur.require_not_empty(what);
    return read_number_rows(cur, columns, what, what);
}

void read_trace_gases(Profile& p, const std::string& data_dir) {
    const std::string path = data_dir + "/atmosphere/lowtran7/trace_gas_profiles.txt";
    const TextInput in = TextInput::from_file(path);
    const auto rows = read_rows(in, 6, "a trace-gas row (z NO SO2 NO2 NH3 HNO3)");
    if (rows.size() != p.size())
        throw DataError(in.at(0), "expected " + std::to_string(p.size()) +
                                      " levels (the AFGL grid), found " +
                                      std::to_string(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (std::abs(rows[i][0] - p.z_km[i]) > 1e-6)
            throw DataError(in.at(0), "level " + std::to_string(i + 1) + " at " +
                                          format_number(rows[i][0]) +
                                          " km is not on the AFGL grid");
        for (int k = 0; k < 5; ++k) p.vmr_ppmv[int(Gas::NO) + k].push_back(rows[i][1 + k]);
    }
}

// Linear interpolation in z of a level quantity (clamped at the ends); `logarithmic`
// interpolates ln(value) (pressure, densities) when both ends are positive.
double interpolate(const std::vector<double>& z, const std::vector<double>& v, double at,
                   bool logarithmic) {
    if (at <= z.front()) return v.front();
    if (at >= z.back()) return v.back();
    const Bracket b = bracket(z, at);
    const std::size_t lo = b.k, hi = lo + 1;
    const double f = b.t;
    if (logarithmic && v[lo] > 0 && v[hi] > 0) return v[lo] * std::pow(v[hi] / v[lo], f);
    return v[lo] + f * (v[hi] - v[lo]);
}

// A model's value at an altitude: pressure (ln P), temperature (linear), gas ppmv (linear).
struct ModelSet {
    std::array<Profile, 7> models;  // index 1..6, loaded on demand
    std::string data_dir;
    const Profile& get(int m) {
        if (models[m].size() == 0) models[m] = afgl_profile(m, data_dir);
        return models[m];
    }
};

double model_p(const Profile& m, double z) { return interpolate(m.z_km, m.p_mb, z, true); }
double model_t(const Profile& m, double z) { return interpolate(m.z_km, m.t_k, z, false); }
double model_ppmv(const Profile& m, Gas g, double z) {
    return interpolate(m.z_km, m.vmr_ppmv[int(g)], z, false);
}

// Which model digit (1-6) a JCHAR character names, or 0.
int model_digit(char c) { return c >= '1' && c <= '6' ? c - '0' : 0; }

[[noreturn]] void bad_jchar(std::size_t layer, int index, char c, std::string_view field) {
    throw DataError(kDeck, "CARD 2C1 layer " + std::to_string(layer + 1) + " JCHAR(" +
                               std::to_string(index + 1) + ") (column " +
                               std::to_string(61 + index) + ", " + std::string(field) +
                               "): unit letter '" + std::string(1, c) + "' is not supported");
}

char jchar_at(const io::CdkLayer& l, int index) {
    return index < int(l.jchar.size()) ? char(std::toupper(l.jchar[index])) : ' ';
}

double layer_pressure_mb(const io::CdkLayer& l, std::size_t i, ModelSet& ms) {
    const char c = jchar_at(l, 0);
    if (c == ' ' || c == 'A') return l.pressure;
    if (c == 'B') return l.pressure * kAtm_mb;
    if (c == 'C') return l.pressure * kAtm_mb / 760.0;
    if (const int m = model_digit(c)) return model_p(ms.get(m), l.altitude_km);
    bad_jchar(i, 0, c, "pressure");
}

double layer_temperature_k(const io::CdkLayer& l, std::size_t i, ModelSet& ms) {
    const char c = jchar_at(l, 1);
    if (c == ' ' || c == 'A') return l.temperature;
    if (c == 'B') return l.temperature + kZeroCelsius_K;
    if (const int m = model_digit(c)) return model_t(ms.get(m), l.altitude_km);
    bad_jchar(i, 1, c, "temperature");
}

// H2O (JCHAR(3)) as ppmv at the layer's p and T; `fallback` is the model for blank.
double layer_h2o_ppmv(const io::CdkLayer& l, std::size_t i, double p, double t, ModelSet& ms,
                      int fallback) {
    const char c = jchar_at(l, 2);
    const double v = l.wmol[0];
    const double mw = kMolarMassH2O_g_mol;
    switch (c) {
        case 'A':
            return v;
        case 'B':
            return v * 1e6 / air_number_density_m3(p, t) * 1e6;  // cm-3 -> ppmv
        case 'C':
            return v * 1e3 * kMolarMassAir_g_mol / mw;  // g/kg -> ppmv
        case 'D':
            return g_m3_to_ppmv(v, mw, p, t);
        case 'E':  // partial pressure (mb): rho = e M / (R T)
            return g_m3_to_ppmv(v * 100.0 * mw / (kGasConstant_J_mol_K * t), mw, p, t);
        case 'F':
        case 'G': {  // dew point: e = e_s(Td), so rho = rho_s(Td) Td / T (ideal gas)
            const double td = c == 'F' ? v : v + kZeroCelsius_K;
            return g_m3_to_ppmv(saturation_vapour_density_g_m3(td) * td / t, mw, p, t);
        }
        case 'H':
            return g_m3_to_ppmv(v / 100.0 * saturation_vapour_density_g_m3(t), mw, p, t);
        case ' ':
            return model_ppmv(ms.get(fallback), Gas::H2O, l.altitude_km);
        default:
            if (const int m = model_digit(c)) return model_ppmv(ms.get(m), Gas::H2O, l.altitude_km);
            bad_jchar(i, 2, c, "H2O");
    }
}

// CO2 or O3 (JCHAR(4), JCHAR(5)) as ppmv.
double layer_gas_ppmv(const io::CdkLayer& l, std::size_t i, int index, Gas gas, double mw, double p,
                      double t, ModelSet& ms, int fallback) {
    const char c = jchar_at(l, index);
    const double v = l.wmol[index - 2];
    switch (c) {
        case 'A':
            return v;
        case 'B':
            return v * 1e6 / air_number_density_m3(p, t) * 1e6;
        case 'C':
            return v * 1e3 * kMolarMassAir_g_mol / mw;
        case 'D':
            return g_m3_to_ppmv(v, mw, p, t);
        case ' ':
            return model_ppmv(ms.get(fallback), gas, l.altitude_km);
        default:
            if (const int m = model_digit(c)) return model_ppmv(ms.get(m), gas, l.altitude_km);
            bad_jchar(i, index, c, gas == Gas::CO2 ? "CO2" : "O3");
    }
}

// The model for one component: M_k when given (1-6), else the US standard (MDEF).
int component_model(const io::CdkCard1& c1, int k) {
    const int m = c1.m[k];
    if (m < 0 || m > 6)
        throw DataError(kDeck, "CARD 1 M" + std::to_string(k + 1) + " = " + std::to_string(m) +
                                   ": expected 0-6");
    return m == 0 ? kUsStandard : m;
}

void push_level(Profile& out, double z, double p, double t) {
    out.z_km.push_back(z);
    out.p_mb.push_back(p);
    out.t_k.push_back(t);
}

// The radiosonde layers of CARD 2C1.
Profile sonde_levels(const io::CdkRun& run, ModelSet& ms) {
    const auto& c1 = run.card1;
    Profile out;
    const auto& layers = run.profile->layers;
    for (std::size_t i = 0; i < layers.size(); ++i) {
        const auto& l = layers[i];
        if (i > 0 && l.altitude_km <= out.z_km.back())
            throw DataError(
                kDeck, "CARD 2C1 layer " + std::to_string(i + 1) + ": altitude ZMDL must increase");
        const double p = layer_pressure_mb(l, i, ms);
        const double t = layer_temperature_k(l, i, ms);
        if (!(p > 0) || !(t > 0))
            throw DataError(kDeck, "CARD 2C1 layer " + std::to_string(i + 1) +
                                       ": pressure and temperature must be positive");
        push_level(out, l.altitude_km, p, t);
        auto& v = out.vmr_ppmv;
        v[int(Gas::H2O)].push_back(layer_h2o_ppmv(l, i, p, t, ms, component_model(c1, 1)));
        v[int(Gas::CO2)].push_back(
            layer_gas_ppmv(l, i, 3, Gas::CO2, kMolarMassCO2_g_mol, p, t, ms, kUsStandard));
        v[int(Gas::O3)].push_back(
            layer_gas_ppmv(l, i, 4, Gas::O3, kMolarMassO3_g_mol, p, t, ms, component_model(c1, 2)));
        // The gases CARD 2C1 does not carry: M4 CH4, M5 N2O, M6 CO, the rest US standard.
        const double z = l.altitude_km;
        v[int(Gas::CH4)].push_back(model_ppmv(ms.get(component_model(c1, 3)), Gas::CH4, z));
        v[int(Gas::N2O)].push_back(model_ppmv(ms.get(component_model(c1, 4)), Gas::N2O, z));
        v[int(Gas::CO)].push_back(model_ppmv(ms.get(component_model(c1, 5)), Gas::CO, z));
        for (Gas g : {Gas::O2, Gas::NO, Gas::SO2, Gas::NO2, Gas::NH3, Gas::HNO3})
            v[int(g)].push_back(model_ppmv(ms.get(kUsStandard), g, z));
    }
    return out;
}

// Above the sonde's top the model atmosphere M1 (or the US standard) continues:
// its levels more than 0.1 km above the top, with pressure scaled by the constant
// ratio p_sonde(top) / p_model(top) (continuous, and hydrostatic in the model's
// shape) and the temperature offset at the top (T_sonde - T_model) fading linearly
// to zero over the next 5 km. Gases are the component models' (M2-M6, else the US
// standard) mixing ratios at those levels.
void continue_with_model(Profile& out, const io::CdkCard1& c1, ModelSet& ms) {
    const Profile& base = ms.get(component_model(c1, 0));
    const double z_top = out.top_km();
    const double p_scale = out.p_mb.back() / model_p(base, z_top);
    const double t_offset = out.t_k.back() - model_t(base, z_top);
    constexpr double kFade_km = 5.0;
    const std::array<int, kGasCount> gas_model = {component_model(c1, 1),
                                                  kUsStandard,
                                                  component_model(c1, 2),
                                                  component_model(c1, 4),
                                                  component_model(c1, 5),
                                                  component_model(c1, 3),
                                                  kUsStandard,
                                                  kUsStandard,
                                                  kUsStandard,
                                                  kUsStandard,
                                                  kUsStandard,
                                                  kUsStandard};
    for (std::size_t j = 0; j < base.size(); ++j) {
        const double z = base.z_km[j];
        if (z <= z_top + 0.1) continue;
        const double fade = std::max(0.0, 1.0 - (z - z_top) / kFade_km);
        push_level(out, z, base.p_mb[j] * p_scale, base.t_k[j] + t_offset * fade);
        for (int g = 0; g < kGasCount; ++g)
            out.vmr_ppmv[g].push_back(model_ppmv(ms.get(gas_model[g]), Gas(g), z));
    }
}

// MODEL 1-6 with the per-component overrides M1-M6 (same AFGL grid).
Profile standard_model(const io::CdkCard1& c1, ModelSet& ms) {
    Profile out = ms.get(c1.model);
    auto take = [&](int k, auto&& copy) {
        if (c1.m[k] != 0) copy(ms.get(component_model(c1, k)));
    };
    take(0, [&](const Profile& m) { out.p_mb = m.p_mb, out.t_k = m.t_k; });
    take(1, [&](const Profile& m) { out.vmr_ppmv[0] = m.vmr_ppmv[0]; });
    take(2, [&](const Profile& m) { out.vmr_ppmv[int(Gas::O3)] = m.vmr_ppmv[int(Gas::O3)]; });
    take(3, [&](const Profile& m) { out.vmr_ppmv[int(Gas::CH4)] = m.vmr_ppmv[int(Gas::CH4)]; });
    take(4, [&](const Profile& m) { out.vmr_ppmv[int(Gas::N2O)] = m.vmr_ppmv[int(Gas::N2O)]; });
    take(5, [&](const Profile& m) { out.vmr_ppmv[int(Gas::CO)] = m.vmr_ppmv[int(Gas::CO)]; });
    return out;
}

}  // namespace

double air_number_density_cm3(double p_mb, double t_k) {
    return air_number_density_m3(p_mb, t_k) * 1e-6;
}

double saturation_vapour_density_g_m3(double t_k) {
    // LOWTRAN 7 STDMDL/AERNSM (formulas_and_constants.txt item 5), A = 273.15/T.
    const double a = kZeroCelsius_K / t_k;
    return a * std::exp(18.9766 - 14.9595 * a - 2.43882 * a * a);
}

Profile afgl_profile(int model, const std::string& data_dir) {
    if (model < 1 || model > 6)
        throw Error("AFGL model atmosphere " + std::to_string(model) + " does not exist (1-6)");
    const std::string path = find_model_file(model, data_dir);
    const TextInput in = TextInput::from_file(path);
    const auto rows = read_rows(in, 11, "an AFGL level (z p T n_air and 7 gases)");
    Profile p;
    p.model = model;
    for (const auto& r : rows) {
        push_level(p, r[0], r[1], r[2]);
        for (int g = 0; g < 7; ++g) p.vmr_ppmv[g].push_back(r[4 + g]);
    }
    require_monotonic(p.z_km, in.at(0), "altitude");
    read_trace_gases(p, data_dir);
    derive_water(p);
    return p;
}

Profile profile_from_deck(const io::CdkRun& run, const std::string& data_dir) {
    const auto& c1 = run.card1;
    ModelSet ms;
    ms.data_dir = data_dir;
    if (c1.model == 0)
        throw DataError(kDeck,
                        "CARD 1 MODEL 0 (user meteorological data for a horizontal "
                        "path) cannot give a vertical profile; use MODEL 1-6 or 7");
    if (c1.model >= 1 && c1.model <= 6) {
        Profile p = standard_model(c1, ms);
        derive_water(p);
        return p;
    }
    if (c1.model != 7)
        throw DataError(kDeck, "CARD 1 MODEL " + std::to_string(c1.model) + ": expected 1-7");
    if (!run.profile || run.profile->layers.empty())
        throw DataError(kDeck, "CARD 1 MODEL 7 needs the radiosonde layers of CARD 2C/2C1");
    Profile p = sonde_levels(run, ms);
    continue_with_model(p, c1, ms);
    p.model = 7;
    derive_water(p);
    return p;
}

namespace {

// Interpolates a density between two levels: exponential in altitude when both are
// positive (LOWTRAN's rule), else linear.
double density_between(double a, double b, double f) {
    if (a > 0 && b > 0) return a * std::pow(b / a, f);
    return a + f * (b - a);
}

}  // namespace

Profile resample(const Profile& p, double z_lo_km, double z_hi_km,
                 const std::vector<double>& extra_z_km) {
    constexpr double kTol_km = 1e-9;
    if (!(z_lo_km < z_hi_km) || z_lo_km < p.bottom_km() - kTol_km || z_hi_km > p.top_km() + kTol_km)
        throw Error("resample: [" + format_number(z_lo_km) + ", " + format_number(z_hi_km) +
                    "] km is not inside the profile's [" + format_number(p.bottom_km()) + ", " +
                    format_number(p.top_km()) + "] km");
    std::vector<double> z = {z_lo_km, z_hi_km};
    for (double v : p.z_km) z.push_back(v);
    for (double v : extra_z_km) z.push_back(v);
    std::sort(z.begin(), z.end());
    std::vector<double> levels;
    for (double v : z) {
        if (v < z_lo_km - kTol_km || v > z_hi_km + kTol_km) continue;
        if (!levels.empty() && v - levels.back() <= kTol_km) continue;
        levels.push_back(std::clamp(v, p.bottom_km(), p.top_km()));
    }
    Profile out;
    out.model = p.model;
    for (double at : levels) {
        const std::size_t lo = interval_index(p.z_km, at), hi = lo + 1;
        const double f = (at - p.z_km[lo]) / (p.z_km[hi] - p.z_km[lo]);
        const double t = p.t_k[lo] + f * (p.t_k[hi] - p.t_k[lo]);
        const double pr = density_between(p.p_mb[lo], p.p_mb[hi], f);
        push_level(out, at, pr, t);
        const double n_lo = air_number_density_cm3(p.p_mb[lo], p.t_k[lo]);
        const double n_hi = air_number_density_cm3(p.p_mb[hi], p.t_k[hi]);
        const double n = air_number_density_cm3(pr, t);
        for (int g = 0; g < kGasCount; ++g) {
            const auto& v = p.vmr_ppmv[g];
            out.vmr_ppmv[g].push_back(density_between(v[lo] * n_lo, v[hi] * n_hi, f) / n);
        }
        out.h2o_g_m3.push_back(density_between(p.h2o_g_m3[lo], p.h2o_g_m3[hi], f));
        out.rh_percent.push_back(relative_humidity(out.h2o_g_m3.back(), t));
    }
    return out;
}

}  // namespace sigchain::atmos
