// build_radiance's options: the solver, the sky and upwelled grids, and the modelled
// column's own (atmos::ColumnOptions: data, top, wavenumbers; man build_radiance(1)).
// Shared by the spectral samples and the job.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "atmos/column_options.hpp"

namespace sigchain::atmos_table {

// RadianceOptions::streams for --streams auto.
inline constexpr int kAutoStreams = 0;
// --stream-tolerance's and --merge-tau's defaults.
inline constexpr double kDefaultStreamTolerance = 0.01;
inline constexpr double kDefaultMergeTau = 0.01;

// The column's options (data_dir, snd_path, top_km, wavenumbers_cm1) and the builder's.
struct RadianceOptions : atmos::ColumnOptions {
    std::string cdk_path = "<cdk>";  // named in messages about the card deck
    int streams = 16;                // discrete ordinates (even, 4-64), or
                                     // kAutoStreams: chosen per band (stream_choice.hpp)
    // --streams auto: the relative error allowed, as estimated against twice as many
    // streams.
    double stream_tolerance = kDefaultStreamTolerance;
    double sky_zenith_step_deg = 5;          // downwelled hemisphere rings (90 / step rings)
    double sky_azimuth_step_deg = 10;        // cells per ring: 360 / step
    int sky_subsamples = 2;                  // per cell and axis: the cell's radiance is the
                                             // solid-angle mean of subsamples^2 directions
    double upwelled_azimuth_step_deg = 10;   // azimuth nodes of the UPWELLED grid (rad(5))
    std::optional<double> view_azimuth_deg;  // azimuth of positive view angles (clockwise
                                             // from north); default: the deck's PSIPO
    double thermal_min_wavelength_um = 2.5;  // layer emission solved at and above this
    std::optional<double> merge_tau;         // the solver merges consecutive layers while
                                             // their optical depth stays within this (0:
                                             // never); default: merge_tau(options)
    bool coupling = true;                    // solve and write the COUPLING terms (rad(5)):
                                             // one more solve per sample (benchmarks turn it
                                             // off to measure it)
    int max_gas_terms = 12;                  // exponential-sum terms per gas in the solver
                                             // (1: one equivalent Beer's-law depth per layer)
    bool gas_pairs = true;                   // fit a second, strongly overlapping gas too
                                             // (GasColumn::absorption_terms; benchmarks
                                             // turn it off to measure it)
    unsigned threads = 0;                    // worker threads (0: every core); results do
                                             // not depend on it
};

// The optical depth up to which the solver merges thin layers: options.merge_tau when
// given; else with --streams auto kDefaultMergeTau sqrt(stream_tolerance /
// kDefaultStreamTolerance), else kDefaultMergeTau. A merged slab is solved as one
// homogeneous layer; single scattering stays exact, so the error is that of the
// multiple scattering within a slab, second order in its depth: on the Hawkeye deck of
// White (1996), section 4.2.3, the worst table entry moves by 2.6e-4, 1.0e-3 and 7e-3 at
// 0.01, 0.02 and 0.05, 2.6 tau^2 (build_radiance(1), --merge-tau). The square root keeps
// that error the same fraction (about 1/40 there) of the tolerance asked of the streams:
// 0.01 at the default 1 %, 0.022 at 5 %.
inline double merge_tau(const RadianceOptions& o) {
    if (o.merge_tau) return *o.merge_tau;
    if (o.streams != kAutoStreams) return kDefaultMergeTau;
    return kDefaultMergeTau * std::sqrt(o.stream_tolerance / kDefaultStreamTolerance);
}

// Throws UsageError for an option out of range (streams, sky grid).
void check_radiance_options(const RadianceOptions& options);

}  // namespace sigchain::atmos_table
