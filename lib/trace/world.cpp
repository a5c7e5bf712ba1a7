// The world beyond the scene: background plane and effective sky (world.hpp).
#include "trace/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "rt/planck.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;

constexpr int kGrid = 64;  // vertical rays per side over the scene's bounding box

// Mean nadir reflectance (and temperature) of what the scene shows from above: the
// first hit of kGrid x kGrid vertical rays at the centres of a regular grid over the
// bounding box. Returns the number of rays that hit.
int mean_from_above(const TraceContext& c, std::vector<double>& rho, double& temperature_k) {
    const scene::Scene& sc = *c.in.scene;
    const scene::Bounds b = sc.bounds();
    rho.assign(c.n, 0.0);
    temperature_k = -1;
    if (b.empty()) return 0;
    std::vector<double> r(c.n);
    int hits = 0, warm = 0;
    double t_sum = 0;
    for_each_seen_from_above(
        sc, b.lower[0], b.upper[0], b.lower[1], b.upper[1], kGrid, {},
        [&](const scene::Hit& hit, double x, double y) {
            const auto& a = sc.attributes(hit);
            const auto& m = facet_material(*c.in.materials, a, sc.origin(hit));
            m.reflectance(m.curve_at(x, y, static_cast<int>(a.texture_curve)), 0.0,
                          a.thickness_cm, r);
            for (std::size_t k = 0; k < c.n; ++k) rho[k] += r[k];
            ++hits;
            if (c.emission) {
                const double t = c.temperatures_k[hit.object][hit.facet];
                if (t > 0) t_sum += t, ++warm;
            }
        });
    if (hits > 0)
        for (double& v : rho) v /= hits;
    if (warm > 0) temperature_k = t_sum / warm;
    return hits;
}

// The material --background ID names, at nadir, curve 0 (its own).
void from_material(const TraceContext& c, std::vector<double>& rho) {
    const long id = c.opt.background_material;
    const radiometry::MaterialOptics* m = c.in.materials->find(id);
    if (!m)
        throw DataError({"--background", 0},
                        "material " + std::to_string(id) + " is not in the material file");
    rho.assign(c.n, 0.0);
    m->reflectance(0, 0.0, m->thickness_cm, rho);
}

}  // namespace

void for_each_seen_from_above(const scene::Scene& scene, double x0, double x1, double y0,
                              double y1, int side, const std::function<bool(double, double)>& keep,
                              const std::function<void(const scene::Hit&, double, double)>& visit) {
    const scene::Bounds b = scene.bounds();
    if (b.empty() || side < 1) return;
    const double top = b.upper[2] + 1 + 0.01 * (b.upper[2] - b.lower[2]);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const double x = x0 + (i + 0.5) / side * (x1 - x0);
            const double y = y0 + (j + 0.5) / side * (y1 - y0);
            if (keep && !keep(x, y)) continue;
            if (auto hit = scene.intersect({x, y, top}, {0, 0, -1})) visit(*hit, x, y);
        }
}

Background make_background(const TraceContext& c) {
    Background bg;
    if (c.opt.background == BackgroundChoice::None) {
        bg.description = "background world: none (--background none): rays below the horizon see 0";
        return bg;
    }
    const scene::Bounds b = c.in.scene->bounds();
    bg.height = b.empty() ? 0.0 : b.lower[2];
    if (c.opt.background == BackgroundChoice::Material) {
        from_material(c, bg.reflectance);
        bg.description = "background world: material " + std::to_string(c.opt.background_material);
        if (c.emission) {  // the scene's own mean temperature: the .mat has none
            std::vector<double> unused;
            mean_from_above(c, unused, bg.temperature_k);
        }
    } else {
        const int hits = mean_from_above(c, bg.reflectance, bg.temperature_k);
        if (hits == 0) {
            bg.description = "background world: none (nothing seen from above the scene)";
            return bg;
        }
        bg.description = "background world: mean of the scene seen from above (" +
                         std::to_string(hits) + " of " + std::to_string(kGrid * kGrid) +
                         " vertical rays)";
    }
    bg.enabled = true;
    char z[64];
    std::snprintf(z, sizeof z, " at height %g", bg.height);
    bg.description += z;
    // Lambertian, unshadowed: rho (E_sun cos(sun zenith) + E_sky) / pi + (1 - rho) B(T).
    const double cos_sun = c.sun_up ? std::max(0.0, c.sun[2]) : 0.0;
    const auto& wl = c.in.atmosphere->grid().wavelength_um;
    bg.radiance.assign(c.n, 0.0);
    for (std::size_t k = 0; k < c.n; ++k) {
        bg.radiance[k] = bg.reflectance[k] * (c.sun_e[k] * cos_sun + c.sky_e[k]) / kPi;
        if (c.emission && bg.temperature_k > 0)
            bg.radiance[k] += (1 - bg.reflectance[k]) * rt::planck_radiance(wl[k], bg.temperature_k);
    }
    return bg;
}

