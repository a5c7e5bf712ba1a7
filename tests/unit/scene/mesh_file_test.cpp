// Tests for mesh files through Assimp: each format's facets, coordinates after the axis
// rule (the unit square at z = 0 in every file), materials by name or one id, ids, the
// errors, and meshes given as the scene or as an .odb MESH_FILENAME object.
#include "scene/mesh_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "scene/load.hpp"

using namespace sigchain;

namespace {

const std::string kMeshes = std::string(SIGCHAIN_TEST_DATA) + "/meshes/";

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// The corners of facet f's first triangle, "x y z" each (floats as Embree gets them).
std::vector<std::string> corners(const scene::MeshData& m, std::size_t f) {
    std::vector<std::string> out;
    for (std::size_t t = 0; t < m.triangle_facet.size(); ++t) {
        if (m.triangle_facet[t] != f) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m.triangles[3 * t + k];
            char buf[64];
            // Integers expected: exact after the axis turn (x, y, z) -> (x, -z, y).
            std::snprintf(buf, sizeof buf, "%g %g %g", m.vertices[3 * v] + 0.0,
                          m.vertices[3 * v + 1] + 0.0, m.vertices[3 * v + 2] + 0.0);
            out.emplace_back(buf);
        }
        break;
    }
    return out;
}

scene::MeshData read(const std::string& name, std::optional<long> id = {}) {
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    return scene::read_mesh_file({kMeshes + name, &map, id}, scene::DegeneratePolicy::Error,
                                 nullptr);
}

const std::vector<std::string> kFirst{"0 0 0", "1 0 0", "1 1 0"};
const std::vector<std::string> kSecond{"0 0 0", "1 1 0", "0 1 0"};

}  // namespace

TEST(MeshFile, EveryFormatGivesTheSquareAtZeroWithItsMaterials) {
    // glTF and the FBX (which declares +Y up) store the square Y-up: (x, 0, -y).
    for (const char* name : {"two_materials.obj", "two_materials.gltf", "two_materials.glb",
                             "two_materials.fbx"}) {
        SCOPED_TRACE(name);
        const scene::MeshData m = read(name);
        ASSERT_EQ(m.facets.size(), 2u);
        EXPECT_EQ(m.triangle_facet.size(), 2u);
        EXPECT_EQ(corners(m, 0), kFirst);
        EXPECT_EQ(corners(m, 1), kSecond);
        EXPECT_EQ(m.facets[0].material_id, 1);  // grass
        EXPECT_EQ(m.facets[1].material_id, 7);  // asphalt
        // Both face up (+z) after the axis rule.
        EXPECT_GT(m.normals[0][2], 0);
        EXPECT_GT(m.normals[1][2], 0);
    }
    // Ids: OBJ by its statements, the others by mesh and face.
    EXPECT_EQ(read("two_materials.obj").origins[1].id, "1-0-2");
    EXPECT_EQ(read("two_materials.obj").origins[1].line, 10);
    const scene::MeshData g = read("two_materials.gltf");
    EXPECT_EQ(g.origins[1].id, "1-2-1");
    EXPECT_EQ(g.origins[1].line, 0);
    EXPECT_EQ(g.origins[1].description, "mesh 'square-1' (1-2-0), facet 'asphalt' (1-2-1)");
}

TEST(MeshFile, FormatsWithoutMaterialNamesTakeOneId) {
    for (const char* name : {"two_triangles.ply", "two_triangles.stl"}) {
        SCOPED_TRACE(name);
        EXPECT_NE(error_of([&] { read(name); }).find("the face has no material name; give one "
                                                      "material id for the mesh"),
                  std::string::npos);
        const scene::MeshData m = read(name, 3);
        ASSERT_EQ(m.facets.size(), 2u);
        EXPECT_EQ(corners(m, 0), kFirst);
        EXPECT_EQ(corners(m, 1), kSecond);
        EXPECT_EQ(m.facets[0].material_id, 3);
        EXPECT_EQ(m.facets[1].material_id, 3);
        EXPECT_EQ(m.origins[1].id, "1-1-2");
    }
    // One id overrides the names too.
    EXPECT_EQ(read("two_materials.gltf", 5).facets[1].material_id, 5);
}

