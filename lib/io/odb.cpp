// .odb scene assembly (man odb(5)): reader, writer, instance matrices, path resolution.
#include "io/odb.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.hpp"

namespace sigchain::io {

namespace {

constexpr std::array<std::string_view, 9> kKeys = {
    "GDB_FILENAME",     "OBJ_FILENAME", "DEM_FILENAME", "MESH_FILENAME", "MATERIAL_MAP",
    "LANDUSE_FILENAME", "LANDUSE_MAP",  "MATERIAL_ID",  "UNITS"};
// In OdbSource's order.
constexpr std::array<std::string_view, 4> kSources = {"GDB_FILENAME", "OBJ_FILENAME",
                                                      "DEM_FILENAME", "MESH_FILENAME"};

struct Value {
    std::string text;
    SourceLocation where;
};
using Keys = std::map<std::string, Value, std::less<>>;

// True for "KEYWORD {"; "KEYWORD" without its brace is an error.
bool is_open(const Line& line, std::string_view keyword, const LineCursor& c) {
    auto f = split_fields(line.text);
    if (f.empty() || f[0] != keyword) return false;
    if (f.size() == 2 && f[1] == "{") return true;
    throw DataError(c.where(line), "expected '" + std::string(keyword) +
                                       " {' (brace on the same line), found " +
                                       sigchain::quoted(line.text));
}

std::vector<double> numbers(const std::vector<std::string_view>& tokens, const SourceLocation& at,
                            std::string_view what) {
    std::vector<double> out;
    for (auto t : tokens) out.push_back(parse_double(t, at, what));
    return out;
}

double det3(const Matrix4& m) {
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
           m[2] * (m[4] * m[9] - m[5] * m[8]);
}

void check_matrix(const Matrix4& m, const SourceLocation& at) {
    if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
        throw DataError(at, "expected MATRIX last row 0 0 0 1, found " + format_number(m[12]) +
                                " " + format_number(m[13]) + " " + format_number(m[14]) + " " +
                                format_number(m[15]));
    for (int i : {3, 7, 11})
        if (std::abs(m[i]) > kOdbMaxTranslation)
            throw DataError(at, "expected MATRIX translations within +-" +
                                    format_number(kOdbMaxTranslation) + ", found " +
                                    format_number(m[i]));
    double biggest = 0;
    for (int i : {0, 1, 2, 4, 5, 6, 8, 9, 10}) {
        if (std::abs(m[i]) > kOdbMaxScale)
            throw DataError(at, "expected MATRIX 3x3 elements within +-" +
                                    format_number(kOdbMaxScale) + ", found " +
                                    format_number(m[i]));
        biggest = std::max(biggest, std::abs(m[i]));
    }
    if (std::abs(det3(m)) <= 1e-12 * biggest * biggest * biggest)
        throw DataError(at, "expected an invertible MATRIX, found a singular 3x3 part");
}

// The documented ranges of an instance's components (odb(5)): translations within
// kOdbMaxTranslation, |scale| in [1/kOdbMaxScale, kOdbMaxScale], rotations within
// +-kOdbMaxRotation_deg. Within them the 3x3 part is finite and invertible.
void check_components(const OdbInstance& inst, const SourceLocation& at) {
    for (int i = 0; i < 3; ++i) {
        if (std::abs(inst.translation[i]) > kOdbMaxTranslation)
            throw DataError(at, "expected translations x,y,z within +-" +
                                    format_number(kOdbMaxTranslation) + ", found " +
                                    format_number(inst.translation[i]));
        double s = std::abs(inst.scale[i]);
        if (s > kOdbMaxScale || s < 1 / kOdbMaxScale)
            throw DataError(at, "expected scale factors sx,sy,sz of magnitude " +
                                    format_number(1 / kOdbMaxScale) + " to " +
                                    format_number(kOdbMaxScale) + ", found " +
                                    format_number(inst.scale[i]));
        if (std::abs(inst.rotation_deg[i]) > kOdbMaxRotation_deg)
            throw DataError(at, "expected rotations rx,ry,rz (deg) within +-" +
                                    format_number(kOdbMaxRotation_deg) + ", found " +
                                    format_number(inst.rotation_deg[i]));
    }
}

// MATRIX and 16 numbers, row-major, on this line and the lines that follow.
OdbInstance read_matrix(LineCursor& c, const Line& first) {
    OdbInstance inst;
    inst.is_matrix = true;
    inst.line = first.number;
    auto tokens = split_fields(first.text, true);
    tokens.erase(tokens.begin());  // "MATRIX"
    std::vector<double> v = numbers(tokens, c.where(first), "MATRIX element");
    while (v.size() < 16) {
        const Line& line = c.next("the rest of the 16 MATRIX numbers");
        auto more = numbers(split_fields(line.text, true), c.where(line), "MATRIX element");
        v.insert(v.end(), more.begin(), more.end());
    }
    if (v.size() > 16)
        throw DataError(c.where(), "expected 16 MATRIX numbers, found " + std::to_string(v.size()));
    std::copy(v.begin(), v.end(), inst.matrix.begin());
    check_matrix(inst.matrix, c.where(first));
    return inst;
}

OdbInstance read_components(const LineCursor& c, const Line& line) {
    auto tokens = split_fields(line.text, true);
    if (tokens.size() != 9)
        throw DataError(c.where(line),
                        "expected an instance x,y,z, sx,sy,sz, rx,ry,rz (9 numbers) "
                        "or MATRIX, found " +
                            std::to_string(tokens.size()) +
                            " fields: " + sigchain::quoted(line.text));
    OdbInstance inst;
    inst.line = line.number;
    auto v = numbers(tokens, c.where(line), "instance value");
    for (int i = 0; i < 3; ++i) {
        inst.translation[i] = v[i];
        inst.scale[i] = v[3 + i];
        inst.rotation_deg[i] = v[6 + i];
    }
    if (inst.scale[0] == 0 || inst.scale[1] == 0 || inst.scale[2] == 0)
        throw DataError(c.where(line), "expected non-zero scale factors sx,sy,sz, found " +
                                           sigchain::quoted(tokens[3]) + "," +
                                           sigchain::quoted(tokens[4]) + "," +
                                           sigchain::quoted(tokens[5]));
    check_components(inst, c.where(line));
    return inst;
}

std::vector<OdbInstance> read_instances(LineCursor& c, int open_line) {
    std::vector<OdbInstance> out;
    std::string what = "'}' closing the INSTANCES begun at line " + std::to_string(open_line);
    while (true) {
        const Line& line = c.next(what);
        if (line.text == "}") break;
        auto f = split_fields(line.text, true);
        if (!f.empty() && f[0] == "MATRIX")
            out.push_back(read_matrix(c, line));
        else
            out.push_back(read_components(c, line));
    }
    if (out.empty())
        throw DataError(c.where(),
                        "expected at least one instance in INSTANCES (omit the block "
                        "for one identity instance), found '}'");
    return out;
}

void read_key(const Line& line, const LineCursor& c, std::string_view close_what, Keys& keys) {
    auto eq = line.text.find('=');
    std::string_view key = eq == std::string_view::npos ? "" : trim(line.text.substr(0, eq));
    if (key.empty())
        throw DataError(c.where(line), "expected KEY = value, 'INSTANCES {' or " +
                                           std::string(close_what) + ", found " +
                                           sigchain::quoted(line.text));
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
        throw DataError(c.where(line), "expected an OBJECT key (see odb(5)), found unknown key " +
                                           sigchain::quoted(key));
    std::string value(trim(line.text.substr(eq + 1)));
    if (value.empty())
        throw DataError(c.where(line), "expected a value for " + std::string(key) + ", found none");
    auto it = keys.find(key);
    if (it != keys.end())
        throw DataError(c.where(line), "repeated key " + std::string(key) + " (first at line " +
                                           std::to_string(it->second.where.line) + ")");
    keys.emplace(std::string(key), Value{value, c.where(line)});
}

OdbUnits units_of(const Value& v) {
    std::string u = ascii_lower(v.text);
    if (u == "m" || u == "meters" || u == "metres") return OdbUnits::Meters;
    if (u == "ft" || u == "feet") return OdbUnits::Feet;
    throw DataError(v.where, "expected UNITS m or ft, found " + sigchain::quoted(v.text));
}

// A key that only some sources allow.
void forbid(const Keys& keys, std::string_view key, std::string_view belongs_to) {
    auto it = keys.find(key);
    if (it != keys.end())
        throw DataError(it->second.where, "unexpected key " + std::string(key) +
                                              ": it belongs to " + std::string(belongs_to));
}

void require(const Keys& keys, std::string_view key, const SourceLocation& at,
             std::string_view when) {
    if (!keys.count(key))
        throw DataError(at, "expected key " + std::string(key) + " " + std::string(when) +
                                ", found none in the OBJECT");
}

void apply_source(const Keys& keys, OdbObject& obj, const SourceLocation& close) {
    const Value* src = nullptr;
    for (std::size_t i = 0; i < kSources.size(); ++i) {
        auto it = keys.find(kSources[i]);
        if (it == keys.end()) continue;
        if (src)
            throw DataError(it->second.where,
                            "expected only one of GDB_FILENAME, OBJ_FILENAME, "
                            "MESH_FILENAME and DEM_FILENAME, found a second one");
        src = &it->second;
        obj.source = static_cast<OdbSource>(i);
        obj.path = src->text;
    }
    if (!src)
        throw DataError(close,
                        "expected GDB_FILENAME, OBJ_FILENAME, MESH_FILENAME or DEM_FILENAME in the "
                        "OBJECT begun at line " +
                            std::to_string(obj.line) + ", found '}'");
    const Value& where = *src;
    if (obj.source == OdbSource::Mesh) {  // one of a material map and one material id
        forbid(keys, "LANDUSE_FILENAME", "DEM_FILENAME objects");
        forbid(keys, "LANDUSE_MAP", "DEM_FILENAME objects");
        if (keys.count("MATERIAL_MAP"))
            forbid(keys, "MATERIAL_ID", "DEM_FILENAME and MESH_FILENAME objects without "
                                        "MATERIAL_MAP");
        if (!keys.count("MATERIAL_ID"))
            require(keys, "MATERIAL_MAP", where.where, "(or MATERIAL_ID) with MESH_FILENAME");
        return;
    }
    if (obj.source != OdbSource::Obj)
        forbid(keys, "MATERIAL_MAP", "OBJ_FILENAME and MESH_FILENAME objects");
    if (obj.source != OdbSource::Dem) {
        forbid(keys, "LANDUSE_FILENAME", "DEM_FILENAME objects");
        forbid(keys, "LANDUSE_MAP", "DEM_FILENAME objects");
        forbid(keys, "MATERIAL_ID", "DEM_FILENAME objects without land use");
    }
    if (obj.source == OdbSource::Obj)
        require(keys, "MATERIAL_MAP", where.where, "with OBJ_FILENAME");
    if (obj.source != OdbSource::Dem) return;
    bool landuse = keys.count("LANDUSE_FILENAME") || keys.count("LANDUSE_MAP");
    if (landuse) {
        require(keys, "LANDUSE_FILENAME", where.where, "with LANDUSE_MAP");
        require(keys, "LANDUSE_MAP", where.where, "with LANDUSE_FILENAME");
        forbid(keys, "MATERIAL_ID", "DEM_FILENAME objects without land use");
    } else {
        require(keys, "MATERIAL_ID", where.where, "with DEM_FILENAME and no land use");
    }
}

void apply_keys(const Keys& keys, OdbObject& obj, const SourceLocation& close) {
    apply_source(keys, obj, close);
    auto get = [&](std::string_view k) {
        auto it = keys.find(k);
        return it == keys.end() ? std::string() : it->second.text;
    };
    obj.material_map = get("MATERIAL_MAP");
    obj.landuse_file = get("LANDUSE_FILENAME");
    obj.landuse_map = get("LANDUSE_MAP");
    if (auto it = keys.find("MATERIAL_ID"); it != keys.end())
    {
        obj.material_id = parse_count(it->second.text, it->second.where, "MATERIAL_ID");
        if (*obj.material_id > kMaxMaterialId)
            throw DataError(it->second.where, "expected MATERIAL_ID from 0 to " +
                                                  std::to_string(kMaxMaterialId) + ", found " +
                                                  sigchain::quoted(it->second.text));
    }
    auto u = keys.find("UNITS");
    if (u == keys.end())
        throw DataError(close, "expected key UNITS (m or ft) in the OBJECT begun at line " +
                                   std::to_string(obj.line) + ", found '}'");
    obj.units = units_of(u->second);
}

OdbObject read_object(LineCursor& c, int open_line) {
    OdbObject obj;
    obj.line = open_line;
    Keys keys;
    int instances_line = 0;
    std::string what = "'}' closing the OBJECT begun at line " + std::to_string(open_line);
    while (true) {
        const Line& line = c.next(what);
        if (line.text == "}") break;
        if (is_open(line, "INSTANCES", c)) {
            if (instances_line)
                throw DataError(c.where(line), "repeated INSTANCES block (first at line " +
                                                   std::to_string(instances_line) + ")");
            instances_line = line.number;
            obj.instances = read_instances(c, line.number);
        } else if (is_open(line, "OBJECT", c)) {
            throw DataError(c.where(line), "expected a key or " + what + ", found 'OBJECT {'");
        } else {
            read_key(line, c, what, keys);
        }
    }
    apply_keys(keys, obj, c.where());
    return obj;
}

}  // namespace

Odb parse_odb(const TextInput& in) {
    Odb odb;
    odb.file = in.name();
    LineCursor c(in);
    c.require_not_empty("'OBJECT {'");
    while (!c.at_end()) {
        const Line& line = c.next("'OBJECT {'");
        if (!is_open(line, "OBJECT", c))
            throw DataError(c.where(line),
                            "expected 'OBJECT {', found " + sigchain::quoted(line.text));
        odb.objects.push_back(read_object(c, line.number));
    }
    return odb;
}

namespace {

void write_instance(std::ostream& out, const OdbInstance& inst) {
    if (inst.is_matrix) {
        for (int r = 0; r < 4; ++r) {
            out << (r == 0 ? "        MATRIX" : "              ");
            for (int k = 0; k < 4; ++k) out << ' ' << format_number(inst.matrix[4 * r + k]);
            out << '\n';
        }
        return;
    }
    auto triple = [&](const std::array<double, 3>& v) {
        return format_number(v[0]) + "," + format_number(v[1]) + "," + format_number(v[2]);
    };
    out << "        " << triple(inst.translation) << ", " << triple(inst.scale) << ", "
        << triple(inst.rotation_deg) << '\n';
}

}  // namespace

void write_odb(std::ostream& out, const Odb& odb) {
    bool first = true;
    for (const auto& obj : odb.objects) {
        if (!first) out << '\n';
        first = false;
        out << "OBJECT {\n";
        out << "    " << kSources[static_cast<std::size_t>(obj.source)] << " = " << obj.path
            << '\n';
        if (!obj.material_map.empty()) out << "    MATERIAL_MAP = " << obj.material_map << '\n';
        if (!obj.landuse_file.empty()) out << "    LANDUSE_FILENAME = " << obj.landuse_file << '\n';
        if (!obj.landuse_map.empty()) out << "    LANDUSE_MAP = " << obj.landuse_map << '\n';
        if (obj.material_id) out << "    MATERIAL_ID = " << *obj.material_id << '\n';
        out << "    UNITS = " << (obj.units == OdbUnits::Feet ? "ft" : "m") << '\n';
        if (!obj.instances.empty()) {
            out << "    INSTANCES {\n";
            for (const auto& inst : obj.instances) write_instance(out, inst);
            out << "    }\n";
        }
        out << "}\n";
    }
}

namespace {

// sin and cos of an angle in degrees, exact at multiples of 90 deg (so that quarter
// turns give exact matrices).
void sincos_deg(double deg, double& s, double& c) {
    double r = std::fmod(deg, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0) {
        s = 0;
        c = 1;
        return;
    }
    if (r == 90) {
        s = 1;
        c = 0;
        return;
    }
    if (r == 180) {
        s = 0;
        c = -1;
        return;
    }
    if (r == 270) {
        s = -1;
        c = 0;
        return;
    }
    double rad = deg * 3.14159265358979323846 / 180.0;
    s = std::sin(rad);
    c = std::cos(rad);
}

using Mat3 = std::array<double, 9>;

Mat3 mul3(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return m;
}

}  // namespace

Matrix4 instance_matrix(const OdbInstance& inst) {
    if (inst.is_matrix) return inst.matrix;
    double sx, cx, sy, cy, sz, cz;
    sincos_deg(inst.rotation_deg[0], sx, cx);
    sincos_deg(inst.rotation_deg[1], sy, cy);
    sincos_deg(inst.rotation_deg[2], sz, cz);
    Mat3 rx{1, 0, 0, 0, cx, -sx, 0, sx, cx};
    Mat3 ry{cy, 0, sy, 0, 1, 0, -sy, 0, cy};
    Mat3 rz{cz, -sz, 0, sz, cz, 0, 0, 0, 1};
    Mat3 r = mul3(rz, mul3(ry, rx));
    Matrix4 m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j] * inst.scale[j];
        m[4 * i + 3] = inst.translation[i];
    }
    m[15] = 1;
    return m;
}

