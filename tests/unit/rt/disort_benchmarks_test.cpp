// The DISORT test problems (disotest 1-9) against the published/cdisort answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../record_property.hpp"
#include "rt/discrete_ordinates.hpp"
#include "rt/planck.hpp"

namespace sigchain::rt {
namespace {

constexpr double kPi = std::numbers::pi;

struct FluxRecord {
    double utau, direct, down, up, dfdt;
};
struct IntensityRecord {
    double utau, umu, phi, value;
};
struct Case {
    std::string name, title;
    int streams = 16;
    std::vector<Layer> layers;
    std::vector<double> t_top, t_bottom;  // layer temperatures (thermal cases)
    double fbeam = 0, mu0 = 1, phi0 = 0, fisot = 0, albedo = 0;
    bool thermal = false, delta_m = false;
    double wvn_lo = 0, wvn_hi = 0, btemp = 0, ttemp = 0, temis = 0;
    std::vector<FluxRecord> flux;
    std::vector<IntensityRecord> uu;
};

std::string data_path(const std::string& name) {
    return std::string(SIGCHAIN_TEST_DATA) + "/rt/" + name;
}

// Garcia & Siewert Haze-L (column 1) or Cloud C.1 (column 2) moments pmom_l = beta_l/(2l+1).
std::vector<double> garcia_siewert(int column) {
    std::ifstream in(data_path("garcia_siewert_haze_L_cloud_C1_moments.txt"));
    std::vector<double> pmom;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 'l') continue;
        std::istringstream ls(line);
        std::string l, a, b;
        ls >> l >> a >> b;
        const std::string& v = column == 1 ? a : b;
        if (v == "-") break;
        const int k = std::stoi(l);
        pmom.push_back(std::stod(v) / (2 * k + 1));
    }
    return pmom;
}

std::vector<Case> read_cases(const std::string& file) {
    std::ifstream in(data_path(file));
    EXPECT_TRUE(in.good()) << file;
    std::vector<Case> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (key == "CASE") {
            cases.emplace_back();
            ls >> cases.back().name;
            cases.back().title = line;
            continue;
        }
        Case& c = cases.back();
        if (key == "NSTR") {
            ls >> c.streams;
        } else if (key == "LAYER") {
            int i;
            Layer l;
            double tt, tb;
            ls >> i >> l.tau >> l.ssa;
            if (ls >> tt >> tb) c.t_top.push_back(tt), c.t_bottom.push_back(tb);
            c.layers.push_back(l);
        } else if (key == "PMOM") {
            int i;
            ls >> i;
            double v;
            while (ls >> v) c.layers[i - 1].pmom.push_back(v);
        } else if (key == "BEAM") {
            ls >> c.fbeam >> c.mu0 >> c.phi0;
        } else if (key == "FISOT") {
            ls >> c.fisot;
        } else if (key == "ALBEDO") {
            ls >> c.albedo;
        } else if (key == "THERMAL") {
            std::string first;
            ls >> first;
            if (first != "none") {
                c.thermal = true;
                c.wvn_lo = std::stod(first);
                ls >> c.wvn_hi >> c.btemp >> c.ttemp >> c.temis;
            }
        } else if (key == "DELTAM") {
            std::string v;
            ls >> v;
            c.delta_m = v == "yes";
        } else if (key == "FLUX") {
            FluxRecord r;
            ls >> r.utau >> r.direct >> r.down >> r.up >> r.dfdt;
            c.flux.push_back(r);
        } else if (key == "UU") {
            IntensityRecord r;
            ls >> r.utau >> r.umu >> r.phi >> r.value;
            c.uu.push_back(r);
        }
    }
    return cases;
}

// Values printed with few digits are snapped to the exact value they stand for: layer
// optical depths from the case title (VH1's b = 0.03125 is printed 0.0312), depths to the
// nearest level or flux depth within the printing precision.
double snap(double v, const std::vector<double>& exact, double tol) {
    for (double e : exact)
        if (std::abs(v - e) <= tol * std::max(1.0, std::abs(e))) return e;
    return v;
}

struct Errors {
    double flux = 0, intensity = 0;          // worst |error| / tolerance
    double flux_rel = 0, intensity_rel = 0;  // worst relative error among values above the floor
    int flux_fail = 0, intensity_fail = 0, intensity_count = 0;
};

