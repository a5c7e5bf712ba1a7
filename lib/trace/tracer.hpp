// The tracer core shared by every sampling strategy: the read-only render state
// (TraceContext), the facet frame, material lookup, and the per-thread Tracer that
// follows rays (intersection and its refinement, sun visibility, radiance arriving
// along a ray, one-bounce shading, emission) and counts them. The hemisphere part of
// a primary hit is left to a HemisphereStrategy (hemisphere.hpp).
//
// Conventions (documented in trace(1)):
// - Facet frame: z = the geometric normal flipped toward the incoming ray; x = the
//   horizontal unit vector up x z (the facet's strike direction), or east for a
//   horizontal facet; y = z x x.
// - A ray that leaves the scene sees the world beyond it (world.hpp): above the ENU
//   horizon the sky (L_ds, plus L_de with emission) interpolated between the .rad's
//   cells (or, for a secondary ray, read from its table: --sky-lookup), below it the
//   background plane. A primary ray's miss is the renderer's.
// - Radiance in W cm-2 sr-1 um-1, irradiance W cm-2 um-1, distances in scene units.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/numeric.hpp"
#include "geo/vec3.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "trace/arena.hpp"
#include "trace/bounce_estimate.hpp"
#include "radiometry/sky_interpolation.hpp"
#include "radiometry/sky_irradiance.hpp"
#include "radiometry/sky_table.hpp"
#include "trace/render_options.hpp"
#include "trace/world.hpp"

