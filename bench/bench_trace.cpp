// Benchmark of trace's render(): a generated scene of a
// 1001 x 1001-vertex terrain (2 million triangles) and 3000 instanced trees, a 512 x
// 512 frame camera, golfball sampling, 3 bands x 7 spectral samples. Prints the total
// time, the rays cast, Mrays/s, the Mrays/s of a bare Embree loop casting the same
// rays: (1) the rays render() casts for golfball sampling (the primary rays, the 61
// golf-ball rays about each hit's normal, the shadow rays to the sun from the primary
// and secondary hits), (2) as many rays with uniformly random upward directions from
// the primary hits, (3) the rays of (1) as packets of 8 neighbouring pixels (a
// wavefront's grouping); the ratios and the peak memory.
//
// A plain program (not Google Benchmark): one long run, not repeated timings.
// Usage: bench_trace [VERTICES_PER_SIDE [TREES [IMAGE_SIDE]]] (default 1001 3000 512).
// With BENCH_PHASES set it also prints each phase's times to stderr (bench/trace_ceiling.sh).
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "imaging/camera.hpp"
#include "imaging/sensor.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "trace/golfball.hpp"
#include "trace/render.hpp"
#include "bench_timing.hpp"
#include "trace_bench_scene.hpp"

namespace {

using namespace sigchain;
using namespace sigchain::bench;

constexpr double kSunZenithDeg = 35, kSunAzimuthDeg = 150;
constexpr int kRepeats = 2;  // render and the golf-ball bare loop: best of this many runs

// With BENCH_PHASES set in the environment, each timed phase prints "phase NAME START END"
// (steady-clock seconds: CLOCK_MONOTONIC on Linux) to stderr on leaving its scope, so that
// bench/trace_ceiling.sh can split a perf profile recorded with -k CLOCK_MONOTONIC.
class Phase {
public:
    explicit Phase(const char* name) : m_name(name), m_t0(Clock::now()) {}
    Phase(const Phase&) = delete;
    Phase& operator=(const Phase&) = delete;
    ~Phase() {
        if (!std::getenv("BENCH_PHASES")) return;
        auto secs = [](Clock::time_point t) {
            return std::chrono::duration<double>(t.time_since_epoch()).count();
        };
        std::fprintf(stderr, "phase %s %.6f %.6f\n", m_name, secs(m_t0), secs(Clock::now()));
    }

private:
    const char* m_name;
    Clock::time_point m_t0;
};

double peak_memory_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// 512 x 512 nadir camera 1500 m above the terrain's centre, north up, 9 um pixels
// behind a 9 mm lens: a 768 m footprint.
imaging::FrameCamera bench_camera(long side) {
    imaging::FrameCamera cam;
    cam.position = {0, 0, 1500};
    cam.forward = {0, 0, -1};
    cam.right = {1, 0, 0};
    cam.down = geo::cross(cam.forward, cam.right);
    cam.focal_length_mm = 9 * 512.0 / static_cast<double>(side);
    cam.pixel_pitch_mm = 0.009;
    cam.rows = cam.columns = side;
    return cam;
}

// ---- The bare Embree loop: the same geometry, Embree 3 directly. ----

struct BareScene {
    RTCDevice device = nullptr;
    RTCScene top = nullptr, tree = nullptr, terrain = nullptr;
    ~BareScene() {
        if (terrain) rtcReleaseScene(terrain);
        if (tree) rtcReleaseScene(tree);
        if (top) rtcReleaseScene(top);
        if (device) rtcReleaseDevice(device);
    }
};

void add_triangles(RTCDevice device, RTCScene scene, const scene::MeshData& m) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.vertices.size() / 3));
    std::copy(m.vertices.begin(), m.vertices.end(), v);
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                                             RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                             m.triangles.size() / 3));
    std::copy(m.triangles.begin(), m.triangles.end(), t);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
}

