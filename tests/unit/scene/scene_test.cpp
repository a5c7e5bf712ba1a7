// Tests for the Embree scene: instance normals against the analytic normal of the
// transformed facet, 1000 instances against the same copies flattened by hand,
// occlusion against nearest-hit queries, bounds.
#include "core/numeric.hpp"
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <tuple>

#include "scene/mesh_build.hpp"

using namespace sigchain;
using scene::Affine;
using scene::MeshData;
using sigchain::geo::Vec3;

namespace {

using sigchain::kRadPerDeg;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& v) {
    double n = std::hypot(v[0], v[1], v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
}

Vec3 apply(const Affine& t, const Vec3& p) {
    Vec3 q;
    for (int r = 0; r < 3; ++r)
        q[r] = t[4 * r] * p[0] + t[4 * r + 1] * p[1] + t[4 * r + 2] * p[2] + t[4 * r + 3];
    return q;
}

// T Rz Rx S as a 3x4 affine (odb(5) order, no y rotation).
Affine make_affine(Vec3 scale, double rx_deg, double rz_deg, Vec3 translation) {
    double cx = std::cos(rx_deg * kRadPerDeg), sx = std::sin(rx_deg * kRadPerDeg);
    double cz = std::cos(rz_deg * kRadPerDeg), sz = std::sin(rz_deg * kRadPerDeg);
    // Rz * Rx
    double r[3][3] = {{cz, -sz * cx, sz * sx}, {sz, cz * cx, -cz * sx}, {0, sx, cx}};
    Affine a;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) a[4 * i + j] = r[i][j] * scale[j];
        a[4 * i + 3] = translation[i];
    }
    return a;
}

// A closed box 0..1 x 0..1 x 0..2 with outward-wound quads: six facets.
MeshData box_mesh() {
    scene::MeshBuilder b(scene::DegeneratePolicy::Error, nullptr);
    std::uint32_t v[8];
    for (int i = 0; i < 8; ++i)
        v[i] = b.add_vertex({double(i & 1), double((i >> 1) & 1), 2.0 * (i >> 2)});
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; ++f) {
        scene::FacetAttributes a;
        a.material_id = 10 + f;
        scene::FacetOrigin o{"box", f + 1, "face " + std::to_string(f + 1),
                             "1-1-" + std::to_string(f + 1)};
        b.add_facet({v[faces[f][0]], v[faces[f][1]], v[faces[f][2]], v[faces[f][3]]}, a, o);
    }
    return b.take();
}

// The i-th of 1000 placements: a 40 x 25 grid, each turned, tilted and scaled differently.
Affine tree_placement(int i) {
    double x = 3.0 * (i % 40), y = 3.0 * (i / 40);
    return make_affine({0.5 + 0.001 * i, 0.8 - 0.0003 * i, 1.0 + 0.0007 * i}, 0.011 * i, 0.37 * i,
                       {x, y, 0.01 * (i % 7)});
}

}  // namespace

