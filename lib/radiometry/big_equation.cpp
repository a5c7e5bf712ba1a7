// Beers (1957) first-order error propagation through the Big Equation of White (1996),
// sections 5.1.2 and 5.2.4 (big_equation.hpp).
#include "radiometry/big_equation.hpp"

#include <cmath>
#include <stdexcept>

namespace sigchain::radiometry {

const std::array<std::string_view, kDirsigVariables> kDirsigVariableNames = {
    "total_transmission",    "solar_scattering_term",        "background_specular_component",
    "specular_reflectivity", "specularity",                  "background_diffuse_component",
    "diffuse_reflectivity",  "upwelled_radiance"};

const std::array<std::string_view, kProposedVariables> kProposedVariableNames = {
    "total_transmission", "emissive_component",  "solar_radiance",
    "reflectance",        "downwelled_radiance", "upwelled_radiance"};

namespace {

// The bracket of White (1996), section 5.1.2: (A + Bs) r_s s + (A + Bd) r_d (1 - s) + L_e.
double dirsig_bracket(const DirsigTerms& t) {
    const double s = t.specularity;
    return (t.solar_scattering + t.background_specular) * t.specular_reflectivity * s +
           (t.solar_scattering + t.background_diffuse) * t.diffuse_reflectivity * (1 - s) +
           t.emissive;
}

}  // namespace

double dirsig_radiance(const DirsigTerms& t) {
    return t.total_transmission * dirsig_bracket(t) + t.upwelled;
}

double proposed_radiance(const ProposedTerms& t) {
    const double inner = t.emissive + (t.solar + t.downwelled) * t.reflectance + t.transmissive;
    return t.total_transmission * inner + t.upwelled;
}

// The factors of White (1996), section 5.1.2's S^2 formula, term by term (with L_e in
// the tau2 factor, which White's formula, written for L_e = 0, leaves out).
std::array<double, kDirsigVariables> dirsig_partials(const DirsigTerms& t) {
    const double tau = t.total_transmission, s = t.specularity;
    const double spec_in = t.solar_scattering + t.background_specular;
    const double diff_in = t.solar_scattering + t.background_diffuse;
    return {dirsig_bracket(t),
            tau * (t.specular_reflectivity * s + t.diffuse_reflectivity * (1 - s)),
            tau * t.specular_reflectivity * s,
            tau * spec_in * s,
            tau * (spec_in * t.specular_reflectivity - diff_in * t.diffuse_reflectivity),
            tau * t.diffuse_reflectivity * (1 - s),
            tau * diff_in * (1 - s),
            1.0};
}

// White (1996), section 5.2.4's S^2 formula, term by term.
std::array<double, kProposedVariables> proposed_partials(const ProposedTerms& t) {
    const double tau = t.total_transmission;
    return {t.emissive + (t.solar + t.downwelled) * t.reflectance + t.transmissive,
            tau,
            tau * t.reflectance,
            tau * (t.solar + t.downwelled),
            tau * t.reflectance,
            1.0};
}

std::array<double, kDirsigVariables> dirsig_values(const DirsigTerms& t) {
    return {t.total_transmission,  t.solar_scattering,   t.background_specular,
            t.specular_reflectivity, t.specularity,      t.background_diffuse,
            t.diffuse_reflectivity,  t.upwelled};
}

std::array<double, kProposedVariables> proposed_values(const ProposedTerms& t) {
    return {t.total_transmission, t.emissive,   t.solar,
            t.reflectance,        t.downwelled, t.upwelled};
}

ErrorBudget beers_propagation(std::span<const double> partials, std::span<const double> sigmas) {
    if (partials.size() != sigmas.size())
        throw std::invalid_argument("beers_propagation: one error per partial derivative");
    ErrorBudget b;
    double sum = 0, sum_sq = 0;
    for (std::size_t i = 0; i < partials.size(); ++i) {
        const double c = std::abs(partials[i] * sigmas[i]);
        b.contribution.push_back(c);
        sum += c;
        sum_sq += c * c;
    }
    b.sigma = std::sqrt(sum_sq);  // Beers (1957): S_Y^2 = sum (dY/dX_i S_Xi)^2
    for (double c : b.contribution) {
        b.share_percent.push_back(sum > 0 ? 100 * c / sum : 0);
        b.variance_percent.push_back(sum_sq > 0 ? 100 * c * c / sum_sq : 0);
    }
    return b;
}

std::vector<double> relative_errors(std::span<const double> values,
                                    std::span<const double> percent) {
    if (values.size() != percent.size())
        throw std::invalid_argument("relative_errors: one percentage per value");
    std::vector<double> s;
    for (std::size_t i = 0; i < values.size(); ++i) s.push_back(std::abs(values[i]) * percent[i] / 100);
    return s;
}

}  // namespace sigchain::radiometry
