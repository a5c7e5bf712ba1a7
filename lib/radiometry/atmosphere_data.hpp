// The shared state of radiometry::Atmosphere (atmosphere.hpp), for the files that
// implement it: atmosphere.cpp and atmosphere_coupling.cpp. Internal to lib/radiometry.
#pragma once

#include <string>
#include <vector>

#include "radiometry/atmosphere.hpp"

namespace sigchain::radiometry {

struct Atmosphere::Data {
    SpectralGrid grid;
    bool sun_known = false;
    double sun_zenith_deg = 0, sun_azimuth_deg = 0;
    geo::Vec3 sun_direction{0, 0, 1};
    std::vector<double> es;             // Es per sample (exoatmospheric)
    std::vector<double> es_tau1;        // Es * tau1 per sample
    std::vector<double> sun_at_ground;  // es_tau1, or zeros when the sun is down
    // View angles (increasing) and, per view, per sample: tau2, L_us, L_ue.
    std::vector<double> view_angles_deg, range_km;
    std::vector<double> tau2, scattered, emitted;  // [view * samples + k]
    bool has_sky = false;
    std::vector<SkyCell> cells;           // ring by ring, azimuth increasing
    std::vector<double> ring_edges_deg;   // rings + 1 zenith edges, 0 .. 90
    std::vector<double> azimuth_hi_deg;   // upper azimuth edge of each column
    std::vector<double> ring_cos_edges;   // cos of the inner ring edges, decreasing
    double uniform_azimuth_step_deg = 0;  // > 0 when every column has this width
    int rings = 0, columns = 0;
    std::vector<double> sky_irradiance, sky_emitted_irradiance;  // horizontal, per sample
    // The UPWELLED grid (rad(5), SIGCHAIN_RAD 1.1) when every file has the same one:
    // view-zenith rings (increasing), azimuth nodes (increasing in [0, 360)), and per
    // node, per sample L_us and L_ue at [(ring * azimuths + a) * samples + k].
    bool has_upwelled = false;
    std::vector<double> up_zenith_deg, up_azimuth_deg;
    std::vector<double> up_scattered, up_emitted;

    bool sun_up() const { return sun_known && sun_zenith_deg < 90; }
    void place_sun(double zenith_deg, double azimuth_deg) {
        sun_known = true;
        sun_zenith_deg = zenith_deg;
        sun_azimuth_deg = azimuth_deg;
        sun_direction = geo::direction_from_degrees(zenith_deg, azimuth_deg);
        sun_at_ground = sun_up() ? es_tau1 : std::vector<double>(es_tau1.size(), 0.0);
    }
    void merge_spectra(const std::vector<io::Rad>& rads, const std::vector<std::string>& files);
    void merge_views(const std::vector<io::Rad>& rads);
    void build_sky_grid(const io::RadSky& sky);
    SkyCell merge_sky_cell(const std::vector<io::Rad>& rads, std::size_t c);
    // The COUPLING terms (rad(5), SIGCHAIN_RAD 1.2) when every file has them: per
    // sample S and t_d_down, and per view, per sample t_d_up at [view * samples + k].
    bool has_coupling = false;
    std::vector<double> spherical_albedo, diffuse_down, diffuse_up;
    void load_coupling(const std::vector<io::Rad>& rads, const std::vector<std::string>& files);
    void load_upwelled(const std::vector<io::Rad>& rads, const std::vector<std::string>& files);
};

}  // namespace sigchain::radiometry