// With `terrain_instance`, the terrain is an instance of its own scene (a diagnostic:
// what one more BVH level costs on the terrain; scene::Scene attaches an untransformed
// placement directly); otherwise its triangles sit in the top-level scene beside the
// tree instances, as scene::Scene does.
void build_bare(BareScene& b, int n, int trees, bool terrain_instance) {
    b.device = rtcNewDevice(nullptr);
    if (!b.device) {
        std::fprintf(stderr, "bench_trace: cannot create an Embree device\n");
        std::exit(1);
    }
    rtcSetDeviceErrorFunction(
        b.device,
        [](void*, RTCError code, const char* message) {
            std::fprintf(stderr, "bench_trace: embree error %d: %s\n", static_cast<int>(code),
                         message ? message : "");
        },
        nullptr);
    b.top = rtcNewScene(b.device);
    b.tree = rtcNewScene(b.device);
    if (terrain_instance) {
        b.terrain = rtcNewScene(b.device);
        add_triangles(b.device, b.terrain, terrain_mesh(n));
        rtcCommitScene(b.terrain);
        RTCGeometry inst = rtcNewGeometry(b.device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, b.terrain);
        const float identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, identity);
        rtcCommitGeometry(inst);
        rtcAttachGeometry(b.top, inst);  // geometry 0, as the plain terrain would be
        rtcReleaseGeometry(inst);
    } else {
        add_triangles(b.device, b.top, terrain_mesh(n));
    }
    add_triangles(b.device, b.tree, tree_mesh());
    rtcCommitScene(b.tree);
    for (const auto& a : tree_transforms(trees)) {
        RTCGeometry inst = rtcNewGeometry(b.device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, b.tree);
        float xf[12];
        for (int k = 0; k < 12; ++k) xf[k] = static_cast<float>(a[k]);
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xf);
        rtcCommitGeometry(inst);
        rtcAttachGeometry(b.top, inst);
        rtcReleaseGeometry(inst);
    }
    rtcCommitScene(b.top);
}

RTCRayHit make_ray(const geo::Vec3& o, const geo::Vec3& d, float tnear) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(o[0]);
    rh.ray.org_y = static_cast<float>(o[1]);
    rh.ray.org_z = static_cast<float>(o[2]);
    rh.ray.dir_x = static_cast<float>(d[0]);
    rh.ray.dir_y = static_cast<float>(d[1]);
    rh.ray.dir_z = static_cast<float>(d[2]);
    rh.ray.tnear = tnear;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// Runs body(i) for i in [0, count) on `threads` threads (dynamic chunks of 1024 rays).
// The bare Embree reference loop keeps this inlined template on purpose: the renderer's
// sigchain::parallel_for schedules rows (one std::function call each), which would
// cost per ray here and make the reference slower than a bare loop is.
template <class F>
void bare_parallel_for(std::size_t count, unsigned threads, F body) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (;;) {
            std::size_t begin = next.fetch_add(1024);
            if (begin >= count) return;
            std::size_t end = std::min(count, begin + 1024);
            for (std::size_t i = begin; i < end; ++i) body(i);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
}

struct BareResult {
    std::uint64_t rays = 0;
    double seconds = 0;      // wall clock
    double cpu_seconds = 0;  // CPU time of all threads
};

// The result of a loop started at t0 (wall) and c0 (CPU seconds) that cast `rays`.
BareResult finish(Clock::time_point t0, double c0, std::uint64_t rays) {
    BareResult out;
    out.seconds = seconds_since(t0);
    out.cpu_seconds = cpu_seconds() - c0;
    out.rays = rays;
    return out;
}

// What the golf-ball loops share: the sun, the golf-ball rays (matrix 0), the offset off
// a hit (1e-6 of the scene's extent, as render() does), the rays cast so far, and the
// clocks, started when the loop is made.
struct GolfLoop {
    explicit GolfLoop(double extent) : eps(1e-6 * extent) {}
    const geo::Vec3 sun = geo::direction_from_degrees(kSunZenithDeg, kSunAzimuthDeg);
    const std::vector<trace::GolfRay>& golf = trace::golfball_rays(0);
    const double eps;
    std::atomic<std::uint64_t> total{0};
    const Clock::time_point t0 = Clock::now();
    const double c0 = cpu_seconds();
    BareResult finish() const { return ::finish(t0, c0, total); }
};

