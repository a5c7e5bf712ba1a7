// Ray casting rate of the Embree scene and the field-of-view method of
// find_min_max_view_angle: prints rays per second on a 10^5-triangle terrain.
#include <benchmark/benchmark.h>

#include "imaging/sensor.hpp"
#include "imaging/view_angle.hpp"
#include "scene/scene.hpp"

namespace {

using namespace sigchain;

scene::Scene terrain(int side) {
    io::Gdb g;
    g.file = "bench";
    io::GdbPart part;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            io::GdbFacet f;
            double x = i, y = j, z = 0.1 * ((i * 7 + j * 13) % 5);
            f.vertices = {{x, y, z}, {x + 1, y, z}, {x + 1, y + 1, z}, {x, y + 1, z}};
            f.normal = {0, 0, 1};
            part.facets.push_back(f);
        }
    io::GdbObject obj;
    obj.parts.push_back(part);
    g.objects.push_back(obj);
    scene::Scene s;
    s.place(s.add_mesh(g), scene::identity_affine());
    s.commit();
    return s;
}

void BM_FieldOfView(benchmark::State& state) {
    auto s = terrain(224);  // 224^2 quads = ~10^5 triangles
    io::Adv adv;
    adv.target = {112, 112, 0};
    adv.camera = {-200, 112, 300};
    adv.azimuth_deg = 180;
    adv.focal_length_mm = 8;
    adv.rows = adv.columns = 512;
    const imaging::FrameSensor sensor(imaging::frame_camera(adv));
    std::size_t rays = 0;
    for (auto _ : state) {
        auto rep = imaging::find_view_angles(sensor, s, static_cast<int>(state.range(0)));
        rays += rep.rays_cast;
        benchmark::DoNotOptimize(rep);
    }
    state.SetItemsProcessed(static_cast<long>(rays));
}
BENCHMARK(BM_FieldOfView)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
