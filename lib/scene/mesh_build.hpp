// Building a MeshData from polygons (any source: .gdb, mesh files, DEM), with the
// degenerate facet policy of load_scene (error, skip with a warning, or keep).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sigchain::scene {

// What to do with a degenerate facet (coincident vertices or zero area).
enum class DegeneratePolicy {
    Keep,    // mesh it as it is (Embree never reports a hit on a zero-area triangle)
    Skip,    // leave it out and add a warning
    Report,  // keep it as it is and add a warning (trace --shadow-history: therm needs
             // every facet's history)
    Error,   // throw DataError naming it
};

// Appends facets to a MeshData. Vertices are added once and shared by index.
class MeshBuilder {
public:
    // `warnings` receives one "FILE:LINE: DESCRIPTION: why (skipped)" per skipped facet
    // (may be null: the facets are still listed by degenerate()). `refusal_hint` ends
    // the Error policy's message: "(a degenerate facet; HINT)".
    MeshBuilder(DegeneratePolicy policy, std::vector<std::string>* warnings,
                std::string refusal_hint = "trace --allow-degenerate skips it");

    // Adds a vertex (mesh units) and returns its index.
    std::uint32_t add_vertex(const geo::Vec3& p);
    // Adds one facet: the polygon of vertex indices (3 or more, fan-triangulated from the
    // first vertex, so a quad is split along its 0-2 diagonal). Returns false when the
    // facet was skipped as degenerate. Throws DataError (policy Error) naming `origin`.
    // `facing`: the normal the source gives (a .gdb FACE normal), or zero: the
    // polygon's Newell normal (MeshData::normals).
    bool add_facet(const std::vector<std::uint32_t>& polygon, const FacetAttributes& attributes,
                   FacetOrigin origin, const geo::Vec3& facing = {0, 0, 0});

    // True if the triangle (3 vertex indices) winds counter-clockwise seen from +z
    // (its normal (v1 - v0) x (v2 - v0) has z >= 0).
    bool faces_up(const std::vector<std::uint32_t>& triangle) const;

    std::size_t facet_count() const { return m_mesh.facets.size(); }
    // The degenerate facets met so far (Skip and Report), in the order added.
    const std::vector<FacetOrigin>& degenerate() const { return m_degenerate; }
    MeshData take() { return std::move(m_mesh); }

private:
    DegeneratePolicy m_policy;
    std::vector<std::string>* m_warnings;
    std::string m_refusal_hint;
    std::vector<FacetOrigin> m_degenerate;
    MeshData m_mesh;
    std::vector<geo::Vec3> m_points;   // double copies of the vertices: degeneracy, normals
    std::vector<geo::Vec3> m_polygon;  // scratch
};

// Triangulates a .gdb (quads split along the 0-2 diagonal) with per-facet attributes
// (MATERIAL_ID, thickness, temperature, power, exposed area, the FACE normal) and origins, under
// `policy`.
MeshData mesh_from_gdb(const io::Gdb& gdb, DegeneratePolicy policy,
                       std::vector<std::string>* warnings);

// "FILE:LINE: DESCRIPTION" (FILE alone when line is 0) of a facet, for messages.
std::string facet_where(const FacetOrigin& origin);

}  // namespace sigchain::scene
