// The renderer: primary rays per pixel, the radiance leaving each hit facet from the
// hemisphere above it by a sampling strategy (golfball, dirsig, montecarlo), and the
// atmosphere's path terms (seed 3.4, 3.6.5, 5.2.1-5.2.3; brdf.hpp for the weights).
//
// Conventions (documented in trace(1) through /work/briefs/C_render_notes.md):
// - Facet frame: z = the geometric normal flipped toward the incoming ray; x = the
//   horizontal unit vector up x z (the facet's strike direction), or east for a
//   horizontal facet; y = z x x.
// - A primary ray that misses the scene: radiance 0 in every sample.
// - A secondary ray that escapes above the ENU horizon sees the sky cell it points
//   into (L_ds, plus L_de with emission); one that escapes below it sees nothing (0):
//   the world beyond the scene is not modelled.
// - Radiance in W cm-2 sr-1 um-1, irradiance W cm-2 um-1, distances in scene units.
#include "trace/render.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "core/error.hpp"
#include "rt/planck.hpp"
#include "trace/golfball.hpp"
#include "trace/sampling.hpp"
#include "trace/transmission.hpp"

namespace sigchain::trace {
namespace {

using radiometry::Brdf;
using radiometry::LobeShape;
using radiometry::MaterialOptics;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;

double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross3(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 unit(const Vec3& a) { return scaled(a, 1.0 / std::sqrt(dot3(a, a))); }

// Local facet frame (header comment): z normal, x strike, y = z x x.
struct Frame {
    Vec3 x, y, z;
    explicit Frame(const Vec3& n) : z(n) {
        Vec3 h = cross3({0, 0, 1}, n);
        double len = std::sqrt(dot3(h, h));
        x = len > 1e-9 ? scaled(h, 1 / len) : Vec3{1, 0, 0};
        if (len <= 1e-9) x = unit(plus(x, scaled(n, -dot3(x, n))));
        y = cross3(z, x);
    }
    Vec3 to_local(const Vec3& v) const { return {dot3(v, x), dot3(v, y), dot3(v, z)}; }
    Vec3 to_world(const Vec3& v) const {
        return {x[0] * v[0] + y[0] * v[1] + z[0] * v[2], x[1] * v[0] + y[1] * v[1] + z[1] * v[2],
                x[2] * v[0] + y[2] * v[1] + z[2] * v[2]};
    }
};

// A lambertian material has no specular part whatever its SPECULARITY (brdf.hpp:
// w = cos/pi for LobeShape::None).
double specularity_of(const MaterialOptics& m) {
    return m.brdf.shape() == LobeShape::None ? 0.0 : m.specularity;
}
bool has_lobe(const MaterialOptics& m) {
    return m.specularity > 0 && m.brdf.shape() != LobeShape::None &&
           m.brdf.shape() != LobeShape::Delta;
}
bool has_delta(const MaterialOptics& m) {
    return m.specularity > 0 && m.brdf.shape() == LobeShape::Delta;
}

// The facet's material, or DataError naming the facet: a material missing from the
// .mat, or a texture curve the material's .ems does not have.
const MaterialOptics& facet_material(const radiometry::MaterialLibrary& materials,
                                     const scene::FacetAttributes& a,
                                     const scene::FacetOrigin& o) {
    const MaterialOptics* m = materials.find(a.material_id);
    if (!m)
        throw DataError({o.file, o.line}, o.description + ": material " +
                                              std::to_string(a.material_id) +
                                              " is not in the material file");
    if (a.texture_curve >= m->emissivity.size())
        throw DataError({o.file, o.line},
                        o.description + ": texture curve " + std::to_string(a.texture_curve) +
                            " of material " + std::to_string(a.material_id) + " does not exist (" +
                            std::to_string(m->emissivity.size()) + " curve(s))");
    return *m;
}

// Per-thread spectral scratch: a stack of n-sample buffers, grown on first use only.
class Arena {
public:
    explicit Arena(std::size_t n) : m_n(n) {}
    double* take() {
        if (m_top == m_blocks.size()) m_blocks.push_back(std::make_unique<double[]>(m_n));
        double* p = m_blocks[m_top++].get();
        std::fill(p, p + m_n, 0.0);
        return p;
    }
    std::size_t mark() const { return m_top; }
    void release(std::size_t mark) { m_top = mark; }

private:
    std::size_t m_n;
    std::vector<std::unique_ptr<double[]>> m_blocks;
    std::size_t m_top = 0;
};

struct ArenaScope {
    Arena& arena;
    std::size_t mark;
    explicit ArenaScope(Arena& a) : arena(a), mark(a.mark()) {}
    ~ArenaScope() { arena.release(mark); }
};

// What the centre-sample bookkeeping of a primary hit needs (truth layers).
struct HitTruth {
    double sun_visibility = 0;   // 0..1 (spectral mean with transmissive blockers)
    double sky_view = 0;         // projected-solid-angle-weighted escaping fraction / pi
    double temperature_k = -1;
    const double* rho = nullptr;        // reflectance rho(theta_o) per sample
    const double* solar = nullptr;      // reflected solar radiance per sample
    const double* downwelled = nullptr; // reflected sky + neighbours per sample
};

// Shared, read-only render state.
struct Context {
    Context(const RenderInputs& i, const RenderOptions& o) : in(i), opt(o) {}
    const RenderInputs& in;
    const RenderOptions& opt;
    std::size_t n = 0;  // spectral samples
    bool emission = false;
    bool any_transmissive = false;
    double eps = 1e-6;  // ray offset, scene units
    Vec3 sun{};
    bool sun_up = false;
    std::vector<double> sun_e;    // Es tau1 per sample
    std::vector<double> sky_e;    // horizontal sky irradiance (+ emitted with emission)
    std::vector<Vec3> dirsig_pattern;
    // Light sampling of the sky (montecarlo): cell probabilities and their CDF.
    std::vector<double> sky_prob, sky_cdf;
    bool light_sampling = false;
    // Facet temperatures (K, -1 unknown) by placement and facet, with emission only:
    // looked up once here so that no key string is built per hit.
    std::vector<std::vector<double>> temperatures_k;
    bool missing_temperature = false;
};

double cell_weight(const radiometry::SkyCell& c, bool emitted) {
    double w = 0;
    for (double v : c.scattered) w += v;
    if (emitted)
        for (double v : c.emitted) w += v;
    return w * c.solid_angle_sr;
}

Context make_context(const RenderInputs& in, const RenderOptions& opt) {
    Context c(in, opt);
    const auto& atm = *in.atmosphere;
    c.n = atm.grid().size();
    c.emission = in.temperatures != nullptr;
    for (const auto& m : in.materials->materials()) c.any_transmissive |= m.transmissive;
    scene::Bounds b = in.scene->bounds();
    double scale = 1;
    if (!b.empty())
        for (int i = 0; i < 3; ++i)
            scale = std::max({scale, std::abs(b.lower[i]), std::abs(b.upper[i]),
                              b.upper[i] - b.lower[i]});
    // Embree works in float (relative precision 6e-8): an offset of 1e-6 of the
    // scene's largest coordinate or extent (17 float ulps there) clears
    // self-intersection. Larger offsets bias results: raising a canyon floor point by
    // 1e-5 of a 4 km scene (4 cm in a 10 m canyon) raised its sky-view factor by 0.2%.
    c.eps = 1e-6 * scale;
    c.sun = atm.sun_direction();
    c.sun_up = atm.sun_up();
    auto se = atm.sun_irradiance_at_ground();
    c.sun_e.assign(se.begin(), se.end());
    auto sk = atm.sky_irradiance_horizontal();
    c.sky_e.assign(sk.begin(), sk.end());
    if (c.emission) {
        auto ske = atm.sky_emitted_irradiance_horizontal();
        for (std::size_t k = 0; k < c.n && k < ske.size(); ++k) c.sky_e[k] += ske[k];
    }
    if (c.emission) {
        const scene::Scene& sc = *in.scene;
        c.temperatures_k.resize(sc.placement_count());
        for (std::size_t object = 0; object < sc.placement_count(); ++object) {
            std::size_t mesh = sc.mesh_of_placement(object);
            auto& t = c.temperatures_k[object];
            t.assign(sc.facet_count(mesh), -1.0);
            for (std::uint32_t f = 0; f < t.size(); ++f) {
                scene::Hit h;
                h.object = static_cast<std::uint32_t>(object);
                h.facet = f;
                auto it = in.temperatures->find(sc.facet_key(h));
                double celsius = sc.attributes(mesh, f).temperature_c;
                if (it != in.temperatures->end())
                    t[f] = it->second;
                else if (celsius != -1)
                    t[f] = celsius + 273.15;
                else
                    c.missing_temperature = true;
            }
        }
    }
    if (opt.sampling == Sampling::Dirsig)
        for (const auto& d : cosine_pattern(std::max(1L, opt.hemisphere_samples)))
            c.dirsig_pattern.push_back({d[0], d[1], d[2]});
    if (opt.sampling == Sampling::MonteCarlo && atm.has_sky()) {
        double total = 0;
        for (const auto& cell : atm.sky_cells()) {
            c.sky_prob.push_back(cell_weight(cell, c.emission));
            total += c.sky_prob.back();
        }
        c.light_sampling = total > 0 && opt.hemisphere_samples >= 2;
        double run = 0;
        for (double& p : c.sky_prob) {
            p = total > 0 ? p / total : 0;
            run += p;
            c.sky_cdf.push_back(run);
        }
    }
    return c;
}

struct Counters {
    std::uint64_t primary = 0, secondary = 0, shadow = 0, hits = 0;
};

// One thread's renderer.
class Tracer {
public:
    explicit Tracer(const Context& c) : m_c(c), m_arena(c.n) {}

    Counters counters;

    // Radiance leaving the primary ray's first hit toward the sensor into `leave`;
    // `truth` filled on a hit. Returns the first hit, if any.
    std::optional<scene::Hit> primary(const Vec3& origin, const Vec3& dir, long row, long col,
                                      long sample, double* leave, HitTruth* truth) {
        m_row = row, m_col = col, m_sample = sample, m_index = 0;
        ++counters.primary;
        std::fill(leave, leave + m_c.n, 0.0);
        return along(origin, dir, 0.0, 0, 0, leave, truth);
    }

    Arena& arena() { return m_arena; }

private:
    const Context& m_c;
    Arena m_arena;
    long m_row = 0, m_col = 0, m_sample = 0;
    std::uint64_t m_index = 0;  // counter of random numbers within a sample

    double uniform() {
        return uniform01(m_c.opt.seed, static_cast<std::uint64_t>(m_row),
                         static_cast<std::uint64_t>(m_col), static_cast<std::uint64_t>(m_sample),
                         m_index++);
    }

    const MaterialOptics& material_of(const scene::Hit& hit) {
        const auto& a = m_c.in.scene->attributes(hit);
        const MaterialOptics* m = m_c.in.materials->find(a.material_id);
        if (m && a.texture_curve < m->emissivity.size()) return *m;
        return facet_material(*m_c.in.materials, a, m_c.in.scene->origin(hit));  // throws
    }

    double thickness_of(const scene::FacetAttributes& a, const MaterialOptics& m) const {
        return a.thickness_cm >= 0 ? a.thickness_cm : m.thickness_cm;
    }

    double temperature_k(const scene::Hit& hit) const {
        if (!m_c.emission) return -1;
        return m_c.temperatures_k[hit.object][hit.facet];
    }

    // eps(lambda) F(theta_o) B(lambda, T) added to `out` (seed 3.4 big equation,
    // emissive component; Kirchhoff: directional emissivity = 1 - directional reflectance).
    void add_emission(const MaterialOptics& m, int curve, double theta_deg, double t_k,
                      double* out) {
        if (t_k <= 0) return;
        ArenaScope scope(m_arena);
        double* e = m_arena.take();
        m.directional_emissivity(curve, theta_deg, {e, m_c.n});
        const auto& wl = m_c.in.atmosphere->grid().wavelength_um;
        for (std::size_t k = 0; k < m_c.n; ++k)
            out[k] += e[k] * rt::planck_radiance(wl[k], t_k);
    }

    // Spectral visibility of the sun from p (scene frame) into `vis`; returns its mean.
    // Opaque blockers give 0; transmissive ones multiply their slab transmittance
    // (ext(5)) up to max_transmissions.
    double sun_visibility(const Vec3& p, double* vis) {
        std::fill(vis, vis + m_c.n, 1.0);
        ++counters.shadow;
        if (!m_c.any_transmissive) {
            if (!m_c.in.scene->occluded(p, m_c.sun, 0.0, INFINITY)) return 1;
            std::fill(vis, vis + m_c.n, 0.0);
            return 0;
        }
        ArenaScope scope(m_arena);
        double* t = m_arena.take();
        auto material = [this](const scene::Hit& hit) -> const MaterialOptics& {
            return material_of(hit);
        };
        if (!transmit_through(*m_c.in.scene, material, p, m_c.sun, m_c.eps,
                              m_c.opt.max_transmissions, vis, t, m_c.n, counters.shadow)) {
            std::fill(vis, vis + m_c.n, 0.0);
            return 0;
        }
        double mean = 0;
        for (std::size_t k = 0; k < m_c.n; ++k) mean += vis[k];
        return mean / static_cast<double>(m_c.n);
    }

    // Radiance arriving at `origin` from direction `dir` (the first thing hit beyond
    // tnear, its radiance toward origin), into `out` (zeroed by the caller). depth 0:
    // a primary ray (full hemisphere evaluation); depth >= 1: a secondary ray (the
    // hit facet's radiance one bounce deep). Returns the first hit.
    std::optional<scene::Hit> along(const Vec3& origin, const Vec3& dir, double tnear, int depth,
                                    int transmissions, double* out, HitTruth* truth) {
        auto hit = m_c.in.scene->intersect(origin, dir, tnear, INFINITY);
        if (!hit) {
            if (depth > 0 && dir[2] > 0)
                m_c.in.atmosphere->add_sky_radiance(dir, 1.0, {out, m_c.n}, m_c.emission);
            return hit;
        }
        refine(origin, dir, *hit);
        ++counters.hits;
        const MaterialOptics& m = material_of(*hit);
        const auto& a = m_c.in.scene->attributes(*hit);
        Vec3 n = hit->normal;
        if (dot3(n, dir) > 0) n = scaled(n, -1);
        Vec3 point = plus(origin, scaled(dir, hit->distance));
        Vec3 wo = scaled(dir, -1);
        if (depth == 0)
            shade_full(*hit, m, a, point, n, wo, out, truth);
        else if (m_c.opt.bounces >= 1)
            shade_one_bounce(*hit, m, a, point, n, wo, out);
        if (m.transmissive && transmissions < m_c.opt.max_transmissions) {
            ArenaScope scope(m_arena);
            double* t = m_arena.take();
            double* behind = m_arena.take();
            m.transmittance(std::abs(dot3(n, dir)), thickness_of(a, m), {t, m_c.n});
            if (depth == 0) ++counters.primary; else ++counters.secondary;
            along(origin, dir, hit->distance + m_c.eps, depth, transmissions + 1, behind,
                  nullptr);
            for (std::size_t k = 0; k < m_c.n; ++k) out[k] += t[k] * behind[k];
        }
        return hit;
    }

    // Embree intersects in single precision: a hit distance d is known to about
    // 2^-23 d. From a sensor far from the scene (a satellite 705 km up) that error
    // exceeds the ray offset eps, and the offset point can land below its own facet
    // (which then shadows itself). When the error could reach a tenth of eps, the hit
    // is found again from a point on the ray just before it, where single precision is
    // ample, and the distance is summed in double precision.
    void refine(const Vec3& origin, const Vec3& dir, scene::Hit& hit) {
        constexpr double kFloatRelative = 1.2e-7;  // 2^-23
        if (hit.distance * kFloatRelative <= 0.1 * m_c.eps) return;
        const double back = std::max(100 * m_c.eps, 1e-4 * hit.distance);
        const double base = hit.distance - back;
        const Vec3 near = plus(origin, scaled(dir, base));
        if (auto again = m_c.in.scene->intersect(near, dir, 0.0, 2 * back)) {
            again->distance += base;
            hit = *again;
        }
    }

    // Secondary hit B, one bounce deep (seed 5.2.3 step 4):
    // rho_B(theta) [ (1 - s)/pi (E_sun cos(sigma) V + E_sky (1 + cos(beta))/2)
    //               + s lobe(sun) E_sun V ] + emission of B.
    void shade_one_bounce(const scene::Hit& hit, const MaterialOptics& m,
                          const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                          const Vec3& wo, double* out) {
        ArenaScope scope(m_arena);
        double* rho = m_arena.take();
        double* in = m_arena.take();
        double cos_o = std::clamp(dot3(n, wo), 0.0, 1.0);
        double theta_o = std::acos(cos_o) * kDeg;
        const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
        m.reflectance(curve, theta_o, thickness_of(a, m), {rho, m_c.n});
        double s = specularity_of(m);
        double sky_factor = (1 - s) / kPi * (1 + n[2]) / 2;
        for (std::size_t k = 0; k < m_c.n; ++k) in[k] = sky_factor * m_c.sky_e[k];
        double cos_sun = dot3(n, m_c.sun);
        if (m_c.sun_up && cos_sun > 0) {
            double* vis = m_arena.take();
            if (sun_visibility(plus(point, scaled(n, m_c.eps)), vis) > 0) {
                double w = (1 - s) * cos_sun / kPi;
                if (has_lobe(m)) {
                    Frame f(n);
                    w += s * m.brdf.lobe_weight(f.to_local(m_c.sun), f.to_local(wo));
                }
                for (std::size_t k = 0; k < m_c.n; ++k) in[k] += w * m_c.sun_e[k] * vis[k];
            }
        }
        for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho[k] * in[k];
        if (m_c.emission)
            add_emission(m, curve, theta_o, temperature_k(hit),
                         out);
    }

    // Radiance along a secondary ray from p (just above the facet) in world direction d
    // into `li` (zeroed here); true if it escapes to the sky.
    bool incoming(const Vec3& p, const Vec3& d, double* li) {
        std::fill(li, li + m_c.n, 0.0);
        ++counters.secondary;
        return !along(p, d, 0.0, 1, 0, li, nullptr).has_value();
    }

    // Primary hit: rho(theta_o) * (sun + hemisphere) + emission + (transmission, by
    // the caller).
    void shade_full(const scene::Hit& hit, const MaterialOptics& m,
                    const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                    const Vec3& wo, double* out, HitTruth* truth) {
        ArenaScope scope(m_arena);
        Frame f(n);
        Vec3 wo_l = f.to_local(wo);
        double cos_o = std::clamp(wo_l[2], 0.0, 1.0);
        double theta_o = std::acos(cos_o) * kDeg;
        int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
        double* rho = m_arena.take();
        double* solar = m_arena.take();
        double* down = m_arena.take();
        m.reflectance(curve, theta_o, thickness_of(a, m), {rho, m_c.n});
        Vec3 p = plus(point, scaled(n, m_c.eps));

        double visibility = 0;
        double cos_sun = dot3(n, m_c.sun);
        if (m_c.sun_up && cos_sun > 0) {
            double* vis = m_arena.take();
            visibility = sun_visibility(p, vis);
            if (visibility > 0) {
                double w = sun_weight(m, f.to_local(m_c.sun), wo_l, cos_sun);
                for (std::size_t k = 0; k < m_c.n; ++k) solar[k] = w * m_c.sun_e[k] * vis[k];
            }
        }
        double sky_view = 0;
        switch (m_c.opt.sampling) {
        case Sampling::Golfball: sky_view = golfball(m, f, p, wo_l, down); break;
        case Sampling::Dirsig: sky_view = dirsig(m, f, p, wo_l, down); break;
        case Sampling::MonteCarlo: sky_view = montecarlo(m, f, p, wo_l, down); break;
        }
        for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho[k] * (solar[k] + down[k]);
        double t_k = m_c.emission ? temperature_k(hit) : -1;
        if (m_c.emission) add_emission(m, curve, theta_o, t_k, out);
        if (truth) {
            // The truth buffers outlive this scope: they are copied now.
            truth->sun_visibility = visibility;
            truth->sky_view = sky_view;
            truth->temperature_k = t_k;
            for (std::size_t k = 0; k < m_c.n; ++k) {
                m_truth_rho[k] = rho[k];
                m_truth_solar[k] = rho[k] * solar[k];
                m_truth_down[k] = rho[k] * down[k];
            }
            truth->rho = m_truth_rho.data();
            truth->solar = m_truth_solar.data();
            truth->downwelled = m_truth_down.data();
        }
    }

public:
    std::vector<double> m_truth_rho, m_truth_solar, m_truth_down;
    std::vector<Vec3> m_golf_dirs;          // golf-ball ray directions (local frame)
    std::vector<double> m_golf_lobe;        // golf-ball rays' lobe terms (lobe x solid angle)

private:
    // Weight of the sun (a delta of irradiance E): w(sun, wo) of brdf.hpp; the
    // `dirsig` strategy uses DIRSIG 3's weighting instead (dirsig_sun_weight).
    double sun_weight(const MaterialOptics& m, const Vec3& sun_l, const Vec3& wo_l,
                      double cos_sun) const {
        double s = specularity_of(m);
        if (m_c.opt.sampling == Sampling::Dirsig) {
            // DIRSIG 3 (seed 3.6.5, 3.4 secondary-ray logic): the sun sample of the
            // diffuse part weighted (1 - s) cos/pi; that of the specular part by s and
            // the same cos/pi, counted only when the specular direction "points to the
            // sun" (within 10 deg, seed 5.2.3 step 4). Finite where the true lobe peaks.
            Vec3 mir = radiometry::mirror(wo_l);
            double c = std::clamp(dot3(mir, sun_l), -1.0, 1.0);
            double spec = (s > 0 && m.brdf.shape() != LobeShape::None &&
                           std::acos(c) * kDeg <= 10.0) ? s : 0.0;
            return ((1 - s) + spec) * cos_sun / kPi;
        }
        if (s > 0 && has_lobe(m)) return m.brdf.weight(sun_l, wo_l, s);
        return (1 - s) * cos_sun / kPi;
    }

    // Exact mirror term s L_i(mirror) of a delta lobe (dirsig model), into `acc`.
    void add_mirror(double s, const Frame& f, const Vec3& p, const Vec3& wo_l, double* acc) {
        ArenaScope scope(m_arena);
        double* li = m_arena.take();
        incoming(p, f.to_world(radiometry::mirror(wo_l)), li);
        for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += s * li[k];
    }

    // Golf ball (seed 5.2.3; golfball.hpp): one ray per cell or matrix sub-cell (at
    // its centre, or with golfball_jitter drawn inside it), weight (1 - s) projected/pi + s lobe(centre) solid angle / S, rotated so that
    // azimuth 0 is the mirror direction's. S = sum of lobe(centre) solid angle over
    // the rays: the discrete lobe is normalised like the continuous one (brdf.hpp:
    // Int lobe/m = 1), so a uniform sky gives rho L exactly for any lobe. When the
    // rays catch less than half of the lobe (S < 1/2: a lobe narrower than the cells)
    // the lobe is taken as one ray in the mirror direction, weight s, instead.
    // Returns the sky-view factor.
    double golfball(const MaterialOptics& m, const Frame& f, const Vec3& p, const Vec3& wo_l,
                    double* acc) {
        ArenaScope scope(m_arena);
        double* li = m_arena.take();
        double s = specularity_of(m);
        bool lobe = has_lobe(m);
        Vec3 mir = radiometry::mirror(wo_l);
        double h = std::hypot(mir[0], mir[1]);
        double ca = h > 1e-12 ? mir[0] / h : 1, sa = h > 1e-12 ? mir[1] / h : 0;
        int matrix = lobe ? golfball_matrix(std::acos(std::clamp(mir[2], -1.0, 1.0)) * kDeg) : 0;
        const auto& rays = golfball_rays(matrix);
        auto rotate = [&](double cos_theta, double sin_theta, double cos_phi, double sin_phi) {
            // Rotate the ray's azimuth by the mirror azimuth (angle-sum formulas).
            double cp = cos_phi * ca - sin_phi * sa, sp = sin_phi * ca + cos_phi * sa;
            return Vec3{sin_theta * cp, sin_theta * sp, cos_theta};
        };
        // Directions, and each ray's lobe term lobe(d) x the solid angle it stands for:
        // a centre ray stands for its cell's solid angle; a jittered ray is drawn with
        // density cos / projected within its cell, so its cell's lobe integral is
        // estimated by lobe * projected / cos (the diffuse term is projected / pi
        // exactly either way). The lobe terms are computed once and normalised below.
        const bool jitter = m_c.opt.golfball_jitter;
        m_golf_dirs.resize(rays.size());
        m_golf_lobe.assign(rays.size(), 0.0);
        double lobe_sum = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const GolfRay& r = rays[i];
            double area = r.solid_angle_sr;
            if (jitter) {
                // cos^2 uniform in [cos_lo^2, cos_hi^2] gives density prop. to cos theta.
                double lo2 = r.cos_lo * r.cos_lo, hi2 = r.cos_hi * r.cos_hi;
                double c2 = lo2 + uniform() * (hi2 - lo2);
                double c = std::sqrt(c2);
                double phi = r.phi_lo + uniform() * (r.phi_hi - r.phi_lo);
                m_golf_dirs[i] = rotate(c, std::sqrt(std::max(0.0, 1 - c2)), std::cos(phi),
                                        std::sin(phi));
                area = r.projected_sr / std::max(c, 1e-9);
            } else {
                m_golf_dirs[i] = rotate(r.cos_theta, r.sin_theta, r.cos_phi, r.sin_phi);
            }
            if (lobe) {
                m_golf_lobe[i] = m.brdf.lobe_weight(m_golf_dirs[i], wo_l) * area;
                lobe_sum += m_golf_lobe[i];
            }
        }
        bool lobe_rays = lobe && lobe_sum >= 0.5;
        double svf = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const GolfRay& r = rays[i];
            double w = (1 - s) * r.projected_sr / kPi;
            if (lobe_rays) w += s * m_golf_lobe[i] / lobe_sum;
            if (incoming(p, f.to_world(m_golf_dirs[i]), li)) svf += r.projected_sr / kPi;
            if (w == 0) continue;
            for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += w * li[k];
        }
        if (has_delta(m) || (lobe && !lobe_rays)) add_mirror(s, f, p, wo_l, acc);
        return svf;
    }

