// build_radiance: the atmosphere tables of one scene (see build_radiance.hpp): the
// scene's sun and directions, the spectral samples solved in parallel, and the tables
// assembled band by band.
#include "atmos_table/build_radiance.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>

#include "atmos/solar_spectrum.hpp"
#include "atmos_table/deck_options.hpp"
#include "atmos_table/radiance_directions.hpp"
#include "atmos_table/radiance_sample.hpp"
#include "atmos_table/solve_samples.hpp"
#include "atmos_table/stream_choice.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/parallel.hpp"
#include "core/text.hpp"
#include "geo/solar_position.hpp"

namespace sigchain::atmos_table {

namespace {

// The options the samples are solved with: the COUPLING terms (rad(5)) describe the
// atmosphere over a black ground, for trace to add the scene's own ground to the sky;
// with the deck's SALB the sky already holds a ground, so they are left out.
RadianceOptions deck_solver_options(const io::CdkRun& run, const RadianceOptions& o) {
    RadianceOptions solved = o;
    if (run.card1.surface_albedo > 0) solved.coupling = false;
    // Resolved once: the stream choice's probes are solved with a number of streams.
    solved.merge_tau = merge_tau(o);
    return solved;
}

// Which fields of CARD 3A1/3A2 give the deck's sun, for the messages.
std::string deck_sun_fields(int iparm) {
    switch (iparm) {
        case 0:
            return "CARD 3A2 PARM1-PARM4 (columns 1-40, observer and sub-solar point)";
        case 1:
            return "CARD 3A1 IDAY (columns 11-15) and CARD 3A2 PARM1-PARM2 (columns 1-20) and "
                   "TIME (columns 41-50, Greenwich)";
        default:
            return "CARD 3A2 PARM1 (columns 1-10, azimuth from the line of sight) and PARM2 "
                   "(columns 11-20, solar zenith)";
    }
}

// The deck's sun (IEMSCT 2, CARD 3A1/3A2) against the scene node's, which build_radiance
// uses: accepted when they agree within kSunAgreement_deg; with IPARM 1 a TIME equal to
// the scene's local time (as White (1996), section 4.2.3.5, answered it) is accepted
// with a warning; any other disagreement is a DataError naming the fields.
void check_deck_sun(const io::CdkRun& run, const io::Snd& snd, const RadianceReport& rep,
                    const std::string& cdk_path, const Reporter& reporter,
                    std::vector<std::string>& notes) {
    const auto deck = deck_sun(run, snd.year, rep.view_azimuth_deg);
    if (!deck) return;
    const DeckSun scene{rep.sun_zenith_deg, rep.sun_azimuth_deg};
    const double off = sun_separation_deg(*deck, scene);
    const int iparm = run.geometry.iparm;
    const std::string fields = deck_sun_fields(iparm);
    if (off <= kSunAgreement_deg) {
        notes.push_back("sun from the scene node; the deck's (IPARM " + std::to_string(iparm) +
                        ") agrees within " + format_number(off) + " deg");
        return;
    }
    if (iparm == 1) {
        io::CdkRun local = run;
        local.geometry.time_h += snd.gmt_offset_hours;
        const auto shifted = deck_sun(local, snd.year, rep.view_azimuth_deg);
        if (shifted && sun_separation_deg(*shifted, scene) <= kSunAgreement_deg) {
            reporter.warn(cdk_path + ": CARD 3A2 TIME (columns 41-50) " +
                          format_number(run.geometry.time_h) +
                          " h is the scene's local time, not Greenwich time (" +
                          format_number(snd.time_gmt_hours) + " h): the scene node's sun is used");
            notes.push_back("sun from the scene node; the deck's TIME is its local time");
            return;
        }
    }
    throw DataError({cdk_path, 0},
                    fields + " put the sun at zenith " + format_number(deck->zenith_deg) +
                        " deg, azimuth " + format_number(deck->azimuth_deg) +
                        " deg, but the scene node's sun is at zenith " +
                        format_number(scene.zenith_deg) + " deg, azimuth " +
                        format_number(scene.azimuth_deg) + " deg (" + format_number(off) +
                        " deg apart; at most " + format_number(kSunAgreement_deg) + " allowed)");
}

std::vector<double> grid(double min, double increment, long count) {
    std::vector<double> v(static_cast<std::size_t>(count));
    for (long k = 0; k < count; ++k) v[static_cast<std::size_t>(k)] = min + k * increment;
    return v;
}

// The sun at the target (NREL SPA at ground altitude), recorded in `rep`.
geo::SolarPosition target_sun(const io::Snd& snd, RadianceReport& rep) {
    const geo::SolarPosition sun = geo::solar_position(io::scene_site(snd), rep.ground_km * 1000);
    rep.sun_zenith_deg = sun.zenith_deg;
    rep.sun_azimuth_deg = sun.azimuth_deg;
    rep.earth_sun_distance_au = sun.earth_sun_distance_au;
    if (!(sun.zenith_deg < 90))
        rep.notes.push_back("the sun is below the horizon (zenith " +
                            format_number(sun.zenith_deg) + " deg): no solar terms");
    return sun;
}

// The column's figures for the report, and the note when the sensor is above the top.
void report_column(const atmos::ColumnModel& column, const io::Snd& snd, RadianceReport& rep) {
    const atmos::Profile& prof = column.profile();
    rep.ground_km = prof.bottom_km();
    rep.sensor_km = snd.sensor_altitude_km;
    rep.visibility_km = column.visibility_km();
    rep.layers = prof.size() - 1;
    if (snd.sensor_altitude_km > prof.top_km())
        rep.notes.push_back("the sensor lies above the modelled atmosphere (" +
                            format_number(prof.top_km()) +
                            " km): path terms are those of the whole column");
}

// Every spectral sample of every band, band by band, each band from its maximum
// wavenumber down (wavelength increasing), as rad(5) orders them.
std::vector<double> sample_wavenumbers(const io::Snd& snd) {
    std::vector<double> nus;
    for (const io::SndBand& band : snd.bands)
        for (long s = band.sample_count() - 1; s >= 0; --s) nus.push_back(band.wavenumber_cm1(s));
    return nus;
}

// The sky and upwelled grids without their samples.
io::RadSky sky_header(const geo::SolarPosition& sun, const Directions& dirs, bool coupling) {
    io::RadSky sky;
    sky.sun_zenith_deg = std::clamp(sun.zenith_deg, 0.0, 180.0);
    sky.sun_azimuth_deg = wrap_degrees(sun.azimuth_deg);
    sky.zenith_count = dirs.zenith_count;
    sky.azimuth_count = dirs.azimuth_count;
    sky.cells = dirs.cells;
    sky.version_minor = coupling ? 2 : 1;  // 1: the UPWELLED grid; 2: the COUPLING terms
    io::RadUpwelled up;
    up.zenith_count = static_cast<long>(dirs.up_zenith_deg.size());
    up.azimuth_count = static_cast<long>(dirs.up_azimuth_deg.size());
    for (double z : dirs.up_zenith_deg)
        for (double a : dirs.up_azimuth_deg) up.cells.push_back({z, a, {}, {}});
    sky.upwelled = std::move(up);
    if (coupling) {
        io::RadCoupling terms;
        terms.diffuse_up.resize(dirs.view_mu.size());
        sky.coupling = std::move(terms);
    }
    return sky;
}

// Appends one sample's entries to the band's tables.
void append_sample(io::Rad& rad, io::RadSky& sky, const SampleResult& r) {
    rad.samples.push_back(r.sample);
    for (std::size_t v = 0; v < rad.views.size(); ++v) rad.views[v].path.push_back(r.path[v]);
    for (std::size_t c = 0; c < sky.cells.size(); ++c) {
        sky.cells[c].scattered_radiance.push_back(r.ls[c]);
        sky.cells[c].emitted_radiance.push_back(r.le[c]);
    }
    auto& up = sky.upwelled->cells;
    for (std::size_t c = 0; c < up.size(); ++c) {
        up[c].scattered_radiance.push_back(r.us[c]);
        up[c].emitted_radiance.push_back(r.ue[c]);
    }
    if (!sky.coupling) return;
    io::RadCoupling& coupling = *sky.coupling;
    coupling.spherical_albedo.push_back(r.spherical_albedo);
    coupling.diffuse_down.push_back(r.diffuse_down);
    for (std::size_t v = 0; v < coupling.diffuse_up.size(); ++v)
        coupling.diffuse_up[v].push_back(r.diffuse_up[v]);
}

// The streams of every band: the options' own, or with --streams auto each band's
// choice (stream_choice.hpp); `options` receives each band's solver options.
std::vector<StreamChoice> band_streams(const SampleSetup& setup, const io::Snd& snd,
                                       std::vector<RadianceOptions>& options) {
    // The bands' choices are independent: one band per thread. An error is the first
    // band's to fail, whichever thread met it first.
    std::vector<StreamChoice> choices(snd.bands.size());
    std::vector<std::exception_ptr> errors(snd.bands.size());
    const bool automatic = setup.options.streams == kAutoStreams;
    parallel_for(automatic ? static_cast<long>(snd.bands.size()) : 0, {setup.options.threads, {}},
                 [&](long b, unsigned) {
                     const auto i = static_cast<std::size_t>(b);
                     try {
                         choices[i] =
                             choose_streams(setup, probe_wavenumbers(setup.column, snd.bands[i]),
                                            setup.options.stream_tolerance);
                     } catch (...) {
                         errors[i] = std::current_exception();
                     }
                 });
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    for (StreamChoice& c : choices) {
        if (!automatic) c.streams = setup.options.streams;
        options.push_back(setup.options);
        options.back().streams = c.streams;
    }
    return choices;
}

}  // namespace

// The .snd's view angles, none within 0.5 deg of the horizon.
std::vector<double> view_angles(const io::Snd& snd, const std::string& snd_path) {
    const std::vector<double> views =
        grid(snd.view_min_deg, snd.view_increment_deg, snd.view_angle_count());
    for (double v : views)
        if (std::abs(v) >= 89.5)
            // The parsed .snd keeps no line numbers: the message names the view angle.
            throw DataError({snd_path, 0}, "view angle " + format_number(v) +
                                               " deg is within 0.5 deg of the horizon: no "
                                               "ground range");
    return views;
}

// A band's .rad without its samples: spectral range, views and their ranges.
io::Rad rad_header(const io::SndBand& band, const io::Snd& snd, const std::vector<double>& views,
                   double height_km) {
    io::Rad rad;
    const long n = band.sample_count();
    const double max_nu = band.wavenumber_cm1(n - 1);
    rad.sensor_altitude_km = snd.sensor_altitude_km;
    rad.min_wavenumber_cm1 = band.min_wavenumber_cm1;
    rad.max_wavenumber_cm1 = max_nu;
    rad.min_wavelength_um = um_from_cm1(max_nu);
    rad.max_wavelength_um = um_from_cm1(band.min_wavenumber_cm1);
    rad.wavenumber_increment_cm1 = band.increment_cm1;
    rad.min_view_angle_deg = views.front();
    rad.max_view_angle_deg = views.back();
    rad.view_angle_increment_deg = snd.view_increment_deg;
    for (double v : views) {
        io::RadView view;
        view.view_angle_deg = v;
        view.range_km = height_km / std::cos(v * kRadPerDeg);
        rad.views.push_back(view);
    }
    return rad;
}

std::string band_output_path(const std::string& pattern, int band, int band_count) {
    std::string out;
    bool numbered = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        const char next = i + 1 < pattern.size() ? pattern[i + 1] : '\0';
        if (next == 'd') {
            out += std::to_string(band);
            numbered = true;
        } else if (next == '%') {
            out += '%';
        } else {
            throw UsageError("output pattern " + quoted(pattern) +
                             ": '%' must be followed by 'd' (band number) or '%'");
        }
        ++i;
    }
    if (!numbered && band_count > 1)
        throw UsageError("output pattern " + quoted(pattern) +
                         " has no %d, but the scene node has " + std::to_string(band_count) +
                         " bands (e.g. -o NAME-%d.rad)");
    return out;
}