Errors run_case(Case c, double azimuth_accuracy, bool verbose, bool ims = true) {
    // Haze-L and Cloud C.1: the PMOM record (6 decimals) is replaced by the exact expansion,
    // as many moments as the record has (disotest used nmom = nstr = 32 for Haze-L, so its
    // "exact" phase function in the intensity correction is that truncated series).
    for (int column : {1, 2}) {
        if (c.name.rfind(column == 1 ? "4" : "5", 0) != 0) continue;
        std::vector<double> exact = garcia_siewert(column);
        exact.resize(std::min(exact.size(), c.layers[0].pmom.size()));
        c.layers[0].pmom = exact;
    }
    const auto b = c.title.find(" b = ");
    if (b != std::string::npos && c.layers.size() == 1)
        c.layers[0].tau = std::stod(c.title.substr(b + 4));
    // disotest's test 1 beam is FBEAM = pi / UMU0 (31.4159 for mu0 = 0.1), printed 31.42:
    // a beam within the printing precision of pi / mu0 stands for it.
    if (std::abs(c.fbeam * c.mu0 / kPi - 1) < 5e-4) c.fbeam = kPi / c.mu0;
    Problem p;
    p.layers = c.layers;
    p.streams = c.streams;
    p.delta_m = c.delta_m;
    p.beam_flux = c.fbeam;
    p.beam_mu0 = c.mu0;
    p.beam_phi0_deg = c.phi0;
    p.top_isotropic = c.fisot;
    p.albedo = c.albedo;
    p.azimuth_accuracy = azimuth_accuracy;
    // disotest runs with DISORT's intensity correction, TMS and IMS: case 5b's
    // beam-direction intensities (Cloud C.1, umu = -mu0 at tau 3.2 and 12.8) need the
    // IMS part (without it they are 40 % and 54 % high).
    p.secondary_correction = ims;
    std::vector<double> levels{0};
    for (const Layer& l : p.layers) levels.push_back(levels.back() + l.tau);
    double emitted = 0;
    if (c.thermal) {
        for (std::size_t n = 0; n < c.t_top.size(); ++n)
            p.planck_levels.push_back(planck_band(c.wvn_lo, c.wvn_hi, c.t_top[n]));
        p.planck_levels.push_back(planck_band(c.wvn_lo, c.wvn_hi, c.t_bottom.back()));
        p.planck_surface = planck_band(c.wvn_lo, c.wvn_hi, c.btemp);
        p.top_emission = c.temis * planck_band(c.wvn_lo, c.wvn_hi, c.ttemp);
        for (double v : p.planck_levels) emitted = std::max(emitted, v);
        emitted = std::max(emitted, p.planck_surface);
    }
    for (auto& f : c.flux) f.utau = snap(f.utau, levels, 5e-3), p.utau.push_back(f.utau);
    for (auto& u : c.uu) {
        u.utau = snap(u.utau, p.utau, 1e-2);
        if (std::find(p.umu.begin(), p.umu.end(), u.umu) == p.umu.end()) p.umu.push_back(u.umu);
        if (std::find(p.phi_deg.begin(), p.phi_deg.end(), u.phi) == p.phi_deg.end())
            p.phi_deg.push_back(u.phi);
    }
    std::sort(p.umu.begin(), p.umu.end());
    const Result r = solve(p);

    // Tolerances: fluxes 0.1 %, intensities 1 % relative (the required accuracy), with an
    // absolute floor for values near zero: 1e-3 of the case's incident flux scale
    // (beam mu0 F + pi (isotropic + top emission), or pi B of the hottest emitter for the
    // internal-source cases), and that floor / pi for intensities. Below it a relative
    // error is meaningless (the references are printed to 5 digits; 1b's zero dfdt, a
    // conservative layer's, is 0 to rounding).
    const double incident =
        std::max(c.mu0 * c.fbeam + kPi * (c.fisot + p.top_emission), kPi * emitted);
    const double flux_floor = 1e-3 * incident, int_floor = flux_floor / kPi;
    Errors e;
    auto check_flux = [&](double got, double want, const char* what, double utau) {
        const double tol = std::max(1e-3 * std::abs(want), flux_floor);
        const double err = std::abs(got - want);
        e.flux = std::max(e.flux, err / tol);
        if (std::abs(want) > flux_floor) e.flux_rel = std::max(e.flux_rel, err / std::abs(want));
        if (err > tol) {
            ++e.flux_fail;
            if (verbose)
                std::printf("  %s %s utau %g: got %.6g want %.6g\n", c.name.c_str(), what, utau,
                            got, want);
        }
    };
    for (std::size_t i = 0; i < c.flux.size(); ++i) {
        const FluxRecord& f = c.flux[i];
        const LevelResult& l = r.levels[i];
        check_flux(l.direct_down, f.direct, "direct", f.utau);
        check_flux(l.diffuse_down, f.down, "down", f.utau);
        check_flux(l.diffuse_up, f.up, "up", f.utau);
        check_flux(l.dfdt, f.dfdt, "dfdt", f.utau);
    }
    for (const auto& u : c.uu) {
        const std::size_t lev = std::find(p.utau.begin(), p.utau.end(), u.utau) - p.utau.begin();
        const std::size_t iu = std::find(p.umu.begin(), p.umu.end(), u.umu) - p.umu.begin();
        const std::size_t ip =
            std::find(p.phi_deg.begin(), p.phi_deg.end(), u.phi) - p.phi_deg.begin();
        const double got = r.levels.at(lev).intensity.at(iu * p.phi_deg.size() + ip);
        const double tol = std::max(1e-2 * std::abs(u.value), int_floor);
        const double err = std::abs(got - u.value);
        e.intensity = std::max(e.intensity, err / tol);
        ++e.intensity_count;
        if (std::abs(u.value) > int_floor)
            e.intensity_rel = std::max(e.intensity_rel, err / std::abs(u.value));
        if (err > tol) {
            ++e.intensity_fail;
            if (verbose)
                std::printf("  %s I utau %g mu %g phi %g: got %.6g want %.6g\n", c.name.c_str(),
                            u.utau, u.umu, u.phi, got, u.value);
        }
    }
    return e;
}

