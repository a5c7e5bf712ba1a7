// Terrain from a DEM raster (odb(5) DEM_FILENAME) as a MeshData in the scene's local
// east-north-up frame, materials from MATERIAL_ID or a land-use raster and map.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/id_map.hpp"
#include "scene/load.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::scene {

struct DemSource {
    std::string dem_path;             // GDAL raster; band 1 = elevation in object units
    std::optional<long> material_id;  // without land use
    std::string landuse_path;         // with `landuse_map`: band 1 = class (an integer)
    const IdMap* landuse_map = nullptr;
    double meters_per_unit = 1;  // the object's UNITS (elevations and output)
    GeoOrigin origin;            // the scene origin (ENU about it, WGS84)
};

// Every valid cell centre becomes a vertex: its (x, y) in the raster's CRS is turned to
// WGS84 latitude/longitude (OGRCoordinateTransformation, x = easting/longitude), then
// with its elevation (value x meters_per_unit, taken as height above the ellipsoid) to
// east-north-up metres about `origin` (GeographicLib::LocalCartesian), and stored in
// object units (metres / meters_per_unit). Each 2x2 block of cell centres gives two
// triangles, (r,c) (r+1,c) (r+1,c+1) and (r,c) (r+1,c+1) (r,c+1), wound upward; a
// triangle with a nodata (or NaN) corner is dropped. Facet id "1-K-T": K = r*columns
// + c + 1 (the block's upper-left cell, 1-based row-major), T = 1 or 2.
// Land use: the class of the block's upper-left cell, mapped by `landuse_map`.
// Throws IoError (unreadable raster) or DataError (no CRS or geotransform, land-use
// grid differs, unmapped class, fewer than 2 x 2 cells).
MeshData read_dem_mesh(const DemSource& source, DegeneratePolicy policy,
                       std::vector<std::string>* warnings);

// The centre of a DEM's extent, edge to edge (the geotransform at half its columns and
// rows, rotation terms included), on WGS84, at height 0: where a DEM given alone places
// itself (lone_dem_origin). Throws IoError or DataError as read_dem_mesh (no CRS, no
// geotransform, a point that cannot be transformed).
GeoOrigin dem_centre(const std::string& dem_path);

}  // namespace sigchain::scene