namespace sigchain::trace {

inline constexpr double kPi = 3.14159265358979323846;

class Adjacency;

// Shared, read-only render state, made once per render (make_context). `in` is the
// render's inputs with the atmosphere coupled to the scene's environment
// (adjacency.hpp), held by `adjacency`.
struct TraceContext {
    TraceContext(const RenderInputs& i, const RenderOptions& o) : in(i), opt(o) {}
    const RenderInputs& in;
    std::shared_ptr<const Adjacency> adjacency;
    const RenderOptions& opt;
    std::size_t n = 0;  // spectral samples
    bool emission = false;
    bool any_transmissive = false;
    double eps = 1e-6;  // ray offset, scene units
    geo::Vec3 sun{};
    bool sun_up = false;
    std::vector<double> sun_e;  // Es tau1 per sample
    std::vector<double> sky_e;  // horizontal sky irradiance (+ emitted with emission)
    // Facet temperatures (K, -1 unknown) by placement and facet, with emission only:
    // looked up once here so that no key string is built per hit.
    std::vector<std::vector<double>> temperatures_k;
    bool missing_temperature = false;
    int bounces = 1;                 // opt.bounces, kAutoBounces resolved by the estimate
    BounceEstimate bounce_estimate;  // of the scene (bounce_estimate.hpp)
    std::optional<radiometry::SkyInterpolator> sky;  // the sky between the .rad's cells
    // With RenderOptions::sky_table_side > 0: that sky tabulated (sky_table.hpp), read
    // instead of it by add_sky (world.hpp).
    std::optional<radiometry::SkyTable> sky_table;
    // With RenderOptions::open_sky_integrated: the open sky's irradiance by facet
    // normal (sky_irradiance.hpp), of the same interpolated sky as `sky`, one table per
    // distinct incoming fall-off, and each material's table by its place in
    // in.materials->materials() (open_sky_of); both empty when the open sky is sampled.
    std::vector<std::shared_ptr<const radiometry::SkyIrradiance>> open_sky_tables;
    std::vector<const radiometry::SkyIrradiance*> open_sky;
    // The column's vertical optical depth per sample (Atmosphere::column_optical_depth;
    // empty when unknown), for the effective sky (world.hpp).
    std::vector<double> column_depth;
    // With ConvergenceError::Scene: per band, the radiance at the sensor (W cm-2 sr-1
    // um-1) at the band-centre sample of a 20 % grey Lambertian ground seen at nadir
    // (grey_ground_radiance); empty otherwise.
    std::vector<double> grey_radiance;
    Background background;                           // below the horizon (world.hpp)
    // The planes of the scene's mirror facets whose sun images light primary hits
    // (RenderOptions::sun_image_planes; find_mirror_planes), and why there are none when
    // the scene has mirrors, for --verbose ("" otherwise).
    std::vector<scene::Plane> mirror_planes;
    std::string sun_images_skipped;
    // With RenderOptions::uncertainty_layers (prepare_uncertainty): the sun moved by
    // +-zenith_step_deg in zenith, and per sample tau1 and tau1(z +- step) / tau1(z)
    // by Beer's law in a plane-parallel column (column_depth), for the solar term's
    // central difference in sun zenith (uncertainty.hpp).
    double zenith_step_deg = 0;
    geo::Vec3 sun_plus{}, sun_minus{};
    std::vector<double> tau1, tau1_ratio_plus, tau1_ratio_minus;
};

TraceContext make_context(const RenderInputs& in, const RenderOptions& opt);
// Material m's open-sky table (TraceContext::open_sky), or null when the open sky is
// sampled (or m is not one of the library's materials).
const radiometry::SkyIrradiance* open_sky_of(const TraceContext& c,
                                             const radiometry::MaterialOptics& m);
// Per band, the radiance at the sensor at the band-centre sample of a Lambertian ground
// of `reflectance` in the open, seen at nadir (view angle 0 of the .rad tables) under
// the context's sun and sky (trace_context.cpp): --convergence-error scene's scale.
std::vector<double> grey_ground_radiance(const TraceContext& c, double reflectance = 0.2);
// Fills the context's mirror planes (above) from the scene and its materials
// (tracer_sun_images.cpp).
void find_mirror_planes(TraceContext& c);
// Fills the context's uncertainty fields (above) from its atmosphere (tracer_uncertainty.cpp).
void prepare_uncertainty(TraceContext& c);

// Local facet frame (header comment): z normal, x strike, y = z x x.
struct FacetFrame {
    geo::Vec3 x, y, z;
    explicit FacetFrame(const geo::Vec3& n);
    geo::Vec3 to_local(const geo::Vec3& v) const {
        return {geo::dot(v, x), geo::dot(v, y), geo::dot(v, z)};
    }
    geo::Vec3 to_world(const geo::Vec3& v) const {
        return {x[0] * v[0] + y[0] * v[1] + z[0] * v[2], x[1] * v[0] + y[1] * v[1] + z[1] * v[2],
                x[2] * v[0] + y[2] * v[1] + z[2] * v[2]};
    }
};

// A lambertian material has no specular part whatever its SPECULARITY (brdf.hpp:
// w = cos/pi for LobeShape::None).
double specularity_of(const radiometry::MaterialOptics& m);
bool has_lobe(const radiometry::MaterialOptics& m);   // a finite specular lobe
bool has_delta(const radiometry::MaterialOptics& m);  // a mirror (delta) specular part
// The sun's weights for a material shaded in two parts (MaterialOptics::
// split_reflectance): diffuse w_d cos(sun)/pi, specular w_s lobe(sun)/m for a finite
// lobe (a mirror lobe meets the sun on a set of measure zero); `sun_l`, `wo_l` in the
// facet frame.
struct SplitWeight {
    double diffuse = 0, specular = 0;
};
SplitWeight split_sun_weight(const radiometry::MaterialOptics& m,
                             const radiometry::ReflectanceSplit& w, const geo::Vec3& sun_l,
                             const geo::Vec3& wo_l, double cos_sun);
// A ray along `dir` meets the back of a single-sided facet (geometric normal `normal`):
// the facet reflects and emits nothing toward it (mat(5) SIDES).
bool back_is_black(const radiometry::MaterialOptics& m, const geo::Vec3& normal,
                   const geo::Vec3& dir);
// Multiplies the reflectance `rho` (c.n samples) by the material's Gaussian texture gain
// for the hit facet, each value capped at 1 (mat(5) GAUSSIAN TEXTURE); nothing when
// the material has no Gaussian texture.
void apply_texture_gain(const TraceContext& c, const radiometry::MaterialOptics& m,
                        const scene::Hit& hit, double* rho);

// The facet's material, or DataError naming the facet: a material missing from the
// .mat, or a texture curve the material's .ems does not have.
const radiometry::MaterialOptics& facet_material(const radiometry::MaterialLibrary& materials,
                                                 const scene::FacetAttributes& a,
                                                 const scene::FacetOrigin& o);

struct RayCounters {
    std::uint64_t primary = 0, secondary = 0, shadow = 0, hits = 0;
};

// What the truth layers need of one primary sample's hit. The spectral pointers
// point into the Tracer and hold until its next primary().
struct HitTruth {
    double sun_visibility = 0;  // 0..1 (spectral mean with transmissive blockers)
    double sky_view = 0;        // projected-solid-angle-weighted escaping fraction / pi
    double temperature_k = -1;
    const double* rho = nullptr;         // reflectance rho(theta_o) per sample
    const double* solar = nullptr;       // reflected solar radiance per sample
    const double* downwelled = nullptr;  // reflected sky + neighbours per sample
    // With RenderOptions::uncertainty_layers: d(solar)/d(sun zenith) per degree and
    // d(solar + downwelled)/d(SPECULARITY), the sun's and the sky's, per sample
    // (tracer_uncertainty.cpp); else null.
    const double* solar_per_zenith = nullptr;
    const double* solar_per_specularity = nullptr;
};

class HemisphereStrategy;

// One thread's ray follower: not thread-safe, one per worker; the context must
// outlive it.
class Tracer {
public:
    explicit Tracer(const TraceContext& c);
    ~Tracer();
    Tracer(Tracer&&) noexcept;

