// build_radiance with exponential-sum gas absorption (ColumnModel::gas_terms): the
// multiply scattered path radiance in the O2 A band as terms are added, and the thermal
// path radiance on slant lines of sight against the formal solution of the transfer
// equation with the band model's transmittance of the same path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/numeric.hpp"
#include "../record_property.hpp"
#include "atmos/column_model.hpp"
#include "atmos_table/build_radiance.hpp"
#include "core/error.hpp"
#include "rt/planck.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

using sigchain::kRadPerDeg;
const std::string kSource = SIGCHAIN_SOURCE_DIR;

RadianceOptions fast_options(int max_terms) {
    RadianceOptions o;
    o.data_dir = kSource + "/data";
    o.max_gas_terms = max_terms;
    o.coupling = false;  // not read here
    o.sky_subsamples = 1;
    o.sky_zenith_step_deg = 30;
    o.sky_azimuth_step_deg = 90;
    o.upwelled_azimuth_step_deg = 90;
    return o;
}

// The Hawkeye deck of White (1996) and its place and time, one band at `nu`, views
// `views` deg (one step).
io::Snd one_sample(double nu, double sensor_km, double view_max_deg) {
    io::Snd snd = io::read_snd_file(kSource + "/tests/data/build_radiance/small.snd");
    snd.sensor_altitude_km = sensor_km;
    snd.bands = {{nu, nu, 1}};
    snd.view_min_deg = 0;
    snd.view_max_deg = view_max_deg;
    snd.view_increment_deg = view_max_deg > 0 ? view_max_deg : 1;
    return snd;
}

}  // namespace

// The O2 A band centre (13100 cm-1, 0.763 um), Hawkeye deck, sensor at 1 km: the nadir
// path radiance L_us and the zenith sky cell with at most n terms per gas (n = 1 is one
// equivalent Beer's-law depth per layer, as before the sums). Printed as the sequence
// converges; the last two steps (12 and 16 terms: fits within 0.005 in transmittance)
// must agree within 1 %, and one depth must fall short of them by more than 10 %
// (Beer's law on long scattered paths over-absorbs in a band far from it).
TEST(BuildRadianceTerms, OxygenABandPathRadianceConvergesAsTermsAreAdded) {
    const auto deck = io::read_cdk_file(kSource + "/tests/golden/control7/hawkeye.cdk");
    const io::Snd snd = one_sample(13100, 1.0, 0);
    std::printf("terms/gas  solves  L_us(nadir)   L_ds(zenith cell)\n");
    std::vector<double> lus, lds;
    for (int n : {1, 2, 3, 4, 6, 8, 12, 16}) {
        RadianceReport rep;
        const auto rads = build_radiance(deck, snd, fast_options(n), &rep);
        lus.push_back(rads[0].views[0].path[0].scattered_radiance);
        lds.push_back(rads[0].sky->cells[0].scattered_radiance[0]);
        std::printf("%9d  %6ld  %.6g  %.6g\n", n, rep.gas_term_solves, lus.back(), lds.back());
    }
    const std::size_t last = lus.size() - 1;
    EXPECT_NEAR(lus[last - 1] / lus[last], 1.0, 0.01);
    EXPECT_NEAR(lds[last - 1] / lds[last], 1.0, 0.01);
    EXPECT_LT(lus[0] / lus[last], 0.9);
    EXPECT_LT(lds[0] / lds[last], 0.9);
    unit::record("path_16_over_1_term", lus[last] / lus[0]);
    unit::record("sky_16_over_1_term", lds[last] / lds[0]);
    unit::record("path_12_over_16_terms", lus[last - 1] / lus[last]);
    unit::record("sky_12_over_16_terms", lds[last - 1] / lds[last]);
}