double background_distance(const Background& b, const Vec3& origin, const Vec3& dir) {
    if (!b.enabled || !(dir[2] < 0)) return -1;
    return (origin[2] - b.height) / -dir[2];
}

void add_sky(const TraceContext& c, const Vec3& dir, double* out) {
    if (c.sky_table)
        c.sky_table->add(dir, 1.0, {out, c.n});
    else
        c.sky->add(dir, 1.0, {out, c.n}, c.emission);
}

std::string sky_lookup_description(const TraceContext& c) {
    const std::size_t cells = c.in.atmosphere->sky_cells().size();
    if (!c.sky_table)
        return "sky lookup: exact (four-neighbour interpolation between the .rad's " +
               std::to_string(cells) + " sky cells; --sky-lookup)";
    const int side = c.sky_table->side();
    const double kib = 4.0 * side * side * static_cast<double>(cells > 0 ? c.n : 0) / 1024;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "sky lookup: table %d x %d for rays from facets (the interpolation at each "
                  "cell's centre, read by nearest cell, at most %.2f deg away; %.0f KiB); "
                  "camera rays interpolate",
                  side, side, c.sky_table->max_cell_radius_rad() * kDegPerRad, kib);
    return buf;
}

std::string open_sky_description(const TraceContext& c) {
    if (c.open_sky_tables.empty()) return "";
    const auto& materials = c.in.materials->materials();
    long served = 0;
    for (const auto& m : materials) served += has_lobe(m) ? 0 : 1;
    std::size_t nodes = 0;
    for (const auto& t : c.open_sky_tables) nodes += t->nodes_computed();
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "open sky: integrated over each primary hit's hemisphere (%zu table(s) by "
                  "facet normal, one per incoming fall-off, %g x %g deg, %zu of %zu nodes "
                  "computed), hemisphere rays sample what the scene changes; for %ld of %zu "
                  "material(s)%s",
                  c.open_sky_tables.size(), radiometry::SkyIrradiance::kZenithStepDeg,
                  radiometry::SkyIrradiance::kAzimuthStepDeg, nodes,
                  c.open_sky_tables.size() * c.open_sky_tables.front()->node_count(), served,
                  materials.size(),
                  static_cast<std::size_t>(served) < materials.size()
                      ? " (the others have a specular lobe: their rays sample the sky)"
                      : "");
    return buf;
}

void effective_sky(const TraceContext& c, const Sensor& sensor, const Vec3& dir, double* out,
                   double* tau2, double* lus, double* lue) {
    const std::size_t n = c.n;
    std::fill(out, out + n, 0.0);
    // The sky at the ground, interpolated whatever --sky-lookup says: a table's cells
    // would show in the image as steps.
    c.sky->add(dir, 1.0, {out, n}, c.emission);
    const Vec3 down{dir[0], dir[1], -dir[2]};
    c.in.atmosphere->path(down, sensor.view_angle_deg(down), {tau2, n}, {lus, n}, {lue, n});
    double* path = lus;  // L_us (+ L_ue): the air's path radiance below the sensor
    if (c.emission)
        for (std::size_t k = 0; k < n; ++k) path[k] += lue[k];
    const bool bounded = !c.column_depth.empty();
    const double air_masses = 1 / std::max(dir[2], 1e-6);  // along dir, per vertical column
    for (std::size_t k = 0; k < n; ++k) {
        // No more than the part of L0 made below the sensor, for a source uniform in
        // optical depth: L0 (1 - tau2) / (1 - T), T = exp(-delta / mu) the whole
        // column's transmittance along dir (trace(1) RADIOMETRY).
        const double t = bounded ? std::exp(-c.column_depth[k] * air_masses) : 1.0;
        if (t < 1) path[k] = std::min(path[k], out[k] * (1 - tau2[k]) / (1 - t));
        const double above = tau2[k] > 0 ? std::max(0.0, out[k] - path[k]) / tau2[k] : out[k];
        out[k] = std::min(out[k], above);
    }
}

}  // namespace sigchain::trace
