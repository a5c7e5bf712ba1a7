// Tests for control7's answer logic and deck building (lib/control7/control7).
#include "control7/control7.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace sigchain;
using namespace sigchain::control7;

namespace {

const std::string kRsd = SIGCHAIN_TEST_DATA "/white1996/30Sep95800L.rsd";

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

// The answers of White (1996) (tests/data/control7/hawkeye.answers) with the radiosonde path made
// absolute.
std::map<std::string, std::string> seed_overrides(std::map<std::string, std::string> more = {}) {
    more.emplace("rsd", kRsd);
    return more;
}

Control7Result run_seed(const std::map<std::string, std::string>& overrides) {
    LineAnswers answers(TextInput::from_file(SIGCHAIN_TEST_DATA "/control7/hawkeye.answers"));
    Control7Result r = run_control7(answers, overrides);
    EXPECT_FALSE(answers.leftover().has_value());
    return r;
}

std::string deck_of(const io::Cdk& cdk) {
    std::ostringstream out;
    io::write_cdk(out, cdk);
    return out.str();
}

// The answers of White (1996) with the answer to `key` replaced: the DataError message.
std::string error_with(const std::string& key, const std::string& value) {
    try {
        run_seed(seed_overrides({{key, value}}));
    } catch (const DataError& e) {
        return e.what();
    }
    return "(no error)";
}

// A radiosonde in memory.
io::Rsd sonde(std::vector<io::RsdLevel> levels) { return io::Rsd{std::move(levels)}; }

}  // namespace

TEST(Control7, SeedAnswersReproduceTheSeedDeck) {
    Control7Result r = run_seed(seed_overrides());
    EXPECT_EQ(r.deck_path, "flyover.cdk");
    EXPECT_TRUE(r.unused_overrides.empty());
    const auto got = lines_of(deck_of(r.cdk));
    const auto seed = lines_of(file_text(SIGCHAIN_TEST_DATA "/white1996/flyover.cdk"));
    ASSERT_EQ(got.size(), seed.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        SCOPED_TRACE("line " + std::to_string(i + 1));
        if (i == 1) {
            // CARD 2: the deck of White (1996) has VIS 0.000 although its answer was 23 km.
            std::string expected = seed[i];
            expected.replace(30, 10, "    23.000");
            EXPECT_EQ(got[i], expected);
        } else if (i == 25) {
            // CARD 4: 0.4-0.7 um is 14285.714-25000 cm-1 (White's (1996) deck shows a
            // 2000-3333.333 cm-1 run); (25000 - 14285.714)/396 = 27.06 -> DV 25.
            EXPECT_EQ(got[i], " 14285.714 25000.000    25.000");
        } else {
            EXPECT_EQ(got[i], seed[i]);
        }
    }
}

TEST(Control7, SeedDeckParsesBackToTheSameRuns) {
    Control7Result r = run_seed(seed_overrides());
    // Written and read back, the deck reads as the same text (values rounded to the
    // columns once, e.g. V1 14285.714).
    io::Cdk back = io::parse_cdk(TextInput::from_string(deck_of(r.cdk), "deck"));
    EXPECT_EQ(deck_of(back), deck_of(r.cdk));
    const io::CdkRun& run = r.cdk.runs.at(0);
    EXPECT_EQ(run.card1.model, 7);
    EXPECT_EQ(run.profile->layers.size(), 19u);
    EXPECT_EQ(run.profile->title, "HAWKEYE");
    EXPECT_DOUBLE_EQ(run.geometry.time_h, 14.0);
}

TEST(Control7, DewPointsAboveTheLastValidKeepItsDepression) {
    // White (1996), table 4.3 (0800L): dew points missing from 250 mb up; the last valid level,
    // 300 mb, has T -38.1 C and Td -41.2 C (depression 3.1 C), so 250-100 mb get
    // T - 3.1: -50.8, -60.0, -65.6, -71.6 C, the values its table shows.
    io::Rsd raw = sonde({{8.474, 350, -28.5, -34.8},
                         {9.573, 300, -38.1, -41.2},
                         {10.803, 250, -47.7, std::nullopt},
                         {12.253, 200, -56.9, std::nullopt},
                         {14.043, 150, -62.5, std::nullopt},
                         {16.493, 100, -68.5, std::nullopt}});
    io::Rsd filled = fill_missing_dew_points(raw, {"t.rsd", 0});
    const double expected[] = {-34.8, -41.2, -50.8, -60.0, -65.6, -71.6};
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(*filled.levels[i].dew_point_c, expected[i], 1e-9);
}