TEST(MeshFile, ErrorsNameTheFile) {
    const scene::IdMap grass_only = scene::parse_id_map("grass 1\n", "grass.map");
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({kMeshes + "two_materials.gltf", &grass_only, {}},
                                        scene::DegeneratePolicy::Error, nullptr);
              }),
              kMeshes + "two_materials.gltf: material 'asphalt' is not in the material map "
                        "grass.map");
    EXPECT_THROW(read("missing.ply"), IoError);
    const std::string bad = ::testing::TempDir() + "bad.stl";
    std::ofstream(bad) << "garbage\n";
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({bad, nullptr, 1}, scene::DegeneratePolicy::Error,
                                        nullptr);
              }),
              bad + ": Failed to determine STL storage representation for " + bad + ".");
    // An object name used again with another material: Assimp files the face under the
    // first object, out of the file's order, which is refused rather than renumbered.
    const std::string back = ::testing::TempDir() + "back.obj";
    std::ofstream(back) << "v 0 0 0\nv 1 0 0\nv 1 1 0\no X\nusemtl grass\nf 1 2 3\no Y\n"
                           "f 1 2 3\no X\nusemtl asphalt\nf 1 2 3\n";
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({back, &map, {}}, scene::DegeneratePolicy::Error,
                                        nullptr);
              }),
              back + ":8: Assimp gave this face out of the file's order (an object name used "
                     "again after another object?); rename the repeated object");
}

TEST(MeshFile, LoneMeshAsTheSceneAndAsAnOdbObject) {
    scene::LoadOptions opt;
    EXPECT_THROW(scene::load_scene(kMeshes + "two_triangles.stl", opt), UsageError);
    opt.input.material_id = 3;
    scene::LoadReport report;
    const scene::Scene lone = scene::load_scene(kMeshes + "two_triangles.stl", opt, &report);
    EXPECT_EQ(report.facets, 2u);
    auto hit = lone.intersect({0.75, 0.25, 10}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(lone.facet_key(*hit), "1-1-1");
    EXPECT_EQ(lone.attributes(*hit).material_id, 3);
    // glTF is in metres: in a scene in feet the square spans 1 / 0.3048 units.
    opt.input.material_id.reset();
    opt.input.material_map = kMeshes + "two_materials.map";
    opt.scene_meters_per_unit = 0.3048;
    const scene::Scene feet = scene::load_scene(kMeshes + "two_materials.glb", opt);
    EXPECT_NEAR(feet.bounds().upper[0], 1 / 0.3048, 1e-6);
    EXPECT_NEAR(feet.bounds().upper[1], 1 / 0.3048, 1e-6);
    EXPECT_NEAR(feet.bounds().upper[2], 0, 1e-12);
    // MESH_FILENAME with one MATERIAL_ID, placed twice.
    const std::string odb = ::testing::TempDir() + "mesh.odb";
    std::ofstream(odb) << "OBJECT {\n    MESH_FILENAME = " << kMeshes
                       << "two_triangles.ply\n    MATERIAL_ID = 4\n    UNITS = m\n"
                          "    INSTANCES {\n        0,0,0, 1,1,1, 0,0,0\n"
                          "        5,0,0, 1,1,1, 0,0,0\n    }\n}\n";
    const scene::Scene placed = scene::load_scene(odb, {});
    auto second = placed.intersect({5.25, 0.75, 10}, {0, 0, -1});
    ASSERT_TRUE(second);
    EXPECT_EQ(placed.facet_key(*second), "1.2/1-1-2");
    EXPECT_EQ(placed.attributes(*second).material_id, 4);
}
