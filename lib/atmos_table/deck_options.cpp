// What build_radiance makes of a deck's fields (see deck_options.hpp).
#include "atmos_table/deck_options.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "atmos/cirrus.hpp"
#include "atmos/cloud.hpp"
#include "atmos/column_model.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "geo/solar_position.hpp"

namespace sigchain::atmos_table {

namespace {

std::string run_prefix(std::size_t k, std::size_t runs) {
    return runs > 1 ? "run " + std::to_string(k + 1) + ": " : "";
}

// The fields of one run that build_radiance refuses (man build_radiance(1), DECK FIELDS).
void run_refusals(const io::CdkRun& run, const std::string& pre, std::vector<std::string>& out) {
    const io::CdkCard1& c1 = run.card1;
    const io::CdkCard2& c2 = run.card2;
    auto refuse = [&](const std::string& what) { out.push_back(pre + what); };
    if (const auto why = iemsct_refusal(c1)) refuse(*why);
    if (c1.boundary_temperature_k != 0)
        refuse("CARD 1 TBOUND (columns 66-73) is " + format_number(c1.boundary_temperature_k) +
               " K: the ground's temperature and emission come from the scene, rad(5) tables "
               "hold none (use 0)");
    if (c2.icld != 0 && !atmos::CloudModel::modelled(c2.icld) &&
        !atmos::CirrusModel::modelled(c2.icld))
        refuse("CARD 2 ICLD (columns 21-25) is " + std::to_string(c2.icld) +
               ": the NOAA cirrus of LOWTRAN 6, its thickness and base drawn at random, is "
               "not modelled by build_radiance (use 0, the clouds and rain 1-10, or the "
               "cirrus 18-19)");
    if (run.user_optics && c2.icld >= 1 && c2.icld <= 11)
        for (int k = 2; k < 4; ++k) {  // IREG(2) is the cloud's
            if (!run.user_optics->regions[static_cast<std::size_t>(k)]) continue;
            refuse("CARD 2D IREG(" + std::to_string(k + 1) + ") (columns " +
                   std::to_string(5 * k + 1) + "-" + std::to_string(5 * k + 5) +
                   ") is 1 with ICLD " + std::to_string(c2.icld) +
                   ": with a cloud LOWTRAN 7 makes the cloud aerosol region 2 and moves the "
                   "troposphere and stratosphere up one region, which build_radiance does not "
                   "(it keeps its clouds apart from the four aerosol regions); use IREG(1) and "
                   "IREG(2) only, or ICLD 0");
        }
    if (c2.ivsa != 0)
        refuse(
            "CARD 2 IVSA (columns 26-30) is 1: the army vertical structure algorithm is not "
            "modelled by build_radiance (use 0)");
    if (c1.iemsct != 2) return;  // CARD 3A1 exists with IEMSCT 2 only
    const io::CdkGeometry& g = run.geometry;
    if (g.iph == 1)
        refuse(
            "CARD 3A1 IPH (columns 6-10) is 1: a user phase function (CARD 3B) is not "
            "supported (use 0, Henyey-Greenstein with G, or 2)");
    if (g.isourc == 1)
        refuse("CARD 3A1 ISOURC (columns 16-20) is 1: build_radiance's source is the sun (use 0)");
}

// Whether two runs describe the same atmosphere (CARD 1, 2, 2A, 2B, 2C).
bool same_atmosphere(const io::CdkRun& a, const io::CdkRun& b) {
    io::CdkCard1 c1a = a.card1, c1b = b.card1;
    c1a.itype = c1b.itype = 0;  // the path type is the .snd's
    c1a.noprt = c1b.noprt = 0;  // printing
    c1a.im = c1b.im = 0;        // a profile re-read or reused
    return c1a == c1b && a.card2 == b.card2 && a.cirrus == b.cirrus && a.vsa == b.vsa &&
           a.profile == b.profile && a.user_optics == b.user_optics &&
           a.geometry.iph == b.geometry.iph && a.geometry.asymmetry_g == b.geometry.asymmetry_g;
}

// Month and day of day-of-year `doy` (1-based) in `year`.
void month_day(int year, int doy, int& month, int& day) {
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    const int lengths[12] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    month = 1;
    while (month < 12 && doy > lengths[month - 1]) doy -= lengths[month++ - 1];
    day = std::clamp(doy, 1, lengths[month - 1]);
}

double wrap360(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360 : a;
}

// The sun over an observer from the sub-solar point (spherical Earth): zenith is the
// great-circle distance, azimuth the initial bearing toward it. Longitudes deg west.
DeckSun subsolar_sun(double lat, double lon_w, double sun_lat, double sun_lon_w) {
    const double p1 = lat * kRadPerDeg, p2 = sun_lat * kRadPerDeg;
    const double dl =
        (lon_w - sun_lon_w) * kRadPerDeg;  // east longitude difference, sun - observer
    const double c = std::sin(p1) * std::sin(p2) + std::cos(p1) * std::cos(p2) * std::cos(dl);
    const double az =
        std::atan2(std::sin(dl) * std::cos(p2),
                   std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl));
    return {std::acos(std::clamp(c, -1.0, 1.0)) / kRadPerDeg, wrap360(az / kRadPerDeg)};
}

}  // namespace

