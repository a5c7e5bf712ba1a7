// A sky with structure for the sky-lookup tests (sky_table_test.cpp,
// sky_irradiance_test.cpp): two spectral samples over a .rad sky map of any size; and a
// grass-like incoming fall-off for the tests of F (sky_irradiance_test.cpp,
// trace/open_sky_test.cpp, trace/fall_off_test.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/vec3.hpp"
#include "io/rad.hpp"
#include "radiometry/atmosphere.hpp"

namespace sigchain::radiometry::test {

// Sample 0: a clear sky's smooth brightening toward the horizon and toward azimuth 40
// deg. Sample 1: the same with an aureole, a bright peak 20 deg wide around the sun
// (zenith 30 deg, azimuth 150 deg): steep gradients between cells.
inline double sky_sample(int k, double zenith_deg, double azimuth_deg) {
    constexpr double kDeg = std::numbers::pi / 180;
    const double z = zenith_deg * kDeg;
    const double smooth = 0.01 * (1 + 0.8 * (1 - std::cos(z)) +
                                  0.3 * std::sin(z) * std::cos((azimuth_deg - 40) * kDeg));
    if (k == 0) return smooth;
    const geo::Vec3 d = geo::direction_from_degrees(zenith_deg, azimuth_deg);
    const double c = geo::dot(d, geo::direction_from_degrees(30, 150));
    const double angle = std::acos(std::clamp(c, -1.0, 1.0));
    return smooth + 0.05 * std::exp(-std::pow(angle / (10 * kDeg), 2));
}

// That sky over `rings` x `columns` cells, the sun at zenith 30 deg, azimuth 150 deg.
inline Atmosphere aureole_atmosphere(int rings, int columns) {
    io::Rad rad =
        uniform_rad({0.55, 0.65}, 30, 150, 0.1, 0.01, 0.9, 0.001, {-60, 0, 60}, rings, columns);
    for (auto& cell : rad.sky->cells)
        for (int k = 0; k < 2; ++k)
            cell.scattered_radiance[k] = sky_sample(k, cell.zenith_deg, cell.azimuth_deg);
    return Atmosphere::from_rads({rad}, {"aureole.rad"});
}

// F at `deg` from the normal: 1 to 45 deg, then linear to 0.2 at 80 deg and 0.1 at 90
// deg, Case 4's fivefold drop at a high oblique view (White (1996), section 5.2.3).
inline double grass_like_fall_off(double deg) {
    return deg <= 45 ? 1.0 : deg <= 80 ? 1.0 - 0.8 * (deg - 45) / 35.0 : 0.2 - 0.01 * (deg - 80);
}

}  // namespace sigchain::radiometry::test
