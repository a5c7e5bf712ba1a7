// View-angle range by the scene-bounding-box and field-of-view methods (White (1996),
// section 4.2.3.3), for any Sensor.
#include "imaging/view_angle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "imaging/sensor.hpp"

namespace sigchain::imaging {

void AngleAccumulator::add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    ++n;
}

AngleRange AngleAccumulator::range() const { return {lo, hi, suggested_increment_deg(lo, hi), n}; }

double world_view_angle_deg(double view_angle_deg) {
    const double a = std::abs(view_angle_deg);
    const double folded = std::min(a > 90 ? 180 - a : a, kWorldMaxViewAngleDeg);
    return view_angle_deg < 0 ? -folded : folded;
}

Vec3 reference_direction(const FrameCamera& cam) {
    Vec3 h{cam.forward[0], cam.forward[1], 0.0};
    double n = std::hypot(h[0], h[1]);
    if (n > std::sin(0.01 / kDegPerRad)) return {h[0] / n, h[1] / n, 0.0};
    Vec3 up{-cam.down[0], -cam.down[1], 0.0};
    return geo::unit(up);
}

double signed_view_angle_deg(const Vec3& d, const Vec3& ref) {
    Vec3 u = geo::unit(d);
    double off_nadir = std::acos(std::clamp(-u[2], -1.0, 1.0)) * kDegPerRad;
    double along = u[0] * ref[0] + u[1] * ref[1];
    return along < 0 ? -off_nadir : off_nadir;
}

double suggested_increment_deg(double min_deg, double max_deg, int min_steps) {
    double span = std::max(0.0, max_deg - min_deg) / std::max(1, min_steps);
    if (span >= 1.0) return 1.0;
    if (span <= 0.01) return 0.01;
    double p = std::pow(10.0, std::floor(std::log10(span)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * p <= span) return m * p;
    return p;
}

namespace {

// The bounding-box method: the angles of the scene box's corners `b` seen from each of
// `origins`.
AngleRange box_range(const Sensor& sensor, const scene::Bounds& b,
                     const std::vector<geo::Vec3>& origins) {
    AngleAccumulator box;
    for (const geo::Vec3& o : origins)
        for (int i = 0; i < 8; ++i) {
            const geo::Vec3 corner{(i & 1) ? b.upper[0] : b.lower[0],
                                   (i & 2) ? b.upper[1] : b.lower[1],
                                   (i & 4) ? b.upper[2] : b.lower[2]};
            const geo::Vec3 d{corner[0] - o[0], corner[1] - o[1], corner[2] - o[2]};
            if (geo::dot(d, d) > 0) box.add(sensor.view_angle_deg(d));
        }
    return box.range();
}

}  // namespace

ViewAngleReport find_view_angles(const Sensor& sensor, const scene::Scene& scene, int grid) {
    const scene::Bounds b = scene.bounds();
    if (b.empty()) throw DataError({}, "the scene has no facets");
    ViewAngleReport rep;
    const geo::Vec3 ref = sensor.view_angle_reference();
    rep.reference_azimuth_deg =
        std::fmod(std::atan2(ref[0], ref[1]) * 180.0 / std::numbers::pi + 360.0, 360.0);

    AngleAccumulator fov, border;
    std::vector<geo::Vec3> origins;  // of the border rays, for the bounding box
    std::size_t hits = 0;
    auto cast = [&](double row, double col, bool on_border) {
        geo::Vec3 o{}, d{};
        sensor.ray(row, col, o, d);
        const double angle = sensor.view_angle_deg(d);
        if (on_border) {
            border.add(angle);
            origins.push_back(o);
        }
        ++rep.rays_cast;
        if (scene.intersect(o, d)) {
            fov.add(angle);
            ++hits;
        } else
            fov.add(world_view_angle_deg(angle));
    };
    const long rows = sensor.rows(), columns = sensor.columns();
    const double R = static_cast<double>(rows), C = static_cast<double>(columns);
    for (double r : {0.0, R})
        for (double c : {0.0, C}) cast(r, c, true);  // the image's outer corners
    for (long c = 0; c < columns; ++c) {
        cast(0.5, c + 0.5, true);
        cast(R - 0.5, c + 0.5, true);
    }
    for (long r = 0; r < rows; ++r) {
        cast(r + 0.5, 0.5, true);
        cast(r + 0.5, C - 0.5, true);
    }
    const int gr = static_cast<int>(std::min<long>(grid, rows));
    const int gc = static_cast<int>(std::min<long>(grid, columns));
    for (int i = 0; i < gr; ++i)
        for (int j = 0; j < gc; ++j) cast((i + 0.5) * R / gr, (j + 0.5) * C / gc, false);
    rep.unclipped_field_of_view = border.range();
    if (hits > 0) rep.field_of_view = fov.range();
    // A frame camera sees the box from its one position; a moving platform from each
    // of its positions over the image.
    if (const auto viewpoint = sensor.viewpoint()) origins.assign(1, *viewpoint);
    rep.bounding_box = box_range(sensor, b, origins);
    return rep;
}

}  // namespace sigchain::imaging