DeckChoices deck_choices(const io::CdkRun& run) {
    DeckChoices c;
    c.single_scattering = run.card1.imult == 0;
    c.surface_albedo = run.card1.surface_albedo;
    c.solar = run.card1.iemsct == 2;
    return c;
}

std::optional<std::string> iemsct_refusal(const io::CdkCard1& card1) {
    const std::string field = "CARD 1 IEMSCT (columns 11-15) is " + std::to_string(card1.iemsct);
    if (card1.iemsct == 0)
        return field +
               ": a transmittance run computes no radiance, and rad(5) tables hold path and "
               "sky radiances (use 1 for thermal radiance only, 2 with the sun)";
    if (card1.iemsct == 3)
        return field +
               ": a solar irradiance run computes only the sun's transmitted irradiance, and "
               "rad(5) tables hold path and sky radiances (use 2)";
    return std::nullopt;
}

std::vector<std::string> deck_notes(const io::CdkRun& run) {
    std::vector<std::string> notes;
    if (atmos::deck_mie_phase(run.card1, run.geometry))
        notes.push_back(run.card1.iemsct == 1
                            ? "IEMSCT 1: aerosol scattering by LOWTRAN 7's Mie phase functions "
                              "(delta-M), as with IPH 2"
                            : "IPH 2: aerosol scattering by LOWTRAN 7's Mie phase functions "
                              "(delta-M, with the Nakajima-Tanaka TMS and IMS corrections)");
    if (run.card1.iemsct == 1)
        notes.push_back(
            "IEMSCT 1: thermal radiance only: no sun (Es, tau1, L_us, L_ds and the sun's "
            "diffuse transmittance 0)");
    if (run.card1.imult == 0 && run.card1.iemsct == 2)
        notes.push_back("IMULT 0: solar scattering of first order only (single scattering)");
    if (run.card1.surface_albedo > 0)
        notes.push_back("SALB " + format_number(run.card1.surface_albedo) +
                        ": the sky includes the ground's reflection; no COUPLING terms "
                        "(trace would add its own ground to the sky a second time)");
    return notes;
}

std::vector<std::string> deck_refusals(const io::Cdk& deck) {
    std::vector<std::string> out;
    const std::size_t n = deck.runs.size();
    for (std::size_t k = 0; k < n; ++k) {
        const io::CdkRun& run = deck.runs[k];
        if (run.kind != io::CdkRunKind::Full && k > 0) continue;  // CARD 3 or 4 only: no effect
        run_refusals(run, run_prefix(k, n), out);
        if (k > 0 && !same_atmosphere(run, deck.runs.front()))
            out.push_back(run_prefix(k - 1, n) + "CARD 5 IRPT (columns 1-5) is 1 and run " +
                          std::to_string(k + 1) +
                          " changes the atmosphere: build_radiance makes the tables of one "
                          "atmosphere (one deck per atmosphere)");
    }
    return out;
}

void check_deck(const io::Cdk& deck, const std::string& cdk_path) {
    const std::vector<std::string> why = deck_refusals(deck);
    if (!why.empty()) throw DataError({cdk_path, 0}, why.front());
}

std::optional<DeckSun> deck_sun(const io::CdkRun& run, int year, double view_azimuth_deg) {
    const io::CdkGeometry& g = run.geometry;
    if (run.card1.iemsct != 2) return std::nullopt;
    if (g.iparm == 2) return DeckSun{g.parm[1], wrap360(view_azimuth_deg - g.parm[0])};
    if (g.iparm == 0) return subsolar_sun(g.parm[0], g.parm[1], g.parm[2], g.parm[3]);
    // IPARM 1: IDAY and Greenwich TIME; hours beyond 24 roll into the next day.
    double hours = g.time_h;
    int doy = g.iday + static_cast<int>(std::floor(hours / 24));
    hours -= 24 * std::floor(hours / 24);
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    const int days = leap ? 366 : 365;
    if (doy > days) doy -= days, ++year;
    if (doy < 1) --year, doy += (year % 4 == 0 && year % 100 != 0) || year % 400 == 0 ? 366 : 365;
    geo::SolarPositionInput in;
    in.year = year;
    month_day(year, doy, in.month, in.day);
    in.ut_hours = hours;
    in.delta_t_s = geo::default_delta_t_s(year);
    in.latitude_deg = g.parm[0];
    in.longitude_east_deg = g.parm[1] > 180 ? 360 - g.parm[1] : -g.parm[1];
    const geo::SolarPosition sun = geo::solar_position(in);
    return DeckSun{sun.zenith_deg, sun.azimuth_deg};
}

double sun_separation_deg(const DeckSun& a, const DeckSun& b) {
    const double za = a.zenith_deg * kRadPerDeg, zb = b.zenith_deg * kRadPerDeg;
    const double c =
        std::cos(za) * std::cos(zb) +
        std::sin(za) * std::sin(zb) * std::cos((a.azimuth_deg - b.azimuth_deg) * kRadPerDeg);
    return std::acos(std::clamp(c, -1.0, 1.0)) / kRadPerDeg;
}

}  // namespace sigchain::atmos_table
