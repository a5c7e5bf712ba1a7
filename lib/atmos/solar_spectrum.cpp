// LOWTRAN 7's extraterrestrial solar spectrum (function SUN) at 1 AU.
#include "atmos/solar_spectrum.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::atmos {

namespace {

// Where LOWTRAN's function SUN switches from the 20 cm-1 to the 10 cm-1 table, and
// below which it uses its power law (solar_lowtran7_extraterrestrial.txt header).
constexpr double kSwitch_cm1 = 28420;
constexpr double kPowerLawBelow_cm1 = 100;

// Appends a row to a grid, checking that it continues the even spacing.
void append(TextInput const& in, int line, double nu, double e, double dnu, auto& grid) {
    if (grid.e_w_m2_um.empty()) {
        grid.nu0_cm1 = nu;
        grid.dnu_cm1 = dnu;
    } else if (std::abs(nu - grid.nu_end() - dnu) > 1e-6) {
        throw DataError(in.at(line), "expected wavenumber " + format_number(grid.nu_end() + dnu) +
                                         " cm-1 (a " + format_number(dnu) + " cm-1 grid), found " +
                                         format_number(nu));
    }
    grid.e_w_m2_um.push_back(e);
}

}  // namespace

SolarSpectrum SolarSpectrum::load(const std::string& data_dir) {
    const std::string path = data_dir + "/atmosphere/solar_lowtran7_extraterrestrial.txt";
    const TextInput in = TextInput::from_file(path);
    FieldReader cur(in);
    cur.require_not_empty("a solar row (nu lambda E table)");
    SolarSpectrum s;
    while (!cur.at_end()) {
        const auto f = cur.fields(4, "a solar row (nu lambda E table)");
        const int line = cur.line();
        const double nu = cur.number(f[0], "wavenumber");
        const double e = cur.number(f[2], "irradiance");
        if (e < 0) throw DataError(cur.where(), "negative irradiance " + quoted(f[2]));
        if (f[3] == "A") {
            append(in, line, nu, e, 20.0, s.m_coarse);
        } else if (f[3] == "B") {
            append(in, line, nu, e, 10.0, s.m_fine);
        } else {
            throw DataError(cur.where(), "expected table A or B, found " + quoted(f[3]));
        }
    }
    if (s.m_coarse.e_w_m2_um.size() < 4 || s.m_fine.e_w_m2_um.size() < 4 ||
        s.m_coarse.nu0_cm1 != 0 || s.m_coarse.nu_end() < kSwitch_cm1 ||
        s.m_fine.nu0_cm1 > kSwitch_cm1)
        throw DataError(in.at(0), "tables A and B must cover 0-28420 and 28420 cm-1 upwards");
    // Total: trapezoid over both tables in wavenumber of E_lambda dlambda/dnu =
    // E_lambda 1e4 / nu^2 (the integrand vanishes at nu -> 0 as nu^1.93).
    double total = 0;
    auto integrate = [&](const Grid& g, double lo, double hi) {
        for (std::size_t i = 1; i < g.e_w_m2_um.size(); ++i) {
            const double a = g.nu0_cm1 + g.dnu_cm1 * double(i - 1), b = a + g.dnu_cm1;
            if (a < lo - 1e-9 || b > hi + 1e-9 || a <= 0) continue;
            total += 0.5 * (g.e_w_m2_um[i - 1] * 1e4 / (a * a) + g.e_w_m2_um[i] * 1e4 / (b * b)) *
                     g.dnu_cm1;
        }
    };
    integrate(s.m_coarse, 0, kSwitch_cm1);
    integrate(s.m_fine, kSwitch_cm1, s.m_fine.nu_end());
    s.m_total_w_m2 = total;
    return s;
}

// 4-point Lagrange interpolation on an even grid (LOWTRAN's SUN): the nodes i-1..i+2
// around the interval holding nu, shifted inwards at the table's ends.
double SolarSpectrum::lagrange4(const Grid& g, double nu_cm1) {
    const auto n = std::ptrdiff_t(g.e_w_m2_um.size());
    const double x = (nu_cm1 - g.nu0_cm1) / g.dnu_cm1;
    std::ptrdiff_t i0 = std::ptrdiff_t(std::floor(x)) - 1;
    i0 = std::max<std::ptrdiff_t>(0, std::min(i0, n - 4));
    double sum = 0;
    for (int j = 0; j < 4; ++j) {
        double w = 1;
        for (int k = 0; k < 4; ++k)
            if (k != j) w *= (x - double(i0 + k)) / double(j - k);
        sum += w * g.e_w_m2_um[std::size_t(i0 + j)];
    }
    return std::max(0.0, sum);
}

double SolarSpectrum::irradiance_w_m2_um(double nu_cm1) const {
    if (!(nu_cm1 > 0) || nu_cm1 > m_fine.nu_end()) return 0;
    // Below 100 cm-1: LOWTRAN's power law E = 3.50187e-13 nu^3.93281 (W m-2 um-1).
    if (nu_cm1 < kPowerLawBelow_cm1) return 3.50187e-13 * std::pow(nu_cm1, 3.93281);
    return lagrange4(nu_cm1 < kSwitch_cm1 ? m_coarse : m_fine, nu_cm1);
}

double SolarSpectrum::irradiance_w_cm2_um(double wavenumber_cm1) const {
    return irradiance_w_m2_um(wavenumber_cm1) * 1e-4;  // per m2 -> per cm2
}

double SolarSpectrum::total_w_m2() const { return m_total_w_m2; }

}  // namespace sigchain::atmos
