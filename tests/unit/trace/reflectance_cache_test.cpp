// The tracer keeps the reflectance of a view-independent material (flat fall-off,
// opaque, one reflectance) per material and .ems curve instead of evaluating it at
// every secondary hit (tracer.cpp, Tracer::reflectance_at). Checked: the premise (such
// a material's reflectance is the same, bit for bit, at every view angle, and a
// fall-off breaks it), and that the kept values are told apart by material and by
// curve: a box whose walls take two curves of one material renders bit for bit as the
// same box whose walls take two materials of those curves.
#include <gtest/gtest.h>

#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;

const std::vector<double> kWl = {0.45, 0.55, 0.65};

TEST(ReflectanceCache, FlatOpaqueReflectanceDoesNotDependOnTheViewAngle) {
    auto m = radiometry::grey_material(1, 0.3, kWl.size());
    m.emissivity[0] = {0.61, 0.7, 0.83};
    std::vector<double> at0(kWl.size()), at(kWl.size());
    m.reflectance(0, 0.0, -1, at0);
    for (double theta : {0.5, 17.3, 45.0, 71.9, 89.99, 90.0}) {
        m.reflectance(0, theta, -1, at);
        for (std::size_t k = 0; k < at.size(); ++k) EXPECT_EQ(at[k], at0[k]) << theta;
    }
    // With a fall-off the reflectance depends on theta_o: such a material is not kept.
    for (int d = 0; d <= 90; ++d) m.fall_off[d] = 1.0 - 0.5 * d / 90.0;
    m.flat_fall_off = false;
    m.reflectance(0, 60.0, -1, at);
    EXPECT_LT(at[0], at0[0]);
}

// The closed box (-1..1)^3 seen from inside, faces 0-2 and 3-5 in two groups: with
// `two_curves` material 1 with curve 0 and curve 1, else materials 1 and 2 (curve 0).
scene::Scene two_part_box(bool two_curves) {
    test::Mesh mesh;
    constexpr double e = 1.01;  // faces reach past the edges: no cracks (test_scene.hpp)
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            std::array<Vec3, 4> q;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const double corners[4][2] = {{-e, -e}, {e, -e}, {e, e}, {-e, e}};
            for (int i = 0; i < 4; ++i) {
                q[i][axis] = side;
                q[i][u] = corners[i][0];
                q[i][v] = corners[i][1];
            }
            const bool second = mesh.data.facets.size() >= 3;
            mesh.quad(q, second && !two_curves ? 2 : 1);
            if (second && two_curves) mesh.data.facets.back().texture_curve = 1;
        }
    return test::single(mesh.data);
}

image::Image render_box(const scene::Scene& s, const radiometry::MaterialLibrary& mats) {
    // The one-bounce shading of a secondary hit takes the horizontal sky irradiance
    // whatever the box hides: every wall's rho reaches the image.
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 30, 0, 0.0, 0.004, 0.9, 0.0)}, {"sky.rad"});
    test::Ortho cam(4, 4, 0.2, -0.3137, 0.2791, {0, 0, -1}, 0.5);
    RenderInputs in;
    in.scene = &s;
    in.materials = &mats;
    in.atmosphere = &atm;
    in.sensor = &cam;
    RenderOptions o;
    o.sampling = Sampling::Golfball;
    o.background = BackgroundChoice::None;
    o.threads = 1;
    return render(in, o).radiance;
}

TEST(ReflectanceCache, KeptPerMaterialAndCurve) {
    const std::vector<double> e0 = {0.9, 0.8, 0.7}, e1 = {0.4, 0.5, 0.35};
    auto curves = radiometry::grey_material(1, 0.1, kWl.size());
    curves.emissivity = {e0, e1};
    auto first = radiometry::grey_material(1, 0.1, kWl.size());
    first.emissivity = {e0};
    auto second = radiometry::grey_material(2, 0.1, kWl.size());
    second.emissivity = {e1};
    const auto one = radiometry::MaterialLibrary::from_optics({curves});
    const auto two = radiometry::MaterialLibrary::from_optics({first, second});
    const auto a = render_box(two_part_box(true), one);
    const auto b = render_box(two_part_box(false), two);
    ASSERT_EQ(a.data.size(), b.data.size());
    for (std::size_t i = 0; i < a.data.size(); ++i) ASSERT_EQ(a.data[i], b.data[i]) << i;
    // Not a trivial image: the two groups' reflectances both show.
    const auto same = render_box(two_part_box(false),
                                 radiometry::MaterialLibrary::from_optics(
                                     {first, radiometry::grey_material(2, 0.1, kWl.size())}));
    bool differs = false;
    for (std::size_t i = 0; i < a.data.size(); ++i) differs = differs || a.data[i] != same.data[i];
    EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace sigchain::trace
