// LOWTRAN 7 gas absorption: table loading, layer amounts and band-model transmittance.
#include "atmos/gas_absorption.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "atmos/gas_tables_data.hpp"
#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kP0Mb = 1013.25;                    // LOWTRAN reference pressure
constexpr double kT0K = 273.15;                      // LOWTRAN reference temperature
constexpr double kLoschmidtCm3 = 2.6868e19;          // formulas_and_constants.txt item 9
constexpr double kAtmCmPerKmPerPpmv = 3.7194e-21;    // times n_air [cm-3] (STDMDL)
constexpr double kH2oMoleculesPerGm3Km = 3.3429e21;  // cm-2 per (g m-3 km), item 5

// Indices of the Beer's-law amounts after the 41 band amounts.
enum Quantity : int {
    kH2oSelf = GasColumn::kBandCount,  // W_s, molecules cm-2 (times n_w/n296)
    kH2oSelfCold,                      // W_s' = sum f(T) W_s
    kH2oForeign,                       // W_f, molecules cm-2
    kN2,                               // km of N2-equivalent air at STP
    kO2,                               // O2 atm-cm * P/P0
    kO2T1,                             // ... * (T - 220)
    kO2T2,                             // ... * (T - 220)^2
    kO3,                               // atm-cm
    kO3T1,                             // ... * (T - 273.15)
    kO3T2,                             // ... * (T - 273.15)^2
    kHno3,                             // atm-cm
};
static_assert(kHno3 + 1 == GasColumn::kQuantityCount);

constexpr std::array<std::string_view, kBandGases> kGasNames = {
    "H2O", "CO2", "O3", "N2O", "CO", "CH4", "O2", "NO", "SO2", "NO2", "NH3"};

// ---- Table reading -------------------------------------------------------------------

// The numeric columns asked for of a table's rows (row-major) and each row's line.
struct Rows {
    std::string path;
    std::size_t width = 0;
    std::vector<double> v;
    std::vector<int> line;

    std::size_t size() const { return line.size(); }
    double at(std::size_t row, std::size_t c) const { return v[row * width + c]; }
    SourceLocation where(std::size_t row) const { return {path, line[row]}; }
};

// Every significant line of `path` with exactly `columns` fields; parses the fields
// whose indices are in `numeric` (others, e.g. a wavelength printed as 'inf', are
// skipped).
Rows read_rows(const std::string& path, std::size_t columns, const std::vector<int>& numeric) {
    const TextInput input = TextInput::from_file(path);
    FieldReader reader(input);
    reader.require_not_empty("table rows");
    Rows rows{path, numeric.size(), {}, {}};
    const auto lines =
        static_cast<std::size_t>(std::count(input.text().begin(), input.text().end(), '\n') + 1);
    rows.v.reserve(lines * rows.width);
    rows.line.reserve(lines);
    while (!reader.at_end()) {
        const auto fields = reader.fields(columns, "table row");
        for (int c : numeric) rows.v.push_back(reader.number(fields[c], "table value"));
        rows.line.push_back(reader.line());
    }
    return rows;
}

// Checks that column 0 of the first `count` rows is start + step * i (a regular grid).
void check_grid(const Rows& rows, double start, double step, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        double want = start + step * static_cast<double>(i);
        if (std::abs(rows.at(i, 0) - want) > 1e-6)
            throw DataError(rows.where(i), "expected wavenumber " + format_number(want) +
                                               ", found " + format_number(rows.at(i, 0)));
    }
}

// Checks that there are `count` rows on that grid.
void require_grid(const Rows& rows, double start, double step, std::size_t count) {
    // An extra row is named by its line; a missing one has none, so the file is named.
    if (rows.size() != count)
        throw DataError(
            rows.size() > count ? rows.where(count) : SourceLocation{rows.path, 0},
            "expected " + std::to_string(count) + " rows, found " + std::to_string(rows.size()));
    check_grid(rows, start, step, count);
}

