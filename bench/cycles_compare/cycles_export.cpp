// cycles_export: the scene, camera, sun and sky as trace sees them, written for
// bench/cycles_compare/cycles_render.py (Blender's Cycles) to render the same thing.
//
// Usage: cycles_export ADV SCENE MAT RAD... OUTDIR
//   OUTDIR/scene.obj   every placed facet (instances flattened) in the scene frame
//                      (x east, y north, z up, metres), one `usemtl mID_cCURVE` group
//                      per material id and .ems curve, triangles as trace meshes them
//   OUTDIR/scene.txt   key-value lines: the camera (position, forward, right, down,
//                      focal length, pixel pitch, rows, columns: lib/imaging/camera.cpp),
//                      the sun (direction toward it, irradiance at the ground normal to
//                      it per channel), the sky (the .rad sky's horizontal irradiance over
//                      pi per channel: a uniform sky of the same irradiance), the cube
//                      bands of the channels, and one `material KEY R G B` line each
// The channels are the band-centre spectral samples of the first three .rad files
// (radiometry::SpectralGrid::band_centre_sample, what trace's truth layers use).
// Radiometric values are in uW cm-2 (sr-1) um-1, trace's W cm-2 (sr-1) um-1 x 1e6.
//
// A material's colour is its reflectance rho(lambda, theta) = (1 - eps) F(theta)
// (White (1996), section 5.2.3; radiometry::MaterialOptics::reflectance) at theta =
// the camera's view zenith at the image centre, times F at the sun's zenith (trace
// damps incoming light by F(theta_i) too): Cycles' diffuse BSDF has no fall-off, so a
// material with one (the hawkeye grass) is matched at the view's typical angles only.
// A plain program, like bench_convergence; it is not a tool and not installed.
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "imaging/camera.hpp"
#include "io/adv.hpp"
#include "io/mat.hpp"
#include "io/rad.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/load.hpp"

