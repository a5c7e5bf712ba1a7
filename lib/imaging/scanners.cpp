// Primary rays of the pushbroom and line scanners (sensor.hpp): each image position's
// time, the platform's pose then, and the detector's look direction in the body frame.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "imaging/sensor.hpp"
#include "imaging/view_angle.hpp"

namespace sigchain::imaging {

namespace {

// The horizontal across-track direction at the middle of the image (body y, or body x
// when y is vertical): the side of positive view angles.
geo::Vec3 across_track_reference(const Trajectory& trajectory, double t0, double t1) {
    const Pose p = trajectory.pose(0.5 * (t0 + t1));
    for (const geo::Vec3& v : {p.right, p.forward}) {
        const double n = std::hypot(v[0], v[1]);
        if (n > 1e-6) return {v[0] / n, v[1] / n, 0.0};
    }
    return {1, 0, 0};
}

// The image row `row` as its line index k (0 to lines - 1) and the fraction u within it
// (0 to 1; the last line's bottom edge is u = 1).
std::pair<long, double> split_row(double row, long lines) {
    const long k = std::clamp(static_cast<long>(std::floor(row)), 0L, lines - 1);
    return {k, std::clamp(row - static_cast<double>(k), 0.0, 1.0)};
}

std::string span(double t0, double t1) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g to %.9g s", t0, t1);
    return buf;
}

}  // namespace

PushbroomSensor::PushbroomSensor(Trajectory trajectory, PushbroomGeometry g)
    : m_trajectory(std::move(trajectory)), m_g(g) {
    m_trajectory.require_covers(m_g.start_time_s, m_g.end_time_s(), "the pushbroom image");
    m_reference = across_track_reference(m_trajectory, m_g.start_time_s, m_g.end_time_s());
}

double PushbroomSensor::time_of(double row) const {
    const auto [k, u] = split_row(row, m_g.lines);
    return m_g.start_time_s + static_cast<double>(k) * m_g.line_period_s +
           u * m_g.integration_time_s;
}

void PushbroomSensor::ray(double row, double column, geo::Vec3& origin,
                          geo::Vec3& direction) const {
    const double u = split_row(row, m_g.lines).second;
    const Pose pose = m_trajectory.pose(time_of(row));
    const double x = (u - 0.5) * m_g.pitch_mm;
    const double y = (column - 0.5 * static_cast<double>(m_g.detectors)) * m_g.pitch_mm;
    origin = pose.position;
    direction = geo::unit(pose.to_scene({x, y, m_g.focal_length_mm}));
}

void PushbroomSensor::nominal_ray(double row, double column, geo::Vec3& origin,
                                  geo::Vec3& direction) const {
    const double t =
        m_g.start_time_s + (row - 0.5) * m_g.line_period_s + 0.5 * m_g.integration_time_s;
    const Pose pose = m_trajectory.pose(t);
    const double y = (column - 0.5 * static_cast<double>(m_g.detectors)) * m_g.pitch_mm;
    origin = pose.position;
    direction = geo::unit(pose.to_scene({0.0, y, m_g.focal_length_mm}));
}

double PushbroomSensor::view_angle_deg(const geo::Vec3& direction) const {
    return signed_view_angle_deg(direction, m_reference);
}

std::string PushbroomSensor::summary() const {
    return "pushbroom scanner, " + std::to_string(m_g.lines) + " lines of " +
           std::to_string(m_g.detectors) + " detectors, " +
           span(m_g.start_time_s, m_g.end_time_s());
}

LineScannerSensor::LineScannerSensor(Trajectory trajectory, LineScanGeometry g)
    : m_trajectory(std::move(trajectory)), m_g(g) {
    m_trajectory.require_covers(m_g.start_time_s, m_g.end_time_s(), "the line-scanner image");
    m_reference = across_track_reference(m_trajectory, m_g.start_time_s, m_g.end_time_s());
}

double LineScannerSensor::scan_angle_rad(double column) const {
    return m_g.half_angle_rad * (2.0 * column / static_cast<double>(m_g.samples) - 1.0);
}

double LineScannerSensor::time_of(double row, double column) const {
    const long k = split_row(row, rows()).first;
    const long scan = k / m_g.detectors;
    double f = std::clamp(column / static_cast<double>(m_g.samples), 0.0, 1.0);
    if (m_g.bidirectional && scan % 2 == 1) f = 1.0 - f;  // the mirror sweeps back
    return m_g.start_time_s + (static_cast<double>(scan) + f) * m_g.scan_period_s;
}

void LineScannerSensor::ray(double row, double column, geo::Vec3& origin,
                            geo::Vec3& direction) const {
    const auto [k, u] = split_row(row, rows());
    const long d = k % m_g.detectors;
    const double n = static_cast<double>(m_g.detectors);
    double alpha = (static_cast<double>(d) + u - 0.5 * n) * m_g.ifov_rad;
    if (m_g.scan_line_corrector) {
        const double scan = static_cast<double>(k / m_g.detectors);
        const double tf = (time_of(row, column) - m_g.start_time_s) / m_g.scan_period_s - scan;
        alpha -= (tf - 0.5) * n * m_g.ifov_rad;
    }
    const double theta = scan_angle_rad(column);
    const Pose pose = m_trajectory.pose(time_of(row, column));
    origin = pose.position;
    direction = geo::unit(pose.to_scene(
        {std::sin(alpha), std::cos(alpha) * std::sin(theta), std::cos(alpha) * std::cos(theta)}));
}

double LineScannerSensor::view_angle_deg(const geo::Vec3& direction) const {
    return signed_view_angle_deg(direction, m_reference);
}

std::string LineScannerSensor::summary() const {
    return "line scanner, " + std::to_string(m_g.scans) + " scans of " +
           std::to_string(m_g.detectors) + " detector(s) (" + std::to_string(rows()) +
           " lines) of " + std::to_string(m_g.samples) + " samples, " +
           (m_g.bidirectional ? "bidirectional, " : "one-way, ") +
           (m_g.scan_line_corrector ? "scan-line corrector, " : "") +
           span(m_g.start_time_s, m_g.end_time_s());
}

}  // namespace sigchain::imaging