std::vector<double> column(const Rows& rows, std::size_t c) {
    std::vector<double> out;
    out.reserve(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) out.push_back(rows.at(r, c));
    return out;
}

// Whether [lo, hi] (cm-1) reaches within GasTables::kLoadMargin of d's range.
bool wanted(const GasTables::Data& d, double lo, double hi) {
    return hi >= d.nu_lo - GasTables::kLoadMargin && lo <= d.nu_hi + GasTables::kLoadMargin;
}

// band_model_constants.txt's last field: a band's wavenumber ranges, "A-B" (cm-1)
// separated by ';'. Whether one of them is wanted().
bool band_wanted(const GasTables::Data& d, std::string_view ranges, const SourceLocation& where) {
    bool any = false;
    while (true) {
        const auto semi = ranges.find(';');
        const std::string_view range = ranges.substr(0, semi);
        const auto dash = range.find('-');
        if (dash == std::string_view::npos || dash == 0)
            throw DataError(where,
                            "expected wavenumber ranges A-B[;C-D...], found " + quoted(range));
        const double lo = parse_double(range.substr(0, dash), where, "a range's first wavenumber");
        const double hi = parse_double(range.substr(dash + 1), where, "a range's last wavenumber");
        if (!(lo <= hi))
            throw DataError(where, "expected a range A-B with A <= B, found " + quoted(range));
        any = any || wanted(d, lo, hi);
        if (semi == std::string_view::npos) return any;
        ranges.remove_prefix(semi + 1);
    }
}

// band_model_constants.txt: gas band_id a n m w1 w2 w3 CC ranges. `read`: per gas,
// whether one of its bands is wanted (its grid is to be read).
void read_band_constants(GasTables::Data& d, const std::string& dir,
                         std::array<bool, kBandGases>& read) {
    const std::string path = dir + "band_model_constants.txt";
    const TextInput input = TextInput::from_file(path);
    FieldReader reader(input);
    d.band_gas.fill(-1);
    while (!reader.at_end()) {
        auto f = reader.fields(10, "band constants row");
        auto where = reader.where();
        auto gas = std::find(kGasNames.begin(), kGasNames.end(), f[0]);
        if (gas == kGasNames.end())
            throw DataError(where, "expected a gas name, found " + quoted(f[0]));
        long id = parse_long(f[1], where, "band id");
        if (id < kFirstBandId || id >= kFirstBandId + GasColumn::kBandCount)
            throw DataError(where, "expected a band id 17-57, found " + quoted(f[1]));
        auto b = static_cast<std::size_t>(id - kFirstBandId);
        d.band_gas[b] = static_cast<int>(gas - kGasNames.begin());
        d.a[b] = parse_in_range(f[2], where, "band exponent a", 0.1, 1.0);
        d.n_p[b] = parse_double(f[3], where, "pressure exponent n");
        d.m_t[b] = parse_double(f[4], where, "temperature exponent m");
        if (band_wanted(d, f[9], where))
            read[static_cast<std::size_t>(gas - kGasNames.begin())] = true;
    }
    for (std::size_t b = 0; b < d.band_gas.size(); ++b)
        if (d.band_gas[b] < 0)
            // A missing band has no line: the message names the file and the band.
            throw DataError({path, 0}, "band " + std::to_string(b + kFirstBandId) + " missing");
}

