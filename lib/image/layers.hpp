// Per-pixel layers written as a GeoTIFF of float64 or int32 bands: the ground-position
// (IGM) and geometry-lookup (GLT) layers of a scanner image (cube(5), GEOLOCATION
// LAYERS). Written atomically, like every output.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace sigchain::image {

struct Layers {
    long rows = 0, columns = 0;
    std::vector<std::string> names;                     // one per band (the band description)
    std::vector<std::vector<double>> planes;            // one per band, rows * columns, row-major
    bool integer = false;                               // int32 bands (values must be integers)
    std::string srs_wkt;                                // "" for none
    std::optional<std::array<double, 6>> geotransform;  // GDAL's; none for image geometry
    std::optional<double> nodata;
};

// Writes `layers` to `path` (GTiff, band interleaved). Throws IoError on failure,
// DataError when the planes do not match the size.
void write_layers(const std::string& path, const Layers& layers);

}  // namespace sigchain::image
