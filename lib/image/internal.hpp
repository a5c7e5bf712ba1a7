// Helpers shared by the image library's GDAL and OpenImageIO back ends (not a public API).
#pragma once

#include <string>

#include "core/text.hpp"
#include "image/image.hpp"

namespace sigchain::image::detail {

// The lower-case extension of `path` without the dot ("" if none).
// The temporary name used for atomic output: FILE.tmp.PID.
std::string temp_name(const std::string& path);
// Throws IoError "PATH: cannot open: No such file or directory" when `path` is absent.
void require_readable(const std::string& path);

Image read_gdal(const std::string& path);
Image read_oiio(const std::string& path);

}  // namespace sigchain::image::detail