// band_model_GAS.txt: nu lambda Cprime band_id, 5 cm-1 steps, gaps between ranges.
void read_band_grid(GasTables::Data& d, int gas, const std::string& dir) {
    const std::string path = dir + "band_model_" + std::string(kGasNames[gas]) + ".txt";
    const Rows rows = read_rows(path, 4, {0, 2, 3});
    auto& grid = d.grids[gas];
    grid.nu0_cm1 = static_cast<int>(rows.at(0, 0));
    double last = rows.at(0, 0) - 5;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double nu = rows.at(r, 0), cprime = rows.at(r, 1), band_id = rows.at(r, 2);
        if (nu <= last || std::fmod(nu, 5.0) != 0)
            throw DataError(rows.where(r),
                            "expected increasing multiples of 5 cm-1, found " + format_number(nu));
        long id = std::lround(band_id);
        auto b = id - kFirstBandId;
        if (band_id != static_cast<double>(id) || b < 0 || b >= GasColumn::kBandCount ||
            d.band_gas[b] != gas)
            throw DataError(rows.where(r), "expected a band id of " + std::string(kGasNames[gas]) +
                                               ", found " + format_number(band_id));
        auto index = static_cast<std::size_t>((nu - grid.nu0_cm1) / 5);
        grid.cprime.resize(index + 1, 0.0);
        grid.band.resize(index + 1, -1);
        grid.cprime[index] = cprime;
        grid.band[index] = static_cast<std::int8_t>(b);
        last = nu;
    }
}

// Whether the table `name`, whose grid spans lo..hi cm-1, is to be read (else it is
// recorded as skipped).
bool read_table(GasTables::Data& d, const std::string& name, double lo, double hi) {
    if (wanted(d, lo, hi)) return true;
    d.skipped.push_back(name);
    return false;
}

void read_continua(GasTables::Data& d, const std::string& dir) {
    if (read_table(d, "h2o_continuum.txt", -20, 20000)) {
        const Rows rows = read_rows(dir + "h2o_continuum.txt", 4, {0, 1, 2, 3});
        require_grid(rows, -20, 10, 2003);
        d.h2o_self296 = column(rows, 1);
        d.h2o_self260 = column(rows, 2);
        d.h2o_foreign296 = column(rows, 3);
    }
    if (read_table(d, "n2_continuum.txt", 2080, 2740)) {
        const Rows rows = read_rows(dir + "n2_continuum.txt", 3, {0, 2});
        require_grid(rows, 2080, 5, 133);
        d.n2_km = column(rows, 1);
    }
    if (read_table(d, "o2_continuum_1395_1760.txt", 1395, 1760)) {
        const Rows rows = read_rows(dir + "o2_continuum_1395_1760.txt", 5, {0, 2, 3, 4});
        require_grid(rows, 1395, 5, 74);
        d.o2_s0 = column(rows, 1);
        d.o2_a = column(rows, 2);
        d.o2_b = column(rows, 3);
    }
    if (read_table(d, "hno3_band_coefficients.txt", 850, 1735)) {
        const Rows rows = read_rows(dir + "hno3_band_coefficients.txt", 3, {0, 2});
        d.hno3.assign((1735 - 850) / 5 + 1, 0.0);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            double i = (rows.at(r, 0) - 850) / 5;
            if (i < 0 || i >= static_cast<double>(d.hno3.size()) || i != std::floor(i))
                throw DataError(rows.where(r),
                                "expected a wavenumber 850-1735 cm-1 on a 5 cm-1 grid");
            d.hno3[static_cast<std::size_t>(i)] = rows.at(r, 1);
        }
    }
}

void read_ozone(GasTables::Data& d, const std::string& dir) {
    Rows rows = read_rows(dir + "o3_visible_uv_band_coefficients.txt", 4, {1, 3});
    // An extra row is named by its line; a missing one has none, so the file is named.
    if (rows.size() != 102)
        throw DataError(rows.size() > 102 ? rows.where(102) : SourceLocation{rows.path, 0},
                        "expected 102 rows");
    check_grid(rows, 13000, 200, 56);
    for (std::size_t k = 0; k < 57; ++k) d.chappuis.push_back(rows.at(k, 1));  // C8(57) is at 27500

    if (!read_table(d, "o3_hartley_huggins.txt", 27370, 40800)) return;
    rows = read_rows(dir + "o3_hartley_huggins.txt", 5, {0, 2, 3, 4});
    require_grid(rows, 27370, 5, 2687);
    d.hh_c0 = column(rows, 1);
    d.hh_c1 = column(rows, 2);
    d.hh_c2 = column(rows, 3);
}

// ---- Spectral coefficients -----------------------------------------------------------

