// First-order error propagation (Beers, 1957) through the "Big Equation" of White
// (1996), section 5.1.2 (DIRSIG's), and section 5.2.4 (the proposed model's): the
// radiance, its partial derivatives, and each variable's contribution to the error.
//
// Units: every radiance-like term (solar term Es cos(sigma) tau1 / pi, background
// components, emissive, upwelled, the result) in one radiance unit of the caller's
// choice (sigchain's W cm-2 sr-1 um-1, or White's band-integrated "W/cm^2");
// transmittances, reflectivities and specularity unitless. Errors S_X are one-sigma,
// in the unit of their variable (relative_errors() turns White's percentages into them).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace sigchain::radiometry {

// The terms of DIRSIG's Big Equation, White (1996), section 5.1.2:
// L = tau2 [(A + Bs) r_s s + (A + Bd) r_d (1 - s) + L_e] + L_us,
// A = Es cos(sigma) tau1 / pi. Variables in the order of White's table 5.5.
struct DirsigTerms {
    double total_transmission = 1;     // tau2
    double solar_scattering = 0;       // A = Es cos(sigma) tau1 / pi
    double background_specular = 0;    // Bs = L_ds,specular
    double specular_reflectivity = 0;  // r_s, the lobe peak
    double specularity = 0;            // s
    double background_diffuse = 0;     // Bd = L_ds,diffuse
    double diffuse_reflectivity = 0;   // r_d
    double upwelled = 0;               // L_us
    double emissive = 0;               // L_e (therm's; not a variable of table 5.5)
};
inline constexpr std::size_t kDirsigVariables = 8;
// The names of table 5.5, in DirsigTerms order.
extern const std::array<std::string_view, kDirsigVariables> kDirsigVariableNames;

// The proposed model's equation, White (1996), section 5.2.4:
// L = tau2 (L_e + A rho + D rho + L_t) + L_us, D = F L_ds + (1 - F) L_bs.
// Variables in the order of White's table 5.10.
struct ProposedTerms {
    double total_transmission = 1;  // tau2
    double emissive = 0;            // L_e
    double solar = 0;               // A = Es cos(sigma) tau1 / pi
    double reflectance = 0;         // rho, the BRDF's reflectance factor toward the sensor
    double downwelled = 0;          // D
    double upwelled = 0;            // L_us
    double transmissive = 0;        // L_t (not a variable of table 5.10)
};
inline constexpr std::size_t kProposedVariables = 6;
extern const std::array<std::string_view, kProposedVariables> kProposedVariableNames;

double dirsig_radiance(const DirsigTerms& t);
double proposed_radiance(const ProposedTerms& t);
// dL/dX for each variable of table 5.5 (analytic; White's S^2 formula's factors).
std::array<double, kDirsigVariables> dirsig_partials(const DirsigTerms& t);
// dL/dX for each variable of table 5.10.
std::array<double, kProposedVariables> proposed_partials(const ProposedTerms& t);
// The variables of table 5.5 / 5.10 as an array, in the same order (for relative errors).
std::array<double, kDirsigVariables> dirsig_values(const DirsigTerms& t);
std::array<double, kProposedVariables> proposed_values(const ProposedTerms& t);

// Beers (1957), White (1996), section 5.1.2: S_Y^2 = sum_i (dY/dX_i S_Xi)^2, variables
// independent. `contribution[i]` = |dY/dX_i S_Xi| (radiance unit); `share_percent[i]` =
// 100 contribution[i] / sum of contributions, the reading of White's "contributor, about
// 50 %" (the shares of the one-sigma terms; docs/chapter5.md shows that their squares do
// not fit the prose); `variance_percent[i]` = 100 contribution[i]^2 / S_Y^2.
struct ErrorBudget {
    double sigma = 0;  // S_Y
    std::vector<double> contribution, share_percent, variance_percent;
};
ErrorBudget beers_propagation(std::span<const double> partials, std::span<const double> sigmas);

// S_X = percent / 100 * X for each variable: White's tables give errors in percent of
// the value.
std::vector<double> relative_errors(std::span<const double> values,
                                    std::span<const double> percent);

// White's error estimates, percent: table 5.5 (DirsigTerms order) and table 5.10
// (ProposedTerms order).
inline constexpr std::array<double, kDirsigVariables> kTable55Percent = {4,   8.85, 6.35, 2.5,
                                                                          5.0, 6.35, 2.5,  6.35};
inline constexpr std::array<double, kProposedVariables> kTable510Percent = {4,   8.85, 8.85,
                                                                             2.5, 8.85, 6.35};

}  // namespace sigchain::radiometry