// A hit's golf-ball frame (golfball.hpp): the normal n, x and y across it, and the
// rotation (cos, sin) that turns azimuth 0 to the mirror direction of the view d.
struct GolfFrame {
    geo::Vec3 n, x, y;
    double cr = 1, sr = 0;
};

GolfFrame golf_frame(const geo::Vec3& n, const geo::Vec3& d) {
    GolfFrame f;
    f.n = n;
    f.x = geo::cross({0, 0, 1}, n);
    f.x = geo::dot(f.x, f.x) < 1e-12 ? geo::Vec3{1, 0, 0} : geo::unit(f.x);
    f.y = geo::cross(n, f.x);
    const double dn = geo::dot(d, n);
    const geo::Vec3 m{d[0] - 2 * dn * n[0], d[1] - 2 * dn * n[1], d[2] - 2 * dn * n[2]};
    const double phi0 = std::atan2(geo::dot(m, f.y), geo::dot(m, f.x));
    f.cr = std::cos(phi0);
    f.sr = std::sin(phi0);
    return f;
}

// Golf-ball ray g of the frame f, in world coordinates.
geo::Vec3 golf_direction(const trace::GolfRay& g, const GolfFrame& f) {
    const double cp = g.cos_phi * f.cr - g.sin_phi * f.sr;
    const double sp = g.sin_phi * f.cr + g.cos_phi * f.sr;
    geo::Vec3 w;
    for (int a = 0; a < 3; ++a)
        w[a] = g.sin_theta * (cp * f.x[a] + sp * f.y[a]) + g.cos_theta * f.n[a];
    return w;
}

// Casts `primary` rays through the pixels (spp per pixel, jittered), then spreads
// `hemisphere` intersection rays (random upward directions) and `shadow` occlusion
// rays (toward the sun) evenly over the primary hits.
BareResult bare_loop(const BareScene& b, const imaging::FrameCamera& cam, std::uint64_t primary,
                     std::uint64_t hemisphere, std::uint64_t shadow, unsigned threads) {
    const std::size_t pixels = static_cast<std::size_t>(cam.rows) * cam.columns;
    const std::uint64_t spp = std::max<std::uint64_t>(1, primary / pixels);
    std::vector<float> hit_point(3 * primary);
    std::vector<char> hit(primary, 0);
    const auto t0 = Clock::now();
    const double c0 = cpu_seconds();
    bare_parallel_for(primary, threads, [&](std::size_t k) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        std::size_t p = (k / spp) % pixels;
        std::uint64_t state = splitmix64(k);
        double row = static_cast<double>(p / cam.columns) + unit_random(state);
        double col = static_cast<double>(p % cam.columns) + unit_random(state);
        const geo::Vec3 d = cam.direction(row, col);
        RTCRayHit rh = make_ray(cam.position, d, 0.0f);
        rtcIntersect1(b.top, &ctx, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            hit[k] = 1;
            for (int a = 0; a < 3; ++a)
                hit_point[3 * k + a] = static_cast<float>(cam.position[a] + rh.ray.tfar * d[a]);
        }
    });
    std::vector<std::size_t> hits;
    for (std::size_t k = 0; k < primary; ++k)
        if (hit[k]) hits.push_back(k);
    const std::uint64_t h = hits.size();
    const geo::Vec3 sun = geo::direction_from_degrees(kSunZenithDeg, kSunAzimuthDeg);
    if (h > 0)
        bare_parallel_for(h, threads, [&](std::size_t i) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            const float* q = &hit_point[3 * hits[i]];
            geo::Vec3 o{q[0], q[1], q[2] + 1e-2};
            std::uint64_t n_hemi = (i + 1) * hemisphere / h - i * hemisphere / h;
            std::uint64_t n_shadow = (i + 1) * shadow / h - i * shadow / h;
            std::uint64_t state = splitmix64(0xABCDEFULL + i);
            for (std::uint64_t r = 0; r < n_hemi; ++r) {
                // Uniform on the upper hemisphere.
                double z = unit_random(state), phi = 2 * M_PI * unit_random(state);
                double s = std::sqrt(std::max(0.0, 1 - z * z));
                RTCRayHit rh = make_ray(o, {s * std::cos(phi), s * std::sin(phi), z}, 1e-3f);
                rtcIntersect1(b.top, &ctx, &rh);
            }
            for (std::uint64_t r = 0; r < n_shadow; ++r) {
                RTCRayHit rh = make_ray(o, sun, 1e-3f);
                rtcOccluded1(b.top, &ctx, &rh.ray);
            }
        });
    return finish(t0, c0, primary + hemisphere + shadow);
}