namespace {

// The column is asked about the .snd's samples only (the stream choice's probes are
// among them): gas tables beyond are not read.
atmos::ColumnOptions column_options(const RadianceOptions& o, const std::vector<double>& nus) {
    atmos::ColumnOptions column_options = o;
    if (!nus.empty())
        column_options.wavenumbers_cm1.emplace(*std::min_element(nus.begin(), nus.end()),
                                               *std::max_element(nus.begin(), nus.end()));
    return column_options;
}

void note_skipped_gas_tables(const atmos::ColumnModel& column, RadianceReport& rep) {
    if (column.skipped_gas_tables().empty()) return;
    std::string names;
    for (const std::string& n : column.skipped_gas_tables())
        names += (names.empty() ? "" : ", ") + n;
    rep.notes.push_back("gas tables not read (no sample within " +
                        format_number(atmos::GasTables::kLoadMargin) + " cm-1 of them): " + names);
}

// The layers' merge threshold the samples are solved with, and the rule that gave it.
void report_merge_rule(const RadianceOptions& o, const RadianceOptions& solved,
                       RadianceReport& rep) {
    rep.merge_tau = *solved.merge_tau;
    if (o.merge_tau)
        rep.merge_rule = "--merge-tau";
    else if (o.streams == kAutoStreams)
        rep.merge_rule = "--streams auto at " + format_number(100 * o.stream_tolerance) +
                         " %: 0.01 x sqrt(REL / 1 %)";
}

// The deck's notes, and the note when only means over azimuth are tabulated.
void note_deck_and_directions(const io::CdkRun& run, const Directions& dirs,
                              RadianceReport& rep) {
    for (std::string& note : deck_notes(run)) rep.notes.push_back(std::move(note));
    if (dirs.azimuth_means_only)
        rep.notes.push_back(
            "only means over azimuth tabulated (nadir views, whole-ring sky "
            "cells): the solver's Fourier modes above 0 are not solved");
}

// Per band the setup its samples are solved with: `setup` with the band's streams
// (band_options, which must outlive the setups); `setup_of` receives each sample's band.
std::vector<SampleSetup> band_setups(const SampleSetup& setup, const io::Snd& snd,
                                     const std::vector<RadianceOptions>& band_options,
                                     std::vector<std::size_t>& setup_of) {
    std::vector<SampleSetup> setups;
    for (std::size_t b = 0; b < snd.bands.size(); ++b) {
        const int n = band_options[b].streams;
        setups.push_back({setup.column, setup.dirs, setup.solar, band_options[b],
                          setup.views_deg, setup.mu0, setup.sun_up, setup.distance_factor,
                          phase_moments(n), setup.deck, setup.mie});
        setup_of.insert(setup_of.end(), static_cast<std::size_t>(snd.bands[b].sample_count()), b);
    }
    return setups;
}

// The tables, band by band, from the samples' results (in sample_wavenumbers' order);
// the report receives each band's ground irradiance and the samples' counts.
std::vector<io::Rad> assemble_tables(const io::Snd& snd, const SampleSetup& setup,
                                     const geo::SolarPosition& sun, bool coupling,
                                     const std::vector<SampleResult>& results,
                                     RadianceReport& rep) {
    const atmos::Profile& prof = setup.column.profile();
    const double height_km = prof.z_km[setup.column.sensor_level()] - prof.bottom_km();
    std::vector<io::Rad> out;
    std::size_t j = 0;
    for (const io::SndBand& band : snd.bands) {
        io::Rad rad = rad_header(band, snd, setup.views_deg, height_km);
        io::RadSky sky = sky_header(sun, setup.dirs, coupling);
        std::vector<double> ground_irradiance;
        for (long s = 0; s < band.sample_count(); ++s, ++j) {
            append_sample(rad, sky, results[j]);
            ground_irradiance.push_back(results[j].ground_irradiance);
            if (results[j].thermal) ++rep.thermal_samples;
            rep.gas_term_solves += results[j].terms;
        }
        rad.sky = std::move(sky);
        rep.ground_diffuse_irradiance.push_back(std::move(ground_irradiance));
        out.push_back(std::move(rad));
    }
    return out;
}

}  // namespace

