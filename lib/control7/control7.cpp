// control7's interview: the questions asked card by card, in fig. 4.30's order, and the deck
// their answers build (White (1996), section 4.2.3.4-4.2.3.5, figs. 4.29-4.31). How one
// question is asked and checked: asker.hpp.
#include "control7/control7.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "control7/asker.hpp"
#include "core/numeric.hpp"
#include "io/rsd.hpp"

namespace sigchain::control7 {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

void ask_profile(Asker& a, io::CdkRun& run) {
    const int levels = a.integer("levels", "number of atmospheric levels", 1, io::kCdkMaxLayers);
    const SourceLocation levels_at = a.source().where();
    std::string title = a.ask<std::string>("title", [](const std::string& t) {
        if (t.empty() || t.size() > 72)
            throw BadAnswer(
                "expected the name of the new atmosphere (1 to 72 characters), "
                "found " +
                quoted(t));
        return upper(t);  // CONTROL7 writes the name in capitals (fig. 4.31)
    });
    a.ask<bool>("aerosol_by_layer", [](const std::string& t) {
        if (Asker::parse_yes_no(t, "aerosol control by layer"))
            throw BadAnswer(
                "expected aerosol control by layer in [n] (CARD 2C3 input is not "
                "supported), found " +
                quoted(t));
        return false;
    });
    io::Rsd rsd = a.ask<io::Rsd>("rsd", [](const std::string& path) {
        if (path.empty()) throw BadAnswer("expected the radiosonde file name, found ''");
        try {
            io::Rsd raw = io::read_rsd_file(path);
            // The parsed sounding keeps no line numbers: messages name the level.
            return fill_missing_dew_points(raw, {path, 0});
        } catch (const Error& e) {
            throw BadAnswer("radiosonde: " + std::string(e.what()));
        }
    });
    if (static_cast<std::size_t>(levels) > rsd.levels.size()) {
        std::string msg = "expected number of atmospheric levels in " +
                          range_text(1, static_cast<double>(rsd.levels.size())) +
                          " (the levels of the radiosonde file), found " + std::to_string(levels);
        // An --answer comes from the command line: no file, no line.
        if (a.used().count("levels")) throw DataError({"--answer levels", 0}, msg);
        throw DataError(levels_at, msg);
    }
    run.profile = radiosonde_profile(rsd, levels, title);
    for (int i = 0; i < levels; ++i) {
        std::ostringstream line;
        line << "ENTERING DATA FOR LAYER " << (i + 1) << ": ALTITUDE "
             << format_number(run.profile->layers[i].altitude_km);
        a.inform(line.str());
    }
}

// CARD 3A1 and 3A2 (solar/lunar scattered radiance, IEMSCT 2): the geometry of the
// source.
void ask_solar_scattering(Asker& a, io::CdkGeometry& g) {
    g.iparm = a.integer("iparm", "geometry type IPARM", 0, 2);
    g.iph = a.integer("iph", "phase function type IPH", 0, 2, {1},
                      " except 1 (user supplied, not supported)");
    if (g.iph == 0) g.asymmetry_g = a.real("g", "asymmetry parameter g", -1, 1);
    g.iday = a.integer("iday", "day of the year", 1, 366);
    g.isourc = 0;
    if (g.iparm <= 1) {
        g.parm[0] = a.real("obs_lat", "observer latitude (deg north)", -90, 90);
        g.parm[1] = a.real("obs_lon", "observer longitude (deg west)", 0, 360);
        if (g.iparm == 0) {
            g.parm[2] = a.real("src_lat", "source latitude (deg north)", -90, 90);
            g.parm[3] = a.real("src_lon", "source longitude (deg west)", 0, 360);
        } else {
            g.time_h = a.ask<double>("time", [](const std::string& t) {
                double v = Asker::number(t, "time of day (hours)");
                try {
                    return time_answer_hours(v);
                } catch (const std::invalid_argument&) {
                    throw BadAnswer(
                        "expected time of day in [0, 24] (decimal hours) or "
                        "[100, 2400] (HHMM), found " +
                        quoted(t));
                }
            });
        }
        g.path_azimuth_deg = a.real("psipo", "path azimuth (deg east of north)", 0, 360);
    } else {
        g.parm[0] = a.real("rel_azimuth", "relative azimuth (deg)", -180, 180);
        g.parm[1] = a.real("sun_zenith", "solar zenith angle (deg)", 0, 180);
    }
}

void ask_geometry(Asker& a, io::CdkRun& run) {
    io::CdkGeometry g;
    const double gnd = run.card2.ground_altitude_km;
    const int itype = run.card1.itype, iemsct = run.card1.iemsct;
    const std::string alt_range = "altitude (km, ground to 100)";
    g.h1_km = a.real("h1", "H1, initial " + alt_range, gnd, 100);
    auto ask_radius = [&] {
        if (a.yes_no("override_radius", "override the earth radius"))
            g.earth_radius_km = a.real("radius", "earth radius (km)", 6000, 7000);
    };
    if (iemsct == 3) {  // alternate CARD 3
        g.h2_km = a.real("h2", "H2, final " + alt_range, gnd, 100);
        g.zenith_angle_deg = a.real("angle", "initial zenith angle (deg)", 0, 180);
        g.iday = a.integer("iday", "day of the year", 1, 366);
        ask_radius();
        g.isourc = a.integer("isourc", "source (0 sun, 1 moon)", 0, 1);
        if (g.isourc == 1)
            g.moon_phase_angle_deg = a.real("anglem", "moon phase angle (deg)", 0, 180);
        run.geometry = g;
        return;
    }
    if (itype == 1) {
        g.range_km = a.real("range", "path length (km)", 0, 100000, true);
    } else {
        g.h2_km = a.real("h2", "H2, final " + alt_range, itype == 3 ? 0 : gnd, 100);
        g.zenith_angle_deg = a.real("angle", "initial zenith angle (deg)", 0, 180);
        if (itype == 2) {
            g.range_km = a.real("range", "path length (km, 0 from the angles)", 0, 100000);
            g.earth_center_angle_deg = a.ask<double>("beta", [](const std::string& t) {
                std::string l = ascii_lower(t);
                if (l == "n" || l == "no") return 0.0;  // not given (White's (1996) answer "n")
                double v = Asker::number(t, "earth center angle (deg)");
                if (v < 0 || v > 180)
                    throw BadAnswer("expected earth center angle (deg) in [0, 180], found " +
                                    quoted(t));
                return v;
            });
        }
        ask_radius();
        if (itype == 2) g.len = a.yes_no("short_path", "use the short path") ? 0 : 1;
    }
    if (iemsct == 2) ask_solar_scattering(a, g);  // CARD 3A1, 3A2
    run.geometry = g;
}

void ask_spectral(Asker& a, io::CdkRun& run) {
    const double scale = a.ask<double>("units", [](const std::string& t) {
        std::string l = ascii_lower(t);
        if (l == "microns" || l == "micron" || l == "um") return 1.0;
        if (l == "nanometers" || l == "nanometer" || l == "nanometres" || l == "nanometre" ||
            l == "nm")
            return 1e-3;
        throw BadAnswer("expected wavelength units in [microns, nanometers], found " + quoted(t));
    });
    const bool nm = scale < 1;
    const double lo = nm ? 200 : 0.2, hi = nm ? 1e6 : 1000;  // V2 <= 50000 cm-1
    const std::string unit = nm ? "nm" : "microns";
    auto range = a.ask<std::pair<double, double>>("wavelengths", [&](const std::string& t) {
        std::string s = t;
        // "0.4-0.7" (fig. 4.30), "0.4 0.7" or "0.4,0.7": a '-' after a digit separates.
        for (std::size_t i = 1; i < s.size(); ++i)
            if (s[i] == '-' &&
                (std::isdigit(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '.'))
                s[i] = ' ';
        auto f = split_fields(s, true);
        if (f.size() != 2)
            throw BadAnswer("expected starting and ending wavelength (two numbers), found " +
                            quoted(t));
        double w1 = Asker::number(std::string(f[0]), "starting wavelength");
        double w2 = Asker::number(std::string(f[1]), "ending wavelength");
        for (double w : {w1, w2})
            if (w < lo || w > hi)
                throw BadAnswer("expected wavelength (" + unit + ") in " + range_text(lo, hi) +
                                ", found " + quoted(t));
        if (!(w1 < w2))
            throw BadAnswer(
                "expected a starting wavelength below the ending wavelength, "
                "found " +
                quoted(t));
        return std::pair{w1 * scale, w2 * scale};
    });
    const int n = a.integer("intervals", "number of intervals", 1, 396);
    run.spectral = wavelength_to_card4(range.first, range.second, n);
}

// CARD 1: model, path, mode, profiles, boundary (fig. 4.30, first questions).
void ask_card1(Asker& a, io::CdkCard1& c1) {
    c1 = {};
    c1.model = a.integer("model", "model atmosphere", 0, 7);
    if (c1.model == 0 || c1.model == 7) {
        a.ask<bool>("radiosonde", [](const std::string& t) {
            if (!Asker::parse_yes_no(t, "radiosonde input"))
                throw BadAnswer(
                    "expected radiosonde input in [y] (model 0 and 7 layers are "
                    "read from an .rsd file), found " +
                    quoted(t));
            return true;
        });
    }
    if (c1.model == 0)
        c1.itype =
            a.integer("itype", "path type", 1, 1, {}, " (model 0 is for a horizontal path only)");
    else
        c1.itype = a.integer("itype", "path type", 1, 3);
    c1.iemsct = a.integer("iemsct", "execution mode", 0, 3);
    c1.imult = a.integer("imult", "multiple scattering mode", 0, 1);
    static const char* kGases[6][2] = {{"modify_tp", "temperature and pressure"},
                                       {"modify_h2o", "water vapor"},
                                       {"modify_o3", "ozone"},
                                       {"modify_ch4", "CH4"},
                                       {"modify_n2o", "N2O"},
                                       {"modify_co", "CO"}};
    for (int i = 0; i < 6; ++i) {
        if (a.yes_no(kGases[i][0], std::string("modify ") + kGases[i][1]))
            c1.m[i] = a.integer(std::string("m").append(std::to_string(i + 1)),
                                std::string("model for ") + kGases[i][1], 1, 6);
    }
    c1.mdef = 1;  // default profiles for the other gases (fig. 4.31)
    c1.im = (c1.model == 0 || c1.model == 7) ? 1 : 0;
    c1.noprt = a.yes_no("print_profiles", "print the profiles") ? 0 : 1;
    c1.boundary_temperature_k = a.real("tbound", "boundary temperature (K, 0 first level)", 0, 400);
    c1.surface_albedo = a.real("salb", "surface albedo", 0, 1);
}

// CARD 2 aerosols, clouds and ground, with CARD 2A (cirrus) and 2B (VSA) when asked for.
void ask_card2(Asker& a, io::CdkRun& run) {
    io::CdkCard2& c2 = run.card2;
    c2 = {};
    run.cirrus.reset();
    run.vsa.reset();
    c2.ihaze = a.integer("ihaze", "aerosol model IHAZE", 0, 10, {7},
                         " except 7 (user defined, not supported)");
    c2.icstl = 1;  // CONTROL7 writes 1 unless asked (fig. 4.31); LOWTRAN reads it for IHAZE 3
    if (c2.ihaze == 3) {
        c2.icstl = a.integer("icstl", "air mass character", 1, 10);
        c2.wind_speed_m_s = a.real("wss", "current wind speed (m/s)", 0, 50);
        c2.wind_speed_24h_m_s = a.real("whh", "24-hour average wind speed (m/s)", 0, 50);
    } else if (c2.ihaze == 10) {
        c2.wind_speed_m_s = a.real("wss", "current wind speed (m/s)", 0, 50);
    }
    c2.iseasn = a.integer("iseasn", "season", 0, 2);
    c2.ivulcn = a.integer("ivulcn", "volcanic extinction", 0, 8);
    c2.icld = a.ask<int>("icld", [](const std::string& t) {
        double v = Asker::number(t, "cloud model");
        if (v != std::floor(v) || !((v >= 0 && v <= 10) || (v >= 18 && v <= 20)))
            throw BadAnswer(
                "expected cloud model in [0, 10] or [18, 20] (11, user defined, "
                "is not supported), found " +
                quoted(t));
        return static_cast<int>(v);
    });
    if (c2.icld >= 18) {
        io::CdkCirrus c;
        c.thickness_km = a.real("cirrus_thickness", "cirrus thickness (km)", 0, 20);
        c.base_altitude_km = a.real("cirrus_base", "cirrus base altitude (km)", 0, 30);
        c.extinction_km1 = a.real("cirrus_extinction", "cirrus extinction (km-1)", 0, 10);
        run.cirrus = c;
    }
    c2.ivsa = a.yes_no("ivsa", "army vertical structure algorithm") ? 1 : 0;
    if (c2.ivsa == 1) {
        io::CdkVsa v;
        v.cloud_ceiling_km = a.real("vsa_ceiling", "cloud ceiling height (km)", 0, 3);
        v.cloud_thickness_km = a.real("vsa_thickness", "cloud thickness (km)", 0, 3);
        v.inversion_km = a.real("vsa_inversion", "inversion height (km)", 0, 3);
        run.vsa = v;
    }
    if (a.yes_no("override_vis", "override the visibility"))
        c2.visibility_km = a.real("vis", "visibility (km)", 0, 1000, true);
    c2.rain_rate_mm_h = a.real("rain_rate", "rain rate (mm/h)", 0, 200);
    c2.ground_altitude_km = a.ask<double>("gndalt", [](const std::string& t) {
        double v = Asker::number(t, "ground altitude (km)");
        if (v < 0 || v >= 6)
            throw BadAnswer("expected ground altitude (km) in [0, 6), found " + quoted(t));
        return v;
    });
}

// Every question of a run, in fig. 4.30's order.
void ask_full(Asker& a, io::CdkRun& run) {
    ask_card1(a, run.card1);
    ask_card2(a, run);
    run.profile.reset();
    if (run.card1.model == 0 || run.card1.model == 7) ask_profile(a, run);
    ask_geometry(a, run);
    ask_spectral(a, run);
}

int ask_irpt(Asker& a, const io::CdkRun& run) {
    return a.ask<int>("irpt", [&](const std::string& t) {
        double v = Asker::number(t, "IRPT");
        const bool no_card3 = run.card1.imult == 1 && run.card1.iemsct == 2;
        if (v == 0 || v == 1 || v == 4 || (v == 3 && !no_card3)) return static_cast<int>(v);
        if (v == 3)
            throw BadAnswer(
                "expected IRPT in [0, 1, 4] (LOWTRAN 7 cannot repeat CARD 3 with "
                "multiple and solar scattering), found " +
                quoted(t));
        throw BadAnswer("expected IRPT in [0, 1, 3, 4], found " + quoted(t));
    });
}

}  // namespace

double time_answer_hours(double value) {
    if (value >= 0 && value <= 24) return value;
    if (value >= 100 && value <= 2400) {
        double hh = std::floor(value / 100), mm = value - 100 * hh;
        if (mm < 60 && hh * 60 + mm <= 24 * 60) return hh + mm / 60.0;
    }
    throw std::invalid_argument("time out of range");
}

io::CdkSpectral wavelength_to_card4(double start_um, double end_um, int intervals) {
    io::CdkSpectral s;
    s.v1_cm1 = cm1_from_um(end_um);
    s.v2_cm1 = cm1_from_um(start_um);
    double dv = (s.v2_cm1 - s.v1_cm1) / intervals;
    s.dv_cm1 = std::max(5.0, 5.0 * std::round(dv / 5.0));
    return s;
}

Control7Result run_control7(AnswerSource& answers,
                            const std::map<std::string, std::string>& overrides) {
    std::set<std::string> known;
    for (const auto& q : control7_questions()) known.insert(q.key);
    for (const auto& [key, value] : overrides)
        if (!known.count(key))
            throw UsageError("--answer: unknown question '" + key +
                             "' (control7(1) lists the keys)");
    Asker a(answers, overrides);
    Control7Result result;
    result.deck_path = a.ask<std::string>("deck", [](const std::string& t) {
        if (t.empty()) throw BadAnswer("expected a file name for the card deck, found ''");
        return t;
    });
    io::CdkRun run;
    run.kind = io::CdkRunKind::Full;
    ask_full(a, run);
    for (;;) {
        run.irpt = ask_irpt(a, run);
        result.cdk.runs.push_back(run);
        if (run.irpt == 0) break;
        io::CdkRun next = run;
        if (run.irpt == 1) {
            next.kind = io::CdkRunKind::Full;
            ask_full(a, next);
        } else if (run.irpt == 3) {
            next.kind = io::CdkRunKind::Geometry;
            ask_geometry(a, next);
        } else {
            next.kind = io::CdkRunKind::Spectral;
            ask_spectral(a, next);
        }
        run = next;
    }
    for (const auto& [key, value] : overrides)
        if (!a.used().count(key)) result.unused_overrides.push_back(key);
    return result;
}

}  // namespace sigchain::control7
