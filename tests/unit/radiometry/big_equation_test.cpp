// Beers (1957) error propagation through White (1996)'s Big Equation (sections 5.1.2
// and 5.2.4): the analytic partial derivatives against central finite differences (an
// independent check), and the prose percentages of section 5.1.2 (its tables 5.6-5.9
// are figures whose numbers the source does not print) on inputs stated below.
// scripts/chapter5 prints the recorded properties into docs/chapter5.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "radiometry/big_equation.hpp"

namespace sigchain::radiometry {
namespace {

// Central difference of f in variable i of `values` (step h relative to the value, or
// absolute near 0): error O(h^2) times the third derivative, which is 0 here (the
// equation is at most cubic in its variables and quadratic in any one: exact to
// rounding).
template <std::size_t N, class F>
double central_difference(std::array<double, N> x, std::size_t i, F f) {
    const double h = std::max(1e-6, 1e-6 * std::abs(x[i]));
    const double x0 = x[i];
    x[i] = x0 + h;
    const double up = f(x);
    x[i] = x0 - h;
    return (up - f(x)) / (2 * h);
}

DirsigTerms dirsig_from(const std::array<double, kDirsigVariables>& v, double emissive) {
    return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], emissive};
}

ProposedTerms proposed_from(const std::array<double, kProposedVariables>& v, double transmissive) {
    return {v[0], v[1], v[2], v[3], v[4], v[5], transmissive};
}

TEST(BigEquation, DirsigPartialsMatchFiniteDifferences) {
    // Arbitrary, all terms non-zero (an emissive term too, which White's formula omits).
    const DirsigTerms t{0.83, 0.41, 0.027, 0.2, 0.1, 0.09, 0.15, 0.012, 0.004};
    const auto p = dirsig_partials(t);
    const auto f = [&](const std::array<double, kDirsigVariables>& x) {
        return dirsig_radiance(dirsig_from(x, t.emissive));
    };
    for (std::size_t i = 0; i < kDirsigVariables; ++i)
        // Rounding of the difference: about 1e-16 / 1e-6 = 1e-10 of the radiance.
        EXPECT_NEAR(p[i], central_difference(dirsig_values(t), i, f), 1e-8)
            << kDirsigVariableNames[i];
}

TEST(BigEquation, ProposedPartialsMatchFiniteDifferences) {
    const ProposedTerms t{0.87, 0.003, 0.38, 0.17, 0.08, 0.011, 0.002};
    const auto p = proposed_partials(t);
    const auto f = [&](const std::array<double, kProposedVariables>& x) {
        return proposed_radiance(proposed_from(x, t.transmissive));
    };
    for (std::size_t i = 0; i < kProposedVariables; ++i)
        EXPECT_NEAR(p[i], central_difference(proposed_values(t), i, f), 1e-8)
            << kProposedVariableNames[i];
}

TEST(BigEquation, BeersSumsSquaresAndTheSharesSumToAHundred) {
    const std::vector<double> partials{2, -3, 0.5}, sigmas{0.1, 0.2, 0.4};
    const ErrorBudget b = beers_propagation(partials, sigmas);
    EXPECT_DOUBLE_EQ(b.sigma, std::sqrt(0.04 + 0.36 + 0.04));
    EXPECT_DOUBLE_EQ(b.contribution[1], 0.6);  // |dY/dX| S_X, the sign dropped
    EXPECT_NEAR(b.share_percent[0] + b.share_percent[1] + b.share_percent[2], 100, 1e-12);
    EXPECT_NEAR(b.variance_percent[1], 100 * 0.36 / 0.44, 1e-12);
}

// White (1996), section 5.1.2's inputs came from build_radiance runs that the source
// does not print (its tables 5.6 and 5.7 are figures). These are a clear-sky set for a
// nadir view from 1 km with the sun at 45 deg, relative to the solar term A = 1, the
// diffuse-to-direct ratio falling from blue to red as in any clear atmosphere; the
// material is White's (r_d 0.15, r_s 0.2, s 0.1), Bs 10 % of L_ds (section 5.1.3).
struct Band {
    const char* name;
    double tau2, sky, upwelled;
};
constexpr std::array<Band, 3> kBands = {{{"blue", 0.90, 0.14, 0.016},
                                         {"green", 0.93, 0.075, 0.0085},
                                         {"red", 0.95, 0.065, 0.0075}}};

