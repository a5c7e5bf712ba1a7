// Ray-queryable scene geometry on Embree 3: facets from .gdb files, placed by
// instances (an .odb), in the scene frame (x east, y north, z up, scene units).
//
// Ownership: a Scene owns its Embree device and scenes (RAII); it is movable, not
// copyable. After construction it is immutable, and intersect() may be called from
// several threads at once (Embree's rtcIntersect1 on a committed scene is thread-safe).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "io/gdb.hpp"

namespace sigchain::scene {

// Row-major 3x4 affine transform (rotation/scale | translation), object -> scene.
using Affine = std::array<double, 12>;

Affine identity_affine();

struct Hit {
    double distance = 0;       // along the unit ray direction, scene units
    std::uint32_t object = 0;  // index of the placed object (instance order)
    std::uint32_t facet = 0;   // facet index within its mesh (.gdb: file order over parts)
    geo::Vec3 normal{};        // unit geometric normal, scene frame, as the facet is
                               // wound (not flipped toward the ray); a mirroring
                               // placement (det < 0) keeps it on the same side of the
                               // surface (M^-T n), not the mirrored winding
};

// What a facet is made of and how to name it in messages and in .tmp/.shd keys.
struct FacetAttributes {
    long material_id = 0;
    double thickness_cm = -1;         // -1: the material's THICKNESS
    double temperature_c = -1;        // -1: from therm (a .tmp)
    double power = -1;                // W m-2 generated in the facet; -1: the material's (gdb(5))
    double exposed_area = -1;         // faces open to the air; -1: the material's (gdb(5))
    std::uint32_t texture_curve = 0;  // .ems curve (land use / texture map), 0 default
};

// Where a facet came from, for messages ("FILE:LINE: object 'N' (ID), part 'N'
// (ID), facet 'N' (ID): ...") and its key ("1-1-1"; "2.3/1-1-1" in an .odb: object
// 2 of the .odb, its third instance; see tmp(5)).
struct FacetOrigin {
    std::string file;
    int line = 0;
    std::string description;  // "object 'house' (1-0-0), part 'roof' (1-1-0), facet 'n' (1-1-1)"
    std::string id;           // the .gdb FACE id, "1-1-1" (OBJ/DEM: generated, see odb(5))
};

// A triangle mesh from any source (.gdb, OBJ, DEM): vertices in the mesh's own
// units, triangles as vertex indices, each triangle's facet, and per facet its
// attributes and origin.
struct MeshData {
    std::vector<float> vertices;           // x y z ...
    std::vector<std::uint32_t> triangles;  // i j k ...
    std::vector<std::uint32_t> triangle_facet;
    std::vector<FacetAttributes> facets;
    std::vector<FacetOrigin> origins;  // parallel to facets
    // Parallel to facets (MeshBuilder fills it), mesh frame, any length: the side the
    // facet faces. A .gdb FACE normal as given (gdb(5): the normal, not the winding,
    // says which way a facet faces); the Newell normal of its polygon in double
    // precision when that normal is zero, and for OBJ and DEM facets (their winding).
    std::vector<geo::Vec3> normals;
};

// A placed facet's key in .shd and .tmp files (tmp(5)): the placement's prefix ("2.3/"
// in an .odb, "" for a lone .gdb) and the facet's id. trace and therm both name
// facets with it.
std::string facet_key(const std::string& key_prefix, const FacetOrigin& origin);

// Triangulates a .gdb (quads split along the 0-2 diagonal).
MeshData mesh_from_gdb(const io::Gdb& gdb);

// A plane of the scene frame: normal . x = offset, the normal a unit vector whose first
// non-zero component is positive (one plane whichever way its facets face).
struct Plane {
    geo::Vec3 normal{};
    double offset = 0;  // scene units
};

struct Bounds {
    geo::Vec3 lower{};
    geo::Vec3 upper{};
    bool empty() const { return lower[0] > upper[0]; }
};

class Scene {
public:
    Scene();
    ~Scene();
    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;

    // Adds a mesh (its facets split into triangles) once; returns its index for
    // place(). Degenerate facets are kept (they are never hit); io::gdb_problems()
    // reports them.
    std::size_t add_mesh(const io::Gdb& gdb, double scale_to_scene_units = 1.0);
    std::size_t add_mesh(MeshData mesh, double scale_to_scene_units = 1.0);
    // Places a copy of mesh `mesh` with `transform` (an Embree instance).
    // `key_prefix` is prepended to facet ids in keys ("2.3/" for .odb object 2,
    // instance 3; empty for a lone .gdb).
    void place(std::size_t mesh, const Affine& transform, std::string key_prefix = "");
    // Builds the acceleration structures; call once after adding and placing.
    void commit();

    // The nearest hit along origin + t*direction (direction need not be unit), or none.
    std::optional<Hit> intersect(const geo::Vec3& origin, const geo::Vec3& direction) const;
    // The same between distances tnear and tfar (along the normalised direction).
    std::optional<Hit> intersect(const geo::Vec3& origin, const geo::Vec3& direction, double tnear,
                                 double tfar) const;
    // True if anything lies between tnear and tfar (Embree occlusion query; faster).
    bool occluded(const geo::Vec3& origin, const geo::Vec3& direction, double tnear,
                  double tfar) const;

    const FacetAttributes& attributes(const Hit& hit) const;  // constant time
    const FacetOrigin& origin(const Hit& hit) const;
    std::string facet_key(const Hit& hit) const;  // prefix + id
    // Every placed facet once: (object, facet) pairs, for validation and .shd.
    std::size_t placement_count() const;
    std::size_t mesh_of_placement(std::size_t object) const;
    std::size_t facet_count(std::size_t mesh) const;
    const FacetAttributes& attributes(std::size_t mesh, std::uint32_t facet) const;
    const FacetOrigin& origin(std::size_t mesh, std::uint32_t facet) const;
    // Axis-aligned bounds of everything placed (empty() if nothing was).
    Bounds bounds() const;
    std::size_t triangle_count() const;  // over placed copies
    // The distinct planes of the placed triangles whose facet `keep` accepts, in
    // placement and triangle order, at most `limit` + 1 of them (more than `limit`: the
    // caller's to refuse or skip). Two triangles share a plane when their normals agree
    // to 1e-9 in cosine and their offsets to 1e-6 of the scene's extent.
    std::vector<Plane> facet_planes(const std::function<bool(const FacetAttributes&)>& keep,
                                    std::size_t limit) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Loads a .gdb (units from the caller) as a scene with one identity placement.
Scene load_gdb_scene(const std::string& path, double scale_to_scene_units = 1.0);

}  // namespace sigchain::scene
