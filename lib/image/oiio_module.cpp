// The OpenImageIO back end of lib/image, built as the shared module sigchain_oiio and
// loaded on first use (oiio_module.hpp says why). Reading TIFF, PNG, JPEG and Netpbm,
// writing PNG and Netpbm; lib/image does the checks, the temporary folder and the
// rename (oiio_io.cpp). Links OpenImageIO and no sigchain library.
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <vector>

#include "image/oiio_module.hpp"

namespace sigchain::image::oiio {
namespace {

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Interleaved native samples as read -> `image`'s planar floats.
template <typename T>
void deinterleave(const std::vector<T>& in, Image& image) {
    const std::size_t plane = image.plane_size();
    for (std::size_t p = 0; p < plane; ++p)
        for (int c = 0; c < image.channels; ++c)
            image.data[c * plane + p] = static_cast<float>(in[p * image.channels + c]);
}

template <typename T>
bool read_as(ImageInput& in, TypeDesc type, Image& image, std::string& message) {
    std::vector<T> buffer(image.plane_size() * image.channels);
    if (!in.read_image(0, 0, 0, image.channels, type, buffer.data())) {
        message = "cannot read pixels: " + in.geterror();
        return false;
    }
    deinterleave(buffer, image);
    return true;
}

Status read(const std::string& path, Image& image, std::string& message) {
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // alpha-position channels are data
    auto in = ImageInput::open(path, &config);
    if (!in) {
        message = "not a readable image: " + OIIO::geterror();
        return Status::DataError;
    }
    const ImageSpec& spec = in->spec();
    image.rows = spec.height;
    image.columns = spec.width;
    image.channels = spec.nchannels;
    image.data.assign(image.plane_size() * image.channels, 0.0f);
    // Integer samples keep their count values (OpenImageIO would normalise them to 0..1).
    bool ok;
    if (spec.format == TypeDesc::UINT8)
        ok = read_as<std::uint8_t>(*in, TypeDesc::UINT8, image, message);
    else if (spec.format == TypeDesc::UINT16)
        ok = read_as<std::uint16_t>(*in, TypeDesc::UINT16, image, message);
    else
        ok = read_as<float>(*in, TypeDesc::FLOAT, image, message);
    if (!ok) return Status::DataError;
    for (int c = 0; c < spec.nchannels; ++c) image.channel_names.push_back(spec.channel_name(c));
    in->close();
    return Status::Ok;
}

Status can_write(const std::string& path, std::string& message) {
    if (ImageOutput::create(path)) return Status::Ok;
    message = "cannot write this image format: " + OIIO::geterror();
    return Status::IoError;
}

TypeDesc type_of(Sample sample) {
    switch (sample) {
    case Sample::UInt8: return TypeDesc::UINT8;
    case Sample::UInt16: return TypeDesc::UINT16;
    case Sample::Float: break;
    }
    return TypeDesc::FLOAT;
}

Status write(const std::string& path, const std::string& temp, const Image& image,
             Sample sample, const void* pixels, bool plain_netpbm, std::string& message) {
    auto out = ImageOutput::create(path);
    if (!out) return can_write(path, message);
    const TypeDesc type = type_of(sample);
    ImageSpec spec(static_cast<int>(image.columns), static_cast<int>(image.rows), image.channels,
                   type);
    for (int c = 0; c < image.channels && c < static_cast<int>(image.channel_names.size()); ++c)
        spec.channelnames[c] = image.channel_names[c];
    // Counts in an alpha position (2- and 4-channel PNG) are data: never premultiplied.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (plain_netpbm) spec.attribute("pnm:binary", 0);  // readable and diffable
    if (out->open(temp, spec) && out->write_image(type, pixels) && out->close())
        return Status::Ok;
    message = "cannot write: " + out->geterror();
    return Status::IoError;
}

constexpr Api kApi{sizeof(Api), kApiVersion, read, can_write, write};

}  // namespace
}  // namespace sigchain::image::oiio

extern "C" __attribute__((visibility("default"))) const sigchain::image::oiio::Api*
sigchain_oiio_api() {
    return &sigchain::image::oiio::kApi;
}