// Value of a 5 cm-1 table starting at nu0 at the grid point nearest nu; 0 outside.
double nearest(const std::vector<double>& table, double nu0, double nu) {
    double i = std::round((nu - nu0) / 5.0);
    if (i < 0 || i >= static_cast<double>(table.size())) return 0.0;
    return table[static_cast<std::size_t>(i)];
}

// H2O continuum table value, linear between 10 cm-1 points (SINT: the mean of the
// neighbours at odd multiples of 5 cm-1); none at nu >= 20000 cm-1.
double h2o_table(const std::vector<double>& table, double nu) {
    if (nu >= 20000.0 || nu < -20.0) return 0.0;
    double x = (nu + 20.0) / 10.0;
    auto i = static_cast<std::size_t>(x);
    double t = x - static_cast<double>(i);
    double hi = (i + 1 < table.size() - 1) ? table[i + 1] : 0.0;  // the 20000 entry is unused
    return table[i] * (1 - t) + hi * t;
}

// Radiation term nu tanh(hc nu / 2kT) (h2o_continuum.txt header; 0.6952 = k/hc cm-1/K).
double radiation_term(double nu, double t_k) {
    double x = std::exp(-nu / (0.6952 * t_k));
    return nu * (1 - x) / (1 + x);
}

// Ozone Chappuis coefficient (C8DTA): linear in nu on the 200 cm-1 grid 13000-24000,
// towards C8(57) up to 24200, none elsewhere (atm-cm)^-1.
double chappuis(const std::vector<double>& c8, double nu) {
    if (nu < 13000.0 || nu > 24200.0) return 0.0;
    double x = (nu - 13000.0) / 200.0;  // C8(56) at 24000, C8(57) reached at 24200
    auto i = std::min(static_cast<std::size_t>(x), std::size_t{55});
    double t = x - static_cast<double>(i);
    return c8[i] * (1 - t) + c8[i + 1] * t;
}

// Coefficient of every Beer's-law amount at nu: tau = sum coef[q] * amount[q].
using ContinuumCoefficients = std::array<double, GasColumn::kQuantityCount - GasColumn::kBandCount>;

ContinuumCoefficients continuum_coefficients(const GasTables::Data& d, double nu) {
    require_loaded(d, nu);
    ContinuumCoefficients c{};
    constexpr int q0 = GasColumn::kBandCount;
    if (nu < 20000.0) {
        // CKD continuum (h2o_continuum.txt): self correction of 1 Sept 85, a = 200 cm-1.
        const double a2 = 200.0 * 200.0;
        const double corr = 1 - 0.2333 * a2 / ((nu - 1050) * (nu - 1050) + a2);
        const double r296 = radiation_term(nu, 296.0), r260 = radiation_term(nu, 260.0);
        const double s296 = 1e-20 * h2o_table(d.h2o_self296, nu) * corr * r296;
        const double s260 = 1e-20 * h2o_table(d.h2o_self260, nu) * corr * r260;
        const double y1 = 1.025 * 3.159e-8 * std::exp(-2.75e-4 * nu);  // far-wing FUDGE
        const double y2 = 8.97e-6 * std::exp(-1.3e-3 * nu);
        const double fudge = 1 / (1 / y1 + 1 / y2);
        c[kH2oSelf - q0] = s296;
        c[kH2oSelfCold - q0] = s260 - s296;
        c[kH2oForeign - q0] = 1e-20 * (h2o_table(d.h2o_foreign296, nu) + fudge) * r296;
    }
    c[kN2 - q0] = nearest(d.n2_km, 2080, nu);  // n2_continuum.txt: tau = C4 W_N2
    // O2 1395-1760 (o2_continuum_1395_1760.txt): sigma = S0/0.20946, alpha = A,
    // beta = A^2/2 + B.
    const double sigma = nearest(d.o2_s0, 1395, nu) / 0.20946;
    const double alpha = nearest(d.o2_a, 1395, nu);
    c[kO2 - q0] = sigma;
    c[kO2T1 - q0] = sigma * alpha;
    c[kO2T2 - q0] = sigma * (alpha * alpha / 2 + nearest(d.o2_b, 1395, nu));
    // Ozone: Chappuis below 24370 cm-1, Hartley-Huggins (Bass algorithm, 0.269 =
    // 2.69e19 * 1e-20) from 27370 to 40800 cm-1 (o3_hartley_huggins.txt).
    if (nu <= 24370.0) c[kO3 - q0] = chappuis(d.chappuis, nu);
    if (nu >= 27370.0 && nu <= 40800.0) {
        const double c0 = 0.269 * nearest(d.hh_c0, 27370, nu);
        c[kO3 - q0] = c0;
        c[kO3T1 - q0] = c0 * nearest(d.hh_c1, 27370, nu);
        c[kO3T2 - q0] = c0 * nearest(d.hh_c2, 27370, nu);
    }
    c[kHno3 - q0] = nearest(d.hno3, 850, nu);  // hno3_band_coefficients.txt
    return c;
}

