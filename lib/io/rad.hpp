// .rad radiance tables, one per sensor band (White (1996), fig. 4.33; man rad(5)): solar and
// path terms per spectral sample and view angle, plus sigchain's sky hemisphere.
//
// Units throughout: irradiance W cm-2 um-1, radiance W cm-2 sr-1 um-1 (per
// micrometre; rad(5) explains why the "per cm-1" labels of White (1996) are not followed),
// wavelength um, wavenumber cm-1, angles degrees, distances km.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// One spectral sample: the sun-to-ground terms.
struct RadSample {
    double wavelength_um = 0;  // = 1e4 / wavenumber_cm1
    double wavenumber_cm1 = 0;
    double solar_irradiance = 0;  // Es, exoatmospheric, W cm-2 um-1, >= 0
    double sun_transmission = 0;  // tau1, sun to ground, [0, 1]
    bool operator==(const RadSample&) const = default;
};

// The ground-to-sensor terms of one spectral sample along one view angle.
struct RadPathSample {
    double transmission = 0;        // tau2, ground to sensor, [0, 1]
    double emitted_radiance = 0;    // L_ue, upwelled path emission, >= 0
    double scattered_radiance = 0;  // L_us, upwelled path scattering, >= 0
    bool operator==(const RadPathSample&) const = default;
};

// One view-angle block.
struct RadView {
    double view_angle_deg = 0;        // from nadir, signed as build_radiance lays them out
    double range_km = 0;              // ground to sensor along the view, > 0
    std::vector<RadPathSample> path;  // one per spectral sample
    bool operator==(const RadView&) const = default;
};

// One cell of the downwelled sky hemisphere above a horizontal ground facet.
// Frame: zenith from local up; azimuth clockwise from north (scene ENU: y north).
struct RadSkyCell {
    double zenith_deg = 0;                   // cell centre, [0, 90]
    double azimuth_deg = 0;                  // cell centre, [0, 360)
    double solid_angle_sr = 0;               // > 0
    std::vector<double> scattered_radiance;  // L_ds per spectral sample, >= 0
    std::vector<double> emitted_radiance;    // L_de per spectral sample, >= 0
    bool operator==(const RadSkyCell&) const = default;
};

// One cell of the upwelled path-radiance grid (SIGCHAIN_RAD 1.1): the path terms for
// a line of sight from the sensor at a view zenith (off nadir) and an azimuth.
struct RadUpwelledCell {
    double view_zenith_deg = 0;              // line of sight off nadir, [0, 90)
    double azimuth_deg = 0;                  // of the line of sight's horizontal part,
                                             // clockwise from north, [0, 360)
    std::vector<double> scattered_radiance;  // L_us per spectral sample, >= 0
    std::vector<double> emitted_radiance;    // L_ue per spectral sample, >= 0
    bool operator==(const RadUpwelledCell&) const = default;
};

// L_us and L_ue over view zenith x azimuth (optional, SIGCHAIN_RAD 1.1): the full
// azimuth dependence the legacy view-angle table keeps in one vertical plane only.
struct RadUpwelled {
    long zenith_count = 0;               // rings (view zeniths, increasing)
    long azimuth_count = 0;              // cells per ring (same azimuths in every ring, increasing)
    std::vector<RadUpwelledCell> cells;  // ring by ring
    bool operator==(const RadUpwelled&) const = default;
};

// The coupling of the atmosphere with the ground (optional, SIGCHAIN_RAD 1.2; Tanre
// et al. 1981, Vermote et al. 1997): what turns the black-ground tables into those of
// a Lambertian ground and environment (rad(5) COUPLING, trace(1) RADIOMETRY).
struct RadCoupling {
    std::vector<double> spherical_albedo;  // S per spectral sample, [0, 1]
    // t_d_down per spectral sample, [0, 1]: diffuse irradiance at the (black) ground
    // per unit direct normal irradiance above the atmosphere, E_diffuse / (mu_s Es).
    std::vector<double> diffuse_down;
    // t_d_up per legacy view angle (the views' order), per spectral sample, [0, 1]:
    // diffuse radiance at the sensor per unit isotropic ground radiance.
    std::vector<std::vector<double>> diffuse_up;
    bool operator==(const RadCoupling&) const = default;
};

// sigchain's additions after the legacy tables (SIGCHAIN_RAD block).
struct RadSky {
    long version_minor = 0;      // SIGCHAIN_RAD 1[.minor]
    double sun_zenith_deg = 0;   // [0, 180]; > 90 is below the horizon
    double sun_azimuth_deg = 0;  // [0, 360), clockwise from north
    long zenith_count = 0;       // rings of the hemisphere grid
    long azimuth_count = 0;      // cells per ring
    // zenith_count * azimuth_count cells, ring by ring (zenith increasing), azimuth
    // increasing within a ring; every ring has the same azimuths; solid angles sum to 2 pi.
    std::vector<RadSkyCell> cells;
    std::optional<RadUpwelled> upwelled;  // after the sky cells; needs version 1.1
    std::optional<RadCoupling> coupling;  // after those; needs version 1.2
    bool operator==(const RadSky&) const = default;
};

struct Rad {
    double sensor_altitude_km = 0;
    double min_wavelength_um = 0;  // = 1e4 / max_wavenumber_cm1
    double max_wavelength_um = 0;  // = 1e4 / min_wavenumber_cm1
    double min_wavenumber_cm1 = 0;
    double max_wavenumber_cm1 = 0;
    double wavenumber_increment_cm1 = 0;
    double min_view_angle_deg = 0;
    double max_view_angle_deg = 0;
    double view_angle_increment_deg = 0;
    double placeholder = 999;  // header line 11, unused ("N/A" in White (1996))
    // max_wavenumber_cm1 down to min_wavenumber_cm1 by the increment (wavelength increasing).
    std::vector<RadSample> samples;
    // min_view_angle_deg up to max_view_angle_deg by the increment.
    std::vector<RadView> views;
    std::optional<RadSky> sky;  // absent in a DIRSIG file; always written by sigchain
    bool operator==(const Rad&) const = default;
};

Rad parse_rad(const TextInput& in);
void write_rad(std::ostream& out, const Rad& rad);
inline Rad read_rad_file(const std::string& path) { return parse_rad(TextInput::from_file(path)); }
// read_rad_file of every path, the files spread over `threads` threads (0: every core;
// parallel_for), in the paths' order. A file that fails throws what read_rad_file
// throws for it: the first such file in the paths' order, whatever the threads did.
std::vector<Rad> read_rad_files(const std::vector<std::string>& paths, unsigned threads = 0);
FormatHandler rad_format();

}  // namespace sigchain::io
