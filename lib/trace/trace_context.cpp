// The render's shared state (make_context), the facet frame, and the material
// lookups every part of the tracer uses (tracer.hpp).
#include <algorithm>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "trace/adjacency.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {
namespace {

using radiometry::LobeShape;
using radiometry::MaterialOptics;

// Embree works in float (relative precision 6e-8): an offset of 1e-6 of the scene's
// largest coordinate or extent (17 float ulps there) clears self-intersection.
// Larger offsets bias results: raising a canyon floor point by 1e-5 of a 4 km scene
// (4 cm in a 10 m canyon) raised its sky-view factor by 0.2%.
double ray_epsilon(const scene::Scene& sc) {
    scene::Bounds b = sc.bounds();
    double scale = 1;
    if (!b.empty())
        for (int i = 0; i < 3; ++i)
            scale = std::max(
                {scale, std::abs(b.lower[i]), std::abs(b.upper[i]), b.upper[i] - b.lower[i]});
    return 1e-6 * scale;
}

// Facet temperatures (K) by placement and facet: the .tmp's, else the facet's own
// TEMPERATURE (Celsius), else -1 (and c.missing_temperature).
void facet_temperatures(const RenderInputs& in, TraceContext& c) {
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

// The open-sky tables (TraceContext::open_sky): one per distinct incoming fall-off
// (materials that share one share its table; a flat fall-off is all ones), each
// weighted by its materials' F.
void make_open_sky(TraceContext& c) {
    const auto& atm = *c.in.atmosphere;
    std::vector<const MaterialOptics*> owners;  // the first material of each table
    for (const MaterialOptics& m : c.in.materials->materials()) {
        std::size_t t = 0;
        while (t < owners.size() && owners[t]->fall_off != m.fall_off) ++t;
        if (t == owners.size()) {
            owners.push_back(&m);
            std::function<double(double)> fall_off;
            if (!m.flat_fall_off) fall_off = [&m](double cos) { return m.fall_off_cos(cos); };
            c.open_sky_tables.push_back(
                std::make_shared<const radiometry::SkyIrradiance>(atm, c.emission, fall_off));
        }
        c.open_sky.push_back(c.open_sky_tables[t].get());
    }
}

}  // namespace

std::vector<double> grey_ground_radiance(const TraceContext& c, double reflectance) {
    const auto& atm = *c.in.atmosphere;
    std::vector<double> tau2(c.n), scattered(c.n), emitted(c.n), out;
    atm.path(0.0, tau2, scattered, emitted);
    const double mu_sun = c.sun_up ? c.sun[2] : 0.0;
    for (int b = 0; b < static_cast<int>(atm.grid().band_count()); ++b) {
        const std::size_t k = atm.grid().band_centre_sample(b);
        // L = rho / pi (E_s tau1 mu_s + E_sky) tau2 + L_path (White (1996), section 3.1,
        // the Big Equation for a Lambertian facet in the open; c.sky_e has the sky's
        // emission with emission on, as the path's emitted term here).
        const double ground = reflectance / kPi * (c.sun_e[k] * mu_sun + c.sky_e[k]) * tau2[k];
        out.push_back(ground + scattered[k] + (c.emission ? emitted[k] : 0.0));
    }
    return out;
}

TraceContext make_context(const RenderInputs& inputs, const RenderOptions& opt) {
    // The sky with the ground-sky coupling of the scene's environment (adjacency.hpp):
    // the context reads the coupled atmosphere, which the Adjacency holds.
    auto adjacency = std::make_shared<const Adjacency>(inputs, opt);
    const RenderInputs& in = adjacency->inputs();
    TraceContext c(in, opt);
    c.adjacency = adjacency;
    const auto& atm = *in.atmosphere;
    c.n = atm.grid().size();
    c.emission = in.temperatures != nullptr;
    for (const auto& m : in.materials->materials()) c.any_transmissive |= m.transmissive;
    c.eps = ray_epsilon(*in.scene);
    c.sun = atm.sun_direction();
    c.sun_up = atm.sun_up();
    auto se = atm.sun_irradiance_at_ground();
    c.sun_e.assign(se.begin(), se.end());
    auto sk = atm.sky_irradiance_horizontal();
    c.sky_e.assign(sk.begin(), sk.end());
    if (c.emission) {
        auto ske = atm.sky_emitted_irradiance_horizontal();
        for (std::size_t k = 0; k < c.n && k < ske.size(); ++k) c.sky_e[k] += ske[k];
        facet_temperatures(in, c);
    }
    c.sky.emplace(atm);
    if (opt.sky_table_side > 0) c.sky_table.emplace(atm, opt.sky_table_side, c.emission);
    if (opt.open_sky_integrated && atm.has_sky()) make_open_sky(c);
    c.column_depth = atm.column_optical_depth();
    if (opt.convergence_min > 0 && opt.convergence_error == ConvergenceError::Scene)
        c.grey_radiance = grey_ground_radiance(c);
    c.background = make_background(c);
    c.bounce_estimate = estimate_bounces(c);
    c.bounces = opt.bounces == kAutoBounces ? c.bounce_estimate.bounces : opt.bounces;
    find_mirror_planes(c);
    if (opt.uncertainty_layers) prepare_uncertainty(c);
    return c;
}

const radiometry::SkyIrradiance* open_sky_of(const TraceContext& c, const MaterialOptics& m) {
    if (c.open_sky.empty()) return nullptr;
    const auto& all = c.in.materials->materials();
    const std::less<const MaterialOptics*> before;
    if (before(&m, all.data()) || !before(&m, all.data() + all.size())) return nullptr;
    return c.open_sky[static_cast<std::size_t>(&m - all.data())];
}

FacetFrame::FacetFrame(const geo::Vec3& n) : z(n) {
    geo::Vec3 h = geo::cross({0, 0, 1}, n);
    double len = geo::norm(h);
    x = len > 1e-9 ? geo::scale(h, 1 / len) : geo::Vec3{1, 0, 0};
    if (len <= 1e-9) {
        geo::Vec3 v = geo::add(x, geo::scale(n, -geo::dot(x, n)));
        x = geo::scale(v, 1.0 / geo::norm(v));
    }
    y = geo::cross(z, x);
}

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

bool back_is_black(const MaterialOptics& m, const geo::Vec3& normal, const geo::Vec3& dir) {
    return !m.double_sided && geo::dot(normal, dir) > 0;
}

void apply_texture_gain(const TraceContext& c, const MaterialOptics& m, const scene::Hit& hit,
                        double* rho) {
    if (!m.gaussian_texture) return;
    double g = m.texture_gain(c.opt.seed, hit.object, hit.facet);
    for (std::size_t k = 0; k < c.n; ++k) rho[k] = std::min(1.0, g * rho[k]);
}

const MaterialOptics& facet_material(const radiometry::MaterialLibrary& materials,
                                     const scene::FacetAttributes& a, const scene::FacetOrigin& o) {
    const MaterialOptics* m = materials.find(a.material_id);
    if (!m)
        throw DataError({o.file, o.line}, o.description + ": material " +
                                              std::to_string(a.material_id) +
                                              " is not in the material file");
    if (a.texture_curve >= m->emissivity.size())
        throw DataError({o.file, o.line}, o.description + ": texture curve " +
                                              std::to_string(a.texture_curve) + " of material " +
                                              std::to_string(a.material_id) + " does not exist (" +
                                              std::to_string(m->emissivity.size()) + " curve(s))");
    return *m;
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

}  // namespace sigchain::trace
