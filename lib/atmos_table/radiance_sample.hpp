// One spectral sample of build_radiance: the column at one wavenumber handed to the
// discrete-ordinate solver (solar scattering, and layer emission in the thermal
// infrared) and the table entries read from its intensities. Internal to lib/atmos_table.
#pragma once

#include <optional>
#include <vector>

#include "atmos/column_model.hpp"
#include "atmos/mie_layers.hpp"
#include "atmos/solar_spectrum.hpp"
#include "atmos_table/deck_options.hpp"
#include "atmos_table/radiance_directions.hpp"
#include "atmos_table/radiance_options.hpp"
#include "io/rad.hpp"

namespace sigchain::atmos_table {

// What every sample shares: the column, the directions, the sun. Read-only while the
// samples are solved, so one setup serves every thread.
struct SampleSetup {
    const atmos::ColumnModel& column;
    const Directions& dirs;
    const atmos::SolarSpectrum& solar;
    const RadianceOptions& options;
    const std::vector<double>& views_deg;  // view angles, deg from nadir
    double mu0 = 1;                        // cosine of the sun's zenith
    bool sun_up = false;
    double distance_factor = 1;  // (1 AU / Earth-Sun distance)^2
    int moments = 0;             // phase-function moments handed to the solver
    DeckChoices deck;            // IMULT 0 (single scattering), SALB (ground in the sky)
    // IPH 2: the Mie functions at the sample's wavelength (solve_sample sets it when
    // column.mie()).
    const atmos::MieOptics* mie = nullptr;
};

// The table entries of one spectral sample (radiances W cm-2 sr-1 um-1).
struct SampleResult {
    io::RadSample sample;
    std::vector<io::RadPathSample> path;  // per view
    std::vector<double> ls, le;           // per sky cell: scattered, emitted
    std::vector<double> us, ue;           // per upwelled cell: scattered, emitted
    double ground_irradiance = 0;         // diffuse downward at the ground, W cm-2 um-1
    // The coupling terms (rad(5) COUPLING; rt/coupling.hpp): spherical albedo S, the
    // sun beam's diffuse transmittance to the ground t_d_down = E_diffuse / (mu0 Es)
    // (0 with the sun down) and t_d_up per view (per unit isotropic ground radiance).
    double spherical_albedo = 0, diffuse_down = 0;
    std::vector<double> diffuse_up;
    bool thermal = false;                 // layer emission solved
    int terms = 1;                        // exponential-sum terms solved (gas_terms)
};

// What every solve of a sample shares, whatever its streams (prepare_sample): the
// column's layers, the Mie functions (with `moments` moments), the sun and the
// exponential-sum terms.
struct SamplePrep {
    double nu = 0;  // cm-1
    int moments = 0;
    std::optional<atmos::MieOptics> mie;  // IPH 2 only (and when the setup has none)
    std::vector<atmos::LayerOptics> col;  // bottom first
    io::RadSample sample;
    atmos::GasColumn::Terms terms;
    bool thermal = false;  // layer emission solved
};
SamplePrep prepare_sample(const SampleSetup& setup, double nu_cm1);

// Solves the sample at wavenumber nu_cm1. Thread-safe for one setup.
SampleResult solve_sample(const SampleSetup& setup, double nu_cm1);
// The same from its preparation, which must have been made with setup's moments (else
// sigchain::Error): the probes of --streams auto solve one sample at several streams.
SampleResult solve_sample(const SampleSetup& setup, const SamplePrep& prep);

}  // namespace sigchain::atmos_table