TEST(Control7, DewPointGapsBelowAndBetweenValidLevels) {
    io::Rsd raw = sonde({{0, 1000, 20, std::nullopt},
                         {1, 900, 15, 10},  // depression 5
                         {2, 800, 10, std::nullopt},
                         {3, 700, 5, -5}});  // depression 10
    io::Rsd filled = fill_missing_dew_points(raw, {"t.rsd", 0});
    EXPECT_DOUBLE_EQ(*filled.levels[0].dew_point_c, 15);   // first depression kept
    EXPECT_DOUBLE_EQ(*filled.levels[2].dew_point_c, 2.5);  // depression 7.5 halfway
}

TEST(Control7, RadiosondeWithoutTemperatureOrDewPointsIsRejected) {
    EXPECT_THROW(
        fill_missing_dew_points(sonde({{0, 1000, std::nullopt, 5}, {1, 900, 10, 5}}), {"t.rsd", 0}),
        DataError);
    EXPECT_THROW(
        fill_missing_dew_points(sonde({{0, 1000, 20, std::nullopt}, {1, 900, 10, std::nullopt}}),
                                {"t.rsd", 0}),
        DataError);
}

TEST(Control7, RadiosondeLayersAreCard2C1WithUnitFlags) {
    io::CdkProfile p =
        radiosonde_profile(sonde({{0.218, 998, 23.8, 7.8}, {0.639, 950, 14.7, 6.4}}), 1, "X");
    ASSERT_EQ(p.layers.size(), 1u);
    EXPECT_EQ(p.layers[0].jchar, "ABG");
    EXPECT_DOUBLE_EQ(p.layers[0].pressure, 998);
    EXPECT_DOUBLE_EQ(p.layers[0].temperature, 23.8);
    EXPECT_EQ(p.layers[0].wmol, (std::array<double, 3>{7.8, 0, 0}));
}

TEST(Control7, WavelengthsBecomeWavenumbers) {
    io::CdkSpectral s = wavelength_to_card4(0.4, 0.7, 396);
    EXPECT_NEAR(s.v1_cm1, 1e4 / 0.7, 1e-9);
    EXPECT_DOUBLE_EQ(s.v2_cm1, 25000);
    EXPECT_DOUBLE_EQ(s.dv_cm1, 25);
    // 3-5 um in 396 intervals: 3.37 cm-1 steps, LOWTRAN 7's minimum 5.
    EXPECT_DOUBLE_EQ(wavelength_to_card4(3, 5, 396).dv_cm1, 5);
    // Nanometres: the same range.
    LineAnswers in(TextInput::from_file(SIGCHAIN_TEST_DATA "/control7/hawkeye.answers"));
    Control7Result r =
        run_control7(in, seed_overrides({{"units", "nm"}, {"wavelengths", "400 700"}}));
    EXPECT_NEAR(r.cdk.runs[0].spectral.v1_cm1, 1e4 / 0.7, 1e-9);
    EXPECT_NEAR(r.cdk.runs[0].spectral.v2_cm1, 25000, 1e-9);
}

TEST(Control7, TimeAnswersInHoursOrHhmm) {
    EXPECT_DOUBLE_EQ(time_answer_hours(19.5), 19.5);
    EXPECT_DOUBLE_EQ(time_answer_hours(1400), 14);
    EXPECT_DOUBLE_EQ(time_answer_hours(1930), 19.5);
    EXPECT_THROW(time_answer_hours(30), std::invalid_argument);
    EXPECT_THROW(time_answer_hours(1260), std::invalid_argument);
    EXPECT_THROW(time_answer_hours(2500), std::invalid_argument);
}