std::vector<Matrix4> placements(const OdbObject& object) {
    if (object.instances.empty()) return {instance_matrix(OdbInstance{})};
    std::vector<Matrix4> out;
    for (const auto& inst : object.instances) out.push_back(instance_matrix(inst));
    return out;
}

std::vector<std::string> odb_coincident_instances(const Odb& odb) {
    // Same geometry (source, file, units, maps, material) and the same matrix, exactly.
    using Key = std::tuple<int, std::string, int, std::string, std::string, long, Matrix4>;
    std::map<Key, std::vector<int>> lines;  // -> the lines of its instances, in file order
    std::vector<const std::vector<int>*> order;
    for (const auto& obj : odb.objects) {
        auto placed = placements(obj);
        for (std::size_t i = 0; i < placed.size(); ++i) {
            Key key{static_cast<int>(obj.source), obj.path, static_cast<int>(obj.units),
                    obj.material_map, obj.landuse_file + "\n" + obj.landuse_map,
                    obj.material_id.value_or(-1), placed[i]};
            auto [it, fresh] = lines.try_emplace(std::move(key));
            if (fresh) order.push_back(&it->second);
            it->second.push_back(obj.instances.empty() ? obj.line : obj.instances[i].line);
        }
    }
    std::vector<std::string> out;
    for (const auto* group : order) {
        if (group->size() < 2) continue;
        std::string others;
        for (std::size_t k = 1; k < group->size() && k <= 5; ++k)
            others += (k > 1 ? ", " : "") + std::to_string((*group)[k]);
        if (group->size() > 6) others += ", ...";
        out.push_back(SourceLocation{odb.file, group->front()}.str() + ": " +
                      std::to_string(group->size() - 1) +
                      " more instance(s) of the same object with the same placement (line" +
                      (group->size() > 2 ? "s " : " ") + others +
                      "): coincident copies render the same surfaces again");
    }
    return out;
}

double meters_per_odb_unit(OdbUnits units) { return units == OdbUnits::Feet ? 0.3048 : 1.0; }

std::string resolve_odb_path(const Odb& odb, const std::string& path) {
    namespace fs = std::filesystem;
    fs::path p(path);
    if (p.is_absolute() || odb.file.empty() || odb.file == "-") return path;
    fs::path dir = fs::path(odb.file).parent_path();
    return dir.empty() ? path : (dir / p).string();
}

namespace {

// "1 facet", "2 facets" (for summaries).
std::string plural(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

FormatHandler odb_format() {
    return {"odb", "scene assembly (after DIRSIG 3.x's ODB)",
            [](const TextInput& in) {
                Odb odb = parse_odb(in);
                std::size_t copies = 0;
                for (const auto& obj : odb.objects) copies += placements(obj).size();
                std::ostringstream s;
                s << plural(odb.objects.size(), "object") << ", " << plural(copies, "placement");
                return s.str();
            },
            [](const TextInput& in, std::ostream& out) { write_odb(out, parse_odb(in)); }};
}

}  // namespace sigchain::io
