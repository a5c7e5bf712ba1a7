// What build_radiance makes of a LOWTRAN 7 deck's fields (man build_radiance(1), DECK
// FIELDS): the fields it honours (IEMSCT 1 and 2, IMULT, SALB, IPH 0 with G, the sun of
// CARD 3A1/3A2 checked against the scene node's), and the refusals, each naming its
// card, field and columns (man cdk(5)). control7 asks deck_refusals() too, so that it
// never writes a deck build_radiance refuses without saying so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/cdk.hpp"

namespace sigchain::atmos_table {

// The deck's choices build_radiance honours beyond the column itself.
struct DeckChoices {
    bool single_scattering = false;  // IMULT 0: solar scattering of first order only
    double surface_albedo = 0;       // SALB: Lambertian ground coupled to the sky
    bool solar = true;               // IEMSCT 2; IEMSCT 1 (thermal radiance only): no sun,
                                     // Es, tau1, L_us, L_ds and t_d_down are 0
};

// The refusal of CARD 1 IEMSCT, or nothing: 1 (thermal radiance) and 2 (with solar
// scattering) are honoured; 0 (transmittance) and 3 (directly transmitted solar
// irradiance) compute no radiance, so the tables' radiances would be false zeros.
std::optional<std::string> iemsct_refusal(const io::CdkCard1& card1);

DeckChoices deck_choices(const io::CdkRun& run);
// What those choices mean for the tables, one note each (build_radiance -v).
std::vector<std::string> deck_notes(const io::CdkRun& run);

// Every reason build_radiance refuses the deck, one message each ("CARD 1 TBOUND
// (columns 66-73) is 290: ..."), first run first; empty when the deck is accepted.
std::vector<std::string> deck_refusals(const io::Cdk& deck);

// Throws DataError (file cdk_path, no line: the parsed deck keeps none) with the first
// of deck_refusals().
void check_deck(const io::Cdk& deck, const std::string& cdk_path);

// The sun the deck's CARD 3A1/3A2 describe (IEMSCT 2), as seen from the target:
// zenith and azimuth (deg, clockwise from north). IPARM 0: observer and sub-solar
// point (spherical Earth); IPARM 1: observer, IDAY and Greenwich TIME (NREL SPA in
// `year`, which the deck does not give); IPARM 2: solar zenith PARM2 and azimuth
// view_azimuth - PARM1 (PARM1 is the sun's azimuth relative to the line of sight).
struct DeckSun {
    double zenith_deg = 0, azimuth_deg = 0;
};
std::optional<DeckSun> deck_sun(const io::CdkRun& run, int year, double view_azimuth_deg);

// Angle (deg) between two sun directions.
double sun_separation_deg(const DeckSun& a, const DeckSun& b);

// The deck's sun and the scene node's agree within this (deg): the deck's fields are
// F10.3 (TIME to 1.8 s moves the sun <= 0.008 deg) and LOWTRAN's sun is geometric while
// the scene's (SPA) is refracted, by 0.03 deg at 60 deg zenith and 0.17 deg at 85 deg;
// one minute of time moves the sun by up to 0.25 deg, a wrong hour by ~15 deg.
inline constexpr double kSunAgreement_deg = 0.25;

}  // namespace sigchain::atmos_table
