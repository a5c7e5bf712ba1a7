// A scanner image's geolocation products, as airborne imaging spectrometers ship them
// (cube(5), GEOLOCATION LAYERS): the IGM, each pixel's ground position (map easting,
// northing, height; WGS84 longitude, latitude; scene x, y, z), and the GLT, for each
// cell of a north-up map grid the image pixel that sees it (nearest neighbour).
// Thread-safety: free functions; the scene and sensor are only read.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "imaging/georef.hpp"
#include "imaging/sensor.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging {

// Each pixel's ground position in the output frame: map easting and northing (the map
// CRS's units) when geo-placed, else scene x and y (scene units); NaN where the pixel
// sees no ground.
struct GroundGrid {
    long rows = 0, columns = 0;
    std::vector<geo::Vec3> scene;               // scene frame, scene units
    std::vector<std::array<double, 2>> map_xy;  // the output frame's x and y
};

// A geometry lookup table: for a north-up grid of `cell` (the output frame's units)
// whose top-left corner is (x0, y0), the 1-based source column and row of each cell,
// 0 where no pixel's ground point lies within `reach` of the cell's centre.
struct Glt {
    long rows = 0, columns = 0;
    double x0 = 0, y0 = 0, cell = 0, reach = 0;
    std::vector<double> column, row;  // row-major, integers
};

// Nearest-neighbour GLT of `grid`: cell size the geometric mean of the median ground
// spacings between row and column neighbours, reach the larger of the two. Ties go to
// the first pixel in row-major order, so the table is reproducible. Throws DataError
// (naming `where`) when no pixel sees the ground or the grid would exceed 64 times the
// image's pixel count (rays grazing the horizon).
Glt make_glt(const GroundGrid& grid, const std::string& where);

// Writes the IGM (`igm_path`, when not empty) and the GLT (`glt_path`) of rows
// [row_begin, row_end) as GeoTIFFs (cube(5), GEOLOCATION LAYERS), atomically. `note`
// receives one line for -v.
void write_ground_layers(const Sensor& sensor, const scene::Scene& scene,
                         const std::optional<GeoPlacement>& place, double meters_per_unit,
                         std::optional<double> plane_height, long row_begin, long row_end,
                         const std::string& igm_path, const std::string& glt_path,
                         std::string& note);

}  // namespace sigchain::imaging
