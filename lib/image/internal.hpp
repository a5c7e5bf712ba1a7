// Helpers shared by the image library's GDAL and OpenImageIO back ends (not a public API).
#pragma once

#include <string>
#include <vector>

#include "core/text.hpp"
#include "image/image.hpp"

namespace sigchain::image::detail {

// The lower-case extension of `path` without the dot ("" if none).
// Throws IoError "PATH: cannot open: No such file or directory" when `path` is absent.
void require_readable(const std::string& path);

Image read_gdal(const std::string& path);
Image read_oiio(const std::string& path);
// Throws UsageError naming `path` when GDAL's GTiff driver rejects a KEY=VALUE option.
void validate_gtiff_options(const std::string& path, const std::vector<std::string>& options);
// A GeoTIFF of counts (`bits` 8, 12 or 16) or float32 samples (`bits` 32), gray bands.
void write_gtiff(const std::string& path, const Image& image, int bits,
                 const WriteOptions& options);

}  // namespace sigchain::image::detail