// ---- Layer amounts ---------------------------------------------------------------------

// Integral over a layer of thickness dz of a quantity varying exponentially between
// its level values f1, f2 (linearly when one is zero or they are nearly equal).
double layer_integral(double f1, double f2, double dz) {
    if (f1 > 0 && f2 > 0 && std::abs(f1 - f2) > 1e-9 * std::max(f1, f2))
        return (f1 - f2) / std::log(f1 / f2) * dz;
    return 0.5 * (f1 + f2) * dz;
}

// Integrands (per km) of every amount on one level; temperature-weighted sums are
// formed per layer and left 0 here.
std::array<double, GasColumn::kQuantityCount> level_integrands(const GasTables::Data& d,
                                                               const Profile& p, std::size_t k) {
    std::array<double, GasColumn::kQuantityCount> f{};
    const double pr = p.p_mb[k] / kP0Mb, tr = kT0K / p.t_k[k];
    const double n_air = kLoschmidtCm3 * pr * tr;  // cm-3, ideal gas
    std::array<double, kBandGases> density{};      // g cm-2 per km (H2O), atm-cm per km
    density[0] = 0.1 * p.h2o_g_m3[k];
    for (int g = 1; g < kBandGases; ++g) density[g] = n_air * p.vmr_ppmv[g][k] * kAtmCmPerKmPerPpmv;
    for (int b = 0; b < GasColumn::kBandCount; ++b)
        f[b] = density[d.band_gas[b]] * std::pow(pr, d.n_p[b]) * std::pow(tr, d.m_t[b]);
    const double n_w = p.h2o_g_m3[k] * kH2oMoleculesPerGm3Km * 1e-5;  // cm-3
    const double n296 = kLoschmidtCm3 * kT0K / 296.0;
    f[kH2oSelf] = n_w * (n_w / n296) * 1e5;
    f[kH2oForeign] = n_w * ((n_air - n_w) / n296) * 1e5;
    f[kN2] = 0.781 * pr * pr * std::pow(tr, 1.5);
    f[kO2] = density[int(Gas::O2)] * pr;
    f[kO3] = density[int(Gas::O3)];
    f[kHno3] = pr * tr * p.vmr_ppmv[int(Gas::HNO3)][k] * 0.1;
    return f;
}

void check_profile(const Profile& p) {
    const std::size_t n = p.size();
    bool ok = n >= 2 && p.p_mb.size() == n && p.t_k.size() == n && p.h2o_g_m3.size() == n;
    for (const auto& v : p.vmr_ppmv) ok = ok && v.size() == n;
    if (!ok) throw std::invalid_argument("GasColumn: profile needs >= 2 levels and every column");
    for (std::size_t k = 0; k < n; ++k)
        if (!(p.p_mb[k] > 0 && p.t_k[k] > 0) || (k > 0 && !(p.z_km[k] > p.z_km[k - 1])))
            throw std::invalid_argument("GasColumn: bad profile level " + std::to_string(k));
}

}  // namespace

