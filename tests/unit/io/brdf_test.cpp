// Tests for the .brdf tabulated-BRDF reader and writer (lib/io/brdf).
#include "io/brdf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kHeader =
    "# sigchain-brdf 1\n"
    "theta_i_deg = 0 60\n"
    "theta_o_deg = 0 60\n"
    "phi_deg = 0 180\n";

// Every grid point of kHeader's grid with value v, in the file order.
std::string rows(double v) {
    std::ostringstream s;
    for (int i : {0, 60})
        for (int o : {0, 60})
            for (int p : {0, 180}) s << i << ' ' << o << ' ' << p << ' ' << v << '\n';
    return s.str();
}

BrdfTable parse(const std::string& text) {
    return parse_brdf(TextInput::from_string(text, "t.brdf"));
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

}  // namespace

TEST(Brdf, ParsesGridsAndRowsInAnyOrder) {
    std::string text =
        "# sigchain-brdf 1\n# a comment\nphi_deg = 0, 90, 180\n"
        "theta_o_deg = 30\ntheta_i_deg = 10 20\n"
        "20 30 180 0.5  # last\n10 30 0 0.1\n10 30 90 0.2\n10 30 180 0.3\n"
        "20 30 0 0.4\n20 30 90 0.45\n";
    BrdfTable t = parse(text);
    EXPECT_EQ(t.theta_i_deg, (std::vector<double>{10, 20}));
    EXPECT_EQ(t.theta_o_deg, (std::vector<double>{30}));
    EXPECT_EQ(t.phi_deg, (std::vector<double>{0, 90, 180}));
    EXPECT_EQ(t.at(0, 0, 1), 0.2);
    EXPECT_EQ(t.at(1, 0, 2), 0.5);
}

TEST(Brdf, RewriteReadsBack) {
    BrdfTable t = parse(kHeader + rows(0.318));
    std::ostringstream out;
    write_brdf(out, t);
    EXPECT_EQ(parse(out.str()), t);
    EXPECT_EQ(out.str().rfind("# sigchain-brdf 1\n", 0), 0u);
}

TEST(Brdf, ShippedExampleParses) {
    BrdfTable t = read_brdf_file(SIGCHAIN_SOURCE_DIR "/data/brdf/rpv_grassland.brdf");
    EXPECT_EQ(t.phi_deg.front(), 0);
    EXPECT_EQ(t.phi_deg.back(), 180);
    EXPECT_EQ(t.values.size(), t.theta_i_deg.size() * t.theta_o_deg.size() * t.phi_deg.size());
}

TEST(Brdf, ShippedExampleIsRahmanGrassland) {
    // Rahman, Pinty & Verstraete (1993), eq. 4-8, with their grassland parameters
    // (table 1: rho0 0.183, k 0.780, Theta -0.1), evaluated here independently of
    // scripts/rpv-brdf; the file holds 6 significant digits.
    BrdfTable t = read_brdf_file(SIGCHAIN_SOURCE_DIR "/data/brdf/rpv_grassland.brdf");
    const double rho0 = 0.183, k = 0.780, big_theta = -0.1, pi = std::acos(-1.0);
    auto rpv = [&](double ti_deg, double to_deg, double phi_deg) {
        const double ti = ti_deg * pi / 180, to = to_deg * pi / 180, phi = phi_deg * pi / 180;
        const double ci = std::cos(ti), co = std::cos(to);
        const double cg = ci * co + std::sin(ti) * std::sin(to) * std::cos(phi);
        const double hg = (1 - big_theta * big_theta) /
                          std::pow(1 + big_theta * big_theta + 2 * big_theta * cg, 1.5);
        const double g2 = std::tan(ti) * std::tan(ti) + std::tan(to) * std::tan(to) -
                          2 * std::tan(ti) * std::tan(to) * std::cos(phi);
        const double h = 1 + (1 - rho0) / (1 + std::sqrt(std::max(0.0, g2)));
        return rho0 / pi * std::pow(ci * co * (ci + co), k - 1) * hg * h;
    };
    auto at = [&](double ti, double to, double phi) {
        auto index = [](const std::vector<double>& axis, double v) {
            return static_cast<std::size_t>(std::find(axis.begin(), axis.end(), v) - axis.begin());
        };
        const std::size_t i = index(t.theta_i_deg, ti), o = index(t.theta_o_deg, to),
                          p = index(t.phi_deg, phi);
        return t.values[t.value_index(i, o, p)];
    };
    for (auto [ti, to, phi] : {std::array<double, 3>{0, 0, 0}, {30, 30, 0}, {30, 30, 180},
                               {60, 20, 90}, {85, 45, 135}})
        EXPECT_NEAR(at(ti, to, phi), rpv(ti, to, phi), 1e-5 * rpv(ti, to, phi))
            << ti << " " << to << " " << phi;
    EXPECT_GT(at(30, 30, 0), at(30, 30, 180));  // the hot spot: back-scattering
}

TEST(Brdf, ErrorsNameFileAndLine) {
    EXPECT_EQ(error_of("# sigchain-brdf 2\n"),
              "t.brdf:1: expected sigchain-brdf version 1 or 1.N, found '2'");
    EXPECT_EQ(error_of("# sigchain-brdf 1\ntheta_i_deg = 0 60\nfoo = 1\n"),
              "t.brdf:3: expected theta_i_deg, theta_o_deg or phi_deg = values, found 'foo = 1'");
    EXPECT_EQ(error_of("# sigchain-brdf 1\ntheta_i_deg = 0 60 50\n"),
              "t.brdf:2: expected theta_i_deg strictly increasing, found 50 after 60");
    EXPECT_EQ(error_of("# sigchain-brdf 1\ntheta_i_deg = 0 95\n"),
              "t.brdf:2: expected theta_i_deg in [0, 90], found '95'");
    EXPECT_EQ(error_of("# sigchain-brdf 1\nphi_deg = 0 90\n"),
              "t.brdf:2: expected phi_deg from 0 to 180, found 0 to 90");
    EXPECT_EQ(error_of(kHeader + "0 0 0 0.1\n0 0 0 0.2\n"),
              "t.brdf:6: repeated grid point (first on line 5)");
    EXPECT_EQ(error_of(kHeader + "0 0 45 0.1\n"),
              "t.brdf:5: expected phi_deg on its grid line, found 45");
    EXPECT_EQ(error_of(kHeader + "0 0 0 -0.1\n"),
              "t.brdf:5: expected brdf (sr-1) 0 or more, found '-0.1'");
    EXPECT_EQ(error_of(kHeader + "0 0 0\n").substr(0, 9), "t.brdf:5:");
    std::string missing = kHeader + rows(0.1);
    missing.erase(missing.rfind("60 60 180"));
    EXPECT_EQ(error_of(missing),
              "t.brdf:11: expected a row for theta_i 60, theta_o 60, phi 180, found none in the "
              "file");
}
