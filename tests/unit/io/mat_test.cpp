// Tests for the .mat material database reader and writer (lib/io/mat).
#include "io/mat.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

// A minimal complete entry; line numbers matter to the error tests below.
const std::string kEntry =
    "MATERIAL_ENTRY_BEGIN\n"              // 1
    "MATERIAL_NAME = grass\n"             // 2
    "MATERIAL_ID = 1\n"                   // 3
    "SPECIFIC_HEAT = 1\n"                 // 4
    "THERMAL_CONDUCTIVITY = 12.5\n"       // 5
    "MASS_DENSITY = 1.0\n"                // 6
    "SPECULARITY = 0.0\n"                 // 7
    "VISIBLE_EMISSIVITY = 0.79\n"         // 8
    "THERMAL_EMISSIVITY = 0.93\n"         // 9
    "EXPOSED_AREA = -0.25\n"              // 10
    "OPTICAL_DESCRIPTION = OPAQUE\n"      // 11
    "EMISSIVITY_FILE = fall_grass.ems\n"  // 12
    "MATERIAL_ENTRY_END\n";               // 13

// kEntry with its first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to, std::string text = kEntry) {
    auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test text lacks " + from);
    return text.replace(at, from.size(), to);
}

// A second entry (lines 14..26 after kEntry) with another name and id.
std::string second(const std::string& name = "asphalt", const std::string& id = "2") {
    return edited("MATERIAL_ID = 1", "MATERIAL_ID = " + id,
                  edited("MATERIAL_NAME = grass", "MATERIAL_NAME = " + name));
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_mat(TextInput::from_string(text, "t.mat")); });
}

std::string written(const Mat& mat) {
    std::ostringstream out;
    write_mat(out, mat);
    return out.str();
}

Mat parsed(const std::string& text) { return parse_mat(TextInput::from_string(text, "t.mat")); }

void expect_same(const Material& a, const Material& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.specific_heat_cal_g_c, b.specific_heat_cal_g_c);
    EXPECT_EQ(a.thermal_conductivity_dcs, b.thermal_conductivity_dcs);
    EXPECT_EQ(a.mass_density_g_cm3, b.mass_density_g_cm3);
    EXPECT_EQ(a.specularity, b.specularity);
    EXPECT_EQ(a.visible_emissivity, b.visible_emissivity);
    EXPECT_EQ(a.thermal_emissivity, b.thermal_emissivity);
    EXPECT_EQ(a.exposed_area, b.exposed_area);
    EXPECT_EQ(a.optical, b.optical);
    EXPECT_EQ(a.emissivity_file, b.emissivity_file);
    EXPECT_EQ(a.thickness_cm, b.thickness_cm);
    EXPECT_EQ(a.extinction_file, b.extinction_file);
    EXPECT_EQ(a.texture_file, b.texture_file);
    EXPECT_EQ(a.use_gaussian_texture, b.use_gaussian_texture);
    EXPECT_EQ(a.double_sided, b.double_sided);
    EXPECT_EQ(a.self_generated_power, b.self_generated_power);
    EXPECT_EQ(a.reflectance_model, b.reflectance_model);
    EXPECT_EQ(a.cone_half_angle_deg, b.cone_half_angle_deg);
    EXPECT_EQ(a.phong_exponent, b.phong_exponent);
    EXPECT_EQ(a.exponential_width_deg, b.exponential_width_deg);
    EXPECT_EQ(a.table_file, b.table_file);
    EXPECT_EQ(a.style, b.style);
}

// A DIRSIG 3.x brace entry using every optional tag.
const std::string kFull =
    "MATERIAL_ENTRY {\n"
    "    MATERIAL_NAME = oak leaves, summer\n"
    "    MATERIAL_ID = 40\n"
    "    SPECIFIC_HEAT = 0.9\n"
    "    THERMAL_CONDUCTIVITY = 3.2\n"
    "    MASS_DENSITY = 0.6\n"
    "    SPECULARITY = 0.1\n"
    "    VISIBLE_EMISSIVITY = 0.8\n"
    "    THERMAL_EMISSIVITY = 0.95\n"
    "    EXPOSED_AREA = 1\n"
    "    THICKNESS = 0.05\n"
    "    OPTICAL_DESCRIPTION = UNIFORM_TRANSMISSION\n"
    "    EMISSIVITY_FILE = oak.ems\n"
    "    EXTINCTION_FILE = leaves.ext\n"
    "    TEXTURE_FILE = oak.tex\n"
    "    USE_GAUSSIAN_TEXTURE = TRUE\n"
    "    DOUBLE_SIDED = TRUE\n"
    "    SELF_GENERATED_POWER = 0\n"
    "    REFLECTANCE_MODEL = phong\n"
    "    PHONG_EXPONENT = 12.5\n"
    "}\n";

}  // namespace

