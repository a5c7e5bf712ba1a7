// OBJ facets (order, ids, lines, materials, triangle coordinates) as the hand-written
// reader gave them, recorded before that reader was replaced by Assimp: the mesh reader
// must give the same for every statement the old reader handled.
#include <gtest/gtest.h>

#include "scene/id_map.hpp"
#include "scene/mesh_file.hpp"

using namespace sigchain;

namespace {

const std::string kMeshes = std::string(SIGCHAIN_TEST_DATA) + "/meshes/";

// One facet as a line of text: id, line, material, description, then its triangles'
// vertex coordinates (floats, as Embree gets them) in order.
std::vector<std::string> facets_of(const scene::MeshData& m) {
    std::vector<std::string> out(m.facets.size());
    for (std::size_t f = 0; f < m.facets.size(); ++f)
        out[f] = m.origins[f].id + " line " + std::to_string(m.origins[f].line) + " material " +
                 std::to_string(m.facets[f].material_id) + " " + m.origins[f].description + ":";
    for (std::size_t t = 0; t < m.triangle_facet.size(); ++t) {
        std::string& s = out[m.triangle_facet[t]];
        s += " (";
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m.triangles[3 * t + k];
            char buf[64];
            std::snprintf(buf, sizeof buf, "%s%.9g %.9g %.9g", k ? ", " : "", m.vertices[3 * v],
                          m.vertices[3 * v + 1], m.vertices[3 * v + 2]);
            s += buf;
        }
        s += ")";
    }
    return out;
}

scene::MeshData read_features() {
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    return scene::read_mesh_file({kMeshes + "features.obj", &map, {}},
                                 scene::DegeneratePolicy::Error, nullptr);
}

}  // namespace

TEST(ObjParity, FacetsIdsOrderAndCoordinatesAsTheHandWrittenReaderGaveThem) {
    const std::vector<std::string> expected{
        "0-0-1 line 11 material 1 "
        "object '' (0-0-0), part '' (0-0-0), facet 'grass' (0-0-1): "
        "(0 0 0, 2 0 0, 3 1 0) "
        "(0 0 0, 3 1 0, 1 2 0) "
        "(0 0 0, 1 2 0, -1 1 0)",
        "1-1-2 line 20 material 7 "
        "object 'block' (1-0-0), part 'top' (1-1-0), facet 'asphalt' (1-1-2): "
        "(10.1000004 0.300000012 0.25, 11.6999998 0.300000012 0.25, 11.6999998 1.89999998 0.25) "
        "(10.1000004 0.300000012 0.25, 11.6999998 1.89999998 0.25, "
        "10.1000004 1.89999998 1.33333337)",
        "1-1-3 line 23 material 1 "
        "object 'block' (1-0-0), part 'top' (1-1-0), facet 'grass' (1-1-3): "
        "(10.1000004 0.300000012 0.25, 11.6999998 0.300000012 0.25, "
        "10.1000004 1.89999998 1.33333337)",
        "1-2-4 line 25 material 1 "
        "object 'block' (1-0-0), part 'side' (1-2-0), facet 'grass' (1-2-4): "
        "(10.1000004 0.300000012 0.25, 11.6999998 0.300000012 0.25, 11.6999998 1.89999998 0.25)",
        "2-2-5 line 28 material 7 "
        "object 'post' (2-0-0), part 'side' (2-2-0), facet 'asphalt' (2-2-5): "
        "(0 0 0, 2 0 0, 1 2 0)",
        "2-3-6 line 30 material 7 "
        "object 'post' (2-0-0), part 'top' (2-3-0), facet 'asphalt' (2-3-6): "
        "(2 0 0, 3 1 0, 1 2 0)",
    };
    const std::vector<std::string> got = facets_of(read_features());
    EXPECT_EQ(got, expected);
}