    // DIRSIG 3 (seed 3.4, 3.6.5): diffuse part (1 - s) x the mean over a fixed
    // cosine-distributed pattern; specular part s x L_i(mirror), for every lobe shape.
    double dirsig(const MaterialOptics& m, const Frame& f, const Vec3& p, const Vec3& wo_l,
                  double* acc) {
        ArenaScope scope(m_arena);
        double* li = m_arena.take();
        double s = specularity_of(m);
        const auto& pattern = m_c.dirsig_pattern;
        double w = (1 - s) / static_cast<double>(pattern.size());
        long escaped = 0;
        for (const Vec3& d : pattern) {
            if (incoming(p, f.to_world(d), li)) ++escaped;
            for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += w * li[k];
        }
        if (s > 0 && m.brdf.shape() != LobeShape::None) add_mirror(s, f, p, wo_l, acc);
        return static_cast<double>(escaped) / static_cast<double>(pattern.size());
    }

    // Light-sampling density (per sr, ENU direction) of the sky map.
    double sky_pdf(const Vec3& d) const {
        int c = m_c.in.atmosphere->sky_cell(d);
        if (c < 0) return 0;
        return m_c.sky_prob[static_cast<std::size_t>(c)] /
               m_c.in.atmosphere->sky_cells()[static_cast<std::size_t>(c)].solid_angle_sr;
    }