GasTables GasTables::load(const std::string& data_dir) {
    return load(data_dir, -std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity());
}

GasTables GasTables::load(const std::string& data_dir, double nu_lo_cm1, double nu_hi_cm1) {
    if (!(nu_lo_cm1 <= nu_hi_cm1)) throw std::invalid_argument("GasTables::load: empty range");
    auto d = std::make_shared<Data>();
    d->nu_lo = nu_lo_cm1;
    d->nu_hi = nu_hi_cm1;
    const std::string dir = data_dir + "/atmosphere/lowtran7/";
    std::array<bool, kBandGases> grids{};
    read_band_constants(*d, dir, grids);
    for (int g = 0; g < kBandGases; ++g) {
        if (grids[static_cast<std::size_t>(g)])
            read_band_grid(*d, g, dir);
        else
            d->skipped.push_back("band_model_" + std::string(kGasNames[g]) + ".txt");
    }
    read_continua(*d, dir);
    read_ozone(*d, dir);
    return GasTables(std::move(d));
}

const std::vector<std::string>& GasTables::skipped() const { return m_data->skipped; }

void require_loaded(const GasTables::Data& d, double nu) {
    if (!(nu >= d.nu_lo && nu <= d.nu_hi))
        throw std::logic_error("gas tables: " + format_number(nu) +
                               " cm-1 lies outside the range they were read for");
}

GasColumn::GasColumn(const GasTables& tables, const Profile& profile)
    : m_tables(tables.m_data), m_levels(profile.size()) {
    check_profile(profile);
    const GasTables::Data& d = *m_tables;
    m_cumulative.assign(m_levels * kQuantityCount, 0.0);
    auto below = level_integrands(d, profile, 0);
    for (std::size_t k = 0; k + 1 < m_levels; ++k) {
        auto above = level_integrands(d, profile, k + 1);
        const double dz = profile.z_km[k + 1] - profile.z_km[k];
        std::array<double, kQuantityCount> layer{};
        for (int q = 0; q < kQuantityCount; ++q) layer[q] = layer_integral(below[q], above[q], dz);
        // Temperature-weighted sums at the layer's mean temperature.
        const double t = 0.5 * (profile.t_k[k] + profile.t_k[k + 1]);
        layer[kH2oSelfCold] = std::clamp((296.0 - t) / (296.0 - 260.0), 0.0, 1.0) * layer[kH2oSelf];
        layer[kO2T1] = layer[kO2] * (t - 220.0);
        layer[kO2T2] = layer[kO2] * (t - 220.0) * (t - 220.0);
        layer[kO3T1] = layer[kO3] * (t - kT0K);
        layer[kO3T2] = layer[kO3] * (t - kT0K) * (t - kT0K);
        for (int q = 0; q < kQuantityCount; ++q)
            m_cumulative[(k + 1) * kQuantityCount + q] =
                m_cumulative[k * kQuantityCount + q] + layer[q];
        below = above;
    }
}

// -ln of LOWTRAN's band-model transmittance (C W)^a = 10^(a (log10 W + C')) of one
// absorber's band at nu on the path lo..hi at cosine mu; 0 where LOWTRAN's T is 1.
double GasColumn::band_optical_depth(int gas, double nu, std::size_t lo, std::size_t hi,
                                     double mu) const {
    require_loaded(*m_tables, nu);
    const auto& grid = m_tables->grids[gas];
    double i = std::round((nu - grid.nu0_cm1) / 5.0);
    if (i < 0 || i >= static_cast<double>(grid.band.size())) return 0.0;
    const auto index = static_cast<std::size_t>(i);
    const int band = grid.band[index];
    if (band < 0) return 0.0;
    return band_depth_of_amount(band, grid.cprime[index], amount(band, lo, hi) / mu);
}