std::vector<io::Rad> build_radiance(const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& o, RadianceReport* report,
                                    const Reporter& reporter) {
    check_radiance_options(o);
    if (deck.runs.empty()) throw Error("the card deck holds no run");
    const io::CdkRun& run = deck.runs.front();
    check_deck(deck, o.cdk_path);
    RadianceReport rep;
    const std::vector<double> nus = sample_wavenumbers(snd);
    const atmos::ColumnModel column(run, snd.sensor_altitude_km, column_options(o, nus));
    note_skipped_gas_tables(column, rep);
    report_column(column, snd, rep);
    const geo::SolarPosition sun = target_sun(snd, rep);
    const atmos::SolarSpectrum solar = atmos::SolarSpectrum::load(o.data_dir);
    rep.view_azimuth_deg =
        wrap_degrees(o.view_azimuth_deg ? *o.view_azimuth_deg : run.geometry.path_azimuth_deg);
    check_deck_sun(run, snd, rep, o.cdk_path, reporter, rep.notes);
    const std::vector<double> views = view_angles(snd, o.snd_path);
    const Directions dirs = directions(views, rep.view_azimuth_deg, rep.sun_azimuth_deg, o);
    const double distance_factor = 1 / (sun.earth_sun_distance_au * sun.earth_sun_distance_au);
    const RadianceOptions solved = deck_solver_options(run, o);
    report_merge_rule(o, solved, rep);
    const DeckChoices choices = deck_choices(run);
    if (!choices.solar && sun.zenith_deg < 90)
        reporter.warn(o.cdk_path +
                      ": CARD 1 IEMSCT (columns 11-15) is 1 (thermal radiance "
                      "only) but the scene node's sun is up (zenith " +
                      format_number(sun.zenith_deg) + " deg): the tables hold no sunlight");
    const SampleSetup setup{column,
                            dirs,
                            solar,
                            solved,
                            views,
                            std::cos(sun.zenith_deg * kRadPerDeg),
                            sun.zenith_deg < 90 && choices.solar,
                            distance_factor,
                            phase_moments(o.streams),
                            choices};
    note_deck_and_directions(run, dirs, rep);
    // Per band its streams (--streams auto: band_streams), the samples solved with them.
    std::vector<RadianceOptions> band_options;
    rep.band_streams = band_streams(setup, snd, band_options);
    std::vector<std::size_t> setup_of;
    const std::vector<SampleSetup> setups = band_setups(setup, snd, band_options, setup_of);
    std::vector<SampleResult> results;
    if (!solve_samples(setups, setup_of, nus, reporter, results)) return {};
    std::vector<io::Rad> out = assemble_tables(snd, setup, sun, solved.coupling, results, rep);
    if (rep.thermal_samples == 0)
        rep.notes.push_back("layer emission not solved: every sample is below " +
                            format_number(o.thermal_min_wavelength_um) + " um (L_ue = L_de = 0)");
    if (report) *report = std::move(rep);
    return out;
}

}  // namespace sigchain::atmos_table