    Vec3 sample_sky(double u1, double u2, double u3) const {
        auto it = std::upper_bound(m_c.sky_cdf.begin(), m_c.sky_cdf.end(), u1);
        std::size_t i = std::min(static_cast<std::size_t>(it - m_c.sky_cdf.begin()),
                                 m_c.sky_cdf.size() - 1);
        while (m_c.sky_prob[i] == 0 && i > 0) --i;  // guards the u1 = cdf edge case
        const auto& c = m_c.in.atmosphere->sky_cells()[i];
        double clo = std::cos(c.zenith_hi_deg / kDeg), chi = std::cos(c.zenith_lo_deg / kDeg);
        double cz = clo + u2 * (chi - clo);
        double az = c.azimuth_lo_deg + u3 * (c.azimuth_hi_deg - c.azimuth_lo_deg);
        double sz = std::sqrt(std::max(0.0, 1 - cz * cz));
        double ar = az / kDeg;
        return {sz * std::sin(ar), sz * std::cos(ar), cz};
    }

    // Monte Carlo with multiple importance sampling (Veach 1997, ch. 9, balance
    // heuristic): n_b directions from Brdf::sample and n_l from the sky map by cell
    // radiance; each ray's estimate is f L / (n_b p_b + n_l p_l). The delta lobe's
    // mirror term is one exact ray. Returns the (unbiased) sky-view-factor estimate.
    double montecarlo(const MaterialOptics& m, const Frame& f, const Vec3& p, const Vec3& wo_l,
                      double* acc) {
        ArenaScope scope(m_arena);
        double* li = m_arena.take();
        double s = specularity_of(m);
        bool delta = m.brdf.shape() == LobeShape::Delta || m.brdf.shape() == LobeShape::None;
        double s_sample = delta ? 0.0 : s;  // the delta part is not sampled
        long total = std::max(1L, m_c.opt.hemisphere_samples);
        long n_l = m_c.light_sampling ? total / 2 : 0;
        long n_b = total - n_l;
        double svf = 0;
        for (long i = 0; i < total; ++i) {
            double u1 = uniform(), u2 = uniform(), u3 = uniform();
            Vec3 d_l, d_w;
            if (i < n_b) {
                d_l = m.brdf.sample(wo_l, s_sample, u1, u2, u3).wi;
                d_w = f.to_world(d_l);
            } else {
                d_w = sample_sky(u1, u2, u3);
                d_l = f.to_local(d_w);
            }
            if (d_l[2] <= 0) continue;  // below the facet: w = 0
            double fw = delta ? (1 - s) * d_l[2] / kPi : m.brdf.weight(d_l, wo_l, s);
            double denom = static_cast<double>(n_b) * m.brdf.pdf(d_l, wo_l, s_sample);
            if (n_l > 0) denom += static_cast<double>(n_l) * sky_pdf(d_w);
            if (denom <= 0) continue;
            bool escaped = incoming(p, d_w, li);
            if (escaped) svf += d_l[2] / kPi / denom;
            for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += fw / denom * li[k];
        }
        if (has_delta(m)) add_mirror(s, f, p, wo_l, acc);
        return svf;
    }
};

// Pixel accumulation of the truth layers (truth_layer_names order).
enum TruthLayer {
    kHit, kMaterial, kObject, kFacet, kShadow, kSkyView, kViewAngle, kRange, kTemperature,
    kFixedLayers
};
constexpr int kPerBand = 5;  // reflectance, solar, downwelled, upwelled, transmission

void render_row(const Context& c, Tracer& tr, long row, long out_row, RenderResult& res,
                std::vector<double>& pixel, std::vector<double>& truth_acc) {
    const auto& cam = *c.in.camera;
    const auto& atm = *c.in.atmosphere;
    const std::size_t n = c.n;
    const long spp = std::max(1L, c.opt.samples_per_pixel);
    Arena& arena = tr.arena();
    ArenaScope scope(arena);
    double* leave = arena.take();
    double* tau2 = arena.take();
    double* lus = arena.take();
    double* lue = arena.take();
    const auto& grid = atm.grid();
    const int bands = static_cast<int>(grid.band_count());
    std::vector<std::size_t> centre;  // per band; small, once per row
    for (int b = 0; b < bands; ++b) centre.push_back(grid.band_centre_sample(b));
    for (long col = 0; col < cam.columns(); ++col) {
        std::fill(pixel.begin(), pixel.end(), 0.0);
        std::fill(truth_acc.begin(), truth_acc.end(), 0.0);
        long hits = 0;
        for (long i = 0; i < spp; ++i) {
            auto off = stratified_offset(i, spp, uniform01(c.opt.seed, row, col, i, ~0ULL),
                                         uniform01(c.opt.seed, row, col, i, ~1ULL));
            Vec3 o, d;
            cam.ray(static_cast<double>(row) + off[0], static_cast<double>(col) + off[1], o, d);
            HitTruth ht;
            auto hit = tr.primary(o, d, row, col, i, leave, c.opt.truth ? &ht : nullptr);
            if (!hit) continue;
            ++hits;
            double va = cam.view_angle_deg(d);
            atm.path(d, va, {tau2, n}, {lus, n}, {lue, n});
            for (std::size_t k = 0; k < n; ++k) {
                double l = tau2[k] * leave[k] + lus[k] + (c.emission ? lue[k] : 0.0);
                pixel[k] += l;
            }
            if (!c.opt.truth) continue;
            truth_acc[kShadow] += 1 - ht.sun_visibility;
            truth_acc[kSkyView] += ht.sky_view;
            truth_acc[kViewAngle] += va;
            truth_acc[kRange] += hit->distance * c.opt.meters_per_unit;
            truth_acc[kTemperature] += ht.temperature_k;
            for (int b = 0; b < bands && ht.rho; ++b) {
                std::size_t k = centre[static_cast<std::size_t>(b)];
                double* t = &truth_acc[kFixedLayers + kPerBand * b];
                t[0] += ht.rho[k];
                // At the sensor: pixel = solar + downwelled + upwelled (+ emission).
                t[1] += tau2[k] * ht.solar[k];
                t[2] += tau2[k] * ht.downwelled[k];
                t[3] += lus[k];
                t[4] += tau2[k];
            }
        }
        for (std::size_t k = 0; k < n; ++k)
            res.radiance.at(static_cast<int>(k), out_row, col) =
                static_cast<float>(pixel[k] / static_cast<double>(spp));
        if (!c.opt.truth) continue;
        auto put = [&](int layer, double v) {
            res.truth.at(layer, out_row, col) = static_cast<float>(v);
        };
        put(kHit, static_cast<double>(hits) / static_cast<double>(spp));
        // Categorical layers from the ray through the pixel centre.
        Vec3 o, d;
        cam.ray(row + 0.5, col + 0.5, o, d);
        auto centre_hit = c.in.scene->intersect(o, d);
        put(kMaterial, centre_hit ? c.in.scene->attributes(*centre_hit).material_id : -1);
        put(kObject, centre_hit ? static_cast<double>(centre_hit->object) : -1);
        put(kFacet, centre_hit ? static_cast<double>(centre_hit->facet) : -1);
        double h = static_cast<double>(hits);
        for (int layer = kShadow; layer < static_cast<int>(truth_acc.size()); ++layer) {
            if (layer == kMaterial || layer == kObject || layer == kFacet) continue;
            double v = hits ? truth_acc[static_cast<std::size_t>(layer)] / h : 0.0;
            if (layer == kTemperature && (!hits || v < 0)) v = -1;
            put(layer, v);
        }
        if (hits == 0) put(kViewAngle, cam.view_angle_deg(d));
    }
}

}  // namespace

