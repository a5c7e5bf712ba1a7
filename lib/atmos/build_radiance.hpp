// build_radiance: the atmosphere tables of one scene (seed 3.4, 4.2.3.7; man
// build_radiance(1), rad(5)). From a LOWTRAN 7 card deck (atmosphere, aerosols, ground
// altitude, path azimuth) and a scene node (sensor altitude, bands, view angles, date,
// time, place) it builds a layered plane-parallel atmosphere, solves the radiative
// transfer with multiple scattering over a black surface at every spectral sample, and
// fills one io::Rad per band.
//
// Units: wavenumber cm-1, wavelength um, altitude km, angles degrees, irradiance
// W cm-2 um-1, radiance W cm-2 sr-1 um-1.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atmos/aerosol.hpp"
#include "atmos/gas_absorption.hpp"
#include "atmos/profile.hpp"
#include "io/cdk.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"

namespace sigchain::atmos {

struct RadianceOptions {
    std::string data_dir;                 // reference data (core/data_dir.hpp)
    std::string snd_path = "<snd>";       // named in messages about the scene node
    std::string cdk_path = "<cdk>";       // and about the card deck
    int streams = 16;                     // discrete ordinates (even, >= 4)
    double sky_zenith_step_deg = 5;       // downwelled hemisphere rings (90 / step rings)
    double sky_azimuth_step_deg = 10;     // cells per ring: 360 / step
    int sky_subsamples = 2;               // per cell and axis: the cell's radiance is the
                                          // solid-angle mean of subsamples^2 directions
    double upwelled_azimuth_step_deg = 10;  // azimuth nodes of the UPWELLED grid (rad(5))
    std::optional<double> view_azimuth_deg;  // azimuth of positive view angles (clockwise
                                             // from north); default: the deck's PSIPO
    double top_km = 100;                  // top of the modelled atmosphere
    double thermal_min_wavelength_um = 2.5;  // layer emission solved at and above this
    double merge_tau = 0.01;              // the solver merges consecutive layers while
                                          // their optical depth stays within this (0: never)
    unsigned threads = 0;                 // worker threads (0: every core); results do
                                          // not depend on it
    std::function<void(long done, long total)> progress;  // per spectral sample
};

// What was computed, for --verbose and tests.
struct RadianceReport {
    double sun_zenith_deg = 0, sun_azimuth_deg = 0;
    double earth_sun_distance_au = 1;
    double view_azimuth_deg = 0;
    double ground_km = 0, sensor_km = 0;
    double visibility_km = 0;
    std::size_t layers = 0;
    long thermal_samples = 0;  // samples where layer emission was solved
    // Per band and spectral sample (in the .rad's order): the diffuse downward
    // irradiance at the ground from the solver's fluxes (scattered + emitted),
    // W cm-2 um-1, to check the hemisphere against.
    std::vector<std::vector<double>> ground_diffuse_irradiance;
    std::vector<std::string> notes;  // what was skipped or assumed
};

// The optical properties of one layer at one wavenumber.
struct LayerOptics {
    double tau_rayleigh = 0;
    double tau_aerosol = 0;  // extinction
    double ssa_aerosol = 0;
    double g_aerosol = 0;
    double tau_gas = 0;      // equivalent Beer's-law absorption (GasColumn)
};

// The column between the ground and the top: levels, aerosols and gases.
class ColumnModel {
public:
    ColumnModel(const io::CdkRun& run, double sensor_km, const RadianceOptions& options);
    ColumnModel(const ColumnModel&) = delete;
    ColumnModel& operator=(const ColumnModel&) = delete;

    const Profile& profile() const { return m_profile; }
    std::size_t sensor_level() const { return m_sensor_level; }  // index into profile levels
    double visibility_km() const { return m_aerosol->visibility_km(); }

    // Every layer (bottom first, profile().size() - 1 of them) at wavenumber nu.
    std::vector<LayerOptics> layers(double nu_cm1) const;

    // Equivalent Beer's-law gas absorption depth of every layer (bottom first) such that
    // the vertical band-model transmittance from level `pivot` to every other level is
    // reproduced exactly. The band model is not multiplicative (a layer absorbs less
    // behind a path that has saturated its lines), so no one set of layer depths is
    // exact for every path: pivot = top suits the solar beam (layers() uses it),
    // pivot = 0 the emission reaching the ground (L_de), pivot = the sensor level the
    // emission reaching the sensor (L_ue).
    std::vector<double> gas_depths_from(double nu_cm1, std::size_t pivot) const;
    static std::vector<LayerOptics> with_gas_depths(std::vector<LayerOptics> layers,
                                                    const std::vector<double>& gas);

    // Direct (unscattered) transmittance between levels i < j at cosine of zenith mu:
    // band-model gas transmittance times exp(-(Rayleigh + aerosol extinction) / mu).
    double direct_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                std::size_t level_i, std::size_t level_j, double mu) const;

private:
    Profile m_profile;
    std::size_t m_sensor_level = 0;
    std::optional<AerosolModel> m_aerosol;
    std::unique_ptr<GasTables> m_gas_tables;  // GasColumn may refer to both: the model
    std::unique_ptr<GasColumn> m_gas;         // is neither copied nor moved
};

// The output name of band `band` (1-based) of `band_count`: every "%d" in `pattern`
// becomes the band number and "%%" a literal "%". A pattern without "%d" names the
// only band; with several bands that is a UsageError, as is any other "%" sequence.
std::string band_output_path(const std::string& pattern, int band, int band_count);

// Throws UsageError for an option out of range (streams, sky grid).
void check_radiance_options(const RadianceOptions& options);

// The tables of every band of `snd` (one io::Rad each, in the .snd's band order).
// Uses the deck's first run. Throws DataError for what cannot be modelled (naming the
// card or the .snd field), Error for an inconsistent request.
std::vector<io::Rad> build_radiance(const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& options,
                                    RadianceReport* report = nullptr);

}  // namespace sigchain::atmos