TEST(SceneNormals, InstanceRotatedAndScaledNonUniformlyHasTheAnalyticNormal) {
    MeshData tri;
    tri.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    tri.triangles = {0, 1, 2};
    tri.triangle_facet = {0};
    tri.facets = {scene::FacetAttributes{5, -1, -1, 0}};
    tri.origins = {scene::FacetOrigin{"t", 1, "tri", "1-1-1"}};
    scene::Scene s;
    std::size_t m = s.add_mesh(tri);
    Affine t = make_affine({2, 3, 0.5}, 30, 40, {5, 6, 7});
    s.place(m, t, "1.1/");
    s.commit();
    // Independent reference: the normal of the transformed vertices, by their winding.
    Vec3 a = apply(t, {0, 0, 0}), b = apply(t, {1, 0, 0}), c = apply(t, {0, 1, 0});
    Vec3 n = unit(cross(sub(b, a), sub(c, a)));
    Vec3 centroid{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    Vec3 from{centroid[0] + 4 * n[0], centroid[1] + 4 * n[1], centroid[2] + 4 * n[2]};
    auto hit = s.intersect(from, {-n[0], -n[1], -n[2]});
    ASSERT_TRUE(hit);
    // Float vertices, float instance transform: a few float ulps of the coordinates
    // (|x| < 12) in the distance; the normal comes from exact object-space edges and a
    // double normal matrix, so only float rounding of Ng (1e-7) remains.
    EXPECT_NEAR(hit->distance, 4.0, 1e-5);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(hit->normal[k], n[k], 1e-6) << k;
    EXPECT_EQ(s.facet_key(*hit), "1.1/1-1-1");
    EXPECT_EQ(s.attributes(*hit).material_id, 5);
}

TEST(SceneInstancing, ThousandInstancesMatchThousandFlattenedCopies) {
    MeshData box = box_mesh();
    const int kCopies = 1000;
    const std::size_t nf = box.facets.size();
    // The flattened copies: vertices transformed here (double, then float).
    MeshData flat;
    for (int i = 0; i < kCopies; ++i) {
        Affine t = tree_placement(i);
        auto base = static_cast<std::uint32_t>(flat.vertices.size() / 3);
        for (std::size_t v = 0; v + 2 < box.vertices.size(); v += 3) {
            Vec3 p = apply(t, {box.vertices[v], box.vertices[v + 1], box.vertices[v + 2]});
            for (double c : p) flat.vertices.push_back(static_cast<float>(c));
        }
        for (std::uint32_t k : box.triangles) flat.triangles.push_back(base + k);
        for (std::uint32_t f : box.triangle_facet)
            flat.triangle_facet.push_back(static_cast<std::uint32_t>(i * nf + f));
        flat.facets.insert(flat.facets.end(), box.facets.begin(), box.facets.end());
        flat.origins.insert(flat.origins.end(), box.origins.begin(), box.origins.end());
    }
    scene::Scene inst, one;
    std::size_t m = inst.add_mesh(box);
    for (int i = 0; i < kCopies; ++i)
        inst.place(m, tree_placement(i), "1." + std::to_string(i + 1) + "/");
    inst.commit();
    one.place(one.add_mesh(flat), scene::identity_affine());
    one.commit();
    EXPECT_EQ(inst.triangle_count(), one.triangle_count());
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(inst.bounds().lower[k], one.bounds().lower[k], 1e-4);
        EXPECT_NEAR(inst.bounds().upper[k], one.bounds().upper[k], 1e-4);
    }
    // A 200 x 200 grid of oblique rays over the 120 x 75 field.
    int hits = 0, edge_disagreements = 0;
    double worst_distance = 0, worst_normal = 0;
    for (int r = 0; r < 200; ++r)
        for (int c = 0; c < 200; ++c) {
            Vec3 o{-5 + 130.0 * (c + 0.371) / 200, -5 + 85.0 * (r + 0.529) / 200, 30};
            Vec3 d{0.13, -0.07, -1};
            auto a = inst.intersect(o, d);
            auto b = one.intersect(o, d);
            ASSERT_EQ(a.has_value(), b.has_value()) << r << " " << c;
            if (!a) continue;
            ++hits;
            // The flattened vertices are rounded to float at |x| < 150 (half an ulp,
            // 150 * FLT_EPSILON / 2) where the instanced ones are rounded at |x| < 2 and
            // moved by Embree's float transform: the facet planes differ by about
            // 150 * FLT_EPSILON, and a hit at incidence cos(theta) moves along the ray
            // by that over |cos(theta)|. 4x margin for the ray transform's own rounding.
            double cos_incidence =
                std::abs(a->normal[0] * d[0] + a->normal[1] * d[1] + a->normal[2] * d[2]) /
                std::hypot(d[0], d[1], d[2]);
            double tol = 4 * 150 * FLT_EPSILON / std::max(cos_incidence, 1e-3);
            EXPECT_NEAR(a->distance, b->distance, tol) << r << " " << c;
            worst_distance =
                std::max(worst_distance, std::abs(a->distance - b->distance) * cos_incidence);
            std::size_t flat_facet = a->object * nf + a->facet;
            if (flat_facet != b->facet) {
                // Only possible on a shared edge of two facets: same distance there.
                ++edge_disagreements;
                continue;
            }
            EXPECT_EQ(inst.attributes(*a).material_id, one.attributes(*b).material_id);
            for (int k = 0; k < 3; ++k) {
                // The flat copy's edges (>= 0.4 long) join float vertices rounded at
                // |x| < 150: their directions are uncertain by 2 x 150 * FLT_EPSILON / 2
                // / 0.4 = 4.5e-5, and so is the normal.
                EXPECT_NEAR(a->normal[k], b->normal[k], 4.5e-5) << r << " " << c;
                worst_normal = std::max(worst_normal, std::abs(a->normal[k] - b->normal[k]));
            }
        }
    EXPECT_GT(hits, 3000);  // the boxes cover about a tenth of the field
    EXPECT_LE(edge_disagreements, 2);
    std::printf("instancing: %d hits, max |dt|cos %.3g, max |dn| %.3g, %d edge ties\n", hits,
                worst_distance, worst_normal, edge_disagreements);
}

