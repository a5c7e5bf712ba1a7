// Land-cover classification of multispectral reference imagery into material classes
// (White (1996), section 5.2.5.2: material maps from classification of reference imagery), and the
// resampling of a class map onto another grid (a DEM's) by majority.
// Thread-safety: free functions on value types.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geo/raster.hpp"

namespace sigchain::landcover {

// Class numbers as written in land-use rasters (0 is never a class).
enum class LandCover : int { Water = 1, Vegetation = 2, Urban = 3, Sand = 4 };
inline constexpr int kClassCount = 4;
const char* class_name(LandCover c);

// Landsat ETM+ digital numbers of one pixel (bands 1-5: blue, green, red, NIR, SWIR1).
struct EtmPixel {
    double blue = 0, green = 0, red = 0, nir = 0, swir1 = 0;
};

// The rule, on digital numbers (not reflectance: an index of DNs is only a proxy),
// applied in this order:
//   water      if NIR < water_nir_max and SWIR1 < water_swir_max (water absorbs
//              both; turbid coastal water stays dark in NIR and SWIR);
//   vegetation if NDVI_DN = (NIR - red) / (NIR + red) >= vegetation_ndvi_min;
//   sand       if red >= sand_red_min (bright bare soil, beach sand, dunes);
//   urban      otherwise (built-up mix of roofs, roads, bare and sparse cover).
struct Rule {
    double water_nir_max = 30;
    double water_swir_max = 25;
    double vegetation_ndvi_min = 0.25;
    double sand_red_min = 95;
};

LandCover classify_pixel(const EtmPixel& p, const Rule& rule);

// Classifies an ETM+ raster with at least 5 bands (band order 1, 2, 3, 4, 5, ...) read
// from `path`. Returns rows * columns class numbers, row-major. Throws DataError
// (naming `path`) for < 5 bands.
std::vector<int> classify_raster(const geo::GeoRaster& etm, const Rule& rule,
                                 const std::string& path);

// Fraction of each class (index 0 = class 1) among the given class numbers.
std::array<double, kClassCount> class_fractions(const std::vector<int>& classes);

// Resamples a class map from a fine grid `src` (geotransform, rows, columns) onto the
// DEM grid `dst` so that DEM cell (r, c) holds the majority class of the source pixels
// whose centres lie in the square between DEM cell centres (r, c) and (r+1, c+1) (the
// block whose two triangles odb(5) gives that cell's class). Ties go to the lower
// class number; a square with no source centre (off the source) takes the source pixel
// nearest its centre, clamped to the source. Both grids must be north-up in one CRS.
std::vector<int> majority_on_dem_blocks(const std::vector<int>& src_classes, long src_rows,
                                        long src_columns, const std::array<double, 6>& src_gt,
                                        long dst_rows, long dst_columns,
                                        const std::array<double, 6>& dst_gt);

}  // namespace sigchain::landcover
