// Building footprints read with GDAL/OGR from a vector file (GeoPackage, shapefile, ...).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scenegen/extrude.hpp"

namespace sigchain::scenegen {

// One footprint: its feature id and outer ring in the local frame (m, x east, y north,
// relative to Footprints::origin).
struct Footprint {
    std::int64_t feature_id = 0;
    Ring ring;
};

struct Footprints {
    std::string crs_name;  // the layer's projected CRS name
    // Local origin in the layer's CRS (m): the extent's centre, rounded to 1 m.
    std::array<double, 2> origin{};
    std::array<double, 4> extent{};  // local frame min x, min y, max x, max y (m)
    std::vector<Footprint> buildings;
};

// The polygons of the first layer of path, shifted to a local frame about the extent's
// centre. The layer must be in a projected CRS in metres (no reprojection is done; a
// transverse Mercator's scale error over a few hundred metres is below 0.05 %).
// Throws DataError for a layer that is missing, not projected in metres, or holds
// something other than polygons without holes; IoError if the file cannot be opened.
Footprints read_footprints(const std::string& path);

}  // namespace sigchain::scenegen
