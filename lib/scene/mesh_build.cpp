// MeshBuilder: polygons to triangles with per-facet attributes, degenerate facets.
#include "scene/mesh_build.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"
#include "io/gdb.hpp"

namespace sigchain::scene {

std::string facet_where(const FacetOrigin& origin) {
    std::string where = SourceLocation{origin.file, origin.line}.str();
    return origin.description.empty() ? where : where + ": " + origin.description;
}

MeshBuilder::MeshBuilder(DegeneratePolicy policy, std::vector<std::string>* warnings,
                         std::string refusal_hint)
    : m_policy(policy), m_warnings(warnings), m_refusal_hint(std::move(refusal_hint)) {}

std::uint32_t MeshBuilder::add_vertex(const geo::Vec3& p) {
    for (double c : p) m_mesh.vertices.push_back(static_cast<float>(c));
    m_points.push_back(p);
    return static_cast<std::uint32_t>(m_points.size() - 1);
}

bool MeshBuilder::faces_up(const std::vector<std::uint32_t>& t) const {
    const geo::Vec3& a = m_points.at(t.at(0));
    const geo::Vec3& b = m_points.at(t.at(1));
    const geo::Vec3& c = m_points.at(t.at(2));
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) >= 0;
}

bool MeshBuilder::add_facet(const std::vector<std::uint32_t>& polygon,
                            const FacetAttributes& attributes, FacetOrigin origin,
                            const geo::Vec3& facing) {
    if (polygon.size() < 3)
        throw DataError({origin.file, origin.line},
                        origin.description + ": a facet needs at least 3 vertices");
    m_polygon.clear();
    for (std::uint32_t i : polygon) {
        const geo::Vec3& p = m_points.at(i);
        if (!geo::within_coordinate_limit(p))
            throw DataError({origin.file, origin.line},
                            (origin.description.empty() ? "" : origin.description + ": ") +
                                "a vertex (" + format_number(p[0]) + ", " + format_number(p[1]) +
                                ", " + format_number(p[2]) + ") is " +
                                (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])
                                     ? "beyond +-1e9 scene units (Embree's single precision)"
                                     : "not finite"));
        m_polygon.push_back(p);
    }
    if (m_policy != DegeneratePolicy::Keep) {
        std::string why = io::polygon_degeneracy(m_polygon);
        if (!why.empty()) {
            if (m_policy == DegeneratePolicy::Error)
                throw DataError({origin.file, origin.line},
                                (origin.description.empty() ? "" : origin.description + ": ") +
                                    why + " (a degenerate facet; " + m_refusal_hint + ")");
            m_degenerate.push_back(origin);
            if (m_policy == DegeneratePolicy::Report) {
                if (m_warnings) m_warnings->push_back(facet_where(origin) + ": " + why + " (kept)");
            } else {
                if (m_warnings)
                    m_warnings->push_back(facet_where(origin) + ": " + why + " (skipped)");
                return false;
            }
        }
    }
    auto facet = static_cast<std::uint32_t>(m_mesh.facets.size());
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        m_mesh.triangles.insert(m_mesh.triangles.end(), {polygon[0], polygon[k], polygon[k + 1]});
        m_mesh.triangle_facet.push_back(facet);
    }
    m_mesh.facets.push_back(attributes);
    m_mesh.origins.push_back(std::move(origin));
    m_mesh.normals.push_back(geo::norm(facing) > 0 ? facing : io::newell_normal(m_polygon));
    return true;
}

MeshData mesh_from_gdb(const io::Gdb& gdb, DegeneratePolicy policy,
                       std::vector<std::string>* warnings) {
    MeshBuilder b(policy, warnings);
    std::vector<std::uint32_t> polygon;
    for (const auto& obj : gdb.objects)
        for (const auto& part : obj.parts)
            for (const auto& f : part.facets) {
                polygon.clear();
                for (const auto& v : f.vertices) polygon.push_back(b.add_vertex(v));
                FacetAttributes a;
                a.material_id = f.material_id;
                a.thickness_cm = f.thickness_cm;
                a.temperature_c = f.temperature_c;
                a.power = f.power;
                a.exposed_area = f.exposed_area;
                FacetOrigin o{gdb.file, f.line,
                              "object " + quoted(obj.name) + " (" + obj.id + "), part " +
                                  quoted(part.name) + " (" + part.id + "), facet " +
                                  quoted(f.name) + " (" + f.id + ")",
                              f.id};
                b.add_facet(polygon, a, std::move(o), f.normal);
            }
    return b.take();
}

}  // namespace sigchain::scene