// Thermal path radiance at nadir and 40 deg from a sensor at 20 km, no aerosol, in the
// 8-12 um window (Rayleigh scattering is ~1e-5 there): against the formal solution
// sum_k (B_k + B_k+1)/2 [T(k+1 -> S, mu) - T(k -> S, mu)] with the band model's
// transmittance of each slant path (GasColumn, independent of the solver). One
// equivalent depth per layer (max_gas_terms 1, as before the sums) is exact toward the
// sensor only at nadir and overestimates the slant path (Beer's law on the vertical
// depth). With the sums, nadir stays within the fit's bound plus 0.5 % (an error d in
// every path's transmittance moves sum_k B_k dT_k by at most 2 d max B, summing by
// parts, d = kGasThermalTolerance; 0.5 % for the trapezoid against the solver's Planck
// linear in optical depth), and at 40 deg the error and the error of the 40/0 ratio
// must shrink: only the strongest gas is carried by sums, the others keep Beer's law on
// their equivalent depths, so the slant error falls (measured, at 40 deg: 4.6 to 2.8 %
// at 950 cm-1, 6.4 to 1.0 % at 1150 cm-1) without vanishing.
TEST(BuildRadianceTerms, ThermalPathRadianceFollowsTheSlantPathTransmittance) {
    auto deck = io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk");
    deck.runs[0].card2.ihaze = 0;
    RadianceOptions o = fast_options(12);
    o.streams = 8;  // no scattering to speak of: the streams only carry the emission
    RadianceOptions one_depth = o;
    one_depth.max_gas_terms = 1;
    std::printf("cm-1   view  formal      one depth (ratio)   sums (ratio)\n");
    for (double nu : {950.0, 1150.0}) {
        const io::Snd snd = one_sample(nu, 20.0, 40);
        const auto after = build_radiance(deck, snd, o);
        const auto before = build_radiance(deck, snd, one_depth);
        const ColumnModel column(deck.runs[0], snd.sensor_altitude_km, o);
        const Profile& p = column.profile();
        const std::size_t sensor = column.sensor_level();
        const auto col = column.layers(nu);
        double formal[2], sums[2], one[2];
        for (int v = 0; v < 2; ++v) {
            const double mu = std::cos(v * 40 * kRadPerDeg);
            formal[v] = 0;
            for (std::size_t k = 0; k < sensor; ++k)
                formal[v] += 0.5 *
                             (rt::planck_radiance(1e4 / nu, p.t_k[k]) +
                              rt::planck_radiance(1e4 / nu, p.t_k[k + 1])) *
                             (column.direct_transmittance(nu, col, k + 1, sensor, mu) -
                              column.direct_transmittance(nu, col, k, sensor, mu));
            sums[v] = after[0].views[v].path[0].emitted_radiance;
            one[v] = before[0].views[v].path[0].emitted_radiance;
            const std::string at =
                std::to_string(int(nu)) + "cm1_" + std::to_string(v * 40) + "deg";
            unit::record("sums_relative_error_" + at, sums[v] / formal[v] - 1);
            unit::record("one_depth_relative_error_" + at, one[v] / formal[v] - 1);
            std::printf("%5.0f  %4d  %.5g  %.5g (%.4f)  %.5g (%.4f)\n", nu, v * 40, formal[v],
                        one[v], one[v] / formal[v], sums[v], sums[v] / formal[v]);
            double b_max = 0;
            for (std::size_t k = 0; k <= sensor; ++k)
                b_max = std::max(b_max, rt::planck_radiance(1e4 / nu, p.t_k[k]));
            const double bound = 2 * ColumnModel::kGasThermalTolerance * b_max / formal[v] + 0.005;
            if (v == 0)
                EXPECT_NEAR(sums[v] / formal[v], 1.0, bound) << nu << " cm-1, nadir";
            else
                EXPECT_LT(std::abs(sums[v] / formal[v] - 1), std::abs(one[v] / formal[v] - 1))
                    << nu << " cm-1, 40 deg";
        }
        const double want = formal[1] / formal[0];
        std::printf("%5.0f  40/0  %.4f  %.4f              %.4f\n", nu, want, one[1] / one[0],
                    sums[1] / sums[0]);
        EXPECT_LT(std::abs(sums[1] / sums[0] / want - 1), std::abs(one[1] / one[0] / want - 1))
            << nu;
    }
}

}  // namespace sigchain::atmos_table

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from

TEST(BuildRadianceTerms, GasTermsOutOfRangeIsUsageError) {
    RadianceOptions o;
    o.max_gas_terms = 0;
    EXPECT_THROW(check_radiance_options(o), UsageError);
    o.max_gas_terms = 17;
    EXPECT_THROW(check_radiance_options(o), UsageError);
    o.max_gas_terms = 16;
    EXPECT_NO_THROW(check_radiance_options(o));
}

}  // namespace sigchain::atmos_table
