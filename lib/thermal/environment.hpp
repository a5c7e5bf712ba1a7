// The surroundings that drive a facet's temperature (White (1996), section 3.4; wth(5)): weather
// interpolated in time, sky long-wave emission, convection, solar irradiance and the
// sun's direction, sampled on the thermal model's time grid.
#pragma once

#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "io/snd.hpp"
#include "io/wth.hpp"

namespace sigchain::thermal {

inline constexpr double kStefanBoltzmann = 5.670374419e-8;  // W m-2 K-4 (CODATA 2018)
inline constexpr double kWattsPerSquareMeterPerLangleyPerHour = 41840.0 / 3600.0;  // 11.62

// The weather at one time, linearly interpolated between the .wth rows around it.
struct WeatherSample {
    double air_k = 0;
    double vapour_pressure_hpa = 0;
    double wind_m_s = 0;
    double direct_horizontal_w_m2 = 0;   // from the file; < 0: compute (the file gives 0)
    double diffuse_horizontal_w_m2 = 0;  // from the file; < 0: compute
    double sky_exposure = 1;             // 0 overcast .. 1 clear
};

// Throws DataError naming `file` when time_h lies outside the rows.
WeatherSample interpolate_weather(const io::Wth& wth, double time_h, const std::string& file);

// Saturation vapour pressure over water, hPa: Magnus form with Alduchov & Eskridge
// (1996, J. Appl. Meteor. 35, 601) coefficients, 6.1094 exp(17.625 t / (t + 243.04)).
double saturation_vapour_pressure_hpa(double t_c);
// The row's vapour pressure: from the relative humidity, or the dew point when it is -1.
double vapour_pressure_hpa(const io::WthRow& row);

// Clear-sky effective emissivity, Brutsaert (1975, Water Resour. Res. 11, 742):
// 1.24 (e / T)^(1/7), e in hPa, T in K.
double clear_sky_emissivity(double air_k, double vapour_pressure_hpa);
// With a cloud fraction c (1 - sky exposure): Crawford & Duchon (1999, J. Appl.
// Meteor. 38, 474) eq. 20, c + (1 - c) eps_clear.
double sky_emissivity(double clear_sky_emissivity, double cloud_fraction);

// Convective heat-transfer coefficient, W m-2 K-1, McAdams (1954) as given by
// Watmuff, Charters & Proctor (1977): h = 5.7 + 3.8 v, v the wind speed in m/s.
double convection_coefficient(double wind_m_s);

// Relative air mass, Kasten & Young (1989, Appl. Opt. 28, 4735); zenith in degrees
// (refracted), valid to the horizon.
double air_mass(double zenith_deg);

// Clear-sky direct normal irradiance, W m-2, Meinel & Meinel (1976) with the
// Earth-Sun distance: 1353 / R^2 x 0.7^(AM^0.678); 0 with the sun below the horizon.
double clear_sky_direct_normal_w_m2(double zenith_deg, double earth_sun_au);
// Clear-sky diffuse irradiance on a horizontal surface: 10 % of the direct beam on it
// (Meinel & Meinel 1976, global = 1.1 x direct), 0.1 x DNI x cos(zenith).
double clear_sky_diffuse_horizontal_w_m2(double zenith_deg, double earth_sun_au);

// The environment at one time on the thermal grid.
struct EnvironmentStep {
    double time_h = 0;  // the .wth clock: hours from midnight of the day before
    double air_k = 0;
    double convection_w_m2_k = 0;   // h
    double sky_longwave_w_m2 = 0;   // eps_sky sigma T_air^4, the whole sky hemisphere
    double direct_normal_w_m2 = 0;  // beam irradiance on a surface facing the sun
    double diffuse_horizontal_w_m2 = 0;
    geo::Vec3 sun{0, 0, 1};  // unit vector toward the sun, scene frame (x E, y N, z up)
    bool sun_up = false;
};

struct EnvironmentSummary {
    long computed_insolation_steps = 0;  // steps whose insolation was computed (file gave 0)
};

// Samples from start_h to end_h (inclusive) every step_s seconds (the last step may
// be shorter so that end_h is a sample). Throws DataError naming wth_file when the
// weather does not cover the interval.
std::vector<EnvironmentStep> sample_environment(const io::Wth& wth, const std::string& wth_file,
                                                const io::Snd& snd, double start_h, double end_h,
                                                double step_s, EnvironmentSummary* summary);

}  // namespace sigchain::thermal
