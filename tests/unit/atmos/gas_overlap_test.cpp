// Two overlapping gases' exponential sums (GasColumn::absorption_terms, gas_terms.cpp):
// where a second gas's band overlaps the fitted one strongly, the product of both sums
// against the band model's product transmittance on the column's slant and partial paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../record_property.hpp"
#include "atmos/gas_absorption.hpp"
#include "atmos/profile.hpp"
#include "io/cdk.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

// Largest |sum of terms - band model| (transmittance) over the paths from every level
// to the top and from the ground to every level, at 1, 2, 5, 10 and 20 air masses
// (plane parallel: mu = 1 / m; GasColumn::transmittance multiplies every gas's band
// model and the continua, which the terms carry as Beer's law).
double worst_error(const GasColumn& col, const GasColumn::Terms& terms, double nu) {
    const std::size_t top = col.size() - 1;
    double worst = 0;
    auto check = [&](std::size_t i, std::size_t j) {
        for (double m : {1.0, 2.0, 5.0, 10.0, 20.0}) {
            double sum = 0;
            for (std::size_t t = 0; t < terms.weight.size(); ++t) {
                double tau = 0;
                for (std::size_t l = i; l < j; ++l) tau += terms.depth[t][l];
                sum += terms.weight[t] * std::exp(-m * tau);
            }
            worst = std::max(worst, std::abs(sum - col.transmittance(nu, i, j, 1 / m)));
        }
    };
    for (std::size_t k = 0; k < top; ++k) check(k, top);
    for (std::size_t k = 1; k < top; ++k) check(0, k);
    return worst;
}

}  // namespace

// H2O over the O2 B (0.69 um) and gamma (0.63 um) bands in the US standard atmosphere:
// every 5 cm-1 interval within 0.005 in transmittance with build_radiance's 12 terms per
// gas (the fit is built to: each sum within 0.005 / 3, the pruned pairs at most
// 0.005 / 3 of the weight); the strongest gas's sum alone, the other gas in equivalent
// depths, errs by up to 0.19 there (printed).
TEST(GasOverlap, ProductOfTwoSumsMatchesTheBandModelsProduct) {
    const auto deck =
        io::read_cdk_file(SIGCHAIN_SOURCE_DIR "/tests/data/build_radiance/rural23.cdk");
    const Profile p = profile_from_deck(deck.runs[0], SIGCHAIN_SOURCE_DIR "/data");
    const GasTables tables = GasTables::load(SIGCHAIN_SOURCE_DIR "/data");
    const GasColumn col(tables, p);
    double worst_pairs = 0, worst_single = 0;
    int paired = 0;
    std::size_t most_terms = 0;
    for (double lo : {14400.0, 15750.0})
        for (double nu = lo; nu <= lo + 200; nu += 5) {
            const auto terms = col.absorption_terms(nu, 20, 0.005, 12);
            const auto single = col.absorption_terms(nu, 20, 0.005, 12, false);
            EXPECT_EQ(single.gas2, -1);
            const double e = worst_error(col, terms, nu);
            EXPECT_LE(e, 0.005) << nu << " cm-1, gases " << terms.gas << " " << terms.gas2;
            worst_pairs = std::max(worst_pairs, e);
            worst_single = std::max(worst_single, worst_error(col, single, nu));
            if (terms.gas2 >= 0) {
                ++paired;
                EXPECT_NE(terms.gas2, terms.gas);
                most_terms = std::max(most_terms, terms.weight.size());
                double w = 0;
                for (double x : terms.weight) w += x;
                EXPECT_NEAR(w, 1.0, 1e-12);
            }
        }
    EXPECT_GT(paired, 40);  // the pairs are used where the bands overlap
    std::printf(
        "H2O and O2: worst %.4f with pairs (%d of 82 intervals paired, at most %zu "
        "terms), %.4f with the strongest gas's sum only\n",
        worst_pairs, paired, most_terms, worst_single);
    unit::record("largest_error", worst_pairs);
    unit::record("limit", 0.005);
    unit::record("largest_error_one_sum", worst_single);
    unit::record("most_terms", double(most_terms));
}

// No second gas where the overlap is weak: in the visible window (0.5-0.55 um) the
// terms are those of the strongest gas alone, as without pairs.
TEST(GasOverlap, WeakOverlapKeepsOneSum) {
    const auto deck =
        io::read_cdk_file(SIGCHAIN_SOURCE_DIR "/tests/data/build_radiance/rural23.cdk");
    const Profile p = profile_from_deck(deck.runs[0], SIGCHAIN_SOURCE_DIR "/data");
    const GasTables tables = GasTables::load(SIGCHAIN_SOURCE_DIR "/data");
    const GasColumn col(tables, p);
    for (double nu = 18200; nu <= 20000; nu += 50) {
        const auto a = col.absorption_terms(nu, 20, 0.005, 12);
        const auto b = col.absorption_terms(nu, 20, 0.005, 12, false);
        EXPECT_EQ(a.gas2, -1) << nu;
        EXPECT_EQ(a.weight, b.weight) << nu;
        EXPECT_EQ(a.depth, b.depth) << nu;
    }
}