    // Radiance leaving the primary ray's first hit toward the sensor into `leave`;
    // `truth` filled on a hit (may be null). Returns the first hit, if any. The
    // random numbers of the sample are those of (seed, row, col, sample).
    std::optional<scene::Hit> primary(const geo::Vec3& origin, const geo::Vec3& dir, long row,
                                      long col, long sample, double* leave, HitTruth* truth);

    // For the strategies. Radiance along a secondary ray from p (just above the
    // facet) in world direction d into `li` (zeroed here); true if it escapes to the sky.
    bool incoming(const geo::Vec3& p, const geo::Vec3& d, double* li);
    // The same without the open sky (--open-sky integrated, the control variate): a ray
    // that escapes upward brings nothing; one that hits a facet its radiance, one that
    // escapes below the horizon the background's. True if it escapes.
    bool incoming_from_scene(const geo::Vec3& p, const geo::Vec3& d, double* li);
    // Exact mirror term s L_i(mirror) of a delta lobe, added to `acc`.
    void add_mirror(double s, const FacetFrame& f, const geo::Vec3& p, const geo::Vec3& wo_l,
                    double* acc);
    // The sample's next uniform number in [0, 1).
    double uniform();
    // The first facet along the ray, its distance refined in double precision (as
    // every ray of the tracer), or none; counts nothing.
    std::optional<scene::Hit> first_hit(const geo::Vec3& origin, const geo::Vec3& dir) const;

    Arena& arena() { return m_arena; }
    const TraceContext& context() const { return m_c; }
    const RayCounters& counters() const { return m_counters; }

private:
    const TraceContext& m_c;
    Arena m_arena;
    std::unique_ptr<HemisphereStrategy> m_strategy;
    RayCounters m_counters;
    long m_row = 0, m_col = 0, m_sample = 0;
    std::uint64_t m_index = 0;  // counter of random numbers within a sample
    std::vector<double> m_truth_rho, m_truth_solar, m_truth_down;
    std::vector<double> m_truth_per_zenith, m_truth_per_specularity;

