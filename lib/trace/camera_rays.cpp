// Primary rays of the frame camera.
#include "geom/view_angle.hpp"
#include "trace/render.hpp"

#include <cmath>

namespace sigchain::trace {

FrameRayGenerator::FrameRayGenerator(geom::FrameCamera camera) : m_camera(std::move(camera)) {
    geom::Vec3 ref = geom::reference_direction(m_camera);
    m_reference_azimuth_deg = std::atan2(ref[0], ref[1]) * 180.0 / M_PI;
}

long FrameRayGenerator::rows() const { return m_camera.rows; }
long FrameRayGenerator::columns() const { return m_camera.columns; }

void FrameRayGenerator::ray(double row, double column, Vec3& origin, Vec3& direction) const {
    origin = m_camera.position;
    direction = m_camera.direction(row, column);
}

double FrameRayGenerator::view_angle_deg(const Vec3& direction) const {
    double a = m_reference_azimuth_deg * M_PI / 180.0;
    return geom::signed_view_angle_deg(direction, {std::sin(a), std::cos(a), 0.0});
}

}  // namespace sigchain::trace
