// The interface between lib/image and its OpenImageIO back end. The back end is a
// shared module (sigchain_oiio, built from oiio_module.cpp, installed in
// LIBDIR/sigchain/) that lib/image opens with dlopen on the first image it reads or
// writes through OpenImageIO (oiio_io.cpp), so that a process that reads or writes no
// PNG, JPEG, Netpbm or OpenImageIO TIFF does not load OpenImageIO's ~260 shared
// libraries (0.25 s of start-up per process on Debian 12).
//
// Both sides are built together by the same compiler, so C++ types cross the boundary;
// errors cross as a Status and a message, never as exceptions of sigchain's types (the
// module links no sigchain library: it is linked with --no-undefined).
#pragma once

#include <cstdint>
#include <string>

#include "image/image.hpp"

namespace sigchain::image::oiio {

// Raise when Api or the types it passes change: the loader refuses a module built with
// another version or another sizeof(Api).
inline constexpr std::uint32_t kApiVersion = 1;

// The sample type of interleaved pixels handed to write.
enum class Sample : int { UInt8, UInt16, Float };
// Ok, or which error lib/image throws (DataError names the image, IoError is
// "PATH: message").
enum class Status : int { Ok, DataError, IoError };

struct Api {
    std::uint32_t size;     // sizeof(Api) in the module
    std::uint32_t version;  // kApiVersion in the module
    // Reads `path` into `image` (rows, columns, channels, planar data, channel names;
    // integer samples keep their count values, channels in alpha position are data).
    Status (*read)(const std::string& path, Image& image, std::string& message);
    // Ok when OpenImageIO has a writer for `path`'s extension.
    Status (*can_write)(const std::string& path, std::string& message);
    // Writes interleaved `pixels` of `sample` type and `image`'s size and channel names
    // into `temp` with the writer of `path`'s extension; `plain_netpbm` asks for
    // plain-text PGM/PPM.
    Status (*write)(const std::string& path, const std::string& temp, const Image& image,
                    Sample sample, const void* pixels, bool plain_netpbm,
                    std::string& message);
};

}  // namespace sigchain::image::oiio

// The module's one entry point (looked up with dlsym by this name).
extern "C" const sigchain::image::oiio::Api* sigchain_oiio_api();
