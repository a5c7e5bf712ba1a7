// The facets therm needs from a scene (see scene_facets.hpp).
#include "thermal/scene_facets.hpp"

#include <cmath>

#include "core/text.hpp"
#include "io/gdb.hpp"
#include "io/odb.hpp"

namespace sigchain::thermal {

namespace {

Vec3 unit(const Vec3& v) {
    double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0)) return {0, 0, 0};
    return {v[0] / n, v[1] / n, v[2] / n};
}

// Normal transformed by the inverse transpose of the 3x3 part of a row-major 4x4:
// the cofactor matrix (inverse transpose x det), which keeps the direction for det > 0
// and keeps the normal on the same side of the surface when det < 0 once re-signed.
Vec3 transform_normal(const io::Matrix4& m, const Vec3& n) {
    auto a = [&](int r, int c) { return m[static_cast<std::size_t>(r * 4 + c)]; };
    double cof[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
        }
    double det = a(0, 0) * cof[0][0] + a(0, 1) * cof[0][1] + a(0, 2) * cof[0][2];
    double s = det < 0 ? -1.0 : 1.0;
    Vec3 out{};
    for (int r = 0; r < 3; ++r)
        out[static_cast<std::size_t>(r)] =
            s * (cof[r][0] * n[0] + cof[r][1] * n[1] + cof[r][2] * n[2]);
    return unit(out);
}

void add_gdb(const io::Gdb& gdb, const io::Matrix4* placement, const std::string& prefix,
             std::vector<SceneFacet>& out) {
    for (const auto& object : gdb.objects)
        for (const auto& part : object.parts)
            for (const auto& face : part.facets) {
                SceneFacet f;
                f.key = prefix + face.id;
                Vec3 n = unit(face.normal);
                if (n == Vec3{0, 0, 0}) n = unit(io::newell_normal(face.vertices));
                if (n == Vec3{0, 0, 0})
                    throw DataError({gdb.file, face.line},
                                    "facet " + face.id + ": no normal (zero area)");
                f.normal = placement ? transform_normal(*placement, n) : n;
                f.material_id = face.material_id;
                f.thickness_cm = face.thickness_cm;
                f.power = face.power;
                f.exposed_area = face.exposed_area;
                f.temperature_c = face.temperature_c;
                f.where = {gdb.file, face.line};
                out.push_back(std::move(f));
            }
}

}  // namespace

std::vector<SceneFacet> read_scene_facets(const std::string& path) {
    std::vector<SceneFacet> out;
    if (file_extension(path) != "odb") {
        add_gdb(io::read_gdb_file(path), nullptr, "", out);
        return out;
    }
    const io::Odb odb = io::read_odb_file(path);
    for (std::size_t k = 0; k < odb.objects.size(); ++k) {
        const io::OdbObject& object = odb.objects[k];
        if (object.source != io::OdbSource::Gdb)
            throw DataError({odb.file, object.line},
                            "therm reads .gdb objects only (OBJ and DEM objects not supported)");
        const io::Gdb gdb = io::read_gdb_file(io::resolve_odb_path(odb, object.path));
        const auto matrices = io::placements(object);
        for (std::size_t i = 0; i < matrices.size(); ++i)
            add_gdb(gdb, &matrices[i], std::to_string(k + 1) + "." + std::to_string(i + 1) + "/",
                    out);
    }
    return out;
}

}  // namespace sigchain::thermal
