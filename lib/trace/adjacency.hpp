// The coupling of the scene with the atmosphere (trace(1) RADIOMETRY, Adjacency): light reflected
// by the surroundings and scattered back down (ground-sky coupling) or toward the
// sensor (adjacency effect). The model is 6S's (Tanre et al. 1981, Appl. Opt. 20,
// 3676; Vermote et al. 1997, IEEE TGRS 35, 675) over a uniform environment of mean
// reflectance rho_bar:
//   E_sky = E_sky(0) + E_tot(0) rho_bar S / (1 - rho_bar S)      (added isotropically)
//   L_adj = t_d_up(view) rho_bar E_tot(0) / (pi (1 - rho_bar S))  (added to L_us)
// with S, t_d_down, t_d_up from the .rad's COUPLING terms (rad(5)) and E_tot(0) =
// mu_s Es (tau1 + t_d_down). Over a uniform Lambertian plain of reflectance rho this
// is the plane-parallel solution for a ground of albedo rho exactly.
//
// rho_bar: the mean reflectance of the scene seen from above within a disc of radius
// RenderOptions::adjacency_radius_m about the ground point the image centre sees,
// sampled by a regular grid of vertical rays (so each facet counts by its area seen
// from above), each hit's directional-hemispherical reflectance rho(theta_sun) at the
// sun's incidence on it (nadir with the sun down). The world beyond the scene is taken
// to be like the scene (only hits count). Shadows in the environment are ignored.
//
// Units: irradiance W cm-2 um-1, radiance W cm-2 sr-1 um-1, reflectance 0..1.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "trace/render_options.hpp"

namespace sigchain::trace {

// The render's coupling, made once per render (make_context). Immutable afterwards,
// so one serves every thread.
class Adjacency {
public:
    // Decides whether the coupling applies (options.adjacency, the .rad's COUPLING
    // terms, the sun, the threshold kNegligible) and, when it does, computes rho_bar
    // and the coupled atmosphere. `in` must outlive this object.
    Adjacency(const RenderInputs& in, const RenderOptions& options);
    Adjacency(const Adjacency&) = delete;
    Adjacency& operator=(const Adjacency&) = delete;

    bool active() const { return m_active; }
    // Why the coupling is not modelled (for RenderStats::skipped), empty when active.
    const std::string& skipped() const { return m_skipped; }
    // The render's inputs, with the coupled atmosphere when active.
    const RenderInputs& inputs() const { return m_inputs; }
    // rho_bar per grid sample (empty when no environment was sampled).
    const std::vector<double>& environment_reflectance() const { return m_rho_bar; }
    // Adds L_adj for the view angle (deg, signed as in the .rad; linear between the
    // table's view angles, clamped) to `lus` (grid().size() values). Nothing when
    // inactive.
    void add_path(double view_angle_deg, double* lus) const;

    // Below this, rho_bar S and rho_bar t_d_up (at every sample and view) change the
    // image by less than 1e-5 of a white ground's radiance, under a 16-bit sensor's
    // quantum (1.5e-5): the coupling is skipped.
    static constexpr double kNegligible = 1e-5;

private:
    RenderInputs m_inputs;
    radiometry::Atmosphere m_coupled;
    bool m_active = false;
    std::string m_skipped;
    std::vector<double> m_rho_bar;
    std::vector<double> m_view_deg;  // the table's view angles, increasing
    std::vector<double> m_l_adj;     // L_adj per view, per sample: [view * n + k]
};

// The sky increment E_tot rho_bar S / (1 - rho_bar S) (W cm-2 um-1) and the adjacency
// radiance per unit t_d_up, rho_bar E_tot / (pi (1 - rho_bar S)) (W cm-2 sr-1 um-1):
// the model's two terms for one spectral sample (header comment).
double coupled_sky_increment(double e_tot, double rho_bar, double s);
double adjacency_radiance_per_td(double e_tot, double rho_bar, double s);

// rho_bar per grid sample of the scene about ground point `centre` (scene units)
// within `radius` (scene units), from `side` x `side` vertical rays; empty when no ray
// hits (header comment).
std::vector<double> environment_reflectance(const RenderInputs& in, const geo::Vec3& centre,
                                            double radius, int side);

}  // namespace sigchain::trace