TEST(Mat, SeedSampleParsesToTheSeedValues) {
    Mat mat = read_mat_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.mat");
    ASSERT_EQ(mat.materials.size(), 1u);
    const Material& m = mat.materials[0];
    EXPECT_EQ(m.name, "grass");
    EXPECT_EQ(m.id, 1);
    EXPECT_EQ(m.specific_heat_cal_g_c, 1);
    EXPECT_EQ(m.thermal_conductivity_dcs, 12.5);
    EXPECT_EQ(m.mass_density_g_cm3, 1.0);
    EXPECT_EQ(m.specularity, 0.0);
    EXPECT_EQ(m.visible_emissivity, 0.79);
    EXPECT_EQ(m.thermal_emissivity, 0.93);
    EXPECT_EQ(m.exposed_area, -0.25);
    EXPECT_EQ(m.thickness_cm, 1.275);
    EXPECT_EQ(m.optical, OpticalDescription::Opaque);
    EXPECT_EQ(m.emissivity_file, "fall_grass.ems");
    EXPECT_EQ(m.use_gaussian_texture, false);
    EXPECT_TRUE(m.extinction_file.empty());
    EXPECT_TRUE(m.texture_file.empty());
    EXPECT_FALSE(m.reflectance_model.has_value());
    EXPECT_EQ(effective_model(m), ReflectanceModel::Dirsig);
    EXPECT_EQ(m.style, MaterialEntryStyle::BeginEnd);
    EXPECT_EQ(m.line, 25);
    EXPECT_EQ(mat.find(1), &m);
    EXPECT_EQ(mat.find(2), nullptr);
}

TEST(Mat, BraceEntryWithEveryOptionalTag) {
    Mat mat = parsed(kFull);
    const Material& m = mat.materials.at(0);
    EXPECT_EQ(m.name, "oak leaves, summer");
    EXPECT_EQ(m.style, MaterialEntryStyle::Braces);
    EXPECT_EQ(m.optical, OpticalDescription::UniformTransmission);
    EXPECT_EQ(m.extinction_file, "leaves.ext");
    EXPECT_EQ(m.texture_file, "oak.tex");
    EXPECT_EQ(m.use_gaussian_texture, true);
    EXPECT_EQ(m.double_sided, true);
    EXPECT_EQ(m.self_generated_power, 0.0);
    EXPECT_EQ(m.reflectance_model, ReflectanceModel::Phong);
    EXPECT_EQ(m.phong_exponent, 12.5);
}

TEST(Mat, TagsInAnyOrderAndValuesCaseInsensitive) {
    std::string text = edited("MATERIAL_NAME = grass\nMATERIAL_ID = 1\n",
                              "MATERIAL_ID = 1\nMATERIAL_NAME = grass\n");
    text = edited("OPAQUE", "opaque", text);
    Mat mat = parsed(text);
    EXPECT_EQ(mat.materials.at(0).name, "grass");
    EXPECT_EQ(mat.materials.at(0).optical, OpticalDescription::Opaque);
}

TEST(Mat, EveryModelWithItsParameter) {
    auto model = [](const std::string& tags) {
        return effective_model(
            parsed(edited("MATERIAL_ENTRY_END", tags + "MATERIAL_ENTRY_END")).materials.at(0));
    };
    EXPECT_EQ(model("REFLECTANCE_MODEL = lambertian\n"), ReflectanceModel::Lambertian);
    EXPECT_EQ(model("REFLECTANCE_MODEL = dirsig\n"), ReflectanceModel::Dirsig);
    EXPECT_EQ(model("REFLECTANCE_MODEL = cone\nCONE_HALF_ANGLE_DEG = 5\n"), ReflectanceModel::Cone);
    EXPECT_EQ(model("REFLECTANCE_MODEL = exponential\nEXPONENTIAL_WIDTH_DEG = 10\n"),
              ReflectanceModel::Exponential);
    EXPECT_EQ(model("REFLECTANCE_MODEL = table\nTABLE_FILE = paint.brdf\n"),
              ReflectanceModel::Table);
}

