// Per-pixel geolocation arrays (GDAL's GEOLOCATION layout, cube(5) Georeferencing):
// writing, reading, joining row parts, and the lattice of ground control points that
// travels inside an image when its arrays are left behind.
// Thread-safety: free functions, no shared state (GDAL set-up is thread-safe).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/gdal_output.hpp"
#include "image/image.hpp"

namespace sigchain::image {

// The no-data value of the geolocation arrays (cube(5)).
inline constexpr double kGeolocationNodata = -999999.0;

// Geolocation arrays in memory: row-major x (longitude) and y (latitude), deg WGS84.
struct GeolocationArrays {
    long rows = 0, columns = 0;
    std::vector<double> x, y;
    std::string srs_wkt;                  // the arrays' own SRS
    double nodata = kGeolocationNodata;  // where a pixel sees no ground
};

// Writes `arrays` as a float64 GeoTIFF of 2 bands, band 1 x and band 2 y at each
// pixel's centre, atomically. DataError when the vectors do not hold rows * columns.
void write_geolocation(const std::string& path, const GeolocationArrays& arrays);
// The same, written and left to be committed with an image (GdalOutput::finish):
// `arrays` must outlive the result.
std::unique_ptr<GdalOutput> stage_geolocation(const std::string& path,
                                              const GeolocationArrays& arrays);
// Reads arrays write_geolocation made. DataError naming `path` when it is not such a
// file (2 bands); IoError when unreadable.
GeolocationArrays read_geolocation(const std::string& path);
// The geolocation arrays' name beside an output: NAME.geoloc.tif for NAME.EXT.
std::string geolocation_name(const std::string& output_path);
// Where the arrays named by an image at `image_path` are: the file name of `named`
// beside the image (as written: sigchain names them so), else `named` as it is
// (relative to the working directory, as GDAL resolves it).
std::string find_geolocation(const std::string& named, const std::string& image_path);

// A lattice of at most 17 x 17 of the arrays' pixel centres (corners and edges
// included) as ground control points, skipping no-data pixels.
std::vector<GroundControlPoint> gcp_lattice(const GeolocationArrays& arrays);

}  // namespace sigchain::image
