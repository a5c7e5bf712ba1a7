// Reading TIFF, PNG, JPEG and Netpbm, and writing PNG and Netpbm counts, through
// OpenImageIO (TIFF is written through GDAL: gdal_write.cpp).
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "core/error.hpp"
#include "core/output.hpp"
#include "image/image.hpp"
#include "image/internal.hpp"

namespace sigchain::image {
namespace {

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Interleaved native samples (as read or to be written) <-> planar floats.
template <typename T>
void deinterleave(const std::vector<T>& in, Image& image) {
    const std::size_t plane = image.plane_size();
    for (std::size_t p = 0; p < plane; ++p)
        for (int c = 0; c < image.channels; ++c)
            image.data[c * plane + p] = static_cast<float>(in[p * image.channels + c]);
}

template <typename T>
std::vector<T> interleave(const Image& image) {
    const std::size_t plane = image.plane_size();
    std::vector<T> out(plane * image.channels);
    for (std::size_t p = 0; p < plane; ++p)
        for (int c = 0; c < image.channels; ++c)
            out[p * image.channels + c] = static_cast<T>(image.data[c * plane + p]);
    return out;
}

template <typename T>
// Errors in this file name the image only: binary rasters have no lines.
void read_as(ImageInput& in, TypeDesc type, const std::string& path, Image& image) {
    std::vector<T> buffer(image.plane_size() * image.channels);
    if (!in.read_image(0, 0, 0, image.channels, type, buffer.data()))
        throw DataError({path, 0}, "cannot read pixels: " + in.geterror());
    deinterleave(buffer, image);
}

// Writes `pixels` (interleaved, of `type`) into a private temporary folder with the
// plugin chosen by the final name's extension, then renames into place.
void write_oiio(const std::string& path, const Image& image, TypeDesc type, const void* pixels) {
    auto out = ImageOutput::create(path);
    if (!out) throw IoError(path + ": cannot write this image format: " + OIIO::geterror());
    ImageSpec spec(static_cast<int>(image.columns), static_cast<int>(image.rows), image.channels,
                   type);
    for (int c = 0; c < image.channels && c < static_cast<int>(image.channel_names.size()); ++c)
        spec.channelnames[c] = image.channel_names[c];
    // Counts in an alpha position (2- and 4-channel PNG) are data: never premultiplied.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (image.channels > 4 && file_extension(path) == "png")
        throw DataError({path, 0}, "PNG holds at most 4 channels; use a TIFF for " +
                                       std::to_string(image.channels) + " bands");
    const std::string ext = file_extension(path);
    if (ext == "pgm" || ext == "ppm" || ext == "pnm") {
        if (image.channels != 1 && image.channels != 3)
            throw DataError({path, 0},
                            "PGM/PPM hold 1 or 3 channels, not " + std::to_string(image.channels));
        if (type != TypeDesc::UINT8)  // OpenImageIO 2.4 garbles 16-bit plain PNM
            throw DataError({path, 0}, "PGM/PPM output holds 8-bit counts only");
        spec.attribute("pnm:binary", 0);  // plain (text) Netpbm: readable and diffable
    }
    // OpenImageIO opens its file itself: it goes into a private folder beside the target.
    const TempDir folder(path);
    const std::string temp = folder.file(std::filesystem::path(path).filename().string());
    bool ok = out->open(temp, spec) && out->write_image(type, pixels) && out->close();
    if (!ok) throw IoError(path + ": cannot write: " + out->geterror());
    commit_moves({{temp, path}});
}

}  // namespace

namespace detail {

Image read_oiio(const std::string& path) {
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // alpha-position channels are data
    auto in = ImageInput::open(path, &config);
    if (!in) throw DataError({path, 0}, "not a readable image: " + OIIO::geterror());
    const ImageSpec& spec = in->spec();
    Image image(spec.height, spec.width, spec.nchannels);
    // Integer samples keep their count values (OpenImageIO would normalise them to 0..1).
    if (spec.format == TypeDesc::UINT8)
        read_as<std::uint8_t>(*in, TypeDesc::UINT8, path, image);
    else if (spec.format == TypeDesc::UINT16)
        read_as<std::uint16_t>(*in, TypeDesc::UINT16, path, image);
    else
        read_as<float>(*in, TypeDesc::FLOAT, path, image);
    for (int c = 0; c < spec.nchannels; ++c) image.channel_names.push_back(spec.channel_name(c));
    in->close();
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
        write_oiio(path, counts, TypeDesc::UINT8, pixels.data());
    } else {  // 12-bit counts are stored in 16-bit samples
        auto pixels = interleave<std::uint16_t>(counts);
        write_oiio(path, counts, TypeDesc::UINT16, pixels.data());
    }
}

void write_float(const std::string& path, const Image& image, const WriteOptions& options) {
    if (is_tiff(path)) return detail::write_gtiff(path, image, 32, options);
    check_write_options(path, options);
    auto pixels = interleave<float>(image);
    write_oiio(path, image, TypeDesc::FLOAT, pixels.data());
}

}  // namespace sigchain::image
