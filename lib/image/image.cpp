// The Image value type, cube format selection and helpers shared by the readers and writers.
#include "image/image.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "core/error.hpp"
#include "image/internal.hpp"

namespace sigchain::image {

Image::Image(long rows_, long columns_, int channels_, float fill)
    : rows(rows_),
      columns(columns_),
      channels(channels_),
      data(static_cast<std::size_t>(channels_) * rows_ * columns_, fill) {}

CubeFormat cube_format_of(const std::string& path) {
    const std::string ext = file_extension(path);
    if (ext == "tif" || ext == "tiff") return CubeFormat::GeoTiff;
    if (ext == "img" || ext == "hdr" || ext == "bsq" || ext == "dat") return CubeFormat::Envi;
    throw UsageError(path + ": unknown cube format (use .img or .hdr for ENVI, .tif for GeoTIFF)");
}

void check_write_options(const std::string& path, const WriteOptions& options) {
    for (const std::string& kv : options.creation_options) {
        const auto eq = kv.find('=');
        if (eq == 0 || eq == std::string::npos)
            throw UsageError("--co " + kv + ": expected KEY=VALUE");
    }
    const std::string ext = file_extension(path);
    if (!options.creation_options.empty() && ext != "tif" && ext != "tiff")
        throw UsageError(path + ": --co applies to GeoTIFF (.tif) outputs only");
    if (!options.creation_options.empty())
        detail::validate_gtiff_options(path, options.creation_options);
}

Image read_image(const std::string& path) {
    detail::require_readable(path);
    const std::string ext = file_extension(path);
    // PNG, JPEG and Netpbm (plain and raw PGM/PPM; GDAL reads only raw) through
    // OpenImageIO; TIFF through GDAL first (GeoTIFF band metadata), then OpenImageIO
    // for TIFF layouts GDAL declines; everything else through GDAL.
    if (ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "pgm" || ext == "ppm" ||
        ext == "pnm")
        return detail::read_oiio(path);
    if (ext == "tif" || ext == "tiff") {
        try {
            return detail::read_gdal(path);
        } catch (const DataError&) {
            return detail::read_oiio(path);
        }
    }
    return detail::read_gdal(path);
}

namespace detail {

void require_readable(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw IoError(path + ": cannot open: No such file or directory");
    if (std::filesystem::is_directory(path, ec))
        throw IoError(path + ": cannot open: is a directory");
}

}  // namespace detail
}  // namespace sigchain::image