TEST(SceneOcclusion, OccludedAgreesWithIntersectOnRandomRays) {
    scene::Scene s;
    std::size_t m = s.add_mesh(box_mesh());
    for (int i = 0; i < 1000; ++i) s.place(m, tree_placement(i));
    s.commit();
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(0, 1);
    int blocked = 0, compared = 0;
    for (int i = 0; i < 20000; ++i) {
        Vec3 o{-10 + 140 * u(rng), -10 + 95 * u(rng), 3 * u(rng)};
        double z = 2 * u(rng) - 1, phi = 2 * std::numbers::pi * u(rng);
        Vec3 d{std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
        double tnear = 0.01, tfar = 20 * u(rng);
        auto hit = s.intersect(o, d, tnear, tfar);
        // A hit within float rounding of tfar may go either way: skip those.
        auto far = s.intersect(o, d, tnear, 1e30);
        if (far && std::abs(far->distance - tfar) < 1e-4) continue;
        ++compared;
        bool occ = s.occluded(o, d, tnear, tfar);
        EXPECT_EQ(occ, hit.has_value()) << i;
        EXPECT_EQ(hit.has_value(), far && far->distance <= tfar) << i;
        blocked += occ;
    }
    EXPECT_GT(blocked, 1000);
    EXPECT_LT(blocked, compared - 1000);
}

TEST(SceneBounds, ExactBoundsOfPlacedCopiesAndEmptyScene) {
    scene::Scene empty;
    empty.commit();
    EXPECT_TRUE(empty.bounds().empty());
    EXPECT_FALSE(empty.intersect({0, 0, 10}, {0, 0, -1}));
    scene::Scene s;
    std::size_t m = s.add_mesh(box_mesh());
    s.place(m, make_affine({2, 1, 1}, 0, 90, {10, 0, 0}));  // x -> y (scaled 2), y -> -x
    s.commit();
    // The box 0..2 x 0..1 x 0..2 turned a quarter about z: x in -1..0, y in 0..2, +10 east.
    EXPECT_NEAR(s.bounds().lower[0], 9, 1e-6);
    EXPECT_NEAR(s.bounds().upper[0], 10, 1e-6);
    EXPECT_NEAR(s.bounds().lower[1], 0, 1e-6);
    EXPECT_NEAR(s.bounds().upper[1], 2, 1e-6);
    EXPECT_NEAR(s.bounds().upper[2], 2, 1e-6);
    EXPECT_EQ(s.triangle_count(), 12u);
    EXPECT_EQ(s.placement_count(), 1u);
    EXPECT_EQ(s.facet_count(0), 6u);
    // Hits are bounded by tnear/tfar along the unit direction.
    EXPECT_TRUE(s.intersect({9.5, 1, 10}, {0, 0, -5}, 0, 8.1));
    EXPECT_FALSE(s.intersect({9.5, 1, 10}, {0, 0, -5}, 0, 7.9));
    EXPECT_FALSE(
        s.intersect({9.5, 1, 10}, {0, 0, -5}, 8.1, 9.9));  // misses the top, not yet the bottom
    EXPECT_TRUE(s.occluded({9.5, 1, 10}, {0, 0, -5}, 8.1, 10.1));  // the bottom at 10
}

TEST(SceneThreads, ConcurrentQueriesMatchSerialOnes) {
    scene::Scene s;
    std::size_t m = s.add_mesh(box_mesh());
    for (int i = 0; i < 1000; ++i)
        s.place(m, tree_placement(i), "1." + std::to_string(i + 1) + "/");
    s.commit();
    const int kRays = 20000;
    auto ray = [](int i) {
        return std::pair<Vec3, Vec3>{
            {-5 + 130.0 * ((i * 7919) % kRays) / kRays, -5 + 85.0 * i / kRays, 30}, {0.2, 0.1, -1}};
    };
    using Answer = std::tuple<bool, double, std::uint32_t, std::uint32_t>;
    auto answer = [](const std::optional<scene::Hit>& h) {
        return h ? Answer{true, h->distance, h->object, h->facet} : Answer{false, 0, 0, 0};
    };
    std::vector<Answer> serial(kRays), parallel(kRays);
    for (int i = 0; i < kRays; ++i) {
        auto [o, d] = ray(i);
        auto h = s.intersect(o, d);
        serial[i] = answer(h);
    }
    std::vector<std::thread> workers;
    for (int t = 0; t < 4; ++t)
        workers.emplace_back([&, t] {
            for (int i = t; i < kRays; i += 4) {
                auto [o, d] = ray(i);
                auto h = s.intersect(o, d);
                parallel[i] = answer(h);
            }
        });
    for (auto& w : workers) w.join();
    EXPECT_EQ(serial, parallel);  // the same query gives the same answer, bit for bit
}

TEST(SceneNormals, MirroringPlacementKeepsNormalsOutward) {
    scene::Scene s;
    std::size_t m = s.add_mesh(box_mesh());
    s.place(m, make_affine({-1, 1, 1}, 0, 0, {0, 0, 0}));  // x mirrored: box x -1..0
    s.commit();
    // M^-T n: the outward normals of the box stay outward (top +z, west wall -x),
    // although the mirrored triangles wind the other way round.
    auto top = s.intersect({-0.5, 0.5, 10}, {0, 0, -1});
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->normal[2], 1, 1e-12);
    auto west = s.intersect({-10, 0.5, 1}, {1, 0, 0});
    ASSERT_TRUE(west);
    EXPECT_NEAR(west->distance, 9, 1e-6);
    EXPECT_NEAR(west->normal[0], -1, 1e-12);
}