// -ln T of the band model at scaled amount w (band_optical_depth's last step).
double GasColumn::band_depth_of_amount(int band, double cprime, double w) const {
    if (w < 1e-20) return 0.0;
    const double x = m_tables->a[band] * (std::log10(w) + cprime);
    return x <= -6.0 ? 0.0 : std::pow(10.0, x);
}

double GasColumn::band_transmittance(Gas gas, double nu, std::size_t i, std::size_t j,
                                     double mu) const {
    if (gas == Gas::HNO3) return 1.0;
    if (i > j) std::swap(i, j);
    return std::exp(-band_optical_depth(static_cast<int>(gas), nu, i, j, mu));
}

double GasColumn::continuum_optical_depth(double nu, std::size_t i, std::size_t j,
                                          double mu) const {
    if (i > j) std::swap(i, j);
    const auto c = continuum_coefficients(*m_tables, nu);
    double tau = 0.0;
    for (std::size_t q = 0; q < c.size(); ++q) tau += c[q] * amount(kBandCount + int(q), i, j);
    return tau / mu;
}

double GasColumn::transmittance(double nu, std::size_t i, std::size_t j, double mu) const {
    if (i >= m_levels || j >= m_levels || !(mu > 0 && mu <= 1 + 1e-12))
        throw std::invalid_argument("GasColumn::transmittance: level or mu out of range");
    if (i > j) std::swap(i, j);
    double tau = continuum_optical_depth(nu, i, j, mu);
    for (int g = 0; g < kBandGases; ++g) tau += band_optical_depth(g, nu, i, j, mu);
    return std::exp(-tau);
}

double GasColumn::transmittance_along(double nu, std::size_t i, std::size_t j,
                                      const std::vector<double>& air_mass) const {
    if (i >= m_levels || j >= m_levels || air_mass.size() + 1 < m_levels)
        throw std::invalid_argument("GasColumn::transmittance_along: level out of range");
    if (i > j) std::swap(i, j);
    auto slant = [&](int q) {  // path amount of quantity q
        double w = 0.0;
        for (std::size_t k = i; k < j; ++k) w += air_mass[k] * amount(q, k, k + 1);
        return w;
    };
    const auto c = continuum_coefficients(*m_tables, nu);
    double tau = 0.0;
    for (std::size_t q = 0; q < c.size(); ++q) tau += c[q] * slant(kBandCount + int(q));
    for (int g = 0; g < kBandGases; ++g) {  // continuum_coefficients checked nu
        const auto& grid = m_tables->grids[g];
        const double x = std::round((nu - grid.nu0_cm1) / 5.0);
        if (x < 0 || x >= static_cast<double>(grid.band.size())) continue;
        const auto index = static_cast<std::size_t>(x);
        const int band = grid.band[index];
        if (band >= 0) tau += band_depth_of_amount(band, grid.cprime[index], slant(band));
    }
    return std::exp(-tau);
}

// Adds one gas's band-model equivalent depths: the difference of -ln T of vertical
// paths from the top (header comment).
void GasColumn::add_equivalent_band_depth(int g, double nu, std::vector<double>& tau) const {
    const std::size_t top = m_levels - 1;
    double above = 0.0;  // -ln T(top..k+1)
    for (std::size_t k = top; k-- > 0;) {
        const double here = band_optical_depth(g, nu, k, top, 1.0);
        tau[k] += here - above;
        above = here;
    }
}

void GasColumn::add_continuum_depth(double nu, std::vector<double>& tau) const {
    const auto c = continuum_coefficients(*m_tables, nu);
    for (std::size_t k = 0; k + 1 < m_levels; ++k)
        for (std::size_t q = 0; q < c.size(); ++q)
            tau[k] += c[q] * amount(kBandCount + int(q), k, k + 1);
}

std::vector<double> GasColumn::layer_absorption_depth(double nu) const {
    std::vector<double> tau(m_levels - 1, 0.0);
    for (int g = 0; g < kBandGases; ++g) add_equivalent_band_depth(g, nu, tau);
    add_continuum_depth(nu, tau);
    return tau;
}

}  // namespace sigchain::atmos
