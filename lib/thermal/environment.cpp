// The surroundings that drive a facet's temperature (see environment.hpp).
#include "thermal/environment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "geo/scene_clock.hpp"

namespace sigchain::thermal {

namespace {

constexpr double kKelvinOffset = 273.15;

std::string hours_str(double h) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << h;
    return s.str();
}

// Measured insolation (Ly/h -> W m-2), or -1 when the file says "compute" (0).
double measured_w_m2(double a_ly_h, double b_ly_h, double f) {
    if (a_ly_h <= 0 || b_ly_h <= 0) return -1;
    return ((1 - f) * a_ly_h + f * b_ly_h) * kWattsPerSquareMeterPerLangleyPerHour;
}

}  // namespace

WeatherSample interpolate_weather(const io::Wth& wth, double time_h, const std::string& file) {
    const auto& rows = wth.rows;
    const double tol = io::kWthTimeTolerance_h;
    if (rows.empty() || time_h < rows.front().time_h - tol || time_h > rows.back().time_h + tol)
        // No line: the window as a whole falls short, no one row is wrong.
        throw DataError({file, 0}, "the weather window (" +
                                       (rows.empty() ? std::string("no rows")
                                                     : hours_str(rows.front().time_h) + " to " +
                                                           hours_str(rows.back().time_h) + " h") +
                                       ") does not cover " + hours_str(time_h) + " h");
    // The rows around time_h; before the first (within the tolerance) that row alone.
    const std::size_t i0 = rows.size() > 1 ? interval_index(rows, time_h, &io::WthRow::time_h) : 0;
    const std::size_t i1 = time_h < rows.front().time_h ? 0 : std::min(i0 + 1, rows.size() - 1);
    const io::WthRow& a = rows[i0];
    const io::WthRow& b = rows[i1];
    double f = b.time_h > a.time_h ? (time_h - a.time_h) / (b.time_h - a.time_h) : 0.0;
    f = std::clamp(f, 0.0, 1.0);
    auto lerp = [f](double x, double y) { return (1 - f) * x + f * y; };
    WeatherSample s;
    s.air_k = lerp(a.air_temperature_c, b.air_temperature_c) + kKelvinOffset;
    s.vapour_pressure_hpa = lerp(vapour_pressure_hpa(a), vapour_pressure_hpa(b));
    s.wind_m_s = lerp(a.wind_speed_m_s, b.wind_speed_m_s);
    s.direct_horizontal_w_m2 = measured_w_m2(a.direct_insolation_ly_h, b.direct_insolation_ly_h, f);
    s.diffuse_horizontal_w_m2 =
        measured_w_m2(a.diffuse_insolation_ly_h, b.diffuse_insolation_ly_h, f);
    s.sky_exposure = std::clamp(lerp(a.sky_exposure, b.sky_exposure), 0.0, 1.0);
    return s;
}

double saturation_vapour_pressure_hpa(double t_c) {
    return 6.1094 * std::exp(17.625 * t_c / (t_c + 243.04));
}

double vapour_pressure_hpa(const io::WthRow& row) {
    if (row.relative_humidity_pct < 0) return saturation_vapour_pressure_hpa(row.dew_point_c);
    return row.relative_humidity_pct / 100.0 *
           saturation_vapour_pressure_hpa(row.air_temperature_c);
}

double clear_sky_emissivity(double air_k, double vapour_pressure_hpa) {
    return std::min(1.0, 1.24 * std::pow(std::max(vapour_pressure_hpa, 0.0) / air_k, 1.0 / 7.0));
}

double sky_emissivity(double clear, double cloud_fraction) {
    double c = std::clamp(cloud_fraction, 0.0, 1.0);
    return c + (1 - c) * clear;
}

double convection_coefficient(double wind_m_s) { return 5.7 + 3.8 * std::max(wind_m_s, 0.0); }