    const radiometry::MaterialOptics& material_of(const scene::Hit& hit) const;
    double temperature_k(const scene::Hit& hit) const;
    void add_emission(const radiometry::MaterialOptics& m, int curve, double theta_deg, double t_k,
                      double* out);
    double sun_visibility(const geo::Vec3& p, double* vis);
    std::optional<scene::Hit> along(const geo::Vec3& origin, const geo::Vec3& dir, double tnear,
                                    int depth, int transmissions, double* out, HitTruth* truth);
    // along()'s work once the ray has hit: the facet's radiance toward origin, as deep as
    // `depth` says, plus what its transmission lets through.
    void shade_hit(const geo::Vec3& origin, const geo::Vec3& dir, scene::Hit& hit, int depth,
                   int transmissions, double* out, HitTruth* truth);
    void refine(const geo::Vec3& origin, const geo::Vec3& dir, scene::Hit& hit) const;
    void add_world(const geo::Vec3& origin, const geo::Vec3& dir, double* out) const;
    void shade_one_bounce(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                          const scene::FacetAttributes& a, const geo::Vec3& point,
                          const geo::Vec3& n, const geo::Vec3& wo, double* out);
    void shade_path(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                    const scene::FacetAttributes& a, const geo::Vec3& point, const geo::Vec3& n,
                    const geo::Vec3& wo, int depth, double* out);
    void shade_full(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                    const scene::FacetAttributes& a, const geo::Vec3& point, const geo::Vec3& n,
                    const geo::Vec3& wo, double* out, HitTruth* truth);
    void keep_truth(double visibility, double sky_view, double t_k, const double* rho,
                    const double* solar, const double* down, HitTruth& truth);
    // Where a primary hit's hemisphere pass began: the point above the facet and the
    // sample's random-number counter, so that the uncertainty's second pass over the
    // same rays (keep_specularity_rate) draws the same numbers.
    struct HemispherePass {
        geo::Vec3 p;
        std::uint64_t index = 0;
    };
    // The rates of a primary hit into the truth (tracer_uncertainty.cpp): the solar
    // term's in sun zenith, and the reflected radiance's in SPECULARITY (sun and sky);
    // `sun` the unreflected solar term w F E tau1 V per sample, `rho` the reflectance;
    // for a split material each part apart.
    void keep_sun_rates(const radiometry::MaterialOptics& m, const FacetFrame& f,
                        const geo::Vec3& wo_l, const double* rho, const double* sun,
                        const HemispherePass& pass, HitTruth& truth);
    void keep_split_sun_rates(const radiometry::MaterialOptics& m,
                              const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                              const geo::Vec3& wo_l, const double* rho_d, const double* sun_d,
                              const double* rho_s, const double* sun_s, const HemispherePass& pass,
                              HitTruth& truth);
    // d(reflected radiance)/d(SPECULARITY) per sample into m_truth_per_specularity: the
    // parts' incoming sun and sky at unit weight (the hemisphere's rays again, from
    // `pass`), the specular part's times rho_s less the diffuse part's times rho_d.
    void keep_specularity_rate(const radiometry::MaterialOptics& m,
                               const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                               const geo::Vec3& wo_l, const double* rho_d, const double* rho_s,
                               const HemispherePass& pass);
    // The strategy's sun weight times the incoming fall-off for the sun along `sun`.
    double sun_weight_toward(const radiometry::MaterialOptics& m, const FacetFrame& f,
                             const geo::Vec3& wo_l, const geo::Vec3& sun) const;
    // The same three shadings for a material whose diffuse and specular parts reflect
    // differently (tracer_split.cpp): each sum kept in two parts, multiplied by rho_d
    // and rho_s. Every other material takes the functions above, unchanged.
    void shade_one_bounce_split(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                                const scene::FacetAttributes& a, const geo::Vec3& point,
                                const geo::Vec3& n, const geo::Vec3& wo, double* out);
    void shade_path_split(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                          const scene::FacetAttributes& a, const geo::Vec3& point,
                          const geo::Vec3& n, const geo::Vec3& wo, int depth, double* out);
    void shade_full_split(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                          const scene::FacetAttributes& a, const geo::Vec3& point,
                          const geo::Vec3& n, const geo::Vec3& wo, double* out, HitTruth* truth);
    // rho_d (texture curve and Gaussian gain) and rho_s of the hit at theta_o.
    void split_reflectances(const scene::Hit& hit, const radiometry::MaterialOptics& m,
                            const scene::FacetAttributes& a, int curve, double theta_o_deg,
                            double* rho_d, double* rho_s);
    // The sun's images in the context's mirror planes seen from p (just above a primary
    // hit's facet, frame f), weighted as the strategy weights the sun (sun_weight) and
    // added to `acc`; the split form into the diffuse and specular sums
    // (tracer_sun_images.cpp).
    void add_sun_images(const radiometry::MaterialOptics& m, const FacetFrame& f,
                        const geo::Vec3& p, const geo::Vec3& wo_l, double* acc);
    void add_sun_images_split(const radiometry::MaterialOptics& m,
                              const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                              const geo::Vec3& p, const geo::Vec3& wo_l, double* diffuse,
                              double* specular);
    // The image of the sun in `plane` seen from p above a facet of normal n: its
    // direction into `dir` and its irradiance normal to the beam per sample into `e`
    // (the sun's, times the mirror's specular reflectance and the mirror point's view of
    // the sun); false when p does not see it.
    bool sun_image(const scene::Plane& plane, const geo::Vec3& p, const geo::Vec3& n,
                   geo::Vec3& dir, double* e);
    // The sun's weight at a secondary hit (wo_l toward the ray's origin, facet frame):
    // (1 - s) cos/pi plus the specular part, secondary_specular_sun (tracer_secondary.cpp).
    double secondary_sun_weight(const radiometry::MaterialOptics& m, const geo::Vec3& sun_l,
                                const geo::Vec3& wo_l, double cos_sun) const;
    // The specular part's sun weight at a secondary hit for a part of weight `specular`:
    // the lobe's value toward the sun, or with --sampling proposed White (1996), section
    // 5.2.3 step 4's rule (tracer_secondary.cpp).
    double secondary_specular_sun(const radiometry::MaterialOptics& m, double specular, bool lobe,
                                  bool delta, const geo::Vec3& sun_l, const geo::Vec3& wo_l,
                                  double cos_sun) const;
    // The sun's two parts at `point` (normal n, facet frame f) into in_d and in_s,
    // E F(sun) V times split_sun_weight (or the strategy's for a primary hit, `primary`).
    // Returns the sun's mean visibility.
    double add_split_sun(const radiometry::MaterialOptics& m, const radiometry::ReflectanceSplit& w,
                         const FacetFrame& f, const geo::Vec3& p, const geo::Vec3& wo_l,
                         bool primary, double* in_d, double* in_s);
};

}  // namespace sigchain::trace
