// Reading TIFF, PNG, JPEG and Netpbm, and writing PNG and Netpbm counts, through
// OpenImageIO (TIFF is written through GDAL: gdal_write.cpp). OpenImageIO itself is
// called by the module sigchain_oiio (oiio_module.cpp), which this file loads on the
// first such image (oiio_module.hpp says why); the checks, the temporary folder and the
// rename stay here.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/module_loader.hpp"
#include "core/output.hpp"
#include "image/image.hpp"
#include "image/internal.hpp"
#include "image/oiio_module.hpp"

namespace sigchain::image {
namespace {

using oiio::Sample;
using oiio::Status;

// The module's functions, loaded once per process (thread-safe); IoError
// "IMAGE: cannot load the OpenImageIO module PATH: REASON" when it cannot be loaded.
const oiio::Api& module_for(const std::string& image_path) {
    static std::once_flag once;
    static LoadedModule<oiio::Api> module;
    std::call_once(once, [] {
        module = load_module<oiio::Api>(SIGCHAIN_OIIO_MODULE_NAME, "sigchain_oiio_api",
                                        "OpenImageIO", oiio::kApiVersion);
    });
    if (!module.api) throw IoError(image_path + ": " + module.error);
    return *module.api;
}

// Throws the error `status` stands for. Errors in this file name the image only:
// binary rasters have no lines.
void check(Status status, const std::string& path, const std::string& message) {
    if (status == Status::DataError) throw DataError({path, 0}, message);
    if (status == Status::IoError) throw IoError(path + ": " + message);
}

// Planar floats -> interleaved native samples to be written.
template <typename T>
std::vector<T> interleave(const Image& image) {
    const std::size_t plane = image.plane_size();
    std::vector<T> out(plane * image.channels);
    for (std::size_t p = 0; p < plane; ++p)
        for (int c = 0; c < image.channels; ++c)
            out[p * image.channels + c] = static_cast<T>(image.data[c * plane + p]);
    return out;
}

// Writes `pixels` (interleaved, of `sample` type) into a private temporary folder with the
// writer chosen by the final name's extension, then renames into place.
void write_oiio(const std::string& path, const Image& image, Sample sample, const void* pixels) {
    const oiio::Api& module = module_for(path);
    std::string message;
    check(module.can_write(path, message), path, message);
    const std::string ext = file_extension(path);
    if (image.channels > 4 && ext == "png")
        throw DataError({path, 0}, "PNG holds at most 4 channels; use a TIFF for " +
                                       std::to_string(image.channels) + " bands");
    const bool netpbm = ext == "pgm" || ext == "ppm" || ext == "pnm";
    if (netpbm) {
        if (image.channels != 1 && image.channels != 3)
            throw DataError({path, 0},
                            "PGM/PPM hold 1 or 3 channels, not " + std::to_string(image.channels));
        if (sample != Sample::UInt8)  // OpenImageIO 2.4 garbles 16-bit plain PNM
            throw DataError({path, 0}, "PGM/PPM output holds 8-bit counts only");
    }
    // OpenImageIO opens its file itself: it goes into a private folder beside the target.
    const TempDir folder(path);
    const std::string temp = folder.file(std::filesystem::path(path).filename().string());
    // Netpbm is written plain (text): readable and diffable.
    check(module.write(path, temp, image, sample, pixels, netpbm, message), path, message);
    // Read back: OpenImageIO 2.4's PNG writer does not report a failed write (a full
    // disk left a 0-byte PNG and exit 0), so the samples on disk are what proves it:
    // counts exactly; floats (which a format may quantise) by reading whole.
    Image back;
    if (module.read(temp, back, message) != Status::Ok || back.rows != image.rows ||
        back.columns != image.columns || back.channels != image.channels ||
        (sample != Sample::Float && back.data != image.data))
        throw IoError(path + ": write error: the image did not reach the disk as written" +
                      (message.empty() ? std::string(" (a full disk?)") : ": " + message));
    commit_moves({{temp, path}});
}

}  // namespace

namespace detail {

Image read_oiio(const std::string& path) {
    const oiio::Api& module = module_for(path);
    Image image;
    std::string message;
    check(module.read(path, image, message), path, message);
    return image;
}

}  // namespace detail

namespace {

bool is_tiff(const std::string& path) {
    const std::string ext = file_extension(path);
    return ext == "tif" || ext == "tiff";
}

}  // namespace

void write_counts(const std::string& path, const Image& counts, int bits,
                  const WriteOptions& options) {
    if (bits != 8 && bits != 12 && bits != 16)
        throw UsageError("unsupported bit depth " + std::to_string(bits) + " (use 8, 12 or 16)");
    const double max_count = std::ldexp(1.0, bits) - 1;
    for (float v : counts.data)
        if (!(v >= 0 && v <= max_count) || v != std::floor(v))
            throw DataError({path, 0}, "count " + std::to_string(v) + " is not an integer in 0.." +
                                           std::to_string(static_cast<long>(max_count)));
    if (is_tiff(path)) return detail::write_gtiff(path, counts, bits, options);
    check_write_options(path, options);
    if (bits == 8) {
        auto pixels = interleave<std::uint8_t>(counts);
        write_oiio(path, counts, Sample::UInt8, pixels.data());
    } else {  // 12-bit counts are stored in 16-bit samples
        auto pixels = interleave<std::uint16_t>(counts);
        write_oiio(path, counts, Sample::UInt16, pixels.data());
    }
}

void write_float(const std::string& path, const Image& image, const WriteOptions& options) {
    if (is_tiff(path)) return detail::write_gtiff(path, image, 32, options);
    check_write_options(path, options);
    auto pixels = interleave<float>(image);
    write_oiio(path, image, Sample::Float, pixels.data());
}

}  // namespace sigchain::image
