// Ray-queryable scene geometry on Embree 3: facets from .gdb files, placed by
// instances (an .odb), in the scene frame (x east, y north, z up, scene units).
//
// Ownership: a Scene owns its Embree device and scenes (RAII); it is movable, not
// copyable. After construction it is immutable, and intersect() may be called from
// several threads at once (Embree's rtcIntersect1 on a committed scene is thread-safe).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/gdb.hpp"

namespace sigchain::scene {

using Vec3 = std::array<double, 3>;
// Row-major 3x4 affine transform (rotation/scale | translation), object -> scene.
using Affine = std::array<double, 12>;

Affine identity_affine();

struct Hit {
    double distance = 0;       // along the unit ray direction, scene units
    std::uint32_t object = 0;  // index of the placed object (instance order)
    std::uint32_t facet = 0;   // facet index within its .gdb (file order over parts)
};

struct Bounds {
    Vec3 lower{};
    Vec3 upper{};
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
    // Places a copy of mesh `mesh` with `transform` (an Embree instance).
    void place(std::size_t mesh, const Affine& transform);
    // Builds the acceleration structures; call once after adding and placing.
    void commit();

    // The nearest hit along origin + t*direction (direction need not be unit), or none.
    std::optional<Hit> intersect(const Vec3& origin, const Vec3& direction) const;
    // Axis-aligned bounds of everything placed (empty() if nothing was).
    Bounds bounds() const;
    std::size_t triangle_count() const;  // over placed copies

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Loads a .gdb (units from the caller) as a scene with one identity placement.
Scene load_gdb_scene(const std::string& path, double scale_to_scene_units = 1.0);

}  // namespace sigchain::scene