TEST(Control7, EveryOutOfRangeAnswerNamesItsRange) {
    EXPECT_EQ(error_with("model", "8"),
              "--answer model: expected model atmosphere in [0, 7], found '8'");
    EXPECT_EQ(error_with("model", "2.5"),
              "--answer model: expected model atmosphere in [0, 7], found '2.5'");
    EXPECT_EQ(error_with("model", "seven"),
              "--answer model: expected model atmosphere (a number), found 'seven'");
    EXPECT_EQ(error_with("itype", "4"), "--answer itype: expected path type in [1, 3], found '4'");
    EXPECT_EQ(error_with("iemsct", "-1"),
              "--answer iemsct: expected execution mode in [0, 3], found '-1'");
    EXPECT_EQ(error_with("imult", "2"),
              "--answer imult: expected multiple scattering mode in [0, 1], found '2'");
    EXPECT_EQ(error_with("modify_o3", "maybe"),
              "--answer modify_o3: expected modify ozone in [y, n], found 'maybe'");
    EXPECT_EQ(error_with("salb", "1.5"),
              "--answer salb: expected surface albedo in [0, 1], found '1.5'");
    EXPECT_EQ(error_with("ihaze", "7"),
              "--answer ihaze: expected aerosol model IHAZE in [0, 10] except 7 (user defined, "
              "not supported), found '7'");
    EXPECT_EQ(error_with("ihaze", "11"),
              "--answer ihaze: expected aerosol model IHAZE in [0, 10] except 7 (user defined, "
              "not supported), found '11'");
    EXPECT_EQ(error_with("iseasn", "3"), "--answer iseasn: expected season in [0, 2], found '3'");
    EXPECT_EQ(error_with("ivulcn", "9"),
              "--answer ivulcn: expected volcanic extinction in [0, 8], found '9'");
    EXPECT_EQ(error_with("icld", "11"),
              "--answer icld: expected cloud model in [0, 10] or [18, 20] (11, user defined, is "
              "not supported), found '11'");
    EXPECT_EQ(error_with("vis", "0"),
              "--answer vis: expected visibility (km) in (0, 1000], found '0'");
    EXPECT_EQ(error_with("gndalt", "6"),
              "--answer gndalt: expected ground altitude (km) in [0, 6), found '6'");
    EXPECT_EQ(error_with("levels", "35"),
              "--answer levels: expected number of atmospheric levels in [1, 34], found '35'");
    EXPECT_EQ(error_with("levels", "20"),
              "--answer levels: expected number of atmospheric levels in [1, 19] (the levels of "
              "the radiosonde file), found 20");
    EXPECT_EQ(error_with("aerosol_by_layer", "y"),
              "--answer aerosol_by_layer: expected aerosol control by layer in [n] (CARD 2C3 "
              "input is not supported), found 'y'");
    EXPECT_EQ(error_with("h1", "0.1"),
              "--answer h1: expected H1, initial altitude (km, ground to 100) in [0.218, 100], "
              "found '0.1'");
    EXPECT_EQ(error_with("angle", "181"),
              "--answer angle: expected initial zenith angle (deg) in [0, 180], found '181'");
    EXPECT_EQ(error_with("iparm", "3"),
              "--answer iparm: expected geometry type IPARM in [0, 2], found '3'");
    EXPECT_EQ(error_with("iph", "1"),
              "--answer iph: expected phase function type IPH in [0, 2] except 1 (user "
              "supplied, not supported), found '1'");
    EXPECT_EQ(error_with("iday", "367"),
              "--answer iday: expected day of the year in [1, 366], found '367'");
    EXPECT_EQ(error_with("obs_lat", "91"),
              "--answer obs_lat: expected observer latitude (deg north) in [-90, 90], found '91'");
    EXPECT_EQ(error_with("obs_lon", "-1"),
              "--answer obs_lon: expected observer longitude (deg west) in [0, 360], found '-1'");
    EXPECT_EQ(error_with("time", "2500"),
              "--answer time: expected time of day in [0, 24] (decimal hours) or [100, 2400] "
              "(HHMM), found '2500'");
    EXPECT_EQ(error_with("psipo", "361"),
              "--answer psipo: expected path azimuth (deg east of north) in [0, 360], found "
              "'361'");
    EXPECT_EQ(error_with("units", "feet"),
              "--answer units: expected wavelength units in [microns, nanometers], found 'feet'");
    EXPECT_EQ(error_with("wavelengths", "0.1-0.7"),
              "--answer wavelengths: expected wavelength (microns) in [0.2, 1000], found "
              "'0.1-0.7'");
    EXPECT_EQ(error_with("wavelengths", "0.7-0.4"),
              "--answer wavelengths: expected a starting wavelength below the ending "
              "wavelength, found '0.7-0.4'");
    EXPECT_EQ(error_with("intervals", "397"),
              "--answer intervals: expected number of intervals in [1, 396], found '397'");
    EXPECT_EQ(error_with("irpt", "2"), "--answer irpt: expected IRPT in [0, 1, 3, 4], found '2'");
    EXPECT_EQ(error_with("irpt", "3"),
              "--answer irpt: expected IRPT in [0, 1, 4] (LOWTRAN 7 cannot repeat CARD 3 with "
              "multiple and solar scattering), found '3'");
}

TEST(Control7, BadAnswerInAFileNamesFileAndLine) {
    std::string text = file_text(SIGCHAIN_TEST_DATA "/control7/hawkeye.answers");
    text.replace(text.find("\n7 "), 3, "\n9 ");
    LineAnswers in(TextInput::from_string(text, "h.answers"));
    try {
        run_control7(in, seed_overrides());
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "h.answers:6: expected model atmosphere in [0, 7], found '9'");
    }
}