// Records the worst relative errors over the file's cases (scripts/accuracy), and for
// case 5b (Cloud C.1) its own and, without the IMS correction, its intensities' worst.
void run_file(const std::string& file) {
    double flux_rel = 0, intensity_rel = 0;
    for (const Case& c : read_cases(file)) {
        const Errors e = run_case(c, 0.0, true);
        std::printf(
            "case %-3s flux max rel err %.2e (err/tol %.2f)  intensity max rel err %.2e "
            "(err/tol %.2f, %d values)\n",
            c.name.c_str(), e.flux_rel, e.flux, e.intensity_rel, e.intensity, e.intensity_count);
        EXPECT_EQ(e.flux_fail, 0) << c.title;
        EXPECT_EQ(e.intensity_fail, 0) << c.title;
        flux_rel = std::max(flux_rel, e.flux_rel);
        intensity_rel = std::max(intensity_rel, e.intensity_rel);
        if (c.name == "5b") {
            unit::record("case_5b_flux_relative_error", e.flux_rel);
            unit::record("case_5b_intensity_relative_error", e.intensity_rel);
            unit::record("case_5b_intensity_relative_error_without_ims",
                         run_case(c, 0.0, false, false).intensity_rel);
        }
    }
    unit::record("flux_relative_error", flux_rel);
    unit::record("intensity_relative_error", intensity_rel);
    unit::record("flux_limit", 1e-3);
    unit::record("intensity_limit", 1e-2);
}

TEST(DisortBenchmark, Test1IsotropicScattering) { run_file("disort_test01.txt"); }
TEST(DisortBenchmark, Test2Rayleigh) { run_file("disort_test02.txt"); }
TEST(DisortBenchmark, Test3HenyeyGreenstein) { run_file("disort_test03.txt"); }
TEST(DisortBenchmark, Test4HazeL) { run_file("disort_test04.txt"); }
TEST(DisortBenchmark, Test5CloudC1) { run_file("disort_test05.txt"); }
TEST(DisortBenchmark, Test6NoScattering) { run_file("disort_test06.txt"); }
TEST(DisortBenchmark, Test7Thermal) { run_file("disort_test07.txt"); }
TEST(DisortBenchmark, Test8TwoLayers) { run_file("disort_test08.txt"); }
TEST(DisortBenchmark, Test9SixLayers) { run_file("disort_test09.txt"); }

}  // namespace
}  // namespace sigchain::rt
