// .mat material database (White (1996), fig. 4.34, DIRSIG 3; man mat(5)): tagged material entries.
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

enum class OpticalDescription { Opaque, UniformTransmission, NonuniformTransmission };

// How trace samples the reflectance of a surface (mat(5), REFLECTANCE MODELS;
// trace(1), RADIOMETRY).
// Files without REFLECTANCE_MODEL (every legacy file) mean Dirsig.
enum class ReflectanceModel { Lambertian, Dirsig, Cone, Phong, Exponential, Table };

// How the entry was delimited, kept so that a rewrite keeps the file's style:
// MATERIAL_ENTRY_BEGIN .. MATERIAL_ENTRY_END (DIRSIG 3, White (1996)) or
// MATERIAL_ENTRY { .. } (DIRSIG 3.x).
enum class MaterialEntryStyle { BeginEnd, Braces };

// One material. Thermal units follow DCS THERM as White's (1996) values imply (see mat(5),
// UNITS, for what is certain and what is not).
struct Material {
    std::string name;                     // MATERIAL_NAME (may contain spaces)
    long id = 0;                          // MATERIAL_ID, 0 or more, unique in the file
    double specific_heat_cal_g_c = 0;     // SPECIFIC_HEAT, cal g-1 C-1
    double thermal_conductivity_dcs = 0;  // THERMAL_CONDUCTIVITY, DCS units (mat(5))
    double mass_density_g_cm3 = 0;        // MASS_DENSITY, g cm-3
    double specularity = 0;               // 0 = all diffuse .. 1 = all specular
    double visible_emissivity = 0;        // solar absorptivity, 0..1
    double thermal_emissivity = 0;        // 0..1
    double exposed_area = 0;              // DCS THERM exposed-area term (White (1996): -0.25)
    OpticalDescription optical = OpticalDescription::Opaque;
    std::string emissivity_file;  // .ems file name, as written
    // Optional tags (absent: nullopt or empty).
    std::optional<double> thickness_cm;
    std::string extinction_file;  // .ext; required for the transmissions
    std::string texture_file;
    std::optional<bool> use_gaussian_texture;       // absent means FALSE
    std::optional<double> gaussian_texture_stddev;  // relative, [0, 1]; absent: from the .ems
    std::optional<bool> double_sided;               // absent: trace takes TRUE (mat(5) SIDES)
    std::optional<double> self_generated_power;     // DCS THERM units (mat(5))
    // sigchain's reflectance model and its parameters (only the model's own).
    std::optional<ReflectanceModel> reflectance_model;  // absent means Dirsig
    std::optional<double> cone_half_angle_deg;          // cone: (0, 90]
    std::optional<double> phong_exponent;               // phong: 0 or more
    std::optional<double> exponential_width_deg;        // exponential: (0, 90]
    std::string table_file;                             // table: BRDF table file
    // SPECULAR_CURVE: the curve of the EMISSIVITY_FILE whose 1 - emissivity is the
    // specular reflectance (absent: the diffuse curve's); refused with lambertian.
    std::optional<long> specular_curve;
    int specular_curve_line = 0;  // its line, for errors found with the .ems
    MaterialEntryStyle style = MaterialEntryStyle::BeginEnd;
    int line = 0;  // line of the entry's opening keyword
    std::map<std::string, int, std::less<>> tag_lines;  // each tag's line

    // The line of `tag`, or the entry's line when the tag is absent (errors about a
    // file or value a tag names point at that tag).
    int line_of(std::string_view tag) const {
        const auto it = tag_lines.find(tag);
        return it == tag_lines.end() ? line : it->second;
    }
};

struct Mat {
    std::string file;
    std::vector<Material> materials;  // in file order

    // The material with this id, or nullptr.
    const Material* find(long id) const;
};

ReflectanceModel effective_model(const Material& m);

// W m-1 K-1 per DCS conductivity unit (1e-4 cal cm-1 s-1 C-1; see mat(5) UNITS).
// The largest MATERIAL_ID (mat(5)): trace indexes materials by id in a table of
// kMaxMaterialId + 1 slots.
inline constexpr long kMaxMaterialId = 1L << 24;

inline constexpr double kWattsPerMeterKelvinPerDcsConductivity = 0.04184;

Mat parse_mat(const TextInput& in);
void write_mat(std::ostream& out, const Mat& mat);
inline Mat read_mat_file(const std::string& path) { return parse_mat(TextInput::from_file(path)); }

FormatHandler mat_format();

}  // namespace sigchain::io
