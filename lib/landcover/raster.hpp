// Class rasters: a land-use class map written as a one-band Byte GeoTIFF on a given
// grid (lib/geo/raster.hpp reads rasters and places them on WGS84).
// Thread-safety: free functions on value types.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geo/crs.hpp"

namespace sigchain::landcover {

// Writes `classes` (rows * columns, row-major) as a one-band Byte GeoTIFF with the
// given geotransform and CRS, atomically (temporary name, then rename). Throws IoError.
void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes, const std::array<double, 6>& geotransform,
                        const geo::Crs& crs);

}  // namespace sigchain::landcover
