// Geo-referenced rasters for land-cover work: read all bands with the geotransform and
// CRS (GDAL), write a class raster as a GeoTIFF, and locate a raster on the WGS84
// ellipsoid (its centre's latitude and longitude, and the grid convergence there).
// Thread-safety: free functions on value types.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sigchain::landcover {

// A north-up raster: band-major values, row 0 at the top.
struct GeoRaster {
    long rows = 0;
    long columns = 0;
    int bands = 0;
    std::vector<double> values;           // bands * rows * columns, band-major
    std::array<double, 6> geotransform{};  // GDAL's: x0, dx, 0, y0, 0, dy (CRS units, m)
    std::string crs_wkt;                  // the CRS as WKT

    double at(int band, long r, long c) const {
        return values[(static_cast<std::size_t>(band) * rows + r) * columns + c];
    }
};

// Reads every band of a GDAL raster as doubles. Throws IoError (cannot open) or
// DataError (no geotransform, a rotated grid, no CRS).
GeoRaster read_geo_raster(const std::string& path);

// Writes `classes` (rows * columns, row-major) as a one-band Byte GeoTIFF with the
// given geotransform and CRS, atomically (temporary name, then rename).
void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes,
                        const std::array<double, 6>& geotransform, const std::string& crs_wkt);

// Where a raster's centre is on WGS84, and how its grid is turned there.
struct RasterPlacement {
    double latitude_deg = 0;   // north positive
    double longitude_deg = 0;  // east positive
    // Angle from local true east (ENU) to the raster's +x (column) direction,
    // counter-clockwise seen from above (deg): adv(5)'s twist for a plan view whose
    // columns run along the raster's columns.
    double grid_rotation_deg = 0;
};

// The centre of the raster's full extent (edge to edge), via OGR to WGS84, and the grid
// rotation measured with GeographicLib's LocalCartesian over 1 km of grid x.
RasterPlacement raster_placement(const GeoRaster& raster);

}  // namespace sigchain::landcover
