// Frame camera from an .adv: pinhole geometry and primary-ray directions.
//
// Frames: scene frame x east, y north, z up (scene units). Sensor frame: `right`
// (increasing column), `down` (increasing row) and `forward` (line of sight), with
// right x down = forward. Conventions are those of adv(5).
#pragma once

#include "geo/vec3.hpp"
#include "io/adv.hpp"

namespace sigchain::imaging {

using geo::Vec3;

struct FrameCamera {
    Vec3 position{};  // pinhole, scene units
    Vec3 forward{};   // unit, camera point -> target point
    Vec3 right{};     // unit, image column direction
    Vec3 down{};      // unit, image row direction
    double focal_length_mm = 0;
    double pixel_pitch_mm = 0;
    long rows = 0;
    long columns = 0;

    // Unit direction of the ray through image-plane position (row, column) in pixel
    // units, where (0, 0) is the top-left corner of the top-left pixel and pixel
    // centres are at +0.5 (so (rows/2, columns/2) is the optical axis).
    Vec3 direction(double row, double column) const;
};

// Builds the camera: forward from the two points; right from the azimuth (the
// horizontal vector (-sin a, cos a, 0) made perpendicular to forward), turned by the
// twist t about forward toward the image's up direction (right' = cos t right +
// sin t up, up = -down); down = forward x right. Throws DataError (at the .adv's
// angles line) if the azimuth's vector is parallel to the line of sight.
FrameCamera frame_camera(const io::Adv& adv, const std::string& adv_file = "");

}  // namespace sigchain::imaging
