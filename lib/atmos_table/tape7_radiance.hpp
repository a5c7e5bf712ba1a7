// build_radiance with LOWTRAN 7 or MODTRAN as the solver (man build_radiance(1) TAPE7,
// t7m(5), tape7(5)): as DIRSIG 3's build_radiance ran LOWTRAN 7 once per path and
// assembled the results (White (1996), section 4.2.3.7), this writes one LOWTRAN 7
// deck per path the .rad needs and a run list (.t7m), then assembles the .rad of each
// band from the TAPE7s the user's runs wrote.
//
// Units: wavenumber cm-1, wavelength um, altitude km, angles degrees; the .rad's
// irradiance W cm-2 um-1 and radiance W cm-2 sr-1 um-1 (TAPE7's per cm-1 converted).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "atmos_table/radiance_options.hpp"
#include "io/cdk.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"
#include "io/t7m.hpp"

namespace sigchain::atmos_table {

// The decks of every run and the run list naming their TAPE7s.
struct Tape7Decks {
    io::T7m list;
    std::vector<std::pair<std::string, io::Cdk>> decks;  // file name (.tp5), one-run deck
};

// One deck per path, from the card deck's first run (its atmosphere, aerosols, IMULT
// and profile kept; SALB 0, a black ground as rad(5) tables are): the sun path
// (IEMSCT 3, ground to space at the sun's zenith), each view angle of `snd` (IEMSCT 2,
// sensor to ground) and each cell centre of the sky grid of `options` (IEMSCT 2, ground
// to space); the sun is given as IPARM 2 (its zenith and the line of sight's azimuth
// relative to it) computed as build_radiance does (NREL SPA at the target). IEMSCT 1
// and no sun run when the sun is below the horizon; IEMSCT 1 runs too for a deck of
// IEMSCT 1, whose tables then have Es and tau1 0. DataError for IEMSCT 0 and 3
// (iemsct_refusal). CARD 4 spans every band's samples with half an increment on either
// side, DV the smallest band increment rounded down to a multiple of 5 cm-1, within 5
// to 20 cm-1 (LOWTRAN 7's step and resolution).
Tape7Decks tape7_decks(const io::Cdk& deck, const io::Snd& snd, const RadianceOptions& options);

// The .rad of every band of `snd` from the TAPE7s of `list` (file names relative to
// `list_dir`). Each sample is the mean over the sample's interval (its wavenumber +-
// half the band's increment, within the TAPE7's range) of the TAPE7 values,
// piecewise linear in wavenumber, converted to per um row by row. Throws DataError
// (at the list or the TAPE7) for a run missing, set up for another path or sun, or
// not covering a sample; the sky grid, sun and view azimuth come from the list and
// must agree with `snd` and `options.view_azimuth_deg` (when given) within 0.01 deg.
std::vector<io::Rad> tape7_radiance(const io::T7m& list, const std::string& list_path,
                                    const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& options);

}  // namespace sigchain::atmos_table
