// build_radiance --streams auto: the fewest discrete ordinates a band needs for the
// entries its tables hold (man build_radiance(1), STREAMS). Internal to lib/atmos_table.
//
// The rule: for N = 4, 6, 8, 12, 16, 24, 32 in turn, the band's probe samples (its
// centre sample and its most scattering one) are solved, each with one equivalent gas
// depth, with N and with 2N streams; N's error is estimated as twice the largest
// relative difference of its tables from 2N's (an error falling at least as 1/N:
// stream_choice.cpp), and the first N whose estimate is within the tolerance is the
// band's (the estimate is checked against 32 streams in
// tests/unit/atmos_table/stream_choice_test.cpp).
#pragma once

#include <array>
#include <vector>

#include "atmos_table/radiance_sample.hpp"
#include "io/snd.hpp"

namespace sigchain::atmos_table {

// The orders --streams auto chooses from, ascending.
inline constexpr std::array<int, 7> kStreamCandidates{4, 6, 8, 12, 16, 24, 32};

// What was chosen for one band (--verbose, tests).
struct StreamChoice {
    int streams = 0;                        // the band's streams
    int check_streams = 0;                  // the order it was compared with (2 streams)
    double estimated_error = 0;             // twice the largest table_difference from 2N
    bool within_tolerance = true;           // false: no candidate agreed; the largest is used
    std::vector<double> probe_wavenumbers;  // cm-1, the samples compared
};

// The band's probe samples (cm-1): its centre sample and the sample with the largest
// scattering optical depth of the column (Rayleigh plus aerosol scattering), once if
// they coincide.
std::vector<double> probe_wavenumbers(const atmos::ColumnModel& column, const io::SndBand& band);

// The largest relative difference of `a` from the reference `b` over every entry the
// .rad holds of a sample. Radiances (path, sky and upwelled; scattered and emitted):
// each against its reference value, or against a thousandth of the largest reference
// entry of its table where that is larger (an entry a thousand times fainter than its
// table's brightest does not set the streams). The coupling terms through the radiance
// each one changes (stream_choice.cpp): |dS| / (1 - S), |dt_d_down| / (tau1 +
// t_d_down), |dt_d_up| / (tau2 + t_d_up).
double table_difference(const SampleResult& a, const SampleResult& b);

// The stream choice of one band (the rule above) from `setup` (whose options' streams
// are ignored), comparing at `probes` (cm-1) with relative tolerance `tolerance`.
// Deterministic: the same inputs give the same choice on every thread count.
StreamChoice choose_streams(const SampleSetup& setup, const std::vector<double>& probes,
                            double tolerance);

// The phase-function moments handed to the solver at `streams` (at least the streams,
// and enough for the single-scattering correction: build_radiance.cpp).
int phase_moments(int streams);

}  // namespace sigchain::atmos_table
