// White (1996), section 5.1.2's sensitivity setup rendered under the section 4.2.3
// atmosphere: the Hawkeye deck's tables (tests/data/chapter5: build_radiance on
// tests/golden/control7/hawkeye.cdk for a sensor at 1 km, the sun at 53.2 deg zenith,
// 218.3 deg azimuth), White's target material, the scenes and sensors of his cases 1-4
// (DIRSIG) and 1a-4a (the proposed model, section 5.2.4), and the parts of a render the
// error budgets read. Shared by white_budget_test.cpp and uncertainty_budget_test.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/rad.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace::white {

using geo::Vec3;
using radiometry::MaterialLibrary;
using radiometry::MaterialOptics;

inline constexpr double kPi = 3.14159265358979323846;
inline double rad(double deg) { return deg * kPi / 180; }

inline const std::vector<std::string> kBands{"blue", "green", "red"};

// The three bands' tables, named blue, green and red.
inline std::vector<io::Rad> hawkeye_rads() {
    std::vector<io::Rad> r;
    for (int b = 1; b <= 3; ++b)
        r.push_back(io::read_rad_file(SIGCHAIN_TEST_DATA "/chapter5/hawkeye_1km-" +
                                      std::to_string(b) + ".rad"));
    return r;
}
inline radiometry::Atmosphere hawkeye(const std::vector<io::Rad>& rads) {
    return radiometry::Atmosphere::from_rads(rads, {"blue.rad", "green.rad", "red.rad"});
}

// White's target (section 5.1.2, case 4 of section 5.1.3): diffuse reflectivity r_d,
// a specular lobe of reflectivity r_s (its "peak") covering a fraction s of the
// hemisphere, specularity s. As DIRSIG's big equation has it, r_s is the specular part's
// own reflectance (mat(5) SPECULAR_CURVE: curve 1), the parts weighted 1 - s and s. The
// lobe: a mirror (delta) for DIRSIG (its "delta function" model, section 5.2.2), or for
// the proposed model a uniform cone over the fraction s of the hemisphere by solid
// angle (half angle acos(1 - s): 25.8 deg for 0.1, 41.4 deg for 0.25). Material 1.
inline MaterialOptics target(double r_d, double r_s, double s, bool mirror, std::size_t samples) {
    radiometry::Brdf lobe =
        mirror ? radiometry::Brdf::delta() : radiometry::Brdf::cone(std::acos(1 - s) * 180 / kPi);
    MaterialOptics m = radiometry::grey_material(1, r_d, samples, s, std::move(lobe));
    m.name = "target";
    m.emissivity.push_back(std::vector<double>(samples, 1 - r_s));
    m.specular_curve = 1;
    return m;
}
// The tall object of case 2: "a gray 10% diffuse reflector". Material 2.
inline MaterialOptics wall_material(std::size_t samples) {
    MaterialOptics m = radiometry::grey_material(2, 0.1, samples);
    m.name = "wall";
    return m;
}

struct Material {
    double r_d, r_s, s;
};
inline constexpr Material kCase1Material{0.15, 0.2, 0.1};  // cases 1-3
inline constexpr Material kCase4Material{0.1, 0.4, 0.25};  // case 4

// Parallel rays along `dir` through the ground points origin + r v + c u (r, c pixel
// coordinates): an orthographic sensor with any axes. View angle from the nadir.
class Parallel final : public Sensor {
public:
    Parallel(long rows, long cols, Vec3 origin, Vec3 u, Vec3 v, Vec3 dir, double distance)
        : m_rows(rows),
          m_cols(cols),
          m_o(origin),
          m_u(u),
          m_v(v),
          m_d(geo::unit(dir)),
          m_distance(distance) {}
    long rows() const override { return m_rows; }
    long columns() const override { return m_cols; }
    void ray(double row, double col, Vec3& o, Vec3& d) const override {
        const Vec3 g = geo::add(m_o, geo::add(geo::scale(m_u, col), geo::scale(m_v, row)));
        o = geo::add(g, geo::scale(m_d, -m_distance));
        d = m_d;
    }
    double view_angle_deg(const Vec3& d) const override {
        return std::acos(std::clamp(-d[2], -1.0, 1.0)) * 180 / kPi;
    }

private:
    long m_rows, m_cols;
    Vec3 m_o, m_u, m_v, m_d;
    double m_distance;
};

// White's sensor (section 5.1.2): nadir, 1 km above the ground, a field of view of 20
// deg (-10 to 10 deg) on both axes; rows x cols pixels.
class Frame final : public Sensor {
public:
    Frame(long rows, long cols) : m_rows(rows), m_cols(cols) {}
    long rows() const override { return m_rows; }
    long columns() const override { return m_cols; }
    void ray(double row, double col, Vec3& o, Vec3& d) const override {
        const double t = std::tan(rad(10));
        const double x = t * (2 * col / static_cast<double>(m_cols) - 1);
        const double y = t * (1 - 2 * row / static_cast<double>(m_rows));
        o = {0, 0, 1000};
        d = geo::unit(Vec3{x, y, -1});
    }
    double view_angle_deg(const Vec3& d) const override {
        return std::acos(std::clamp(-d[2], -1.0, 1.0)) * 180 / kPi;
    }

private:
    long m_rows, m_cols;
};

