// A tabulated BRDF (brdf(5)) as the angular shape of reflection: interpolation,
// normalisation to the Brdf contract (brdf.hpp) and importance sampling.
//
// Interpolation: trilinear in (theta_i, theta_o, phi) with the table's own grids, each
// angle clamped to its grid's range (a table from 0 to 80 deg holds its 80 deg values
// to 90); phi is the relative azimuth folded into [0, 180] deg (an isotropic surface:
// f(phi) = f(-phi)). The table is used as given: reciprocity is not imposed.
//
// Normalisation: the table gives the angular shape only; the material's .ems gives
// the reflectance rho(lambda, theta_o). The weight is
//     w(wi, wo) = f(wi, wo) cos(theta_i) / A(theta_o),
//     A(theta_o) = Int f(wi, wo) cos(theta_i) d(omega_i)   (the table's own albedo),
// so Int w = 1 over the hemisphere. Trilinear interpolation is linear in theta_o, so
// A(theta_o) is exactly the linear interpolation of A at the theta_o nodes, where it
// is integrated exactly (piecewise linear in theta_i and phi; closed forms).
//
// Frame: directions in the facet frame (z = normal, wo.z > 0); phi = 0 when wi and wo
// have the same azimuth (back-scattering, the hot spot), 180 deg at the mirror
// direction. Thread-safety: immutable after construction.
#pragma once

#include <vector>

#include "geo/vec3.hpp"
#include "io/brdf.hpp"

namespace sigchain::radiometry {

class TableLobe {
public:
    // Throws std::invalid_argument for a table whose albedo is 0 at every theta_o node.
    explicit TableLobe(const io::BrdfTable& table);

    // The interpolated table f(wi, wo), sr-1 (0 for wi below the horizon).
    double brdf(const geo::Vec3& wi, const geo::Vec3& wo) const;
    // w(wi, wo) of the header comment, per sr.
    double weight(const geo::Vec3& wi, const geo::Vec3& wo) const;
    // A(theta_o) of the header comment (dimensionless).
    double albedo(double theta_o_rad) const;
    // A direction drawn with density pdf(., wo), u1..u3 uniform in [0, 1): the theta_o
    // node by its share of w, then a cell of that node's (theta_i, phi) grid by its
    // mass (tabulated CDF), uniform in solid angle within the cell, phi's sign at random;
    // a tenth of the draws are cosine-weighted so that pdf > 0 wherever w > 0.
    geo::Vec3 sample(const geo::Vec3& wo, double u1, double u2, double u3) const;
    double pdf(const geo::Vec3& wi, const geo::Vec3& wo) const;

private:
    std::vector<double> m_ti, m_to, m_phi;   // grids, rad
    std::vector<double> m_f;                 // values, table order
    std::vector<double> m_albedo;            // A at the theta_o nodes
    std::vector<std::vector<double>> m_cdf;  // per theta_o node: cell CDF (empty: A = 0)

    double node_brdf(std::size_t o, double theta_i, double phi) const;
    double node_albedo(std::size_t o) const;
    void build_cdf(std::size_t o);
    // The two theta_o nodes bracketing theta_o and their shares of w (sum 1).
    void node_shares(double theta_o, std::size_t node[2], double share[2]) const;
    double cell_density(std::size_t o, double theta_i, double phi) const;
};

}  // namespace sigchain::radiometry
