// Reading the .cdk LOWTRAN 7 card deck (White (1996), fig. 4.31; man cdk(5)). Writing is in
// cdk_write.cpp.
#include "io/cdk.hpp"

#include <sstream>

#include "io/cdk_card2d.hpp"
#include "io/fortran_columns.hpp"

namespace sigchain::io {

namespace {

using fortran::Card;

constexpr double kAbsoluteZero_c = -273.15;

// The cards of a deck, one line each, in order. A blank line is a card of blanks.
class DeckReader {
public:
    explicit DeckReader(const TextInput& in) : m_cursor(in, LineCursor::Mode::Raw) {}

    // The next card, named for messages; `layout` lists its fields for the
    // end-of-file message ("expected CARD 4 (V1,V2,DV)").
    Card next(const std::string& name, const std::string& layout) {
        const Line& line = m_cursor.next(name + " (" + layout + ")");
        return Card(line.text, m_cursor.where(line), name);
    }
    LineCursor& cursor() { return m_cursor; }

private:
    LineCursor m_cursor;
};

// An integer code that must lie in [lo, hi].
int code(const Card& c, int column, int width, const char* field, long lo, long hi) {
    long v = c.integer(column, width, field);
    if (v < lo || v > hi)
        c.fail(field, column, width,
               "expected " + std::string(field) + " in " + std::to_string(lo) + ".." +
                   std::to_string(hi) + ", found " + quoted(std::to_string(v)));
    return static_cast<int>(v);
}

// A real that must lie in [lo, hi].
double real_in(const Card& c, int column, int width, int decimals, const char* field, double lo,
               double hi) {
    double v = c.real(column, width, decimals, field);
    if (v < lo || v > hi)
        c.fail(field, column, width,
               "expected " + std::string(field) + " in [" + format_number(lo) + ", " +
                   format_number(hi) + "], found " + quoted(format_number(v)));
    return v;
}

// A real that must be at least `lo`.
double real_min(const Card& c, int column, int width, int decimals, const char* field, double lo) {
    double v = c.real(column, width, decimals, field);
    if (v < lo)
        c.fail(field, column, width,
               "expected " + std::string(field) + " of at least " + format_number(lo) + ", found " +
                   quoted(format_number(v)));
    return v;
}

std::string rtrim(std::string s) {
    s.erase(s.find_last_not_of(' ') + 1);
    return s;
}

// --- CARD 1 and CARD 2 --------------------------------------------------------------

CdkCard1 read_card1(DeckReader& r) {
    Card c = r.next("CARD 1", "MODEL,ITYPE,IEMSCT,IMULT,M1-M6,MDEF,IM,NOPRT,TBOUND,SALB");
    CdkCard1 k;
    k.model = code(c, 1, 5, "MODEL", 0, 7);
    k.itype = code(c, 6, 5, "ITYPE", 1, 3);
    k.iemsct = code(c, 11, 5, "IEMSCT", 0, 3);
    k.imult = code(c, 16, 5, "IMULT", 0, 1);
    static const char* names[6] = {"M1", "M2", "M3", "M4", "M5", "M6"};
    for (int i = 0; i < 6; ++i) k.m[i] = code(c, 21 + 5 * i, 5, names[i], 0, 6);
    k.mdef = code(c, 51, 5, "MDEF", 0, 1);
    k.im = code(c, 56, 5, "IM", 0, 1);
    k.noprt = code(c, 61, 5, "NOPRT", 0, 1);
    k.boundary_temperature_k = real_min(c, 66, 8, 3, "TBOUND", 0);
    k.surface_albedo = real_in(c, 74, 7, 2, "SALB", 0, 1);
    c.require_blank_from(81);
    if (k.model == 0 && k.itype != 1)
        c.fail("ITYPE", 6, 5,
               "expected ITYPE 1 with MODEL 0 (meteorological data are for a "
               "horizontal path only), found " +
                   quoted(std::to_string(k.itype)));
    return k;
}

CdkCard2 read_card2(DeckReader& r) {
    Card c = r.next("CARD 2", "IHAZE,ISEASN,IVULCN,ICSTL,ICLD,IVSA,VIS,WSS,WHH,RAINRT,GNDALT");
    CdkCard2 k;
    k.ihaze = code(c, 1, 5, "IHAZE", 0, 10);
    k.iseasn = code(c, 6, 5, "ISEASN", 0, 2);
    k.ivulcn = code(c, 11, 5, "IVULCN", 0, 8);
    k.icstl = code(c, 16, 5, "ICSTL", 0, 10);
    k.icld = code(c, 21, 5, "ICLD", 0, 20);
    if (k.icld > 11 && k.icld < 18)
        c.fail("ICLD", 21, 5,
               "expected ICLD in 0..11 or 18..20, found " + quoted(std::to_string(k.icld)));
    k.ivsa = code(c, 26, 5, "IVSA", 0, 1);
    k.visibility_km = real_min(c, 31, 10, 3, "VIS", 0);
    k.wind_speed_m_s = real_min(c, 41, 10, 3, "WSS", 0);
    k.wind_speed_24h_m_s = real_min(c, 51, 10, 3, "WHH", 0);
    k.rain_rate_mm_h = real_min(c, 61, 10, 3, "RAINRT", 0);
    k.ground_altitude_km = c.real(71, 10, 3, "GNDALT");
    if (k.ground_altitude_km < 0 || k.ground_altitude_km >= 6)
        c.fail("GNDALT", 71, 10,
               "expected GNDALT (km) at least 0 and below 6, found " +
                   quoted(format_number(k.ground_altitude_km)));
    c.require_blank_from(81);
    return k;
}

CdkCirrus read_card2a(DeckReader& r) {
    Card c = r.next("CARD 2A", "CTHIK,CALT,CEXT,ISEED");
    CdkCirrus k;
    k.thickness_km = real_min(c, 1, 10, 3, "CTHIK", 0);
    k.base_altitude_km = real_min(c, 11, 10, 3, "CALT", 0);
    k.extinction_km1 = real_min(c, 21, 10, 3, "CEXT", 0);
    k.iseed = c.integer(31, 10, "ISEED");
    c.require_blank_from(41);
    return k;
}

CdkVsa read_card2b(DeckReader& r) {
    Card c = r.next("CARD 2B", "ZCVSA,ZTVSA,ZINVSA");
    CdkVsa k;
    k.cloud_ceiling_km = c.real(1, 10, 3, "ZCVSA");
    k.cloud_thickness_km = real_min(c, 11, 10, 3, "ZTVSA", 0);
    k.inversion_km = c.real(21, 10, 3, "ZINVSA");
    c.require_blank_from(31);
    return k;
}

// --- CARD 2C and the layers ---------------------------------------------------------

// JCHAR position i (0-based): what it gives the unit of, and the letters allowed
// besides blank (digits 1-6 select a model's default, except in position 15).
struct UnitKey {
    const char* quantity;
    const char* letters;
};
constexpr UnitKey kUnitKeys[15] = {
    {"P", "ABC"},     {"T", "AB"},      {"H2O", "ABCDEFGH"}, {"CO2", "ABCDE"},  {"O3", "ABCDE"},
    {"N2O", "ABCDE"}, {"CO", "ABCDE"},  {"CH4", "ABCDE"},    {"O2", "ABCDE"},   {"NO", "ABCDE"},
    {"SO2", "ABCDE"}, {"NO2", "ABCDE"}, {"NH3", "ABCDE"},    {"HNO3", "ABCDE"}, {"(unused)", ""}};

void check_jchar(const Card& c, const std::string& jchar) {
    for (int i = 0; i < 15; ++i) {
        char ch = jchar[static_cast<std::size_t>(i)];
        const UnitKey& key = kUnitKeys[i];
        bool model_digit = i < 14 && ch >= '1' && ch <= '6';
        if (ch == ' ' || model_digit ||
            std::string_view(key.letters).find(ch) != std::string_view::npos)
            continue;
        std::string allowed = i < 14 ? std::string("blank, 1-6 or one of ") + key.letters : "blank";
        c.fail("JCHAR", 61 + i, 1,
               "expected the unit of " + std::string(key.quantity) + " (" + allowed + "), found " +
                   quoted(std::string(1, ch)));
    }
}

CdkLayer read_layer(DeckReader& r, const std::string& name) {
    Card c = r.next(name, "ZMDL,P,T,WMOL(1),WMOL(2),WMOL(3),JCHAR");
    CdkLayer l;
    l.altitude_km = c.real(1, 10, 3, "ZMDL");
    std::string jchar = c.characters(61, 15);
    check_jchar(c, jchar);
    c.require_blank_from(76);
    l.jchar = rtrim(jchar);
    l.pressure = real_min(c, 11, 10, 3, "P", 0);
    l.temperature = real_min(c, 21, 10, 3, "T", jchar[1] == 'B' ? kAbsoluteZero_c : 0);
    l.wmol[0] = real_min(c, 31, 10, 3, "WMOL(1)", jchar[2] == 'G' ? kAbsoluteZero_c : 0);
    l.wmol[1] = real_min(c, 41, 10, 3, "WMOL(2)", 0);
    l.wmol[2] = real_min(c, 51, 10, 3, "WMOL(3)", 0);
    return l;
}

std::array<double, 9> read_card2c2(DeckReader& r, const std::string& layer) {
    std::array<double, 9> w{};
    Card c = r.next("CARD 2C2 (" + layer + ")", "WMOL(4)-WMOL(11)");
    static const char* names[8] = {"WMOL(4)", "WMOL(5)", "WMOL(6)",  "WMOL(7)",
                                   "WMOL(8)", "WMOL(9)", "WMOL(10)", "WMOL(11)"};
    for (int i = 0; i < 8; ++i) w[i] = real_min(c, 1 + 10 * i, 10, 3, names[i], 0);
    c.require_blank_from(81);
    Card d = r.next("CARD 2C2 continued (" + layer + ")", "WMOL(12)");
    w[8] = real_min(d, 1, 10, 3, "WMOL(12)", 0);
    d.require_blank_from(11);
    return w;
}

CdkLayerAerosol read_card2c3(DeckReader& r, const std::string& layer) {
    Card c =
        r.next("CARD 2C3 (" + layer + ")", "10X,AHAZE,EQLWCZ,RRATZ,IHA1,ICLD1,IVUL1,ISEA1,ICHR");
    if (c.characters(1, 10) != std::string(10, ' '))
        c.fail("10X", 1, 10, "expected blanks, found " + quoted(c.characters(1, 10)));
    CdkLayerAerosol a;
    a.extinction_km1 = real_min(c, 11, 10, 3, "AHAZE", 0);
    a.liquid_water_g_m3 = real_min(c, 21, 10, 3, "EQLWCZ", 0);
    a.rain_rate_mm_h = real_min(c, 31, 10, 3, "RRATZ", 0);
    a.iha1 = code(c, 41, 5, "IHA1", 0, 10);
    a.icld1 = code(c, 46, 5, "ICLD1", 0, 11);
    a.ivul1 = code(c, 51, 5, "IVUL1", 0, 8);
    a.isea1 = code(c, 56, 5, "ISEA1", 0, 2);
    a.ichr = code(c, 61, 5, "ICHR", 0, 1);
    c.require_blank_from(66);
    return a;
}

CdkProfile read_profile(DeckReader& r) {
    Card c = r.next("CARD 2C", "ML,IRD1,IRD2,TITLE");
    CdkProfile p;
    int ml = code(c, 1, 5, "ML", 1, kCdkMaxLayers);
    p.ird1 = code(c, 6, 5, "IRD1", 0, 1);
    p.ird2 = code(c, 11, 5, "IRD2", 0, 1);
    p.title = rtrim(c.characters(16, 72));
    c.require_blank_from(88);
    for (int k = 1; k <= ml; ++k) {
        std::string layer = "layer " + std::to_string(k) + " of ML " + std::to_string(ml);
        std::string name = "CARD 2C1 (" + layer + ")";
        CdkLayer l = read_layer(r, name);
        if (!p.layers.empty() && l.altitude_km <= p.layers.back().altitude_km)
            throw DataError(r.cursor().where(),
                            name + " ZMDL (columns 1-10): expected an altitude above layer " +
                                std::to_string(k - 1) + "'s " +
                                format_number(p.layers.back().altitude_km) + " km, found " +
                                quoted(format_number(l.altitude_km)));
        if (p.ird1 == 1) l.wmol_4_12 = read_card2c2(r, layer);
        if (p.ird2 == 1) l.aerosol = read_card2c3(r, layer);
        p.layers.push_back(std::move(l));
    }
    return p;
}

// --- CARD 3 group ------------------------------------------------------------------

void read_card3(DeckReader& r, CdkGeometry& g) {
    Card c = r.next("CARD 3", "H1,H2,ANGLE,RANGE,BETA,RO,LEN");
    g.h1_km = real_min(c, 1, 10, 3, "H1", 0);
    g.h2_km = real_min(c, 11, 10, 3, "H2", 0);
    g.zenith_angle_deg = real_in(c, 21, 10, 3, "ANGLE", 0, 180);
    g.range_km = real_min(c, 31, 10, 3, "RANGE", 0);
    g.earth_center_angle_deg = real_in(c, 41, 10, 3, "BETA", 0, 180);
    g.earth_radius_km = real_min(c, 51, 10, 3, "RO", 0);
    g.len = code(c, 61, 5, "LEN", 0, 1);
    c.require_blank_from(66);
}

void read_alternate_card3(DeckReader& r, CdkGeometry& g) {
    Card c = r.next("CARD 3 (alternate, IEMSCT=3)", "H1,H2,ANGLE,IDAY,RO,ISOURC,ANGLEM");
    g.h1_km = real_min(c, 1, 10, 3, "H1", 0);
    g.h2_km = real_min(c, 11, 10, 3, "H2", 0);
    g.zenith_angle_deg = real_in(c, 21, 10, 3, "ANGLE", 0, 180);
    g.iday = code(c, 31, 5, "IDAY", 0, 366);
    if (c.characters(36, 5) != std::string(5, ' '))
        c.fail("5X", 36, 5, "expected blanks, found " + quoted(c.characters(36, 5)));
    g.earth_radius_km = real_min(c, 41, 10, 3, "RO", 0);
    g.isourc = code(c, 51, 5, "ISOURC", 0, 1);
    g.moon_phase_angle_deg = real_in(c, 56, 10, 3, "ANGLEM", 0, 180);
    c.require_blank_from(66);
}

void read_card3a2(DeckReader& r, CdkGeometry& g) {
    Card c = r.next("CARD 3A2", "PARM1,PARM2,PARM3,PARM4,TIME,PSIPO,ANGLEM,G");
    if (g.iparm == 2) {
        g.parm[0] = real_in(c, 1, 10, 3, "PARM1", -180, 180);
        g.parm[1] = real_in(c, 11, 10, 3, "PARM2", 0, 180);
    } else {
        g.parm[0] = real_in(c, 1, 10, 3, "PARM1", -90, 90);
        g.parm[1] = real_in(c, 11, 10, 3, "PARM2", 0, 360);
    }
    if (g.iparm == 0) {
        g.parm[2] = real_in(c, 21, 10, 3, "PARM3", -90, 90);
        g.parm[3] = real_in(c, 31, 10, 3, "PARM4", 0, 360);
    } else {
        g.parm[2] = c.real(21, 10, 3, "PARM3");
        g.parm[3] = c.real(31, 10, 3, "PARM4");
    }
    g.time_h = g.iparm == 1 ? real_in(c, 41, 10, 3, "TIME", 0, 24) : c.real(41, 10, 3, "TIME");
    g.path_azimuth_deg = real_in(c, 51, 10, 3, "PSIPO", -360, 360);
    g.moon_phase_angle_deg = real_in(c, 61, 10, 3, "ANGLEM", 0, 180);
    g.asymmetry_g = real_in(c, 71, 10, 3, "G", -1, 1);
    c.require_blank_from(81);
}

void read_phase_function(DeckReader& r, CdkGeometry& g) {
    Card c = r.next("CARD 3B1", "NANGLS");
    int n = code(c, 1, 5, "NANGLS", 1, kCdkMaxPhaseAngles);
    c.require_blank_from(6);
    for (int i = 1; i <= n; ++i) {
        std::string name =
            "CARD 3B2 (angle " + std::to_string(i) + " of NANGLS " + std::to_string(n) + ")";
        Card a = r.next(name, "ANGF,F(1),F(2),F(3),F(4)");
        CdkPhaseAngle p;
        p.angle_deg = real_in(a, 1, 10, 3, "ANGF", 0, 180);
        if (!g.phase_function.empty() && p.angle_deg <= g.phase_function.back().angle_deg)
            a.fail("ANGF", 1, 10,
                   "expected an angle above the previous " +
                       format_number(g.phase_function.back().angle_deg) + ", found " +
                       quoted(format_number(p.angle_deg)));
        static const char* names[4] = {"F(1)", "F(2)", "F(3)", "F(4)"};
        for (int k = 0; k < 4; ++k)
            p.phase_function_sr1[k] = real_min(a, 11 + 10 * k, 10, 3, names[k], 0);
        a.require_blank_from(51);
        g.phase_function.push_back(p);
    }
}

CdkGeometry read_geometry(DeckReader& r, const CdkCard1& card1) {
    CdkGeometry g;
    if (card1.iemsct == 3) {
        read_alternate_card3(r, g);
        return g;
    }
    read_card3(r, g);
    if (card1.iemsct != 2) return g;
    Card c = r.next("CARD 3A1", "IPARM,IPH,IDAY,ISOURC");
    g.iparm = code(c, 1, 5, "IPARM", 0, 2);
    g.iph = code(c, 6, 5, "IPH", 0, 2);
    g.iday = code(c, 11, 5, "IDAY", 0, 366);
    g.isourc = code(c, 16, 5, "ISOURC", 0, 1);
    c.require_blank_from(21);
    if (g.iparm == 1 && g.isourc == 1)
        c.fail("ISOURC", 16, 5, "expected ISOURC 0 (the sun) with IPARM 1, found '1'");
    read_card3a2(r, g);
    if (g.iph == 1) read_phase_function(r, g);
    return g;
}

// --- CARD 4, CARD 5 and the runs ------------------------------------------------------

CdkSpectral read_card4(DeckReader& r) {
    Card c = r.next("CARD 4", "V1,V2,DV");
    CdkSpectral s;
    s.v1_cm1 = real_in(c, 1, 10, 3, "V1", 0, kCdkMaxWavenumber_cm1);
    s.v2_cm1 = real_in(c, 11, 10, 3, "V2", 0, kCdkMaxWavenumber_cm1);
    s.dv_cm1 = c.real(21, 10, 3, "DV");
    c.require_blank_from(31);
    if (s.v2_cm1 <= s.v1_cm1)
        c.fail("V2", 11, 10,
               "expected V2 above V1 (" + format_number(s.v1_cm1) + " cm-1), found " +
                   quoted(format_number(s.v2_cm1)));
    if (s.dv_cm1 <= 0)
        c.fail("DV", 21, 10,
               "expected DV (cm-1) above 0, found " + quoted(format_number(s.dv_cm1)));
    return s;
}

int read_card5(DeckReader& r, const CdkCard1& card1) {
    Card c = r.next("CARD 5", "IRPT");
    long irpt = c.integer(1, 5, "IRPT");
    c.require_blank_from(6);
    if (irpt != 0 && irpt != 1 && irpt != 3 && irpt != 4)
        c.fail("IRPT", 1, 5,
               "expected IRPT 0 (end), 1 (all cards), 3 (CARD 3) or 4 (CARD 4), found " +
                   quoted(std::to_string(irpt)));
    if (irpt == 3 && card1.imult == 1 && card1.iemsct == 2)
        c.fail("IRPT", 1, 5,
               "IRPT 3 cannot follow a run with multiple scattering and solar "
               "scattering (IMULT 1, IEMSCT 2) in LOWTRAN 7; use IRPT 1");
    return static_cast<int>(irpt);
}

// The cards of a full run (the first, or one after IRPT=1); `previous` is the run
// before it, whose profile a run with IM=0 reuses.
CdkRun read_full_run(DeckReader& r, const CdkRun* previous) {
    CdkRun run;
    run.card1 = read_card1(r);
    SourceLocation card1_at = r.cursor().where();
    run.card2 = read_card2(r);
    if (run.card2.icld >= 18) run.cirrus = read_card2a(r);
    if (run.card2.ivsa == 1) run.vsa = read_card2b(r);
    if (run.card1.model == 0 || run.card1.model == 7) {
        if (run.card1.im == 1)
            run.profile = read_profile(r);
        else if (previous && previous->profile)
            run.profile = previous->profile;
        else
            throw DataError(card1_at, "CARD 1 IM (columns 56-60): expected IM 1 with MODEL " +
                                          std::to_string(run.card1.model) +
                                          " (IM 0 reuses an earlier run's profile, and there is "
                                          "none), found '0'");
    }
    // CARD 2D follows the profile (LOWTRAN 7 calls RDEXA after AERNSM).
    if (run.card2.ihaze == 7 || run.card2.icld == 11)
        run.user_optics = read_cdk_card2d([&r](const std::string& name, const std::string& layout) {
            return r.next(name, layout);
        });
    run.geometry = read_geometry(r, run.card1);
    run.spectral = read_card4(r);
    return run;
}

std::string summary(const Cdk& cdk) {
    const CdkRun& first = cdk.runs.front();
    std::ostringstream s;
    s << cdk.runs.size() << (cdk.runs.size() == 1 ? " run" : " runs") << ", MODEL "
      << first.card1.model;
    if (first.profile)
        s << " (" << first.profile->layers.size() << " layers"
          << (first.profile->title.empty() ? "" : ", " + first.profile->title) << ")";
    s << ", IEMSCT " << first.card1.iemsct << ", " << format_number(first.spectral.v1_cm1) << "-"
      << format_number(first.spectral.v2_cm1) << " cm-1 step "
      << format_number(first.spectral.dv_cm1);
    return s.str();
}

}  // namespace

Cdk parse_cdk(const TextInput& in) {
    DeckReader r(in);
    if (trim(in.text()).empty())
        throw DataError(in.at(0), "empty file, expected CARD 1 of a LOWTRAN 7 card deck");
    Cdk cdk;
    CdkRunKind kind = CdkRunKind::Full;
    while (true) {
        const CdkRun* previous = cdk.runs.empty() ? nullptr : &cdk.runs.back();
        CdkRun run = kind == CdkRunKind::Full ? read_full_run(r, previous) : *previous;
        run.kind = kind;
        if (kind == CdkRunKind::Geometry) run.geometry = read_geometry(r, run.card1);
        if (kind == CdkRunKind::Spectral) run.spectral = read_card4(r);
        run.irpt = read_card5(r, run.card1);
        cdk.runs.push_back(std::move(run));
        int irpt = cdk.runs.back().irpt;
        if (irpt == 0) break;
        kind = irpt == 1   ? CdkRunKind::Full
               : irpt == 3 ? CdkRunKind::Geometry
                           : CdkRunKind::Spectral;
    }
    LineCursor& cur = r.cursor();
    while (!cur.at_end()) {
        const Line& line = cur.next("");
        if (!trim(line.text).empty())
            throw DataError(cur.where(line),
                            "unexpected content after the final CARD 5 "
                            "(IRPT 0), found " +
                                quoted(line.text));
    }
    return cdk;
}

FormatHandler cdk_format() {
    return {"cdk", "LOWTRAN 7 card deck (White (1996), fig. 4.31)",
            [](const TextInput& in) { return summary(parse_cdk(in)); },
            [](const TextInput& in, std::ostream& out) { write_cdk(out, parse_cdk(in)); }};
}

}  // namespace sigchain::io
