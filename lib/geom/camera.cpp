// Frame camera geometry from an .adv look-angle file.
#include "geom/camera.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace sigchain::geom {

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(const Vec3& v) {
    double n = std::sqrt(dot(v, v));
    return {v[0] / n, v[1] / n, v[2] / n};
}

FrameCamera frame_camera(const io::Adv& adv, const std::string& adv_file) {
    constexpr double kDeg = std::numbers::pi / 180.0;
    FrameCamera cam;
    cam.position = adv.camera;
    Vec3 los{adv.target[0] - adv.camera[0], adv.target[1] - adv.camera[1],
             adv.target[2] - adv.camera[2]};
    if (dot(los, los) == 0)
        throw DataError({adv_file, 2}, "camera point equals target point: no line of sight");
    cam.forward = normalized(los);
    double a = adv.azimuth_deg * kDeg;
    Vec3 h{-std::sin(a), std::cos(a), 0.0};
    double along = dot(h, cam.forward);
    Vec3 r{h[0] - along * cam.forward[0], h[1] - along * cam.forward[1],
           h[2] - along * cam.forward[2]};
    if (std::sqrt(dot(r, r)) < 1e-6)
        throw DataError({adv_file, 3}, "camera azimuth " + std::to_string(adv.azimuth_deg) +
                                           " deg points along the line of sight; cannot orient "
                                           "the image");
    r = normalized(r);
    Vec3 up = cross(r, cam.forward);  // = -(forward x right)
    double t = adv.twist_deg * kDeg;
    cam.right = normalized({std::cos(t) * r[0] + std::sin(t) * up[0],
                            std::cos(t) * r[1] + std::sin(t) * up[1],
                            std::cos(t) * r[2] + std::sin(t) * up[2]});
    cam.down = cross(cam.forward, cam.right);
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
    return normalized({f * forward[0] + x * right[0] + y * down[0],
                       f * forward[1] + x * right[1] + y * down[1],
                       f * forward[2] + x * right[2] + y * down[2]});
}

}  // namespace sigchain::geom
