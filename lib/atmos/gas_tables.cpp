// LOWTRAN 7's gas tables (GasTables::load, gas_absorption.hpp): the band models'
// constants and grids, the continua and the cross sections, read from
// DATA_DIR/atmosphere/lowtran7/, all of them or those that reach a range of wavenumbers.
#include "atmos/gas_absorption.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "atmos/gas_tables_data.hpp"
#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

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

}  // namespace sigchain::atmos
