// Primary rays of the frame camera (sensor.hpp).
#include <cmath>
#include <utility>

#include "imaging/sensor.hpp"
#include "imaging/view_angle.hpp"

namespace sigchain::imaging {

FrameSensor::FrameSensor(FrameCamera camera) : m_camera(std::move(camera)) {
    geo::Vec3 ref = reference_direction(m_camera);
    m_reference_azimuth_deg = std::atan2(ref[0], ref[1]) * 180.0 / M_PI;
}

long FrameSensor::rows() const { return m_camera.rows; }
long FrameSensor::columns() const { return m_camera.columns; }

void FrameSensor::ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const {
    origin = m_camera.position;
    direction = m_camera.direction(row, column);
}

double FrameSensor::view_angle_deg(const geo::Vec3& direction) const {
    return signed_view_angle_deg(direction, view_angle_reference());
}

geo::Vec3 FrameSensor::view_angle_reference() const {
    double a = m_reference_azimuth_deg * M_PI / 180.0;
    return {std::sin(a), std::cos(a), 0.0};
}

std::string FrameSensor::summary() const {
    return "frame camera, " + std::to_string(m_camera.rows) + " x " +
           std::to_string(m_camera.columns) + " pixels from one position";
}

}  // namespace sigchain::imaging
