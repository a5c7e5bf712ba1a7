// build_radiance with LOWTRAN 7 or MODTRAN as the solver (see tape7_radiance.hpp): the
// decks of the paths a .rad needs, and the .rad assembled from their TAPE7s.
#include "atmos_table/tape7_radiance.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

#include "atmos_table/build_radiance.hpp"
#include "atmos_table/deck_options.hpp"
#include "atmos_table/radiance_directions.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "geo/solar_position.hpp"
#include "io/tape7.hpp"
#include "rt/planck.hpp"

namespace sigchain::atmos_table {

namespace {

// Angles and altitudes agree when within the 3 decimals LOWTRAN 7's F10.3 fields keep.
constexpr double kAngleTolerance_deg = 0.01;
constexpr double kAltitudeTolerance_km = 0.001;

// What the runs depend on: the ground, the sensor, the sun and the views.
struct PathSetup {
    double ground_km = 0, sensor_km = 0;
    double sun_zenith_deg = 0, sun_azimuth_deg = 0;
    double view_azimuth_deg = 0;
    std::vector<double> views;
    int day_of_year = 1;
    bool sun_up() const { return sun_zenith_deg < 90; }
};

// The ground as build_radiance's column takes it: GNDALT, or the profile's lowest level.
double ground_km(const io::CdkRun& run) {
    double bottom = 0;
    if (run.profile && !run.profile->layers.empty())
        bottom = run.profile->layers.front().altitude_km;
    return std::max(run.card2.ground_altitude_km, bottom);
}

int day_of_year(const io::Snd& snd) {
    static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (snd.year % 4 == 0 && snd.year % 100 != 0) || snd.year % 400 == 0;
    int day = snd.day;
    for (int m = 1; m < snd.month; ++m) day += kDays[m - 1] + (m == 2 && leap ? 1 : 0);
    return day;
}

double wrap_180(double deg) {
    const double w = wrap_degrees(deg);
    return w > 180 ? w - 360 : w;
}

PathSetup path_setup(const io::Cdk& deck, const io::Snd& snd, const RadianceOptions& o) {
    if (deck.runs.empty()) throw Error("the card deck holds no run");
    const io::CdkRun& run = deck.runs.front();
    if (const auto why = iemsct_refusal(run.card1)) throw DataError({o.cdk_path, 0}, *why);
    PathSetup p;
    p.ground_km = ground_km(run);
    p.sensor_km = snd.sensor_altitude_km;
    if (!(p.sensor_km > p.ground_km))
        throw DataError({o.snd_path, 0}, "the sensor (" + format_number(p.sensor_km) +
                                             " km) must lie above the ground (" +
                                             format_number(p.ground_km) + " km)");
    const geo::SolarPosition sun = geo::solar_position(io::scene_site(snd), p.ground_km * 1000);
    p.sun_zenith_deg = std::clamp(sun.zenith_deg, 0.0, 180.0);
    p.sun_azimuth_deg = wrap_degrees(sun.azimuth_deg);
    p.view_azimuth_deg =
        wrap_degrees(o.view_azimuth_deg ? *o.view_azimuth_deg : run.geometry.path_azimuth_deg);
    p.views = view_angles(snd, o.snd_path);
    p.day_of_year = day_of_year(snd);
    return p;
}

// CARD 4 over every band's samples, half an increment beyond each end.
io::CdkSpectral spectral_span(const io::Snd& snd) {
    double lo = 1e300, hi = 0, step = 1e300, half = 0;
    for (const io::SndBand& b : snd.bands) {
        const double max_nu = b.wavenumber_cm1(b.sample_count() - 1);
        lo = std::min(lo, b.min_wavenumber_cm1);
        hi = std::max(hi, max_nu);
        step = std::min(step, b.increment_cm1);
        half = std::max(half, b.increment_cm1 / 2);
    }
    // LOWTRAN 7 steps by multiples of 5 cm-1 and resolves 20 cm-1 (Kneizys et al. 1988).
    const double dv = std::clamp(5 * std::floor(step / 5), 5.0, 20.0);
    io::CdkSpectral s;
    s.v1_cm1 = std::max(0.0, dv * std::floor((lo - half) / dv));
    s.v2_cm1 = std::min(io::kCdkMaxWavenumber_cm1, dv * std::ceil((hi + half) / dv));
    s.dv_cm1 = dv;
    return s;
}

// One run's deck: the first run's atmosphere along one path, with the sun as IPARM 2.
io::Cdk path_deck(const io::CdkRun& base, const PathSetup& p, int iemsct, int itype, double h1,
                  double h2, double zenith_deg, double los_azimuth_deg,
                  const io::CdkSpectral& span) {
    io::CdkRun run = base;
    run.kind = io::CdkRunKind::Full;
    run.card1.iemsct = iemsct;
    run.card1.itype = itype;
    run.card1.surface_albedo = 0;  // a black ground: rad(5) tables are those of one
    if (run.card1.model == 0 || run.card1.model == 7) run.card1.im = run.profile ? 1 : 0;
    io::CdkGeometry g;
    g.h1_km = h1;
    g.h2_km = h2;
    g.zenith_angle_deg = zenith_deg;
    g.earth_radius_km = base.geometry.earth_radius_km;
    g.iparm = 2;
    g.iph = base.geometry.iph;
    g.phase_function = base.geometry.phase_function;
    g.asymmetry_g = base.geometry.asymmetry_g;
    g.iday = p.day_of_year;
    g.parm = {wrap_180(los_azimuth_deg - p.sun_azimuth_deg), p.sun_zenith_deg, 0, 0};
    run.geometry = g;
    run.spectral = span;
    run.irpt = 0;
    return io::Cdk{{run}};
}

std::string numbered(const char* stem, std::size_t k, int digits) {
    std::string n = std::to_string(k + 1);
    return stem +
           std::string(static_cast<std::size_t>(std::max(0, digits - static_cast<int>(n.size()))),
                       '0') +
           n;
}

}  // namespace

Tape7Decks tape7_decks(const io::Cdk& deck, const io::Snd& snd, const RadianceOptions& o) {
    check_radiance_options(o);
    const PathSetup p = path_setup(deck, snd, o);
    const io::CdkRun& base = deck.runs.front();
    const io::CdkSpectral span = spectral_span(snd);
    Tape7Decks out;
    io::T7m& list = out.list;
    list.sun_zenith_deg = p.sun_zenith_deg;
    list.sun_azimuth_deg = p.sun_azimuth_deg;
    list.view_azimuth_deg = p.view_azimuth_deg;
    list.sky_zenith_step_deg = 90.0 / std::lround(90.0 / o.sky_zenith_step_deg);
    list.sky_azimuth_step_deg = 360.0 / std::lround(360.0 / o.sky_azimuth_step_deg);
    // IEMSCT 1 (thermal radiance only) keeps its runs thermal whatever the sun; a sun
    // above the horizon still has its run, which the run list asks for (t7m(5)), but its
    // Es and tau1 are not used (tape7_radiance).
    const int radiance = p.sun_up() && base.card1.iemsct == 2 ? 2 : 1;
    if (p.sun_up()) {
        out.decks.emplace_back("sun.tp5", path_deck(base, p, 3, 3, p.ground_km, 0, p.sun_zenith_deg,
                                                    p.sun_azimuth_deg, span));
        list.sun_tape7 = "sun.tp7";
    }
    for (std::size_t k = 0; k < p.views.size(); ++k) {
        const double v = p.views[k];
        const std::string name = numbered("view-", k, 3);
        // Looking down from the sensor: zenith 180 - |v|, toward view_azimuth for v > 0.
        out.decks.emplace_back(
            name + ".tp5",
            path_deck(base, p, radiance, 2, p.sensor_km, p.ground_km, 180 - std::abs(v),
                      p.view_azimuth_deg + (v < 0 ? 180 : 0), span));
        list.views.push_back({v, name + ".tp7", 0});
    }
    const long rings = std::lround(90 / list.sky_zenith_step_deg);
    const long cells = std::lround(360 / list.sky_azimuth_step_deg);
    for (long i = 0; i < rings; ++i)
        for (long j = 0; j < cells; ++j) {
            const double z = (static_cast<double>(i) + 0.5) * list.sky_zenith_step_deg;
            const double a = (static_cast<double>(j) + 0.5) * list.sky_azimuth_step_deg;
            const std::string name = numbered("sky-", list.sky.size(), 4);
            // Looking up from the ground at the cell's centre, to space.
            out.decks.emplace_back(name + ".tp5",
                                   path_deck(base, p, radiance, 3, p.ground_km, 0, z, a, span));
            list.sky.push_back({z, a, name + ".tp7", 0});
        }
    return out;
}

namespace {

// A quantity of one TAPE7 per um, piecewise linear in wavenumber between its rows.
struct Series {
    std::vector<double> nu, value;
};

Series series(const io::Tape7& t, const std::function<double(const io::Tape7Row&)>& per_um) {
    Series s;
    for (const auto& r : t.rows) {
        s.nu.push_back(r.wavenumber_cm1);
        s.value.push_back(per_um(r));
    }
    return s;
}

double at(const Series& s, std::size_t i, double x) {
    const double w = (x - s.nu[i]) / (s.nu[i + 1] - s.nu[i]);
    return s.value[i] + w * (s.value[i + 1] - s.value[i]);
}

// The mean of the piecewise linear series over [lo, hi] (exact: trapezoids on each
// piece).
double mean_over(const Series& s, double lo, double hi) {
    double sum = 0;
    for (std::size_t i = 0; i + 1 < s.nu.size(); ++i) {
        const double a = std::max(lo, s.nu[i]), b = std::min(hi, s.nu[i + 1]);
        if (b > a) sum += (b - a) * (at(s, i, a) + at(s, i, b)) / 2;
    }
    return sum / (hi - lo);
}

// A TAPE7 of the list and what it is for, in messages.
struct Run {
    io::Tape7 tape;
    std::string path;
    std::string what;  // "VIEW -10", "SKY 2.5 5", "SUN"
};

Run load(const std::string& list_path, const std::string& file, std::string what) {
    const std::filesystem::path dir = std::filesystem::path(list_path).parent_path();
    const std::string path =
        std::filesystem::path(file).is_absolute() ? file : (dir / file).string();
    return {io::read_tape7_file(path), path, std::move(what)};
}

// The run's mode and, for LOWTRAN 7, its echoed path must be the one the list says.
void check_run(const Run& r, std::initializer_list<int> modes, double h1, double h2,
               double zenith_deg) {
    const SourceLocation heading{r.path, r.tape.heading_line};
    if (std::find(modes.begin(), modes.end(), r.tape.iemsct) == modes.end())
        throw DataError(heading, "expected the TAPE7 of a " + r.what + " run (IEMSCT " +
                                     std::to_string(*modes.begin()) + "), found IEMSCT " +
                                     std::to_string(r.tape.iemsct));
    if (!r.tape.echo) return;
    const io::Tape7Echo& e = *r.tape.echo;
    if (e.card3_line == 0) return;  // MODEL 0 echoes no CARD 3
    if (std::abs(e.h1_km - h1) > kAltitudeTolerance_km ||
        (h2 > 0 && std::abs(e.h2_km - h2) > kAltitudeTolerance_km) ||
        std::abs(e.zenith_angle_deg - zenith_deg) > kAngleTolerance_deg)
        throw DataError({r.path, e.card3_line},
                        "expected the path of " + r.what + " (H1 " + format_number(h1) +
                            " km, H2 " + format_number(h2) + " km, ANGLE " +
                            format_number(zenith_deg) + " deg), found H1 " +
                            format_number(e.h1_km) + ", H2 " + format_number(e.h2_km) + ", ANGLE " +
                            format_number(e.zenith_angle_deg));
}

// L_ue of a view: LOWTRAN 7's ATMOS holds the black ground's emission B(TBOUND) T too
// (TRANS, statement 400: BBG = BBFN(TBOUND) TX(9) EMISS, EMISS = 1 - SALB), taken out
// here; MODTRAN gives PTH_THRML + THRML_SCT without it.
std::function<double(const io::Tape7Row&)> view_thermal(const Run& r) {
    const std::optional<io::Tape7Echo>& e = r.tape.echo;
    if (!r.tape.thermal_includes_boundary || !e)
        return [](const io::Tape7Row& row) {
            return io::per_micrometre(row.path_thermal, row.wavenumber_cm1);
        };
    if (e->surface_albedo != 0)
        throw DataError({r.path, e->card1_line},
                        "expected SALB 0 (a black ground, as rad(5) tables are), found " +
                            format_number(e->surface_albedo));
    const double t_k = e->boundary_temperature_k;
    return [t_k](const io::Tape7Row& row) {
        const double ground =
            rt::planck_radiance(um_from_cm1(row.wavenumber_cm1), t_k) * row.transmittance;
        return std::max(0.0, io::per_micrometre(row.path_thermal, row.wavenumber_cm1) - ground);
    };
}

double per_um_solar(const io::Tape7Row& r) {
    return io::per_micrometre(r.path_solar, r.wavenumber_cm1);
}
double per_um_thermal(const io::Tape7Row& r) {
    return io::per_micrometre(r.path_thermal, r.wavenumber_cm1);
}
double trans(const io::Tape7Row& r) { return r.transmittance; }

// The mean of a run's quantity over a sample's interval; DataError when the TAPE7
// does not reach the sample.
struct Sampler {
    double nu, half;
    double operator()(const Run& r, const Series& s) const {
        if (nu < s.nu.front() || nu > s.nu.back())
            throw DataError({r.path, r.tape.heading_line},
                            "expected rows covering " + format_number(nu) +
                                " cm-1 (a sample of "
                                "the scene node), found " +
                                format_number(s.nu.front()) + " to " + format_number(s.nu.back()) +
                                " cm-1");
        return mean_over(s, std::max(nu - half, s.nu.front()), std::min(nu + half, s.nu.back()));
    }
};

void check_list(const io::T7m& list, const std::string& list_path, const PathSetup& p) {
    const SourceLocation at{list_path, 0};
    auto differs = [](double a, double b) {
        return std::abs(wrap_180(a - b)) > kAngleTolerance_deg;
    };
    if (differs(list.sun_zenith_deg, p.sun_zenith_deg) ||
        differs(list.sun_azimuth_deg, p.sun_azimuth_deg))
        throw DataError(at, "expected runs for the scene node's sun (zenith " +
                                format_number(p.sun_zenith_deg) + ", azimuth " +
                                format_number(p.sun_azimuth_deg) + " deg), found zenith " +
                                format_number(list.sun_zenith_deg) + ", azimuth " +
                                format_number(list.sun_azimuth_deg) + ": write the decks again");
    if (differs(list.view_azimuth_deg, p.view_azimuth_deg))
        throw DataError(at, "expected runs for view azimuth " + format_number(p.view_azimuth_deg) +
                                " deg, found " + format_number(list.view_azimuth_deg));
}

const io::T7mView& view_run(const io::T7m& list, const std::string& list_path, double v) {
    for (const auto& r : list.views)
        if (std::abs(r.view_angle_deg - v) < 1e-6) return r;
    throw DataError({list_path, 0}, "expected a VIEW run for the scene node's view angle " +
                                        format_number(v) + " deg, found none");
}

// The list's runs and the series read from them: the sun's (none with the sun down),
// one per view and one per sky cell.
struct Runs {
    std::optional<Run> sun;
    Series es, tau1;
    std::vector<Run> views;
    std::vector<std::array<Series, 3>> view_series;  // tau2, L_ue, L_us
    std::vector<Run> sky;
    std::vector<std::array<Series, 2>> sky_series;  // L_ds, L_de
};

Runs load_runs(const io::T7m& list, const std::string& list_path, const PathSetup& p) {
    Runs r;
    if (p.sun_up()) {
        r.sun = load(list_path, list.sun_tape7, "SUN");
        check_run(*r.sun, {3}, p.ground_km, 0, p.sun_zenith_deg);
        r.es = series(r.sun->tape, [](const io::Tape7Row& row) {
            return io::per_micrometre(row.solar_exo, row.wavenumber_cm1);
        });
        r.tau1 = series(r.sun->tape, trans);
    }
    for (double v : p.views) {
        const io::T7mView& entry = view_run(list, list_path, v);
        r.views.push_back(load(list_path, entry.tape7, "VIEW " + format_number(v)));
        check_run(r.views.back(), {1, 2}, p.sensor_km, p.ground_km, 180 - std::abs(v));
        r.view_series.push_back({series(r.views.back().tape, trans),
                                 series(r.views.back().tape, view_thermal(r.views.back())),
                                 series(r.views.back().tape, per_um_solar)});
    }
    for (const io::T7mSky& cell : list.sky) {
        r.sky.push_back(
            load(list_path, cell.tape7,
                 "SKY " + format_number(cell.zenith_deg) + " " + format_number(cell.azimuth_deg)));
        check_run(r.sky.back(), {1, 2}, p.ground_km, 0, cell.zenith_deg);
        r.sky_series.push_back(
            {series(r.sky.back().tape, per_um_solar), series(r.sky.back().tape, per_um_thermal)});
    }
    return r;
}

// The sky grid without its samples: the list's cells with their solid angles.
io::RadSky sky_grid(const io::T7m& list, const PathSetup& p) {
    io::RadSky s;
    s.sun_zenith_deg = p.sun_zenith_deg;
    s.sun_azimuth_deg = p.sun_azimuth_deg;
    s.zenith_count = std::lround(90 / list.sky_zenith_step_deg);
    s.azimuth_count = std::lround(360 / list.sky_azimuth_step_deg);
    for (const io::T7mSky& cell : list.sky) {
        const double z0 = cell.zenith_deg - list.sky_zenith_step_deg / 2;
        const double z1 = cell.zenith_deg + list.sky_zenith_step_deg / 2;
        s.cells.push_back({cell.zenith_deg,
                           cell.azimuth_deg,
                           (std::cos(z0 * kRadPerDeg) - std::cos(z1 * kRadPerDeg)) *
                               list.sky_azimuth_step_deg * kRadPerDeg,
                           {},
                           {}});
    }
    return s;
}

// The band's samples, from its maximum wavenumber down: each the runs' means over the
// sample's interval. With IEMSCT 1 (no sun) the solar entries stay 0.
void append_band_samples(const io::SndBand& band, const Runs& r, int iemsct, io::Rad& rad,
                         io::RadSky& s) {
    for (long k = band.sample_count() - 1; k >= 0; --k) {
        const double nu = band.wavenumber_cm1(k);
        const Sampler mean{nu, band.increment_cm1 / 2};
        io::RadSample sample{um_from_cm1(nu), nu, 0, 0};
        if (r.sun && iemsct == 2) {  // IEMSCT 1: no sun
            sample.solar_irradiance = mean(*r.sun, r.es);
            sample.sun_transmission = std::clamp(mean(*r.sun, r.tau1), 0.0, 1.0);
        }
        rad.samples.push_back(sample);
        for (std::size_t v = 0; v < r.views.size(); ++v)
            rad.views[v].path.push_back(
                {std::clamp(mean(r.views[v], r.view_series[v][0]), 0.0, 1.0),
                 mean(r.views[v], r.view_series[v][1]), mean(r.views[v], r.view_series[v][2])});
        for (std::size_t c = 0; c < r.sky.size(); ++c) {
            s.cells[c].scattered_radiance.push_back(mean(r.sky[c], r.sky_series[c][0]));
            s.cells[c].emitted_radiance.push_back(mean(r.sky[c], r.sky_series[c][1]));
        }
    }
}

}  // namespace

std::vector<io::Rad> tape7_radiance(const io::T7m& list, const std::string& list_path,
                                    const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& o) {
    const PathSetup p = path_setup(deck, snd, o);
    check_list(list, list_path, p);
    const Runs runs = load_runs(list, list_path, p);
    std::vector<io::Rad> out;
    for (const io::SndBand& band : snd.bands) {
        io::Rad rad = rad_header(band, snd, p.views, p.sensor_km - p.ground_km);
        io::RadSky s = sky_grid(list, p);
        append_band_samples(band, runs, deck.runs.front().card1.iemsct, rad, s);
        rad.sky = std::move(s);
        out.push_back(std::move(rad));
    }
    return out;
}

}  // namespace sigchain::atmos_table