DirsigTerms case1(const Band& b) {
    return {b.tau2, 1.0, 0.1 * b.sky, 0.2, 0.1, b.sky, 0.15, b.upwelled, 0};
}

// Case 2: in the shadow of a 10 % diffuse wall that hides the sun and half the sky;
// the wall, lit by its half of the sky, adds 0.1 x half of that; the specular
// direction (the zenith, on the wall's edge) sees the same mixture.
DirsigTerms case2(const Band& b) {
    const double bd = 0.5 * b.sky + 0.5 * 0.1 * 0.5 * b.sky;
    return {b.tau2, 0.0, bd, 0.2, 0.1, bd, 0.15, b.upwelled, 0};
}

ErrorBudget dirsig_budget(const DirsigTerms& t) {
    const auto v = dirsig_values(t);
    const auto sig = relative_errors(v, kTable55Percent);
    const auto p = dirsig_partials(t);
    return beers_propagation(p, sig);
}

enum Var { kTau, kSolar, kBs, kRs, kS, kBd, kRd, kLus };

void record(const std::string& key, double value) {
    ::testing::Test::RecordProperty(key, std::to_string(value));
}

TEST(BigEquation, Case1SunlitSharesAsWhitesProse) {
    std::array<double, 3> solar{};
    for (std::size_t i = 0; i < kBands.size(); ++i) {
        const ErrorBudget e = dirsig_budget(case1(kBands[i]));
        const auto& sh = e.share_percent;
        for (std::size_t v = 0; v < kDirsigVariables; ++v) {
            const std::string name(kDirsigVariableNames[v]);
            record(std::string("case1.") + kBands[i].name + "." + name, sh[v]);
            record(std::string("case1var.") + kBands[i].name + "." + name, e.variance_percent[v]);
        }
        // "solar_scattering_term ... the largest contributor ..., about 50 %": the
        // largest, within 5 points of 50 ("about").
        EXPECT_EQ(std::max_element(sh.begin(), sh.end()) - sh.begin(), kSolar);
        EXPECT_NEAR(sh[kSolar], 50, 5) << kBands[i].name;
        solar[i] = sh[kSolar];
        // "total transmission ..., at 26 %, ... constant across the bands" and "diffuse
        // reflectivity, at 14 %, ... constant": one figure quoted for three bands; we
        // accept one point either side.
        EXPECT_NEAR(sh[kTau], 26, 1) << kBands[i].name;
        EXPECT_NEAR(sh[kRd], 14, 1) << kBands[i].name;
        // "upwelled_radiance and background_diffuse_component ... approximately 4 % in
        // the blue band and 2 % in the green and red": within one point.
        const double expect = i == 0 ? 4 : 2;
        EXPECT_NEAR(sh[kLus], expect, 1) << kBands[i].name;
        EXPECT_NEAR(sh[kBd], expect, 1) << kBands[i].name;
        // "Combined they contribute less than four percent."
        EXPECT_LT(sh[kBs] + sh[kRs] + sh[kS], 4) << kBands[i].name;
    }
    // "roughly equal across the bands (slightly less for the blue)".
    EXPECT_LT(solar[0], solar[1]);
    EXPECT_LT(solar[0], solar[2]);
}

