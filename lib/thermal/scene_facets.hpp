// The facets therm needs from a scene (.gdb, or an .odb of .gdb objects): key, facet
// normal in the scene frame, material and the per-facet thermal overrides.
#pragma once

#include <string>
#include <vector>

#include "core/error.hpp"
#include "thermal/environment.hpp"

namespace sigchain::thermal {

struct SceneFacet {
    std::string key;       // "1-1-1", or "2.3/1-1-1" in an .odb (tmp(5))
    Vec3 normal{0, 0, 1};  // unit, scene frame (placement applied)
    long material_id = 0;
    double thickness_cm = -1;   // -1: the material's THICKNESS
    double power = -1;          // -1: the material's SELF_GENERATED_POWER
    double exposed_area = -1;   // -1: the material's EXPOSED_AREA
    double temperature_c = -1;  // != -1: fixed by the .gdb
    SourceLocation where;       // the .gdb file and the FACE line
};

// Reads a .gdb, or an .odb whose objects are .gdb files (OBJ and DEM objects are
// refused with a DataError at the object's line). The normal is the FACE normal (or,
// if that is zero, the vertices' Newell normal), mapped by the inverse transpose of
// each placement. Throws IoError or DataError.
std::vector<SceneFacet> read_scene_facets(const std::string& path);

}  // namespace sigchain::thermal