namespace {

using namespace sigchain;

constexpr double kMicro = 1e6;  // W -> uW

// Keeps every mesh and placement that load_scene would hand to Embree.
class Collect final : public scene::SceneSink {
public:
    struct Placement {
        std::size_t mesh;
        scene::Affine transform;
    };
    std::vector<scene::MeshData> meshes;
    std::vector<Placement> placements;
    std::size_t add_mesh(scene::MeshData mesh, const io::Gdb*, const SourceLocation&) override {
        meshes.push_back(std::move(mesh));
        return meshes.size() - 1;
    }
    void place(std::size_t mesh, const scene::Affine& t, const std::string&) override {
        placements.push_back({mesh, t});
    }
};

using Key = std::pair<long, std::uint32_t>;  // material id, .ems curve

std::string key_name(const Key& k) {
    std::string name = "m";  // appended, not `"m" + ...`: GCC 12's -Wrestrict false positive
    name += std::to_string(k.first);
    name += "_c";
    name += std::to_string(k.second);
    return name;
}

// Writes the flattened facets, grouped by material key; returns the keys used.
std::vector<Key> write_obj(const Collect& c, const std::string& path) {
    std::ofstream out(path);
    out.precision(9);
    std::map<Key, std::vector<std::array<std::size_t, 3>>> faces;
    std::size_t base = 1;
    for (const auto& p : c.placements) {
        const auto& m = c.meshes[p.mesh];
        const auto& t = p.transform;
        for (std::size_t v = 0; v + 2 < m.vertices.size(); v += 3) {
            double x = m.vertices[v], y = m.vertices[v + 1], z = m.vertices[v + 2];
            out << "v " << t[0] * x + t[1] * y + t[2] * z + t[3] << ' '
                << t[4] * x + t[5] * y + t[6] * z + t[7] << ' '
                << t[8] * x + t[9] * y + t[10] * z + t[11] << '\n';
        }
        for (std::size_t i = 0; i < m.triangle_facet.size(); ++i) {
            const auto& f = m.facets[m.triangle_facet[i]];
            faces[{f.material_id, f.texture_curve}].push_back(
                {base + m.triangles[3 * i], base + m.triangles[3 * i + 1], base + m.triangles[3 * i + 2]});
        }
        base += m.vertices.size() / 3;
    }
    std::vector<Key> keys;
    for (const auto& [k, list] : faces) {
        keys.push_back(k);
        out << "usemtl " << key_name(k) << '\n';
        for (const auto& f : list) out << "f " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    }
    if (!out) throw IoError(path + ": cannot write");
    return keys;
}

void put3(std::ofstream& out, const char* name, const geo::Vec3& v) {
    out << name << ' ' << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
}

int run(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: cycles_export ADV SCENE MAT RAD1 RAD2 RAD3... OUTDIR\n");
        return 2;
    }
    std::string adv_path = argv[1], scene_path = argv[2], mat_path = argv[3];
    std::string dir = argv[argc - 1];
    std::vector<io::Rad> rads;
    std::vector<std::string> rad_files(argv + 4, argv + argc - 1);
    for (const auto& f : rad_files) rads.push_back(io::read_rad_file(f));
    if (rads.size() < 3) throw UsageError("cycles_export: three .rad files (channels) are needed");
    auto adv = io::read_adv_file(adv_path);
    if (adv.units != io::LengthUnit::Meters) throw UsageError("cycles_export: the .adv must be in m");
    auto cam = imaging::frame_camera(adv, adv_path);
    auto atm = radiometry::Atmosphere::from_rads(rads, rad_files);
    const auto& grid = atm.grid();
    auto lib = radiometry::MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid);

    Collect sink;
    std::vector<std::string> warnings;
    scene::assemble_scene(scene_path, scene::LoadOptions{}, sink, &warnings);
    auto keys = write_obj(sink, dir + "/scene.obj");

    std::ofstream out(dir + "/scene.txt");
    out.precision(9);
    put3(out, "camera_position", cam.position);
    put3(out, "camera_forward", cam.forward);
    put3(out, "camera_right", cam.right);
    put3(out, "camera_down", cam.down);
    out << "focal_length_mm " << cam.focal_length_mm << "\npixel_pitch_mm " << cam.pixel_pitch_mm
        << "\nrows " << cam.rows << "\ncolumns " << cam.columns << '\n';
    std::size_t k[3];
    for (int b = 0; b < 3; ++b) k[b] = grid.band_centre_sample(b);
    out << "cube_bands " << k[0] << ' ' << k[1] << ' ' << k[2] << '\n';
    out << "wavelength_um " << grid.wavelength_um[k[0]] << ' ' << grid.wavelength_um[k[1]] << ' '
        << grid.wavelength_um[k[2]] << '\n';
    put3(out, "sun_direction", atm.sun_direction());
    auto sun = atm.sun_irradiance_at_ground();
    out << "sun_irradiance " << sun[k[0]] * kMicro << ' ' << sun[k[1]] * kMicro << ' '
        << sun[k[2]] * kMicro << '\n';
    auto sky = atm.sky_irradiance_horizontal();
    // A uniform sky of radiance L gives a horizontal irradiance of pi L.
    out << "sky_radiance " << sky[k[0]] * kMicro / std::numbers::pi << ' '
        << sky[k[1]] * kMicro / std::numbers::pi << ' ' << sky[k[2]] * kMicro / std::numbers::pi
        << '\n';
    double view_zenith = std::acos(-cam.forward[2]) * 180 / std::numbers::pi;
    double sun_cos = atm.sun_direction()[2];
    out << "material_view_zenith_deg " << view_zenith << '\n';
    std::vector<double> rho(grid.size());
    for (const auto& key : keys) {
        const auto* m = lib.find(key.first);
        if (!m) throw DataError({mat_path, 0}, "no material " + std::to_string(key.first));
        m->reflectance(static_cast<int>(key.second), view_zenith, m->thickness_cm, rho);
        double f_sun = m->fall_off_cos(sun_cos);
        out << "material " << key_name(key);
        for (auto kk : k) out << ' ' << rho[kk] * f_sun;
        out << '\n';
    }
    if (!out) throw IoError(dir + "/scene.txt: cannot write");
    std::size_t tris = 0;
    for (const auto& p : sink.placements) tris += sink.meshes[p.mesh].triangle_facet.size();
    std::fprintf(stderr, "cycles_export: %zu placements, %zu triangles, %zu materials\n",
                 sink.placements.size(), tris, keys.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cycles_export: %s\n", e.what());
        return 1;
    }
}
