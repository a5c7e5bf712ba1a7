// The 3-vector of every geometric computation: positions and directions in the scene
// frame (x east, y north, z up; scene units or unit length), with dot, cross, unit
// and the direction from zenith and azimuth angles. Header only: no library needed.
#pragma once

#include <array>
#include <cmath>

#include "core/numeric.hpp"

namespace sigchain::geo {

// A std::array, so that readers, Embree wrappers and images share its layout.
using Vec3 = std::array<double, 3>;

// The largest coordinate, in scene units, that a vertex, a camera or a platform may
// have. Embree works in single precision: it asserts (aborts) on a ray origin beyond
// about 1.8e18 and drops triangles with a vertex beyond it. 1e9 m is 2.6 times the
// Moon's distance: far beyond any scene, far inside what Embree handles.
inline constexpr double kMaxCoordinate = 1e9;

// Whether every component of `p` is finite and within +-kMaxCoordinate.
inline bool within_coordinate_limit(const Vec3& p) {
    for (double c : p)
        if (!(std::abs(c) <= kMaxCoordinate)) return false;
    return true;
}

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// Euclidean length.
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// a / |a| (each component divided by the length; a must not be zero: the result is
// NaN then, as the caller's check of the length decides what a zero vector means).
inline Vec3 unit(const Vec3& a) {
    const double n = norm(a);
    return {a[0] / n, a[1] / n, a[2] / n};
}

// The unit vector toward zenith angle `zenith_rad` from +z and azimuth `azimuth_rad`
// clockwise from north (+y) toward east (+x): (sin z sin a, sin z cos a, cos z).
inline Vec3 direction_from_angles(double zenith_rad, double azimuth_rad) {
    return {std::sin(zenith_rad) * std::sin(azimuth_rad),
            std::sin(zenith_rad) * std::cos(azimuth_rad), std::cos(zenith_rad)};
}

// The same from angles in degrees (multiplied by pi/180 first).
inline Vec3 direction_from_degrees(double zenith_deg, double azimuth_deg) {
    return direction_from_angles(zenith_deg * kRadPerDeg, azimuth_deg * kRadPerDeg);
}

}  // namespace sigchain::geo