TEST(Mat, RoundTripKeepsValuesAndStyleAndIsIdempotent) {
    for (std::string text : {kEntry, kFull, kEntry + "\n" + kFull + second("tar", "3")}) {
        Mat a = parsed(text);
        std::string once = written(a);
        Mat b = parsed(once);
        ASSERT_EQ(a.materials.size(), b.materials.size());
        for (std::size_t i = 0; i < a.materials.size(); ++i)
            expect_same(a.materials[i], b.materials[i]);
        EXPECT_EQ(written(b), once);
    }
    Mat seed = read_mat_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.mat");
    expect_same(parsed(written(seed)).materials.at(0), seed.materials.at(0));
}

TEST(Mat, RewriteUsesTheSeedTagOrder) {
    std::string out = written(parsed(kEntry));
    EXPECT_EQ(out, edited("MASS_DENSITY = 1.0", "MASS_DENSITY = 1",
                          edited("SPECULARITY = 0.0", "SPECULARITY = 0")));
}

// --- Bad input: one test per class, with the message and the line. ---

TEST(Mat, EmptyFile) {
    EXPECT_EQ(error_of(""), "t.mat: empty file, expected a material entry (MATERIAL_ENTRY_BEGIN)");
    EXPECT_EQ(error_of("# only a comment\n\n"),
              "t.mat: empty file, expected a material entry (MATERIAL_ENTRY_BEGIN)");
}

TEST(Mat, BinaryFile) {
    EXPECT_EQ(error_of(std::string("MATERIAL_ENTRY_BEGIN\n\0\n", 23)),
              "t.mat:2: binary data (NUL byte); expected a text file");
}

TEST(Mat, ContentOutsideAnEntry) {
    EXPECT_EQ(error_of("MATERIAL_NAME = grass\n"),
              "t.mat:1: expected MATERIAL_ENTRY_BEGIN or 'MATERIAL_ENTRY {', found "
              "'MATERIAL_NAME = grass'");
    EXPECT_EQ(error_of("MATERIAL_ENTRY\n{\n"),
              "t.mat:1: expected 'MATERIAL_ENTRY {' (brace on the same line), found "
              "'MATERIAL_ENTRY'");
}

TEST(Mat, TruncatedEntry) {
    EXPECT_EQ(error_of(edited("MATERIAL_ENTRY_END\n", "")),
              "t.mat:12: unexpected end of file, expected MATERIAL_ENTRY_END for the entry begun "
              "at line 1");
}

TEST(Mat, NestedEntry) {
    EXPECT_EQ(error_of(edited("MATERIAL_ENTRY_END\n", "") + kEntry),
              "t.mat:13: expected a tag or MATERIAL_ENTRY_END for the entry begun at line 1, "
              "found 'MATERIAL_ENTRY_BEGIN'");
}

TEST(Mat, MismatchedEntryEnd) {
    EXPECT_EQ(error_of(edited("MATERIAL_ENTRY_END", "}")),
              "t.mat:13: expected a tag or MATERIAL_ENTRY_END for the entry begun at line 1, "
              "found '}'");
}

TEST(Mat, MissingRequiredTag) {
    EXPECT_EQ(error_of(edited("EMISSIVITY_FILE = fall_grass.ems\n", "")),
              "t.mat:12: expected tag EMISSIVITY_FILE in the entry begun at line 1, found "
              "MATERIAL_ENTRY_END");
    std::string braces =
        edited("MATERIAL_ENTRY_BEGIN", "MATERIAL_ENTRY {", edited("MATERIAL_ENTRY_END", "}"));
    EXPECT_EQ(error_of(edited("SPECULARITY = 0.0\n", "", braces)),
              "t.mat:12: expected tag SPECULARITY in the entry begun at line 1, found }");
}

TEST(Mat, UnknownTag) {
    EXPECT_EQ(error_of(edited("SPECULARITY", "SPECULARTY")),
              "t.mat:7: expected a material tag (see mat(5)), found unknown tag 'SPECULARTY'");
}

TEST(Mat, RepeatedTag) {
    EXPECT_EQ(error_of(edited("MATERIAL_ENTRY_END", "SPECULARITY = 0.5\nMATERIAL_ENTRY_END")),
              "t.mat:13: repeated tag SPECULARITY (first at line 7)");
}

TEST(Mat, NotATagLine) {
    EXPECT_EQ(error_of(edited("SPECULARITY = 0.0", "SPECULARITY 0.0")),
              "t.mat:7: expected TAG = value or MATERIAL_ENTRY_END, found 'SPECULARITY 0.0'");
    EXPECT_EQ(error_of(edited("SPECULARITY = 0.0", "SPECULARITY =")),
              "t.mat:7: expected a value for SPECULARITY, found none");
}