std::vector<std::string> truth_layer_names(const radiometry::SpectralGrid& grid) {
    std::vector<std::string> names = {"hit",       "material_id",     "object",
                                      "facet",     "shadow_fraction", "sky_view_factor",
                                      "view_angle_deg", "range_m",    "temperature_k"};
    for (const auto& band : grid.band_names)
        for (const char* q : {"reflectance_", "solar_", "downwelled_", "upwelled_",
                              "transmission_"})
            names.push_back(q + band);
    return names;
}

void validate_scene(const scene::Scene& scene, const radiometry::MaterialLibrary& materials) {
    std::vector<bool> checked;
    for (std::size_t object = 0; object < scene.placement_count(); ++object) {
        std::size_t mesh = scene.mesh_of_placement(object);
        if (mesh < checked.size() && checked[mesh]) continue;
        if (mesh >= checked.size()) checked.resize(mesh + 1, false);
        checked[mesh] = true;
        for (std::uint32_t f = 0; f < scene.facet_count(mesh); ++f)
            facet_material(materials, scene.attributes(mesh, f), scene.origin(mesh, f));
    }
}

RenderResult render(const RenderInputs& inputs, const RenderOptions& options,
                    const std::function<void(long, long)>& progress) {
    auto start = std::chrono::steady_clock::now();
    Context c = make_context(inputs, options);
    const RayGenerator& cam = *inputs.camera;
    long row_begin = std::clamp(options.row_begin, 0L, cam.rows());
    long row_end = options.row_end < 0 ? cam.rows() : std::clamp(options.row_end, row_begin,
                                                                  cam.rows());
    long rows = row_end - row_begin;
    RenderResult res;
    res.radiance = image::Image(rows, cam.columns(), static_cast<int>(c.n));
    res.radiance.wavelength_um = inputs.atmosphere->grid().wavelength_um;
    res.radiance.units = "W cm-2 sr-1 um-1";
    std::vector<std::string> names = truth_layer_names(inputs.atmosphere->grid());
    if (options.truth) {
        res.truth = image::Image(rows, cam.columns(), static_cast<int>(names.size()));
        res.truth.channel_names = names;
    }

    unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
    threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max(1L, rows))));
    std::atomic<long> next{0}, done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_mutex;
    std::vector<Counters> counters(threads);

    auto work = [&](unsigned id, bool report) {
        try {
            Tracer tr(c);
            tr.m_truth_rho.resize(c.n), tr.m_truth_solar.resize(c.n), tr.m_truth_down.resize(c.n);
            std::vector<double> pixel(c.n);
            std::vector<double> truth_acc(options.truth ? names.size() : 0);
            for (long r; !failed && (r = next.fetch_add(1)) < rows;) {
                render_row(c, tr, row_begin + r, r, res, pixel, truth_acc);
                long d = done.fetch_add(1) + 1;
                if (report && progress) progress(d, rows);
            }
            counters[id] = tr.counters;
        } catch (...) {
            std::lock_guard<std::mutex> lock(error_mutex);
            if (!error) error = std::current_exception();
            failed = true;
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t, false);
    work(0, true);
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
    if (progress) progress(rows, rows);

    for (const Counters& k : counters) {
        res.stats.primary_rays += k.primary;
        res.stats.secondary_rays += k.secondary;
        res.stats.shadow_rays += k.shadow;
        res.stats.hits += k.hits;
    }
    auto& skipped = res.stats.skipped;
    if (!c.emission) skipped.push_back("emission (no facet temperatures given)");
    if (c.missing_temperature) skipped.push_back("emission of facets without a temperature");
    if (!c.any_transmissive) skipped.push_back("transmission (no transmissive material)");
    bool lobes = false;
    for (const auto& m : inputs.materials->materials()) lobes |= specularity_of(m) > 0;
    if (!lobes) skipped.push_back("specular lobes (every specularity is 0)");
    if (!inputs.atmosphere->has_sky()) skipped.push_back("downwelled sky (no sky in the .rad)");
    if (options.bounces > 1) skipped.push_back("bounces beyond 1 (secondary hits are one bounce deep)");
    if (options.bounces == 0) skipped.push_back("light from neighbouring facets (bounces 0)");
    res.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
}

}  // namespace sigchain::trace
