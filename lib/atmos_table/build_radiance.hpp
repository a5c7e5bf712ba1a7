// build_radiance: the atmosphere tables of one scene (White (1996), section 3.4, 4.2.3.7; man
// build_radiance(1), rad(5)). From a LOWTRAN 7 card deck (atmosphere, aerosols, ground
// altitude, path azimuth) and a scene node (sensor altitude, bands, view angles, date,
// time, place) it builds a layered plane-parallel atmosphere, solves the radiative
// transfer with multiple scattering over a black surface at every spectral sample, and
// fills one io::Rad per band.
//
// Units: wavenumber cm-1, wavelength um, altitude km, angles degrees, irradiance
// W cm-2 um-1, radiance W cm-2 sr-1 um-1.
#pragma once

#include <string>
#include <vector>

#include "atmos/column_model.hpp"
#include "atmos_table/radiance_options.hpp"
#include "atmos_table/stream_choice.hpp"
#include "core/report.hpp"
#include "io/cdk.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"

namespace sigchain::atmos_table {

// What was computed, for --verbose and tests.
struct RadianceReport {
    double sun_zenith_deg = 0, sun_azimuth_deg = 0;
    double earth_sun_distance_au = 1;
    double view_azimuth_deg = 0;
    double ground_km = 0, sensor_km = 0;
    double visibility_km = 0;
    std::size_t layers = 0;
    double merge_tau = 0;      // the solver merged thin layers up to this optical depth
    std::string merge_rule;    // why that depth (--merge-tau, --streams auto), or empty
    long thermal_samples = 0;  // samples where layer emission was solved
    long gas_term_solves = 0;  // columns solved: one per sample, or its exponential-sum terms
    // Per band and spectral sample (in the .rad's order): the diffuse downward
    // irradiance at the ground from the solver's fluxes (scattered + emitted),
    // W cm-2 um-1, to check the hemisphere against.
    std::vector<std::vector<double>> ground_diffuse_irradiance;
    std::vector<std::string> notes;  // what was skipped or assumed
    // Per band, the streams solved with; with --streams auto also how they were chosen
    // (stream_choice.hpp), else only `streams` is set.
    std::vector<StreamChoice> band_streams;
};

// The output name of band `band` (1-based) of `band_count`: every "%d" in `pattern`
// becomes the band number and "%%" a literal "%". A pattern without "%d" names the
// only band; with several bands that is a UsageError, as is any other "%" sequence.
std::string band_output_path(const std::string& pattern, int band, int band_count);

// The .snd's view angles (min to max by the increment); DataError naming `snd_path` for
// one within 0.5 deg of the horizon.
std::vector<double> view_angles(const io::Snd& snd, const std::string& snd_path);

// A band's .rad without its samples: spectral range, view angles and their ranges to
// the ground (height_km / cos(view), height_km: sensor above the ground).
io::Rad rad_header(const io::SndBand& band, const io::Snd& snd, const std::vector<double>& views,
                   double height_km);

// The tables of every band of `snd` (one io::Rad each, in the .snd's band order).
// Uses the deck's first run. The spectral samples are solved on options.threads
// threads, their progress shown on `reporter` ("spectral samples"); the tables do not
// depend on the thread count. Throws DataError for what cannot be modelled (naming the
// card or the .snd field), Error for an inconsistent request.
std::vector<io::Rad> build_radiance(const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& options,
                                    RadianceReport* report = nullptr,
                                    const Reporter& reporter = Reporter{});

}  // namespace sigchain::atmos_table