// World-space unit normal of a hit, turned toward the ray direction `d` (trees are
// instances: rotation about z and uniform scale, so the normal turns with the matrix).
geo::Vec3 hit_normal(const RTCRayHit& rh, const std::vector<scene::Affine>& trees,
                      const geo::Vec3& d) {
    geo::Vec3 n{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID && rh.hit.instID[0] > 0) {
        const scene::Affine& a = trees[rh.hit.instID[0] - 1];  // geometry 0 is the terrain
        n = {a[0] * n[0] + a[1] * n[1] + a[2] * n[2], a[4] * n[0] + a[5] * n[1] + a[6] * n[2],
             a[8] * n[0] + a[9] * n[1] + a[10] * n[2]};
    }
    n = geo::unit(n);
    if (geo::dot(n, d) > 0) n = {-n[0], -n[1], -n[2]};
    return n;
}

// The rays render() casts with golfball sampling on Lambertian materials, cast bare:
// per pixel `spp` primary rays; per primary hit a shadow ray to the sun (when the sun
// is above the facet) and the 61 golf-ball rays about the normal, turned to the view's
// mirror azimuth (golfball.hpp); per golf-ball ray that hits, a shadow ray to the sun
// from that hit (when the sun is above it). Offsets: 1e-6 of the scene's extent, as
// render() does.
BareResult bare_golfball(const BareScene& b, const imaging::FrameCamera& cam, std::uint64_t spp,
                         const std::vector<scene::Affine>& trees, double extent, unsigned threads) {
    const std::size_t pixels = static_cast<std::size_t>(cam.rows) * cam.columns;
    GolfLoop run(extent);
    bare_parallel_for(pixels * spp, threads, [&](std::size_t k) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        std::uint64_t rays = 1;
        std::size_t p = k / spp;
        std::uint64_t state = splitmix64(k);
        double row = static_cast<double>(p / cam.columns) + unit_random(state);
        double col = static_cast<double>(p % cam.columns) + unit_random(state);
        const geo::Vec3 d = cam.direction(row, col);
        RTCRayHit rh = make_ray(cam.position, d, 0.0f);
        rtcIntersect1(b.top, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
            run.total += rays;
            return;
        }
        const geo::Vec3 n = hit_normal(rh, trees, d);
        geo::Vec3 o;
        for (int a = 0; a < 3; ++a) o[a] = cam.position[a] + rh.ray.tfar * d[a] + run.eps * n[a];
        if (geo::dot(n, run.sun) > 0) {
            RTCRayHit sr = make_ray(o, run.sun, 0.0f);
            rtcOccluded1(b.top, &ctx, &sr.ray);
            ++rays;
        }
        const GolfFrame frame = golf_frame(n, d);
        for (const trace::GolfRay& g : run.golf) {
            const geo::Vec3 w = golf_direction(g, frame);
            RTCRayHit hr = make_ray(o, w, 0.0f);
            rtcIntersect1(b.top, &ctx, &hr);
            ++rays;
            if (hr.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            const geo::Vec3 nb = hit_normal(hr, trees, w);
            if (geo::dot(nb, run.sun) <= 0) continue;
            geo::Vec3 q;
            for (int a = 0; a < 3; ++a) q[a] = o[a] + hr.ray.tfar * w[a] + run.eps * nb[a];
            RTCRayHit sr = make_ray(q, run.sun, 0.0f);
            rtcOccluded1(b.top, &ctx, &sr.ray);
            ++rays;
        }
        run.total += rays;
    });
    return run.finish();
}

