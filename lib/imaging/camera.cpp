// Frame camera geometry from an .adv look-angle file.
#include "imaging/camera.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/numeric.hpp"

namespace sigchain::imaging {

FrameCamera frame_camera(const io::Adv& adv, const std::string& adv_file) {
    FrameCamera cam;
    cam.position = adv.camera;
    Vec3 los{adv.target[0] - adv.camera[0], adv.target[1] - adv.camera[1],
             adv.target[2] - adv.camera[2]};
    if (geo::dot(los, los) == 0)
        throw DataError({adv_file, adv.lines.camera}, "camera point equals target point: no line of sight");
    cam.forward = geo::unit(los);
    double a = adv.azimuth_deg * kRadPerDeg;
    Vec3 h{-std::sin(a), std::cos(a), 0.0};
    double along = geo::dot(h, cam.forward);
    Vec3 r{h[0] - along * cam.forward[0], h[1] - along * cam.forward[1],
           h[2] - along * cam.forward[2]};
    if (geo::norm(r) < 1e-6)
        throw DataError({adv_file, adv.lines.angles}, "camera azimuth " + std::to_string(adv.azimuth_deg) +
                                           " deg points along the line of sight; cannot orient "
                                           "the image");
    r = geo::unit(r);
    Vec3 up = geo::cross(r, cam.forward);  // = -(forward x right)
    double t = adv.twist_deg * kRadPerDeg;
    cam.right = geo::unit({std::cos(t) * r[0] + std::sin(t) * up[0],
                           std::cos(t) * r[1] + std::sin(t) * up[1],
                           std::cos(t) * r[2] + std::sin(t) * up[2]});
    cam.down = geo::cross(cam.forward, cam.right);
    cam.focal_length_mm = adv.focal_length_mm;
    cam.pixel_pitch_mm = adv.pixel_pitch_um * 1e-3;
    cam.rows = adv.rows;
    cam.columns = adv.columns;
    return cam;
}

Vec3 FrameCamera::direction(double row, double column) const {
    double x = (column - 0.5 * static_cast<double>(columns)) * pixel_pitch_mm;
    double y = (row - 0.5 * static_cast<double>(rows)) * pixel_pitch_mm;
    double f = focal_length_mm;
    return geo::unit({f * forward[0] + x * right[0] + y * down[0],
                      f * forward[1] + x * right[1] + y * down[1],
                      f * forward[2] + x * right[2] + y * down[2]});
}

}  // namespace sigchain::imaging