double air_mass(double zenith_deg) {
    double z = std::min(zenith_deg, 90.0);
    return 1.0 / (std::cos(z * kRadPerDeg) + 0.50572 * std::pow(96.07995 - z, -1.6364));
}

double clear_sky_direct_normal_w_m2(double zenith_deg, double earth_sun_au) {
    if (zenith_deg >= 90) return 0;
    return 1353.0 / (earth_sun_au * earth_sun_au) *
           std::pow(0.7, std::pow(air_mass(zenith_deg), 0.678));
}

double clear_sky_diffuse_horizontal_w_m2(double zenith_deg, double earth_sun_au) {
    if (zenith_deg >= 90) return 0;
    return 0.1 * clear_sky_direct_normal_w_m2(zenith_deg, earth_sun_au) *
           std::cos(zenith_deg * kRadPerDeg);
}

namespace {

EnvironmentStep environment_at(const io::Wth& wth, const std::string& wth_file, const io::Snd& snd,
                               double time_h, EnvironmentSummary* summary) {
    const WeatherSample w = interpolate_weather(wth, time_h, wth_file);
    const geo::SolarPosition sp = geo::sun_at_wth_hours(io::scene_site(snd), time_h);

    EnvironmentStep e;
    e.time_h = time_h;
    e.air_k = w.air_k;
    e.convection_w_m2_k = convection_coefficient(w.wind_m_s);
    const double eps_sky =
        sky_emissivity(clear_sky_emissivity(w.air_k, w.vapour_pressure_hpa), 1 - w.sky_exposure);
    e.sky_longwave_w_m2 = eps_sky * kStefanBoltzmann * std::pow(w.air_k, 4);
    const double z = sp.zenith_deg * kRadPerDeg, az = sp.azimuth_deg * kRadPerDeg;
    e.sun = geo::direction_from_angles(z, az);
    e.sun_up = sp.zenith_deg < 90;
    const double cos_z = std::cos(z);
    // Measured direct insolation is read as falling on a horizontal surface (wth(5)).
    if (w.direct_horizontal_w_m2 >= 0)
        e.direct_normal_w_m2 = e.sun_up ? w.direct_horizontal_w_m2 / std::max(cos_z, 0.05) : 0;
    else
        e.direct_normal_w_m2 =
            w.sky_exposure * clear_sky_direct_normal_w_m2(sp.zenith_deg, sp.earth_sun_distance_au);
    if (w.diffuse_horizontal_w_m2 >= 0)
        e.diffuse_horizontal_w_m2 = w.diffuse_horizontal_w_m2;
    else
        e.diffuse_horizontal_w_m2 = w.sky_exposure * clear_sky_diffuse_horizontal_w_m2(
                                                         sp.zenith_deg, sp.earth_sun_distance_au);
    if (summary && (w.direct_horizontal_w_m2 < 0 || w.diffuse_horizontal_w_m2 < 0))
        ++summary->computed_insolation_steps;
    return e;
}

}  // namespace

std::vector<EnvironmentStep> sample_environment(const io::Wth& wth, const std::string& wth_file,
                                                const io::Snd& snd, double start_h, double end_h,
                                                double step_s, EnvironmentSummary* summary) {
    if (!(step_s > 0) || !(end_h >= start_h)) throw Error("environment: bad time grid");
    interpolate_weather(wth, start_h, wth_file);  // both ends covered, or a message
    interpolate_weather(wth, end_h, wth_file);
    const double step_h = step_s / 3600.0;
    const long n = static_cast<long>(std::ceil((end_h - start_h) / step_h - 1e-9));
    std::vector<EnvironmentStep> out;
    out.reserve(static_cast<std::size_t>(n + 1));
    for (long i = 0; i <= n; ++i) {
        double t = i == n ? end_h : start_h + static_cast<double>(i) * step_h;
        out.push_back(environment_at(wth, wth_file, snd, t, summary));
    }
    return out;
}

}  // namespace sigchain::thermal