// The same rays cast as a wavefront would: 8 neighbouring pixels of a row at a time, so
// that each packet holds rays that start close together and run almost parallel (the
// primary rays, then the i-th golf-ball ray of each pixel's hit, then the shadow rays
// from those hits), cast with rtcIntersect8 / rtcOccluded8 and a coherent context. The
// golf-ball rays of one hit, cast together, diverge (an earlier packet trial of render:
// slower); these do not. A measurement of the design only: render casts single rays.
void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHit8* r) {
    rtcIntersect8(valid, s, c, r);
}
void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRay8* r) {
    rtcOccluded8(valid, s, c, r);
}

template <int kLanes, class RayHitN, class RayN>
BareResult bare_golfball_packets(const BareScene& b, const imaging::FrameCamera& cam,
                                 const std::vector<scene::Affine>& trees, double extent,
                                 unsigned threads) {
    const std::size_t pixels = static_cast<std::size_t>(cam.rows) * cam.columns;
    const std::size_t groups = (pixels + kLanes - 1) / kLanes;
    GolfLoop run(extent);
    bare_parallel_for(groups, threads, [&](std::size_t group) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        std::uint64_t rays = 0;
        alignas(64) int valid[kLanes];
        alignas(64) RayHitN rh;
        alignas(64) RayN sr;
        auto set = [](auto& r, int l, const geo::Vec3& o, const geo::Vec3& d) {
            r.org_x[l] = static_cast<float>(o[0]);
            r.org_y[l] = static_cast<float>(o[1]);
            r.org_z[l] = static_cast<float>(o[2]);
            r.dir_x[l] = static_cast<float>(d[0]);
            r.dir_y[l] = static_cast<float>(d[1]);
            r.dir_z[l] = static_cast<float>(d[2]);
            r.tnear[l] = 0.0f;
            r.tfar[l] = INFINITY;
            r.mask[l] = 0xFFFFFFFFu;
            r.time[l] = 0.0f;
            r.flags[l] = 0;
        };
        auto hit_of = [&](int l) {
            RTCRayHit one{};
            one.hit.Ng_x = rh.hit.Ng_x[l];
            one.hit.Ng_y = rh.hit.Ng_y[l];
            one.hit.Ng_z = rh.hit.Ng_z[l];
            one.hit.instID[0] = rh.hit.instID[0][l];
            return one;
        };
        // Primary rays.
        geo::Vec3 d[kLanes], o[kLanes];
        GolfFrame frame[kLanes];
        bool lane_hit[kLanes] = {};
        for (int l = 0; l < kLanes; ++l) {
            const std::size_t p = group * kLanes + l;
            valid[l] = p < pixels ? -1 : 0;
            if (!valid[l]) continue;
            std::uint64_t state = splitmix64(p);
            double row = static_cast<double>(p / cam.columns) + unit_random(state);
            double col = static_cast<double>(p % cam.columns) + unit_random(state);
            d[l] = cam.direction(row, col);
            set(rh.ray, l, cam.position, d[l]);
            rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
            ++rays;
        }
        intersect(valid, b.top, &ctx, &rh);
        alignas(64) int shadow_valid[kLanes];
        for (int l = 0; l < kLanes; ++l) {
            shadow_valid[l] = 0;
            if (!valid[l] || rh.hit.geomID[l] == RTC_INVALID_GEOMETRY_ID) continue;
            lane_hit[l] = true;
            const geo::Vec3 n = hit_normal(hit_of(l), trees, d[l]);
            for (int a = 0; a < 3; ++a)
                o[l][a] = cam.position[a] + rh.ray.tfar[l] * d[l][a] + run.eps * n[a];
            if (geo::dot(n, run.sun) > 0) {
                set(sr, l, o[l], run.sun);
                shadow_valid[l] = -1;
                ++rays;
            }
            frame[l] = golf_frame(n, d[l]);
        }
        occluded(shadow_valid, b.top, &ctx, &sr);
        // The i-th golf-ball ray of every hit, then the shadow rays from their hits.
        for (const trace::GolfRay& g : run.golf) {
            geo::Vec3 w[kLanes];
            for (int l = 0; l < kLanes; ++l) {
                valid[l] = lane_hit[l] ? -1 : 0;
                if (!lane_hit[l]) continue;
                w[l] = golf_direction(g, frame[l]);
                set(rh.ray, l, o[l], w[l]);
                rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
                ++rays;
            }
            intersect(valid, b.top, &ctx, &rh);
            for (int l = 0; l < kLanes; ++l) {
                shadow_valid[l] = 0;
                if (!valid[l] || rh.hit.geomID[l] == RTC_INVALID_GEOMETRY_ID) continue;
                const geo::Vec3 nb = hit_normal(hit_of(l), trees, w[l]);
                if (geo::dot(nb, run.sun) <= 0) continue;
                geo::Vec3 q;
                for (int a = 0; a < 3; ++a)
                    q[a] = o[l][a] + rh.ray.tfar[l] * w[l][a] + run.eps * nb[a];
                set(sr, l, q, run.sun);
                shadow_valid[l] = -1;
                ++rays;
            }
            occluded(shadow_valid, b.top, &ctx, &sr);
        }
        run.total += rays;
    });
    return run.finish();
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 1001;
    const int trees = argc > 2 ? std::atoi(argv[2]) : 3000;
    const long side = argc > 3 ? std::atol(argv[3]) : 512;
    if (n < 2 || trees < 0 || side < 1) {
        std::fprintf(stderr, "usage: bench_trace [VERTICES_PER_SIDE [TREES [IMAGE_SIDE]]]\n");
        return 2;
    }
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::printf(
        "bench_trace: terrain %d x %d vertices (%ld triangles), %d trees, %ld x %ld "
        "pixels, golfball, 3 bands x 7 samples, %u threads\n",
        n, n, 2L * (n - 1) * (n - 1), trees, side, side, threads);
    const auto t_start = Clock::now();

    // Scene through sigchain's Scene (Embree instances for the trees).
    scene::Scene sc;
    const std::size_t terrain = sc.add_mesh(terrain_mesh(n));
    sc.place(terrain, scene::identity_affine());
    const std::size_t tree = sc.add_mesh(tree_mesh());
    int t = 0;
    for (const auto& a : tree_transforms(trees))
        sc.place(tree, a, "2." + std::to_string(++t) + "/");
    sc.commit();
    const double t_scene = seconds_since(t_start);

    // Atmosphere: 3 bands of 7 samples, sun at 35 deg zenith; grey materials.
    std::vector<io::Rad> rads;
    std::vector<std::string> names;
    const double band_start_um[3] = {0.45, 0.53, 0.62};
    for (int b = 0; b < 3; ++b) {
        std::vector<double> wl;
        for (int k = 0; k < 7; ++k) wl.push_back(band_start_um[b] + 0.01 * k);
        io::Rad rad =
            radiometry::uniform_rad(wl, kSunZenithDeg, kSunAzimuthDeg, 0.15, 0.004, 0.9, 0.002);
        // Coupling terms of a clear visible atmosphere (rad(5) COUPLING), so that the
        // render couples the scene with the atmosphere as trace does by default.
        rad.sky->version_minor = 2;
        io::RadCoupling coupling;
        coupling.spherical_albedo.assign(wl.size(), 0.15);
        coupling.diffuse_down.assign(wl.size(), 0.12);
        coupling.diffuse_up.assign(rad.views.size(), std::vector<double>(wl.size(), 0.07));
        rad.sky->coupling = coupling;
        rads.push_back(rad);
        names.push_back("band" + std::to_string(b + 1));
    }
    const auto atmosphere = radiometry::Atmosphere::from_rads(rads, names);
    const std::size_t samples = atmosphere.grid().size();
    const auto materials = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.12, samples), radiometry::grey_material(2, 0.2, samples),
         radiometry::grey_material(3, 0.08, samples), radiometry::grey_material(4, 0.3, samples)});
    const imaging::FrameCamera cam = bench_camera(side);
    const imaging::FrameSensor generator(cam);

    trace::RenderInputs inputs;
    inputs.scene = &sc;
    inputs.atmosphere = &atmosphere;
    inputs.materials = &materials;
    inputs.sensor = &generator;
    trace::RenderOptions options;
    options.sampling = trace::Sampling::Golfball;
    options.samples_per_pixel = 1;
    options.threads = threads;
    // Best of kRepeats runs (wall and CPU time each): the machine may be shared.
    trace::RenderResult result;
    double t_render = 1e300, c_render = 1e300;
    for (int rep = 0; rep < kRepeats; ++rep) {
        const Phase phase("render");
        const auto t0 = Clock::now();
        const double c0 = cpu_seconds();
        result = trace::render(inputs, options);
        t_render = std::min(t_render, seconds_since(t0));
        c_render = std::min(c_render, cpu_seconds() - c0);
    }
    // The same render without the ground-sky coupling and adjacency (adjacency.hpp),
    // side by side: the coupling's share of a render.
    trace::RenderOptions plain = options;
    plain.adjacency = false;
    double t_plain = 1e300;
    for (int rep = 0; rep < kRepeats; ++rep) {
        const Phase phase("render-without-adjacency");
        const auto t0 = Clock::now();
        trace::render(inputs, plain);
        t_plain = std::min(t_plain, seconds_since(t0));
    }
    const double total = t_scene + t_render;  // scene build and one (the best) render
    const double peak_render_mib = peak_memory_mib();
    const auto& s = result.stats;
    const std::uint64_t rays = s.primary_rays + s.secondary_rays + s.shadow_rays;
    const double mrays = static_cast<double>(rays) / t_render / 1e6;
    const double mrays_cpu = static_cast<double>(rays) / c_render / 1e6;

    // The bare Embree loops, same geometry: the golf-ball rays render() casts, and the
    // same number of rays with uniformly random upward hemisphere directions; then the
    // golf-ball rays again with the terrain as an instance (the cost of one more level).
    // Last, the golf-ball rays as 8-pixel packets (bare_golfball_packets), alternating
    // with the single rays.
    BareResult g, b, gi, gp;
    {
        BareScene bare;
        build_bare(bare, n, trees, false);
        auto best = [](BareResult& into, const BareResult& r, int rep) {
            into.rays = r.rays;
            into.seconds = rep ? std::min(into.seconds, r.seconds) : r.seconds;
            into.cpu_seconds = rep ? std::min(into.cpu_seconds, r.cpu_seconds) : r.cpu_seconds;
        };
        for (int rep = 0; rep < kRepeats; ++rep) {
            {
                const Phase phase("bare-golfball");
                best(g,
                     bare_golfball(bare, cam,
                                   static_cast<std::uint64_t>(options.samples_per_pixel),
                                   tree_transforms(trees), kTerrainExtentM, threads),
                     rep);
            }
            if (options.samples_per_pixel != 1) continue;
            const Phase packets("bare-golfball-packets8");
            best(gp,
                 bare_golfball_packets<8, RTCRayHit8, RTCRay8>(bare, cam, tree_transforms(trees),
                                                               kTerrainExtentM, threads),
                 rep);

        }
        const Phase phase("bare-uniform");
        b = bare_loop(bare, cam, s.primary_rays, s.secondary_rays, s.shadow_rays, threads);
    }
    const double peak_bare_mib = peak_memory_mib();
    {
        BareScene bare;
        build_bare(bare, n, trees, true);
        const Phase phase("bare-golfball-instanced");
        gi = bare_golfball(bare, cam, static_cast<std::uint64_t>(options.samples_per_pixel),
                           tree_transforms(trees), kTerrainExtentM, threads);
    }
    const double golf_mrays = static_cast<double>(g.rays) / g.seconds / 1e6;
    const double golf_cpu = static_cast<double>(g.rays) / g.cpu_seconds / 1e6;
    const double bare_mrays = static_cast<double>(b.rays) / b.seconds / 1e6;
    const double bare_cpu = static_cast<double>(b.rays) / b.cpu_seconds / 1e6;
    const double inst_mrays = static_cast<double>(gi.rays) / gi.seconds / 1e6;
    const double inst_cpu = static_cast<double>(gi.rays) / gi.cpu_seconds / 1e6;

    std::printf("scene build (sigchain Scene)   %10.2f s (%zu triangles placed)\n", t_scene,
                sc.triangle_count());
    std::printf("render (best of %d)             %10.2f s (render's own clock, last run: %.2f s)\n",
                kRepeats, t_render, s.seconds);
    std::printf("total (scene + render)         %10.2f s\n", total);
    std::printf(
        "rays cast                      %10llu (%llu primary, %llu secondary, %llu "
        "shadow; %llu hits)\n",
        static_cast<unsigned long long>(rays), static_cast<unsigned long long>(s.primary_rays),
        static_cast<unsigned long long>(s.secondary_rays),
        static_cast<unsigned long long>(s.shadow_rays), static_cast<unsigned long long>(s.hits));
    std::printf("                               Mrays/s   Mrays per CPU s   rays\n");
    std::printf(
        "render                         %7.2f   %7.2f           %llu (%.2f s, %.2f CPU s)\n", mrays,
        mrays_cpu, static_cast<unsigned long long>(rays), t_render, c_render);
    std::printf(
        "bare Embree, golf-ball rays    %7.2f   %7.2f           %llu (%.2f s, %.2f CPU s)\n",
        golf_mrays, golf_cpu, static_cast<unsigned long long>(g.rays), g.seconds, g.cpu_seconds);
    std::printf(
        "bare Embree, uniform hemisphere%7.2f   %7.2f           %llu (%.2f s, %.2f CPU s)\n",
        bare_mrays, bare_cpu, static_cast<unsigned long long>(b.rays), b.seconds, b.cpu_seconds);
    std::printf(
        "bare Embree, golf-ball rays,   %7.2f   %7.2f           %llu (%.2f s, %.2f CPU s)\n"
        "  terrain as an instance\n",
        inst_mrays, inst_cpu, static_cast<unsigned long long>(gi.rays), gi.seconds, gi.cpu_seconds);
    for (const auto& [r, lanes] : {std::pair{gp, 8}}) {
        if (r.rays == 0) continue;
        const double pk = static_cast<double>(r.rays) / r.seconds / 1e6;
        const double pk_cpu = static_cast<double>(r.rays) / r.cpu_seconds / 1e6;
        std::printf(
            "bare Embree, golf-ball rays of %7.2f   %7.2f           %llu (%.2f s, %.2f CPU s)\n"
            "  %d neighbouring pixels as packets (x%.2f single rays)\n",
            pk, pk_cpu, static_cast<unsigned long long>(r.rays), r.seconds, r.cpu_seconds,
            lanes, pk / golf_mrays);
    }
    std::printf("ratio render / bare golf-ball  %7.2f   %7.2f (target >= 0.9)\n",
                mrays / golf_mrays, mrays_cpu / golf_cpu);
    std::printf("ratio render / bare uniform    %7.2f   %7.2f\n", mrays / bare_mrays,
                mrays_cpu / bare_cpu);
    std::printf("ratio render / bare golf-ball, %7.2f   %7.2f\n  terrain instanced\n",
                mrays / inst_mrays, mrays_cpu / inst_cpu);
    std::printf("adjacency and coupling         %10.2f s with, %.2f s without: %+.1f %% (target "
                "< 5 %%)\n",
                t_render, t_plain, 100 * (t_render / t_plain - 1));
    std::printf("peak memory after render       %10.1f MiB (target <= 2048)\n", peak_render_mib);
    std::printf("peak memory with a bare scene  %10.1f MiB\n", peak_bare_mib);
    return 0;
}
