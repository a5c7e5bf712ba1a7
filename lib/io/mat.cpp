// .mat material database (White (1996), fig. 4.34; man mat(5)): reader and writer.
#include "io/mat.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace sigchain::io {

const Material* Mat::find(long id) const {
    for (const auto& m : materials)
        if (m.id == id) return &m;
    return nullptr;
}

ReflectanceModel effective_model(const Material& m) {
    return m.reflectance_model.value_or(ReflectanceModel::Dirsig);
}

namespace {

// One `TAG = value` line.
struct Value {
    std::string tag;
    std::string text;
    SourceLocation where;
};

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& ch : out) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return out;
}

double number_at_least_zero(const Value& v) {
    double x = parse_double(v.text, v.where, v.tag);
    if (x < 0)
        throw DataError(v.where,
                        "expected " + v.tag + " 0 or more, found " + sigchain::quoted(v.text));
    return x;
}

double fraction(const Value& v) { return parse_in_range(v.text, v.where, v.tag, 0, 1); }

double angle_up_to_90(const Value& v) {
    double x = parse_double(v.text, v.where, v.tag);
    if (x <= 0 || x > 90)
        throw DataError(v.where,
                        "expected " + v.tag + " in (0, 90] deg, found " + sigchain::quoted(v.text));
    return x;
}

bool boolean(const Value& v) {
    std::string u = upper(v.text);
    if (u == "TRUE") return true;
    if (u == "FALSE") return false;
    throw DataError(v.where,
                    "expected " + v.tag + " TRUE or FALSE, found " + sigchain::quoted(v.text));
}

constexpr std::array<std::string_view, 3> kOpticalNames = {"OPAQUE", "UNIFORM_TRANSMISSION",
                                                           "NONUNIFORM_TRANSMISSION"};
constexpr std::array<std::string_view, 6> kModelNames = {"lambertian", "dirsig",      "cone",
                                                         "phong",      "exponential", "table"};

OpticalDescription optical(const Value& v) {
    std::string u = upper(v.text);
    for (std::size_t i = 0; i < kOpticalNames.size(); ++i)
        if (u == kOpticalNames[i]) return static_cast<OpticalDescription>(i);
    throw DataError(v.where,
                    "expected OPTICAL_DESCRIPTION OPAQUE, UNIFORM_TRANSMISSION or "
                    "NONUNIFORM_TRANSMISSION, found " +
                        sigchain::quoted(v.text));
}

ReflectanceModel model(const Value& v) {
    std::string u = upper(v.text);
    for (std::size_t i = 0; i < kModelNames.size(); ++i)
        if (u == upper(kModelNames[i])) return static_cast<ReflectanceModel>(i);
    throw DataError(v.where,
                    "expected REFLECTANCE_MODEL lambertian, dirsig, cone, phong, "
                    "exponential or table, found " +
                        sigchain::quoted(v.text));
}

using Text = std::optional<std::string>;
Text num(double x) { return format_number(x); }
Text opt_num(const std::optional<double>& x) { return x ? Text(format_number(*x)) : Text(); }
Text opt_text(const std::string& s) { return s.empty() ? Text() : Text(s); }
Text opt_bool(const std::optional<bool>& b) { return b ? Text(*b ? "TRUE" : "FALSE") : Text(); }

// Every tag: its name, whether it is required, how to read it, how to write it (nullopt:
// not written). The order is that of the header in White (1996) and of the rewrite.
struct TagSpec {
    std::string_view name;
    bool required;
    void (*read)(Material&, const Value&);
    Text (*write)(const Material&);
};