TEST(BigEquation, Case2ShadowUpwelledDominates) {
    for (const Band& b : kBands) {
        const ErrorBudget e = dirsig_budget(case2(b));
        const auto& sh = e.share_percent;
        for (std::size_t v = 0; v < kDirsigVariables; ++v)
            record(std::string("case2.") + b.name + "." + std::string(kDirsigVariableNames[v]),
                   sh[v]);
        // "upwelled_radiance becomes the dominate error contributor ..., at 45-38 %":
        // the largest, within the quoted range (whole percent: half a point either side).
        EXPECT_EQ(std::max_element(sh.begin(), sh.end()) - sh.begin(), kLus) << b.name;
        EXPECT_GE(sh[kLus], 37.5) << b.name;
        EXPECT_LE(sh[kLus], 45.5) << b.name;
        // "The next largest contributors are the background_diffuse_component and the
        // total_transmission, at 20-30 %": second and third. Bd is within the range;
        // tau2's share is tied to Bd's (0.04 R against 0.0635 r_d (1 - s) Bd, R about
        // (r_d (1 - s) + r_s s) Bd), 0.72 of it, so with upwelled at 38-45 % it cannot
        // also reach 20 %: checked at 17 % and more, the difference in docs/chapter5.md.
        std::vector<double> rest(sh);
        rest[kLus] = -1;
        const auto second = std::max_element(rest.begin(), rest.end()) - rest.begin();
        rest[second] = -1;
        const auto third = std::max_element(rest.begin(), rest.end()) - rest.begin();
        EXPECT_EQ(second, kBd) << b.name;
        EXPECT_EQ(third, kTau) << b.name;
        EXPECT_GE(sh[kBd], 20) << b.name;
        EXPECT_LE(sh[kBd], 30) << b.name;
        EXPECT_GE(sh[kTau], 17) << b.name;
        // "This is followed by the diffuse reflectivity and the 'specular' factors."
        EXPECT_GT(sh[kRd], sh[kBs] + sh[kRs] + sh[kS]) << b.name;
    }
}

TEST(BigEquation, EffectiveReflectanceAgainstTheSunAsWhiteComputes) {
    // White (1996), section 5.1.2: the sun, not in the specular direction, is still
    // weighted r_s s + r_d (1 - s) = 0.155 instead of 0.135 (+14.8 %), and 0.175
    // instead of 0.075 (+133 %) for r_d 0.1, r_s 0.4, s 0.25. dL/dA / tau2 is that
    // weight.
    const auto w = [](double rd, double rs, double s) {
        return dirsig_partials({1, 1, 0, rs, s, 0, rd, 0, 0})[kSolar];
    };
    EXPECT_NEAR(w(0.15, 0.2, 0.1), 0.155, 1e-15);
    EXPECT_NEAR(100 * (w(0.15, 0.2, 0.1) / (0.15 * 0.9) - 1), 14.8, 0.05);
    EXPECT_NEAR(w(0.1, 0.4, 0.25), 0.175, 1e-15);
    EXPECT_NEAR(100 * (w(0.1, 0.4, 0.25) / (0.1 * 0.75) - 1), 133, 0.5);
}

// The proposed model's case 1a: the same scene with one reflectance factor toward the
// sensor, rho = r_d (1 - s) + r_s s (White's material, the sun outside the lobe), and
// D = the sky; table 5.10's errors.
TEST(BigEquation, Case1aProposedSharesAreCloseToCase1) {
    for (const Band& b : kBands) {
        const ProposedTerms t{b.tau2, 0, 1.0, 0.15 * 0.9 + 0.2 * 0.1, b.sky, b.upwelled, 0};
        const auto v = proposed_values(t);
        const ErrorBudget e =
            beers_propagation(proposed_partials(t), relative_errors(v, kTable510Percent));
        const ErrorBudget d = dirsig_budget(case1(b));
        for (std::size_t i = 0; i < kProposedVariables; ++i)
            record(std::string("case1a.") + b.name + "." + std::string(kProposedVariableNames[i]),
                   e.share_percent[i]);
        // "Case 1a and 2a results are very similar to the Case 1 and 2 results. The only
        // notable difference is that the error in reflectance is combined into a single
        // term": solar and tau2 within 3 points of case 1 (with the reflectance's share
        // close to the sum of case 1's three reflectance terms, within 2).
        EXPECT_NEAR(e.share_percent[2], d.share_percent[kSolar], 3) << b.name;
        EXPECT_NEAR(e.share_percent[0], d.share_percent[kTau], 3) << b.name;
        EXPECT_NEAR(e.share_percent[3],
                    d.share_percent[kRd] + d.share_percent[kRs] + d.share_percent[kS], 2)
            << b.name;
    }
}

}  // namespace
}  // namespace sigchain::radiometry
