// The angular shape of reflection (scalar; the spectral factor is the material's
// directional reflectance rho(lambda, theta_o)). mat(5) REFLECTANCE
// MODELS, trace(1) RADIOMETRY, White (1996), section 3.6.5 and 5.2.1-5.2.3.
//
// Reflected radiance at a facet, for a viewer in direction wo:
//     L_o(lambda) = rho(lambda, theta_o) * Int w(wi, wo) L_i(lambda, wi) d(omega_i)
// with the weight (per steradian)
//     w(wi, wo) = (1 - s) cos(theta_i) / pi  +  s * lobe(alpha) / m(theta_o)
// where s is the specularity, alpha the angle between wi and the mirror direction of
// wo, lobe() a distribution over directions about the mirror direction with unit
// integral over the sphere, and m(theta_o) the part of it above the facet's
// horizon (so that Int w = 1 over the hemisphere: energy is conserved and a white
// furnace gives L_o = rho L exactly). The `dirsig` model's lobe is a delta: the
// specular term is then s * L_i(mirror direction), handled by the caller
// (is_delta()).
//
// Frame: directions are unit vectors in the facet's local frame, z along the facet
// normal on the viewer's side (wo.z > 0).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "geo/vec3.hpp"
#include "io/brdf.hpp"

namespace sigchain::radiometry {

enum class LobeShape {
    None,         // lambertian: no specular part
    Delta,        // dirsig: mirror direction only
    Uniform,      // cone: constant within a half angle
    LinearCone,   // cone with the .ems lobe table: 1 - alpha / radius(specular angle)
    CosinePower,  // phong: cos^n(alpha), alpha < 90 deg
    Exponential,  // exp(-alpha / width)
    Table,        // a tabulated BRDF (brdf(5), brdf_table.hpp): its shape replaces the lobe
};

struct BrdfSample {
    geo::Vec3 wi{};  // sampled direction (local frame); may be below the horizon
    double pdf = 0;  // density per steradian of the whole mixture (pdf())
};

class Brdf {
public:
    static Brdf lambertian();
    static Brdf delta();                      // dirsig
    static Brdf cone(double half_angle_deg);  // uniform within the half angle
    // White's cone (White (1996), section 5.2.3): radius interpolated in the specular angle from the
    // .ems table rows at 0, 15, ..., 90 deg (base_radius_deg of each row).
    static Brdf linear_cone(const std::array<double, 7>& base_radius_deg);
    // The same cone with the table's depth column alpha (emissivity units, rows at 0, 15,
    // ..., 90 deg): the lobe is then White's (alpha/pi)(1 - phi/beta) above the diffuse
    // (White (1996), section 3), its energy depth_albedo() instead of SPECULARITY's.
    // Throws std::invalid_argument for a depth outside [0, 1].
    static Brdf linear_cone(const std::array<double, 7>& base_radius_deg,
                            const std::array<double, 7>& depth);
    static Brdf phong(double exponent);
    static Brdf exponential(double width_deg);
    // A tabulated BRDF as the lobe: lobe/m is replaced by the table's normalised weight
    // f cos(theta_i) / A(theta_o) (brdf_table.hpp). Throws std::invalid_argument for a
    // table that is 0 everywhere.
    static Brdf table(const io::BrdfTable& table);

    LobeShape shape() const;
    bool is_delta() const;
    bool has_depth() const { return m_depth != nullptr; }
    // Specular albedo of the cone with a depth column for a viewer at cos_theta_o from
    // the normal (the specular angle): Int (alpha/pi)(1 - phi/beta) d(omega) over phi <
    // beta = 2 alpha (1 - sin(beta)/beta), beta in radians, alpha and beta linear in the
    // specular angle between the rows. 0 without a depth column.
    double depth_albedo(double cos_theta_o) const;

    // w(wi, wo) of the header comment for specularity s (0 below the horizon; the
    // delta part is not included: 0 for Delta's specular term).
    double weight(const geo::Vec3& wi, const geo::Vec3& wo, double specularity) const;
    // The specular part alone: lobe(alpha) / m(theta_o), per sr.
    double lobe_weight(const geo::Vec3& wi, const geo::Vec3& wo) const;
    // Importance sampling of w for montecarlo: with probability 1 - s a cosine-
    // weighted direction, with probability s a direction from the (untruncated)
    // lobe about the mirror direction; u1, u2, u3 uniform in [0, 1). pdf() is the
    // density of that mixture, so that w / pdf is an unbiased estimator weight.
    // Lambertian and Delta: cosine samples only, pdf = cos/pi (Delta's mirror term
    // s * L_i(mirror) is the caller's, one exact ray; weight() excludes it).
    BrdfSample sample(const geo::Vec3& wo, double specularity, double u1, double u2,
                      double u3) const;
    double pdf(const geo::Vec3& wi, const geo::Vec3& wo, double specularity) const;

private:
    struct Impl;
    std::shared_ptr<const Impl> m_impl;
    std::shared_ptr<const std::array<double, 7>> m_depth;  // LinearCone's depth column, or null
};

// Mirror direction of wo about the local normal (0, 0, 1).
inline geo::Vec3 mirror(const geo::Vec3& wo) { return {-wo[0], -wo[1], wo[2]}; }

}  // namespace sigchain::radiometry
