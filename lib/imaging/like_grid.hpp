// Rendering on a given raster's grid (trace --like RASTER): each pixel is a cell of the
// raster's map grid, seen from the .adv's camera position through the ground point at
// the cell's position (the scene's top surface there), so that the render lies on the
// raster's CRS, size and geotransform exactly and pixel maths needs no resampling (as
// an orthorectified product: Landsat's terrain-corrected levels). Relief is taken from
// the scene itself (a vertical ray), so a roof or a hill lands at its map position.
// Thread-safety: a GridSensor is immutable after construction (Sensor's contract).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geo/georef.hpp"
#include "image/image.hpp"
#include "imaging/georef.hpp"
#include "imaging/sensor.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging {

// The grid of a raster: its CRS, geotransform and size.
struct LikeGrid {
    geo::Crs crs;
    geo::GeoTransform geotransform{};
    long rows = 0, columns = 0;
};

// Reads the grid of the GDAL raster `path` (trace --like). Throws IoError when it cannot
// be read, DataError naming it when it has no CRS or no geotransform.
LikeGrid read_like_grid(const std::string& path);

// A sensor whose image is `grid`: the ray of image position (row, column) leaves the
// frame camera's position toward the scene point at the map position of (column, row)
// (GDAL's convention), on the scene's top surface there (a vertical ray from above the
// scene), else on the plane z = `plane_height` (scene units). Map positions become
// scene coordinates through `place` (a lattice of the cell corners, interpolated
// bilinearly: the map-to-frame mapping is smooth well within a cell). View angles are
// the frame camera's. Throws DataError when `frame` is not a frame camera or a corner
// cannot be mapped.
std::unique_ptr<Sensor> make_grid_sensor(std::unique_ptr<Sensor> frame, const LikeGrid& grid,
                                         const GeoPlacement& place, const scene::Scene& scene,
                                         double plane_height);

// The georeferencing of rows [row_begin, ...) of a render on `grid`: its CRS and its
// geotransform moved down to row_begin.
image::Georeference like_georeference(const LikeGrid& grid, long row_begin);

}  // namespace sigchain::imaging