const std::array<TagSpec, 24> kTags = {{
    {"MATERIAL_NAME", true, [](Material& m, const Value& v) { m.name = v.text; },
     [](const Material& m) { return Text(m.name); }},
    {"MATERIAL_ID", true,
     [](Material& m, const Value& v) {
         m.id = parse_count(v.text, v.where, v.tag);
         if (m.id > kMaxMaterialId)
             throw DataError(v.where, "expected " + std::string(v.tag) + " from 0 to " +
                                          std::to_string(kMaxMaterialId) + ", found " +
                                          quoted(v.text));
     },
     [](const Material& m) { return Text(std::to_string(m.id)); }},
    {"SPECIFIC_HEAT", true,
     [](Material& m, const Value& v) { m.specific_heat_cal_g_c = number_at_least_zero(v); },
     [](const Material& m) { return num(m.specific_heat_cal_g_c); }},
    {"THERMAL_CONDUCTIVITY", true,
     [](Material& m, const Value& v) { m.thermal_conductivity_dcs = number_at_least_zero(v); },
     [](const Material& m) { return num(m.thermal_conductivity_dcs); }},
    {"MASS_DENSITY", true,
     [](Material& m, const Value& v) { m.mass_density_g_cm3 = number_at_least_zero(v); },
     [](const Material& m) { return num(m.mass_density_g_cm3); }},
    {"SPECULARITY", true, [](Material& m, const Value& v) { m.specularity = fraction(v); },
     [](const Material& m) { return num(m.specularity); }},
    {"VISIBLE_EMISSIVITY", true,
     [](Material& m, const Value& v) { m.visible_emissivity = fraction(v); },
     [](const Material& m) { return num(m.visible_emissivity); }},
    {"THERMAL_EMISSIVITY", true,
     [](Material& m, const Value& v) { m.thermal_emissivity = fraction(v); },
     [](const Material& m) { return num(m.thermal_emissivity); }},
    {"EXPOSED_AREA", true,
     [](Material& m, const Value& v) { m.exposed_area = parse_double(v.text, v.where, v.tag); },
     [](const Material& m) { return num(m.exposed_area); }},
    {"THICKNESS", false,
     [](Material& m, const Value& v) { m.thickness_cm = number_at_least_zero(v); },
     [](const Material& m) { return opt_num(m.thickness_cm); }},
    {"OPTICAL_DESCRIPTION", true, [](Material& m, const Value& v) { m.optical = optical(v); },
     [](const Material& m) {
         return Text(std::string(kOpticalNames[static_cast<std::size_t>(m.optical)]));
     }},
    {"EMISSIVITY_FILE", true, [](Material& m, const Value& v) { m.emissivity_file = v.text; },
     [](const Material& m) { return Text(m.emissivity_file); }},
    {"EXTINCTION_FILE", false, [](Material& m, const Value& v) { m.extinction_file = v.text; },
     [](const Material& m) { return opt_text(m.extinction_file); }},
    {"TEXTURE_FILE", false, [](Material& m, const Value& v) { m.texture_file = v.text; },
     [](const Material& m) { return opt_text(m.texture_file); }},
    {"USE_GAUSSIAN_TEXTURE", false,
     [](Material& m, const Value& v) { m.use_gaussian_texture = boolean(v); },
     [](const Material& m) { return opt_bool(m.use_gaussian_texture); }},
    {"GAUSSIAN_TEXTURE_STDDEV", false,
     [](Material& m, const Value& v) { m.gaussian_texture_stddev = fraction(v); },
     [](const Material& m) { return opt_num(m.gaussian_texture_stddev); }},
    {"DOUBLE_SIDED", false, [](Material& m, const Value& v) { m.double_sided = boolean(v); },
     [](const Material& m) { return opt_bool(m.double_sided); }},
    {"SELF_GENERATED_POWER", false,
     [](Material& m, const Value& v) {
         m.self_generated_power = parse_double(v.text, v.where, v.tag);
     },
     [](const Material& m) { return opt_num(m.self_generated_power); }},
    {"REFLECTANCE_MODEL", false,
     [](Material& m, const Value& v) { m.reflectance_model = model(v); },
     [](const Material& m) {
         if (!m.reflectance_model) return Text();
         return Text(std::string(kModelNames[static_cast<std::size_t>(*m.reflectance_model)]));
     }},
    {"CONE_HALF_ANGLE_DEG", false,
     [](Material& m, const Value& v) { m.cone_half_angle_deg = angle_up_to_90(v); },
     [](const Material& m) { return opt_num(m.cone_half_angle_deg); }},
    {"PHONG_EXPONENT", false,
     [](Material& m, const Value& v) { m.phong_exponent = number_at_least_zero(v); },
     [](const Material& m) { return opt_num(m.phong_exponent); }},
    {"EXPONENTIAL_WIDTH_DEG", false,
     [](Material& m, const Value& v) { m.exponential_width_deg = angle_up_to_90(v); },
     [](const Material& m) { return opt_num(m.exponential_width_deg); }},
    {"TABLE_FILE", false, [](Material& m, const Value& v) { m.table_file = v.text; },
     [](const Material& m) { return opt_text(m.table_file); }},
    {"SPECULAR_CURVE", false,
     [](Material& m, const Value& v) {
         m.specular_curve = parse_count(v.text, v.where, v.tag);
         m.specular_curve_line = v.where.line;
     },
     [](const Material& m) {
         return m.specular_curve ? Text(std::to_string(*m.specular_curve)) : Text();
     }},
}};

