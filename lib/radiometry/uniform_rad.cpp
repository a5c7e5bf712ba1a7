// A synthetic .rad of uniform sun, sky and path terms, for tests and benchmarks
// (declared in atmosphere.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/numeric.hpp"
#include "radiometry/atmosphere.hpp"

namespace sigchain::radiometry {

io::Rad uniform_rad(const std::vector<double>& wavelengths_um, double sun_zenith_deg,
                    double sun_azimuth_deg, double sun_irradiance_at_ground, double sky_radiance,
                    double tau2, double path_radiance, const std::vector<double>& view_angles_deg,
                    int zenith_rings, int azimuth_cells) {
    if (wavelengths_um.empty() || view_angles_deg.empty() || zenith_rings < 1 || azimuth_cells < 1)
        throw std::invalid_argument("uniform_rad: empty grid");
    std::vector<double> wl = wavelengths_um, va = view_angles_deg;
    std::sort(wl.begin(), wl.end());
    std::sort(va.begin(), va.end());
    io::Rad rad;
    rad.sensor_altitude_km = 1;
    rad.min_wavelength_um = wl.front(), rad.max_wavelength_um = wl.back();
    rad.min_wavenumber_cm1 = cm1_from_um(wl.back());
    rad.max_wavenumber_cm1 = cm1_from_um(wl.front());
    rad.wavenumber_increment_cm1 =
        wl.size() > 1 ? (rad.max_wavenumber_cm1 - rad.min_wavenumber_cm1) / (wl.size() - 1) : 0;
    rad.min_view_angle_deg = va.front(), rad.max_view_angle_deg = va.back();
    rad.view_angle_increment_deg = va.size() > 1 ? (va.back() - va.front()) / (va.size() - 1) : 0;
    for (double w : wl) rad.samples.push_back({w, cm1_from_um(w), sun_irradiance_at_ground, 1.0});
    for (double a : va) {
        io::RadView v;
        v.view_angle_deg = a;
        v.range_km = rad.sensor_altitude_km / std::cos(std::min(std::abs(a), 89.0) * kRadPerDeg);
        v.path.assign(wl.size(), io::RadPathSample{tau2, 0.0, path_radiance});
        rad.views.push_back(std::move(v));
    }
    io::RadSky sky;
    sky.sun_zenith_deg = sun_zenith_deg, sky.sun_azimuth_deg = sun_azimuth_deg;
    sky.zenith_count = zenith_rings, sky.azimuth_count = azimuth_cells;
    double dz = 90.0 / zenith_rings, da = 360.0 / azimuth_cells;
    for (int r = 0; r < zenith_rings; ++r)
        for (int c = 0; c < azimuth_cells; ++c) {
            io::RadSkyCell cell;
            cell.zenith_deg = (r + 0.5) * dz;
            cell.azimuth_deg = (c + 0.5) * da;
            // Exact: (cos z_lo - cos z_hi)(a_hi - a_lo).
            cell.solid_angle_sr =
                (std::cos(r * dz * kRadPerDeg) - std::cos((r + 1) * dz * kRadPerDeg)) * da *
                kRadPerDeg;
            cell.scattered_radiance.assign(wl.size(), sky_radiance);
            cell.emitted_radiance.assign(wl.size(), 0.0);
            sky.cells.push_back(std::move(cell));
        }
    rad.sky = std::move(sky);
    return rad;
}

}  // namespace sigchain::radiometry