TEST(Mat, NotANumber) {
    EXPECT_EQ(error_of(edited("MASS_DENSITY = 1.0", "MASS_DENSITY = heavy")),
              "t.mat:6: expected MASS_DENSITY (a number), found 'heavy'");
    EXPECT_EQ(error_of(edited("EXPOSED_AREA = -0.25", "EXPOSED_AREA = nan")),
              "t.mat:10: expected EXPOSED_AREA (a finite number), found 'nan'");
    EXPECT_EQ(error_of(edited("EXPOSED_AREA = -0.25", "EXPOSED_AREA = inf")),
              "t.mat:10: expected EXPOSED_AREA (a finite number), found 'inf'");
    EXPECT_EQ(error_of(edited("MATERIAL_ID = 1", "MATERIAL_ID = 1.5")),
              "t.mat:3: expected MATERIAL_ID (an integer), found '1.5'");
}

TEST(Mat, ValueOutOfRange) {
    EXPECT_EQ(error_of(edited("SPECULARITY = 0.0", "SPECULARITY = 1.5")),
              "t.mat:7: expected SPECULARITY in [0, 1], found '1.5'");
    EXPECT_EQ(error_of(edited("THERMAL_EMISSIVITY = 0.93", "THERMAL_EMISSIVITY = -0.1")),
              "t.mat:9: expected THERMAL_EMISSIVITY in [0, 1], found '-0.1'");
    EXPECT_EQ(error_of(edited("MASS_DENSITY = 1.0", "MASS_DENSITY = -1")),
              "t.mat:6: expected MASS_DENSITY 0 or more, found '-1'");
    EXPECT_EQ(error_of(edited("MATERIAL_ID = 1", "MATERIAL_ID = -3")),
              "t.mat:3: expected MATERIAL_ID (a count, 0 or more), found '-3'");
}

TEST(Mat, BadEnumeratedValues) {
    EXPECT_EQ(error_of(edited("OPAQUE", "CLEAR")),
              "t.mat:11: expected OPTICAL_DESCRIPTION OPAQUE, UNIFORM_TRANSMISSION or "
              "NONUNIFORM_TRANSMISSION, found 'CLEAR'");
    EXPECT_EQ(
        error_of(edited("MATERIAL_ENTRY_END", "USE_GAUSSIAN_TEXTURE = yes\nMATERIAL_ENTRY_END")),
        "t.mat:13: expected USE_GAUSSIAN_TEXTURE TRUE or FALSE, found 'yes'");
    EXPECT_EQ(
        error_of(edited("MATERIAL_ENTRY_END", "REFLECTANCE_MODEL = glossy\nMATERIAL_ENTRY_END")),
        "t.mat:13: expected REFLECTANCE_MODEL lambertian, dirsig, cone, phong, exponential "
        "or table, found 'glossy'");
}

TEST(Mat, TransmissionNeedsAnExtinctionFile) {
    EXPECT_EQ(error_of(edited("OPAQUE", "NONUNIFORM_TRANSMISSION")),
              "t.mat:11: expected tag EXTINCTION_FILE with OPTICAL_DESCRIPTION = "
              "NONUNIFORM_TRANSMISSION, found none in the entry");
}

TEST(Mat, ModelParameters) {
    EXPECT_EQ(
        error_of(edited("MATERIAL_ENTRY_END", "REFLECTANCE_MODEL = phong\nMATERIAL_ENTRY_END")),
        "t.mat:13: expected tag PHONG_EXPONENT with REFLECTANCE_MODEL = phong, found none "
        "in the entry");
    EXPECT_EQ(error_of(edited("MATERIAL_ENTRY_END", "PHONG_EXPONENT = 3\nMATERIAL_ENTRY_END")),
              "t.mat:13: unexpected tag PHONG_EXPONENT: it belongs to REFLECTANCE_MODEL = phong, "
              "this entry's model is dirsig");
    EXPECT_EQ(
        error_of(edited("MATERIAL_ENTRY_END",
                        "REFLECTANCE_MODEL = cone\nCONE_HALF_ANGLE_DEG = 0\nMATERIAL_ENTRY_END")),
        "t.mat:14: expected CONE_HALF_ANGLE_DEG in (0, 90] deg, found '0'");
}

TEST(Mat, DuplicateIdOrName) {
    EXPECT_EQ(error_of(kEntry + second("asphalt", "1")),
              "t.mat:16: duplicate MATERIAL_ID 1 (first in the entry begun at line 1)");
    EXPECT_EQ(error_of(kEntry + second("grass", "2")),
              "t.mat:15: duplicate MATERIAL_NAME 'grass' (first in the entry begun at line 1)");
    EXPECT_EQ(parsed(kEntry + second()).materials.size(), 2u);
}