const TagSpec* find_tag(std::string_view name) {
    for (const auto& t : kTags)
        if (t.name == name) return &t;
    return nullptr;
}

// The parameter tag each model needs (empty: none).
std::string_view parameter_of(ReflectanceModel m) {
    switch (m) {
        case ReflectanceModel::Cone:
            return "CONE_HALF_ANGLE_DEG";
        case ReflectanceModel::Phong:
            return "PHONG_EXPONENT";
        case ReflectanceModel::Exponential:
            return "EXPONENTIAL_WIDTH_DEG";
        case ReflectanceModel::Table:
            return "TABLE_FILE";
        default:
            return {};
    }
}

// The raw tags of one entry, before conversion.
struct RawEntry {
    MaterialEntryStyle style = MaterialEntryStyle::BeginEnd;
    int begin_line = 0;
    int end_line = 0;
    std::map<std::string, Value, std::less<>> tags;
    std::vector<std::string> order;  // tags in line order, so errors come in file order
};

std::string_view closing(MaterialEntryStyle s) {
    return s == MaterialEntryStyle::BeginEnd ? "MATERIAL_ENTRY_END" : "}";
}

// Which opening keyword a line is, if any. "MATERIAL_ENTRY" without its brace is an error.
std::optional<MaterialEntryStyle> opening(const Line& line, const LineCursor& c) {
    if (line.text == "MATERIAL_ENTRY_BEGIN") return MaterialEntryStyle::BeginEnd;
    auto f = split_fields(line.text);
    if (f.empty() || f[0] != "MATERIAL_ENTRY") return std::nullopt;
    if (f.size() == 2 && f[1] == "{") return MaterialEntryStyle::Braces;
    throw DataError(c.where(line), "expected 'MATERIAL_ENTRY {' (brace on the same line), found " +
                                       sigchain::quoted(line.text));
}

void read_tag_line(const Line& line, const LineCursor& c, RawEntry& e) {
    auto eq = line.text.find('=');
    std::string_view tag = eq == std::string_view::npos ? "" : trim(line.text.substr(0, eq));
    if (tag.empty())
        throw DataError(c.where(line), "expected TAG = value or " + std::string(closing(e.style)) +
                                           ", found " + sigchain::quoted(line.text));
    std::string value(trim(line.text.substr(eq + 1)));
    if (!find_tag(tag))
        throw DataError(c.where(line), "expected a material tag (see mat(5)), found unknown tag " +
                                           sigchain::quoted(tag));
    if (value.empty())
        throw DataError(c.where(line), "expected a value for " + std::string(tag) + ", found none");
    auto it = e.tags.find(tag);
    if (it != e.tags.end())
        throw DataError(c.where(line), "repeated tag " + std::string(tag) + " (first at line " +
                                           std::to_string(it->second.where.line) + ")");
    e.tags.emplace(std::string(tag), Value{std::string(tag), value, c.where(line)});
    e.order.emplace_back(tag);
}

RawEntry read_entry(LineCursor& c, MaterialEntryStyle style, int begin_line) {
    RawEntry e;
    e.style = style;
    e.begin_line = begin_line;
    std::string what =
        std::string(closing(style)) + " for the entry begun at line " + std::to_string(begin_line);
    while (true) {
        const Line& line = c.next(what);
        if (line.text == closing(style)) {
            e.end_line = line.number;
            return e;
        }
        bool other_close = line.text == closing(style == MaterialEntryStyle::BeginEnd
                                                    ? MaterialEntryStyle::Braces
                                                    : MaterialEntryStyle::BeginEnd);
        if (other_close || opening(line, c))
            throw DataError(c.where(line),
                            "expected a tag or " + what + ", found " + sigchain::quoted(line.text));
        read_tag_line(line, c, e);
    }
}