// Facet planes: the box's six faces (two triangles each) are six planes; its top and
// bottom's materials (10, 11) select two; a placed copy turned 90 deg about z and moved
// has the analytic planes of the turned box; a second copy in the same place adds none;
// `limit` stops the search one plane past it.
TEST(ScenePlanes, DistinctPlanesOfTheSelectedFacetsInTheSceneFrame) {
    scene::Scene s;
    std::size_t m = s.add_mesh(box_mesh());
    s.place(m, scene::identity_affine());
    s.place(m, make_affine({1, 1, 1}, 0, 90, {10, 0, 0}));  // x -> y, y -> -x: x 9..10, y 0..1
    s.place(m, make_affine({1, 1, 1}, 0, 90, {10, 0, 0}));
    s.commit();
    auto all = [](const scene::FacetAttributes&) { return true; };
    // Untouched box: x = 0, x = 1, y = 0, y = 1, z = 0, z = 2; turned: x = 9, x = 10 (its
    // y faces), y = 0 (shared with the first box), y = 1 (shared), z = 0, z = 2 (shared).
    EXPECT_EQ(s.facet_planes(all, 100).size(), 8u);
    auto flats = s.facet_planes(
        [](const scene::FacetAttributes& a) { return a.material_id <= 11; }, 100);
    ASSERT_EQ(flats.size(), 2u);
    for (const scene::Plane& p : flats) {
        EXPECT_NEAR(p.normal[2], 1, 1e-12);  // the sign convention: first non-zero component > 0
        EXPECT_TRUE(std::abs(p.offset) < 1e-9 || std::abs(p.offset - 2) < 1e-6) << p.offset;
    }
    // The turned box's x faces (its y = 0 and y = 1 faces, ids 12 and 13) at x = 10 and 9.
    auto turned = s.facet_planes(
        [](const scene::FacetAttributes& a) { return a.material_id == 12; }, 100);
    ASSERT_EQ(turned.size(), 2u);  // y = 0 of the first box, x = 10 of the turned one
    EXPECT_NEAR(turned[1].normal[0], 1, 1e-12);
    EXPECT_NEAR(turned[1].offset, 10, 1e-6);
    EXPECT_EQ(s.facet_planes(all, 3).size(), 4u);
}
