// The facets therm needs from a scene (see scene_facets.hpp): a scene::SceneSink.
#include "thermal/scene_facets.hpp"

#include <array>
#include <stdexcept>

#include "scene/mesh_build.hpp"

namespace sigchain::thermal {

namespace {

// v / |v|, or zero when v has no length.
geo::Vec3 unit_or_zero(const geo::Vec3& v) {
    if (!(geo::norm(v) > 0)) return {0, 0, 0};
    return geo::unit(v);
}

// Normal transformed by the inverse transpose of the 3x3 part of a row-major matrix
// of rows of 4 (an .odb's 4x4, a scene::Affine's 3x4): the cofactor matrix
// (inverse transpose x det), which keeps the direction for det > 0 and keeps the
// normal on the same side of the surface when det < 0 once re-signed.
template <std::size_t N>
geo::Vec3 transform_normal(const std::array<double, N>& m, const geo::Vec3& n) {
    auto a = [&](int r, int c) { return m[static_cast<std::size_t>(r * 4 + c)]; };
    geo::Vec3 cof[3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][static_cast<std::size_t>(c)] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
        }
    double det = a(0, 0) * cof[0][0] + a(0, 1) * cof[0][1] + a(0, 2) * cof[0][2];
    double s = det < 0 ? -1.0 : 1.0;
    return unit_or_zero(
        {s * geo::dot(cof[0], n), s * geo::dot(cof[1], n), s * geo::dot(cof[2], n)});
}

// A facet as therm takes it from a mesh: attributes and unit normal, mesh frame (key
// and placement still to come).
SceneFacet facet_of(const scene::FacetAttributes& a, const scene::FacetOrigin& o,
                    const geo::Vec3& normal) {
    SceneFacet f;
    f.normal = unit_or_zero(normal);
    if (f.normal == geo::Vec3{0, 0, 0})
        throw DataError({o.file, o.line}, "facet " + o.id + ": no normal (zero area)");
    f.material_id = a.material_id;
    f.thickness_cm = a.thickness_cm;
    f.power = a.power;
    f.exposed_area = a.exposed_area;
    f.temperature_c = a.temperature_c;
    f.where = {o.file, o.line};
    return f;
}

// therm's sink: each mesh's facets once, appended to the scene's facet list at each
// placement with its key and its normal turned.
class FacetSink final : public scene::SceneSink {
public:
    explicit FacetSink(std::vector<SceneFacet>& out) : m_out(out) {}

    std::size_t add_mesh(scene::MeshData mesh, const io::Gdb*, const SourceLocation&) override {
        if (mesh.normals.size() != mesh.facets.size())
            throw std::invalid_argument("read_scene_facets: a mesh without facet normals");
        Mesh m;
        for (std::size_t f = 0; f < mesh.facets.size(); ++f)
            m.facets.push_back(facet_of(mesh.facets[f], mesh.origins[f], mesh.normals[f]));
        m.origins = std::move(mesh.origins);
        m_meshes.push_back(std::move(m));
        return m_meshes.size() - 1;
    }
    void place(std::size_t mesh, const scene::Affine& t, const std::string& prefix) override {
        const bool identity = t == scene::identity_affine();  // a lone .gdb
        append(mesh, prefix,
               [&](const geo::Vec3& n) { return identity ? n : transform_normal(t, n); });
    }
    void place_in_units(std::size_t mesh, const io::Matrix4& matrix, double,
                        const std::string& prefix) override {
        // A unit scale does not turn a normal: the matrix as the .odb gives it.
        append(mesh, prefix, [&](const geo::Vec3& n) { return transform_normal(matrix, n); });
    }

private:
    struct Mesh {
        std::vector<SceneFacet> facets;  // keys unset, normals in mesh coordinates
        std::vector<scene::FacetOrigin> origins;
    };
    template <class Turn>
    void append(std::size_t mesh, const std::string& prefix, Turn turn) {
        const Mesh& m = m_meshes.at(mesh);
        for (std::size_t f = 0; f < m.facets.size(); ++f) {
            SceneFacet placed = m.facets[f];
            placed.key = scene::facet_key(prefix, m.origins[f]);
            placed.normal = turn(placed.normal);
            m_out.push_back(std::move(placed));
        }
    }

    std::vector<SceneFacet>& m_out;
    std::vector<Mesh> m_meshes;
};

}  // namespace

std::vector<SceneFacet> read_scene_facets(const std::string& path,
                                          const std::optional<scene::GeoOrigin>& origin,
                                          std::vector<std::string>* warnings,
                                          const scene::SceneInput& input, unsigned threads) {
    scene::LoadOptions options;
    options.threads = threads;
    options.input = input;
    options.origin = origin;
    options.allow_degenerate = true;  // every facet has a history (trace keeps them too)
    options.keep_degenerate = true;
    std::vector<SceneFacet> out;
    FacetSink sink(out);
    std::vector<std::string> reported;
    scene::assemble_scene(path, options, sink, warnings ? warnings : &reported);
    return out;
}

}  // namespace sigchain::thermal