// Cross-tag rules: transmissions need an extinction file; a model needs its own
// parameter and no other model's.
void check_combinations(const RawEntry& e, const Material& m) {
    if (m.optical != OpticalDescription::Opaque && m.extinction_file.empty()) {
        const Value& v = e.tags.at("OPTICAL_DESCRIPTION");
        throw DataError(v.where, "expected tag EXTINCTION_FILE with OPTICAL_DESCRIPTION = " +
                                     upper(v.text) + ", found none in the entry");
    }
    ReflectanceModel rm = effective_model(m);
    std::string_view own = parameter_of(rm);
    for (auto other : {ReflectanceModel::Cone, ReflectanceModel::Phong,
                       ReflectanceModel::Exponential, ReflectanceModel::Table}) {
        std::string_view p = parameter_of(other);
        auto it = e.tags.find(p);
        if (p != own && it != e.tags.end())
            throw DataError(it->second.where,
                            "unexpected tag " + std::string(p) +
                                ": it belongs to REFLECTANCE_MODEL = " +
                                std::string(kModelNames[static_cast<std::size_t>(other)]) +
                                ", this entry's model is " +
                                std::string(kModelNames[static_cast<std::size_t>(rm)]));
    }
    auto specular = e.tags.find("SPECULAR_CURVE");
    if (rm == ReflectanceModel::Lambertian && specular != e.tags.end())
        throw DataError(specular->second.where,
                        "unexpected tag SPECULAR_CURVE: REFLECTANCE_MODEL = lambertian has no "
                        "specular part");
    if (!own.empty() && !e.tags.count(own))
        throw DataError(e.tags.at("REFLECTANCE_MODEL").where,
                        "expected tag " + std::string(own) + " with REFLECTANCE_MODEL = " +
                            std::string(kModelNames[static_cast<std::size_t>(rm)]) +
                            ", found none in the entry");
}

Material to_material(const RawEntry& e, const TextInput& in) {
    Material m;
    m.style = e.style;
    m.line = e.begin_line;
    for (const auto& name : e.order) {
        find_tag(name)->read(m, e.tags.at(name));
        m.tag_lines.emplace(name, e.tags.at(name).where.line);
    }
    for (const auto& t : kTags)
        if (t.required && !e.tags.count(t.name))
            throw DataError(in.at(e.end_line), "expected tag " + std::string(t.name) +
                                                   " in the entry begun at line " +
                                                   std::to_string(e.begin_line) + ", found " +
                                                   std::string(closing(e.style)));
    check_combinations(e, m);
    return m;
}

void check_unique(const Mat& mat, const RawEntry& e) {
    const Material& m = mat.materials.back();
    for (std::size_t i = 0; i + 1 < mat.materials.size(); ++i) {
        const Material& o = mat.materials[i];
        if (o.id == m.id)
            throw DataError(e.tags.at("MATERIAL_ID").where,
                            "duplicate MATERIAL_ID " + std::to_string(m.id) +
                                " (first in the entry begun at line " + std::to_string(o.line) +
                                ")");
        if (o.name == m.name)
            throw DataError(e.tags.at("MATERIAL_NAME").where,
                            "duplicate MATERIAL_NAME " + sigchain::quoted(m.name) +
                                " (first in the entry begun at line " + std::to_string(o.line) +
                                ")");
    }
}

}  // namespace

Mat parse_mat(const TextInput& in) {
    Mat mat;
    mat.file = in.name();
    LineCursor c(in);
    c.require_not_empty("a material entry (MATERIAL_ENTRY_BEGIN)");
    while (!c.at_end()) {
        const Line& line = c.next("a material entry");
        auto style = opening(line, c);
        if (!style)
            throw DataError(c.where(line),
                            "expected MATERIAL_ENTRY_BEGIN or 'MATERIAL_ENTRY {', found " +
                                sigchain::quoted(line.text));
        RawEntry e = read_entry(c, *style, line.number);
        mat.materials.push_back(to_material(e, in));
        check_unique(mat, e);
    }
    return mat;
}

void write_mat(std::ostream& out, const Mat& mat) {
    bool first = true;
    for (const auto& m : mat.materials) {
        if (!first) out << '\n';
        first = false;
        bool braces = m.style == MaterialEntryStyle::Braces;
        out << (braces ? "MATERIAL_ENTRY {\n" : "MATERIAL_ENTRY_BEGIN\n");
        for (const auto& t : kTags) {
            Text value = t.write(m);
            if (value) out << (braces ? "    " : "") << t.name << " = " << *value << '\n';
        }
        out << (braces ? "}\n" : "MATERIAL_ENTRY_END\n");
    }
}

FormatHandler mat_format() {
    return {"mat", "material database (White (1996), fig. 4.34)",
            [](const TextInput& in) {
                Mat m = parse_mat(in);
                std::ostringstream s;
                s << m.materials.size() << (m.materials.size() == 1 ? " material" : " materials");
                return s.str();
            },
            [](const TextInput& in, std::ostream& out) { write_mat(out, parse_mat(in)); }};
}

}  // namespace sigchain::io