TEST(Control7, MissingRadiosondeAndTruncatedAnswers) {
    std::string e = error_with("rsd", "/no/such.rsd");
    EXPECT_NE(e.find("--answer rsd: radiosonde: "), std::string::npos) << e;
    EXPECT_NE(e.find("/no/such.rsd"), std::string::npos) << e;
    LineAnswers in(TextInput::from_string("x.cdk\n7\ny\n", "short.answers"));
    try {
        run_control7(in);
        FAIL() << "no error";
    } catch (const DataError& err) {
        EXPECT_STREQ(err.what(),
                     "short.answers:3: unexpected end of the answers, expected the "
                     "answer to 'itype'");
    }
}

TEST(Control7, TerminalReasksAfterABadAnswer) {
    std::string text = file_text(SIGCHAIN_TEST_DATA "/control7/hawkeye.answers");
    // The answers without comments, with two bad answers before the model.
    std::string typed = "flyover.cdk\n12\nabc\n";
    bool first = true;
    for (const auto& l : lines_of(text)) {
        auto t = std::string(trim(l.substr(0, l.find('#'))));
        if (t.empty()) continue;
        if (first) {
            first = false;
            continue;
        }
        typed += (t == "30Sep95800L.rsd" ? kRsd : t) + "\n";
    }
    std::istringstream keyboard(typed);
    std::ostringstream screen;
    TerminalAnswers term(keyboard, screen);
    Control7Result r = run_control7(term);
    EXPECT_EQ(r.cdk, run_seed(seed_overrides()).cdk);
    const std::string s = screen.str();
    EXPECT_NE(s.find("CHOOSE A MODEL NUMBER"), std::string::npos);
    EXPECT_NE(s.find("7 NEW MODEL ATMOSPHERE (RADIOSONDE DATA)"), std::string::npos);
    EXPECT_NE(s.find("control7: expected model atmosphere in [0, 7], found '12'; please answer "
                     "again"),
              std::string::npos);
    EXPECT_NE(s.find("expected model atmosphere (a number), found 'abc'"), std::string::npos);
    EXPECT_NE(s.find("ENTERING DATA FOR LAYER 19: ALTITUDE 16.493"), std::string::npos);
}

TEST(Control7, OverridesReplaceSingleAnswers) {
    Control7Result r = run_seed(seed_overrides({{"vis", "50"}, {"ihaze", "1"}, {"m1", "6"}}));
    EXPECT_DOUBLE_EQ(r.cdk.runs[0].card2.visibility_km, 50);
    EXPECT_EQ(r.cdk.runs[0].card2.ihaze, 1);
    // m1 is asked only after "y" to modify_tp.
    EXPECT_EQ(r.unused_overrides, std::vector<std::string>{"m1"});
    EXPECT_EQ(r.cdk.runs[0].card1.m[0], 0);
    LineAnswers in(TextInput::from_string("x\n", "a"));
    EXPECT_THROW(run_control7(in, {{"no_such_key", "1"}}), UsageError);
}

TEST(Control7, StandardModelWithRepeatedRuns) {
    // Model 6, slant path to space, transmittance; IRPT 4 then 3 then 0.
    const std::string text =
        "us.cdk\n6\n3\n0\n0\nn\nn\nn\nn\nn\nn\nn\n0\n0.1\n1\n0\n0\n0\nn\nn\n0\n0\n"
        "10\n0\n0\nn\n"  // H1, H2 (0), angle, no radius override
        "nanometers\n400-700\n10\n"
        "4\nmicrons\n3-5\n100\n"  // CARD 4 again
        "3\n5\n0\n30\nn\n"        // CARD 3 again
        "0\n";
    LineAnswers in(TextInput::from_string(text, "us.answers"));
    Control7Result r = run_control7(in);
    EXPECT_FALSE(in.leftover().has_value());
    ASSERT_EQ(r.cdk.runs.size(), 3u);
    EXPECT_EQ(r.cdk.runs[1].kind, io::CdkRunKind::Spectral);
    EXPECT_NEAR(r.cdk.runs[1].spectral.v1_cm1, 2000, 1e-9);
    EXPECT_EQ(r.cdk.runs[2].kind, io::CdkRunKind::Geometry);
    EXPECT_DOUBLE_EQ(r.cdk.runs[2].geometry.zenith_angle_deg, 30);
    EXPECT_FALSE(r.cdk.runs[0].profile.has_value());
    EXPECT_EQ(r.cdk.runs[0].card1.im, 0);
    EXPECT_EQ(deck_of(io::parse_cdk(TextInput::from_string(deck_of(r.cdk), "d"))), deck_of(r.cdk));
}

TEST(Control7, QuestionKeysAreUnique) {
    std::set<std::string> keys;
    for (const auto& q : control7_questions()) EXPECT_TRUE(keys.insert(q.key).second) << q.key;
}
