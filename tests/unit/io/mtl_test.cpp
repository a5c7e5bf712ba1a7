// Tests for the Landsat MTL reader (lib/io/mtl): the two Marburg Collection 1 files, the
// pre-collection file of tests/data/landsat, a Collection 2 layout, and malformed input.
#include "io/mtl.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kMarburg = SIGCHAIN_SOURCE_DIR "/data/scenes/marburg/";
const std::string kEtm = kMarburg + "LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt";
const std::string kOli = kMarburg + "LC08_L1TP_195025_20130707_20170503_01_T1_MTL.txt";
const std::string kOld = SIGCHAIN_TEST_DATA "/landsat/L71092085_08520100315_MTL.txt";

Mtl parse(const std::string& text) { return parse_mtl(TextInput::from_string(text, "t.mtl")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

// A minimal valid file: GROUP on line 1, values on lines 2-15 (SUN_AZIMUTH 14, SUN_ELEVATION
// 15), `extra` from line 16, less the line of key `drop`; END_GROUP, END.
std::string minimal(const std::string& extra = "", const std::string& drop = "") {
    std::string body =
        "  SPACECRAFT_ID = \"LANDSAT_7\"\n"
        "  SENSOR_ID = \"ETM\"\n"
        "  DATE_ACQUIRED = 2001-07-30\n"
        "  SCENE_CENTER_TIME = \"10:04:52.5Z\"\n"
        "  CORNER_UL_LAT_PRODUCT = 51.2\n  CORNER_UL_LON_PRODUCT = 7.2\n"
        "  CORNER_UR_LAT_PRODUCT = 51.2\n  CORNER_UR_LON_PRODUCT = 10.7\n"
        "  CORNER_LL_LAT_PRODUCT = 49.2\n  CORNER_LL_LON_PRODUCT = 7.3\n"
        "  CORNER_LR_LAT_PRODUCT = 49.2\n  CORNER_LR_LON_PRODUCT = 10.6\n"
        "  SUN_AZIMUTH = 144.0\n  SUN_ELEVATION = 53.9\n";
    if (!drop.empty()) {
        auto at = body.find("  " + drop + " =");
        body.erase(at, body.find('\n', at) - at + 1);
    }
    return "GROUP = L1_METADATA_FILE\n" + body + extra + "END_GROUP = L1_METADATA_FILE\nEND\n";
}

void expect_band(const Mtl& m, const std::string& name, char gain, double mult, double add,
                 double qmin, double qmax) {
    const MtlBand* b = find_band(m, name);
    ASSERT_NE(b, nullptr) << name;
    EXPECT_EQ(b->gain_state, gain) << name;
    EXPECT_DOUBLE_EQ(*b->radiance_mult, mult) << name;
    EXPECT_DOUBLE_EQ(*b->radiance_add, add) << name;
    EXPECT_DOUBLE_EQ(*b->qcal_min, qmin) << name;
    EXPECT_DOUBLE_EQ(*b->qcal_max, qmax) << name;
}

}  // namespace

TEST(Mtl, MarburgEtmReadsEveryValueAsWritten) {
    Mtl m = read_mtl_file(kEtm);
    EXPECT_EQ(m.format, MtlFormat::Collection1);
    EXPECT_EQ(m.spacecraft, "LANDSAT_7");
    EXPECT_EQ(m.sensor, "ETM");
    EXPECT_EQ(m.product_id, "LE07_L1TP_195025_20010730_20170204_01_T1");
    EXPECT_EQ(m.year, 2001);
    EXPECT_EQ(m.month, 7);
    EXPECT_EQ(m.day, 30);
    EXPECT_DOUBLE_EQ(m.time_gmt_hours, 10 + 4 / 60.0 + 52.9157671 / 3600);
    const MtlCorner want[] = {{51.26868, 7.28558}, {51.26807, 10.75597}, {49.27295, 7.35580},
                              {49.27238, 10.68405}};
    for (int i = 0; i < 4; ++i) EXPECT_EQ(m.corners[i], want[i]) << i;
    EXPECT_DOUBLE_EQ(*m.sun_azimuth_deg, 144.05820926);
    EXPECT_DOUBLE_EQ(*m.sun_elevation_deg, 53.87765310);
    EXPECT_DOUBLE_EQ(*m.earth_sun_distance_au, 1.0151738);
    std::vector<std::string> names;
    for (const auto& b : m.bands) names.push_back(b.name);
    EXPECT_EQ(names, (std::vector<std::string>{"1", "2", "3", "4", "5", "6_VCID_1", "6_VCID_2", "7", "8"}));
    expect_band(m, "1", 'H', 7.7874E-01, -6.97874, 1, 255);
    expect_band(m, "2", 'H', 7.9882E-01, -7.19882, 1, 255);
    expect_band(m, "3", 'H', 6.2165E-01, -5.62165, 1, 255);
    expect_band(m, "4", 'L', 9.6929E-01, -6.06929, 1, 255);  // band 4 in LOW gain
    expect_band(m, "5", 'H', 1.2622E-01, -1.12622, 1, 255);
    expect_band(m, "6_VCID_1", 'L', 6.7087E-02, -0.06709, 1, 255);
    expect_band(m, "6_VCID_2", 'H', 3.7205E-02, 3.16280, 1, 255);
    expect_band(m, "7", 'H', 4.3898E-02, -0.39390, 1, 255);
    expect_band(m, "8", 'L', 9.7559E-01, -5.67559, 1, 255);
    const MtlBand& b4 = *find_band(m, "4");
    EXPECT_DOUBLE_EQ(*b4.radiance_max, 241.1);
    EXPECT_DOUBLE_EQ(*b4.radiance_min, -5.1);
    EXPECT_EQ(b4.gain_line, 163);
    EXPECT_EQ(b4.rescaling_line, 192);
    const MtlBand& b61 = *find_band(m, "6_VCID_1");
    EXPECT_DOUBLE_EQ(*b61.k1, 666.09);
    EXPECT_DOUBLE_EQ(*b61.k2, 1282.71);
    EXPECT_FALSE(find_band(m, "1")->k1);
}

TEST(Mtl, MarburgOliReadsEveryValueAsWritten) {
    Mtl m = read_mtl_file(kOli);
    EXPECT_EQ(m.format, MtlFormat::Collection1);
    EXPECT_EQ(m.spacecraft, "LANDSAT_8");
    EXPECT_EQ(m.sensor, "OLI_TIRS");
    EXPECT_EQ(m.year, 2013);
    EXPECT_EQ(m.month, 7);
    EXPECT_EQ(m.day, 7);
    EXPECT_DOUBLE_EQ(m.time_gmt_hours, 10 + 17 / 60.0 + 42.1661960 / 3600);
    const MtlCorner want[] = {{51.34342, 7.42064}, {51.34001, 10.81471}, {49.18843, 7.49036},
                              {49.18527, 10.73461}};
    for (int i = 0; i < 4; ++i) EXPECT_EQ(m.corners[i], want[i]) << i;
    EXPECT_DOUBLE_EQ(*m.sun_azimuth_deg, 146.98479703);
    EXPECT_DOUBLE_EQ(*m.sun_elevation_deg, 58.99675180);
    EXPECT_DOUBLE_EQ(*m.earth_sun_distance_au, 1.0166988);
    ASSERT_EQ(m.bands.size(), 11u);
    const double mult[] = {1.2147E-02, 1.2438E-02, 1.1462E-02, 9.6653E-03, 5.9147E-03, 1.4709E-03,
                           4.9578E-04, 1.0938E-02, 2.3116E-03, 3.3420E-04, 3.3420E-04};
    const double add[] = {-60.73349, -62.19184, -57.30925, -48.32638, -29.57334, -7.35462,
                          -2.47890,  -54.69217, -11.55793, 0.10000,   0.10000};
    for (int i = 0; i < 11; ++i) {
        const std::string name = std::to_string(i + 1);
        EXPECT_EQ(m.bands[i].name, name);
        expect_band(m, name, 0, mult[i], add[i], 1, 65535);
    }
    EXPECT_DOUBLE_EQ(*find_band(m, "1")->radiance_max, 735.30042);
    EXPECT_DOUBLE_EQ(*find_band(m, "1")->radiance_min, -60.72135);
    EXPECT_DOUBLE_EQ(*find_band(m, "10")->k1, 774.8853);
    EXPECT_DOUBLE_EQ(*find_band(m, "10")->k2, 1321.0789);
    EXPECT_DOUBLE_EQ(*find_band(m, "11")->k1, 480.8883);
    EXPECT_DOUBLE_EQ(*find_band(m, "11")->k2, 1201.1442);
}

TEST(Mtl, PreCollectionFileRescalesFromLminLmaxAndQcal) {
    Mtl m = read_mtl_file(kOld);
    EXPECT_EQ(m.format, MtlFormat::PreCollection);
    EXPECT_EQ(m.spacecraft, "LANDSAT_7");  // "Landsat7"
    EXPECT_EQ(m.sensor, "ETM");            // "ETM+"
    EXPECT_EQ(m.year, 2010);
    EXPECT_EQ(m.month, 3);
    EXPECT_EQ(m.day, 15);
    EXPECT_DOUBLE_EQ(m.time_gmt_hours, 23 + 55 / 60.0 + 11.6634891 / 3600);
    EXPECT_EQ(m.corners[0], (MtlCorner{-35.07, 144.87}));
    EXPECT_EQ(m.corners[3], (MtlCorner{-37.0, 147.59}));
    EXPECT_DOUBLE_EQ(*m.sun_azimuth_deg, 53.7730377);
    EXPECT_DOUBLE_EQ(*m.sun_elevation_deg, 41.5610274);
    EXPECT_FALSE(m.earth_sun_distance_au);
    std::vector<std::string> names;
    for (const auto& b : m.bands) names.push_back(b.name);
    EXPECT_EQ(names, (std::vector<std::string>{"1", "2", "3", "4", "5", "6_VCID_1", "6_VCID_2", "7", "8"}));
    // radiance = (LMAX - LMIN) / (QCALMAX - QCALMIN) * (DN - QCALMIN) + LMIN
    const double lmax4 = 241.1, lmin4 = -5.1, mult4 = (lmax4 - lmin4) / 254;
    expect_band(m, "4", 'L', mult4, lmin4 - mult4 * 1, 1, 255);
    const double mult1 = (191.6 + 6.2) / 254;
    expect_band(m, "1", 'H', mult1, -6.2 - mult1, 1, 255);
    expect_band(m, "6_VCID_1", 'L', 17.04 / 254, -17.04 / 254, 1, 255);
    expect_band(m, "6_VCID_2", 'H', (12.65 - 3.2) / 254, 3.2 - (12.65 - 3.2) / 254, 1, 255);
    for (const auto& b : m.bands) {
        EXPECT_NEAR(*b.radiance_mult * 255 + *b.radiance_add, *b.radiance_max, 1e-12) << b.name;
        EXPECT_NEAR(*b.radiance_mult * 1 + *b.radiance_add, *b.radiance_min, 1e-12) << b.name;
    }
}

TEST(Mtl, Collection2GroupsAndNegativeAzimuth) {
    Mtl m = parse(
        "GROUP = LANDSAT_METADATA_FILE\n"
        "  GROUP = IMAGE_ATTRIBUTES\n"
        "    SPACECRAFT_ID = \"LANDSAT_9\"\n    SENSOR_ID = \"OLI_TIRS\"\n"
        "    DATE_ACQUIRED = 2022-01-05\n    SCENE_CENTER_TIME = \"15:30:00.0000000Z\"\n"
        "    SUN_AZIMUTH = -150.5\n    SUN_ELEVATION = 20.25\n"
        "  END_GROUP = IMAGE_ATTRIBUTES\n"
        "  GROUP = PROJECTION_ATTRIBUTES\n"
        "    CORNER_UL_LAT_PRODUCT = -10\n    CORNER_UL_LON_PRODUCT = -50\n"
        "    CORNER_UR_LAT_PRODUCT = -10\n    CORNER_UR_LON_PRODUCT = -48\n"
        "    CORNER_LL_LAT_PRODUCT = -12\n    CORNER_LL_LON_PRODUCT = -50\n"
        "    CORNER_LR_LAT_PRODUCT = -12\n    CORNER_LR_LON_PRODUCT = -48\n"
        "  END_GROUP = PROJECTION_ATTRIBUTES\n"
        "  GROUP = LEVEL1_RADIOMETRIC_RESCALING\n"
        "    RADIANCE_MULT_BAND_4 = 9.6653E-03\n    RADIANCE_ADD_BAND_4 = -48.32638\n"
        "  END_GROUP = LEVEL1_RADIOMETRIC_RESCALING\n"
        "END_GROUP = LANDSAT_METADATA_FILE\nEND\n");
    EXPECT_EQ(m.format, MtlFormat::Collection2);
    EXPECT_EQ(m.spacecraft, "LANDSAT_9");
    EXPECT_DOUBLE_EQ(*m.sun_azimuth_deg, 360 - 150.5);
    EXPECT_DOUBLE_EQ(m.time_gmt_hours, 15.5);
    ASSERT_EQ(m.bands.size(), 1u);
    EXPECT_DOUBLE_EQ(*m.bands[0].radiance_mult, 9.6653E-03);
}

// The sun is informational (sigchain computes it from the date, time and place): a
// hand-written file for an image that recorded none may leave it out.
TEST(Mtl, SunAnglesAreOptional) {
    Mtl m = parse(minimal("", "SUN_ELEVATION"));
    EXPECT_DOUBLE_EQ(*m.sun_azimuth_deg, 144.0);
    EXPECT_FALSE(m.sun_elevation_deg);
    std::string none = minimal("", "SUN_AZIMUTH");
    none.erase(none.find("  SUN_ELEVATION"), std::string("  SUN_ELEVATION = 53.9\n").size());
    m = parse(none);
    EXPECT_FALSE(m.sun_azimuth_deg);
    EXPECT_FALSE(m.sun_elevation_deg);
}

TEST(Mtl, CommentsAreIgnoredAlsoOverLinesButNotInsideQuotes) {
    Mtl m = parse(minimal("  /* a hand-written file:\n     gain from the table */\n"
                          "  GAIN_BAND_4 = \"L\" /* low */\n"
                          "  ORIGIN = \"a /* not a comment */ b\"\n"));
    EXPECT_EQ(find_band(m, "4")->gain_state, 'L');
    EXPECT_FALSE(find_band(m, "4")->radiance_mult);
    Odl odl = parse_odl(TextInput::from_string(minimal("  ORIGIN = \"a /* x */ b\"\n"), "t"));
    std::ostringstream out;
    write_odl(out, odl);
    EXPECT_NE(out.str().find("  ORIGIN = \"a /* x */ b\"\n"), std::string::npos);
}

TEST(Mtl, MalformedInputNamesFileAndLine) {
    EXPECT_EQ(error_of(""), "t.mtl: empty file, expected an MTL file");
    EXPECT_EQ(error_of("GROUP = L1_METADATA_FILE\n  SUN_AZIMUTH\nEND\n"),
              "t.mtl:2: expected KEY = VALUE, GROUP = NAME or END, found 'SUN_AZIMUTH'");
    EXPECT_EQ(error_of("GROUP = L1_METADATA_FILE\n  GROUP = A\n  END_GROUP = B\n"),
              "t.mtl:3: expected END_GROUP = A (the GROUP on line 2), found 'B'");
    EXPECT_EQ(error_of("GROUP = L1_METADATA_FILE\n  X = 1\n"),
              "t.mtl:2: unexpected end of file, expected END and END_GROUP = L1_METADATA_FILE");
    EXPECT_EQ(error_of("GROUP = L1_METADATA_FILE\n  X = \"open\n"),
              "t.mtl:2: expected a quoted string on one line, found '\"open'");
    EXPECT_EQ(error_of("GROUP = L1_METADATA_FILE\n/* never closed\nEND\n"),
              "t.mtl:2: a /* comment is not closed by */");
    EXPECT_EQ(error_of(minimal() + "X = 1\n"), "t.mtl:18: unexpected content after END, found 'X = 1'");
    EXPECT_EQ(error_of(minimal("", "DATE_ACQUIRED")),
              "t.mtl:16: missing DATE_ACQUIRED or ACQUISITION_DATE (a required MTL value)");
    std::string bad_azimuth = minimal();
    bad_azimuth.replace(bad_azimuth.find("144.0"), 5, "east");
    EXPECT_EQ(error_of(bad_azimuth), "t.mtl:14: expected SUN_AZIMUTH (a number), found 'east'");
    EXPECT_EQ(error_of(minimal("  RADIANCE_MULT_BAND_4 = 0.9\n")),
              "t.mtl:16: RADIANCE_MULT_BAND_4 without its partner RADIANCE_ADD_BAND_4");
    EXPECT_EQ(error_of(minimal("  GAIN_BAND_4 = \"M\"\n")),
              "t.mtl:16: expected GAIN_BAND_4 \"H\" or \"L\", found 'M'");
    EXPECT_EQ(error_of(minimal("  RADIANCE_MULT_BAND_4 = 0\n  RADIANCE_ADD_BAND_4 = 1\n")),
              "t.mtl:16: expected RADIANCE_MULT_BAND_4 above 0, found '0'");
    EXPECT_EQ(error_of(minimal("  SUN_ELEVATION = 50\n")),
              "t.mtl:16: SUN_ELEVATION given again with another value (first on line 15)");
    std::string bad_date = minimal();
    bad_date.replace(bad_date.find("2001-07-30"), 10, "2001-02-30");
    EXPECT_EQ(error_of(bad_date),
              "t.mtl:4: expected DATE_ACQUIRED as YYYY-MM-DD (a valid date from 1972), found '2001-02-30'");
    std::string bad_time = minimal();
    bad_time.replace(bad_time.find("10:04:52.5Z"), 11, "25:04:52.5Z");
    EXPECT_EQ(error_of(bad_time),
              "t.mtl:5: expected SCENE_CENTER_TIME as HH:MM:SS.fffZ (GMT), found '25:04:52.5Z'");
    EXPECT_EQ(error_of("GROUP = OTHER\nEND_GROUP = OTHER\nEND\n"),
              "t.mtl:1: expected GROUP = L1_METADATA_FILE or LANDSAT_METADATA_FILE, found 'GROUP = OTHER'");
}

TEST(Mtl, RewriteIsCanonicalAndParsesToTheSameValues) {
    TextInput in = TextInput::from_file(kEtm);
    std::ostringstream out;
    mtl_format().rewrite(in, out);
    Mtl again = parse_mtl(TextInput::from_string(out.str(), "again"));
    Mtl first = parse_mtl(in);
    again.end_line = first.end_line;  // the lines are the same here, but END's is compared too
    for (std::size_t i = 0; i < first.bands.size(); ++i)
        again.bands[i].gain_line = first.bands[i].gain_line,
        again.bands[i].rescaling_line = first.bands[i].rescaling_line;
    EXPECT_EQ(again, first);
    EXPECT_EQ(out.str(), in.text());  // the USGS file is already canonical
}
