// The GDAL side of writing an image, shared by write_cube and CubeStream (not a public
// API): the temporary dataset with its metadata, and its commit.
#pragma once

#include <memory>
#include <string>

#include "image/gdal_output.hpp"
#include "image/image.hpp"

namespace sigchain::image::detail {

// Checks `header`'s size and per-band lists (not its data), and makes the temporary
// dataset of `header.rows` x `header.columns` x `header.channels` samples of `type`
// (an ENVI .img for a .hdr path) with sigchain's creation options and the user's, its
// band and dataset metadata and its georeferencing set (cube(5)). DataError,
// UsageError (--co on a non-GeoTIFF), IoError.
std::unique_ptr<GdalOutput> create_gdal(const std::string& path, const Image& header,
                                        GDALDataType type, CubeFormat format,
                                        const WriteOptions& options);

// Commits `out` (every band written), with the geolocation arrays of
// header.georef.arrays when there are any: the arrays and the image as one output.
void commit_gdal(GdalOutput& out, const Image& header);

}  // namespace sigchain::image::detail