// Horizontal unit vector toward the sun's azimuth (ENU).
inline Vec3 toward_sun_azimuth(const radiometry::Atmosphere& atm) {
    const double az = rad(atm.sun_azimuth_deg());
    return {std::sin(az), std::cos(az), 0};
}

// The ground: a 4 km square plate of material 1, and for case 2 a wall of material 2,
// 1000 m high and 4 km long, through the origin, facing away from the sun: the target on
// its shaded side within centimetres of its foot sees half the sky and not the sun
// ("causes only half the sky to be visible to the target (and not the sun)").
inline scene::Scene plate(const radiometry::Atmosphere& atm, bool with_wall) {
    test::Mesh m;
    m.quad({{{-2000, -2000, 0}, {2000, -2000, 0}, {2000, 2000, 0}, {-2000, 2000, 0}}}, 1);
    if (with_wall) {
        const Vec3 h = toward_sun_azimuth(atm);
        const Vec3 along{h[1], -h[0], 0};  // horizontal, along the wall
        const Vec3 a = geo::scale(along, -2000), b = geo::scale(along, 2000);
        m.quad({{{b[0], b[1], 0}, {a[0], a[1], 0}, {a[0], a[1], 1000}, {b[0], b[1], 1000}}}, 2);
    }
    return test::single(m.data);
}

// The sensors of the cases: case 1 White's frame camera; case 2 parallel nadir rays on
// an 8 x 8 grid 1-5 cm from the wall's foot (on its shaded side), 1 m along it; cases 3-4
// parallel rays whose mirror direction is the sun ("the specular bounce from the sensor
// strikes the sun"), on a 20 m grid about the origin.
enum class View { Frame, Shadow, Specular };
inline std::unique_ptr<Sensor> sensor(View v, const radiometry::Atmosphere& atm) {
    const Vec3 h = toward_sun_azimuth(atm);
    const Vec3 along{h[1], -h[0], 0};
    if (v == View::Frame) return std::make_unique<Frame>(8, 8);
    if (v == View::Shadow) {
        const Vec3 away = geo::scale(h, -1);
        return std::make_unique<Parallel>(
            8, 8, geo::add(geo::scale(away, 0.01), geo::scale(along, -0.5)),
            geo::scale(along, 1.0 / 8), geo::scale(away, 0.04 / 8), Vec3{0, 0, -1}, 1500);
    }
    const Vec3 sun = atm.sun_direction();
    return std::make_unique<Parallel>(8, 8, geo::add(geo::scale(along, -10), geo::scale(h, -10)),
                                      geo::scale(along, 20.0 / 8), geo::scale(h, 20.0 / 8),
                                      Vec3{sun[0], sun[1], -sun[2]}, 1500);
}

// The options of every budget render: one primary ray per pixel, one bounce, no world
// below the horizon and no ground-sky coupling (White's big equation has neither), the
// truth layers (the parts of the radiance at the sensor).
inline RenderOptions options(Sampling sampling) {
    RenderOptions o;
    o.sampling = sampling;
    o.samples_per_pixel = 1;
    o.hemisphere_samples = 256;  // dirsig's diffuse pattern
    o.bounces = 1;
    o.background = BackgroundChoice::None;
    o.adjacency = false;
    o.truth = true;
    o.threads = 2;
    return o;
}

inline int layer(const RenderResult& r, const std::string& name) {
    const auto& n = r.truth.channel_names;
    const auto it = std::find(n.begin(), n.end(), name);
    if (it == n.end()) throw std::out_of_range("no truth layer " + name);
    return static_cast<int>(it - n.begin());
}

// A pixel's parts at a band centre, at the sensor: the reflected sun S and sky Dn,
// L_us U, tau2 T, the reflectance a uniform sky sees rho, and the radiance L.
struct Parts {
    double s = 0, dn = 0, u = 0, t = 0, rho = 0, l = 0;
};
inline std::vector<Parts> parts(const RenderResult& r, const radiometry::SpectralGrid& grid,
                                std::size_t band) {
    const std::string& b = grid.band_names[band];
    const int ls = layer(r, "solar_" + b), ld = layer(r, "downwelled_" + b),
              lu = layer(r, "upwelled_" + b), lt = layer(r, "transmission_" + b),
              lr = layer(r, "reflectance_" + b), hit = layer(r, "hit");
    const int k = static_cast<int>(grid.band_centre_sample(static_cast<int>(band)));
    std::vector<Parts> out;
    for (long row = 0; row < r.truth.rows; ++row)
        for (long col = 0; col < r.truth.columns; ++col) {
            if (r.truth.at(hit, row, col) != 1) continue;
            out.push_back({r.truth.at(ls, row, col), r.truth.at(ld, row, col),
                           r.truth.at(lu, row, col), r.truth.at(lt, row, col),
                           r.truth.at(lr, row, col), r.radiance.at(k, row, col)});
        }
    return out;
}

}  // namespace sigchain::trace::white
