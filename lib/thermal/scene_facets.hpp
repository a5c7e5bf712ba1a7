// The facets therm needs from a scene (.gdb, or an .odb of .gdb, OBJ and DEM objects):
// key, facet normal in the scene frame, material and the per-facet thermal overrides,
// read through lib/scene (scene::assemble_scene), as trace --shadow-history reads it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geo/vec3.hpp"
#include "scene/load.hpp"

namespace sigchain::thermal {

struct SceneFacet {
    std::string key;            // scene::facet_key: "1-1-1", or "2.3/1-1-1" in an .odb (tmp(5))
    geo::Vec3 normal{0, 0, 1};  // unit, scene frame (placement applied)
    long material_id = 0;
    double thickness_cm = -1;   // -1: the material's THICKNESS
    double power = -1;          // -1: the material's SELF_GENERATED_POWER
    double exposed_area = -1;   // -1: the material's EXPOSED_AREA
    double temperature_c = -1;  // != -1: fixed by the .gdb
    SourceLocation where;       // the facet's file and line (a .gdb FACE, an OBJ f)
};

// Reads a scene as scene::assemble_scene assembles it (the same meshes, placements,
// facet order and keys as trace), every facet kept, degenerate ones too (their text
// goes to `warnings` when it is given). The normal is the .gdb FACE normal, or when
// that is zero (and for OBJ and DEM facets) the Newell normal of the facet's
// polygon, mapped by the inverse transpose of each placement (the side faced is kept
// under a mirroring one). DEM objects need `origin` (the .snd's latitude and
// longitude). Throws IoError or DataError (a facet with no normal: zero area).
// `threads`: a large .gdb's parse (io::parse_gdb; 0: all cores).
std::vector<SceneFacet> read_scene_facets(const std::string& path,
                                          const std::optional<scene::GeoOrigin>& origin = {},
                                          std::vector<std::string>* warnings = nullptr,
                                          const scene::SceneInput& input = {},
                                          unsigned threads = 0);

}  // namespace sigchain::thermal
