// Geo-referenced rasters read with GDAL: the values of one or all bands as doubles, the
// geotransform, the CRS and band 1's nodata value; and where a raster lies on WGS84.
// Thread-safety: free functions on value types.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geo/crs.hpp"

namespace sigchain::geo {

// A raster grid: band-major values, row 0 at the top.
struct GeoRaster {
    long rows = 0;
    long columns = 0;
    int bands = 0;                         // bands read (1 or all the file's)
    std::vector<double> values;            // bands * rows * columns, band-major
    std::array<double, 6> geotransform{};  // GDAL's: x0, dx, rx, y0, ry, dy (CRS units)
    Crs crs;                               // empty when the file names none
    std::optional<double> nodata;          // band 1's nodata value, if it has one

    double at(int band, long r, long c) const {
        return values[(static_cast<std::size_t>(band) * rows + r) * columns + c];
    }
    // Whether v is a value (finite and not band 1's nodata).
    bool valid(double v) const;
};

// The bands read: band 1, all, or none (the grid, CRS and nodata alone).
enum class Bands { First, All, None };

// Reads a GDAL raster. Throws IoError (cannot open or read) or DataError (no band, no
// geotransform, or more cells than this machine's memory holds: the values as doubles
// plus `use_bytes_per_cell` for what the caller builds from each cell, checked before
// anything is allocated). A raster has no lines: errors name the file alone.
GeoRaster read_geo_raster(const std::string& path, Bands bands = Bands::All,
                          double use_bytes_per_cell = 0, const char* use = "");

// Throws DataError unless the grid is north-up (no rotation terms) and has a CRS.
void require_north_up_with_crs(const GeoRaster& raster, const std::string& path);

// Where a raster's centre is on WGS84, and how its grid is turned there.
struct RasterPlacement {
    double latitude_deg = 0;   // north positive
    double longitude_deg = 0;  // east positive
    // Angle from local true east (ENU) to the raster's +x (column) direction,
    // counter-clockwise seen from above (deg): adv(5)'s twist for a plan view whose
    // columns run along the raster's columns.
    double grid_rotation_deg = 0;
};

// The centre of a north-up raster's full extent (edge to edge) on WGS84, and the grid
// rotation measured in the local east-north-up frame there over 1 km of grid x.
// Throws DataError (naming `path`) when the CRS is missing or cannot be transformed.
RasterPlacement raster_placement(const GeoRaster& raster, const std::string& path);

}  // namespace sigchain::geo
