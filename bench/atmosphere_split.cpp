// atmosphere_split: the two diagnostics of docs/atmosphere.md that need build_radiance's
// column from the inside, printed for bench/atmosphere_split.sh.
//
//   atmosphere_split DATA_DIR CDK SENSOR_KM SUN_ZENITH_DEG WINDOW_CM1 BAND_CM1...
//
// 1. In a window (WINDOW_CM1): the nadir path radiance at the sensor, split into single
//    scattering (single_scatter.hpp) and the rest (rt::solve, 16 streams, plane-parallel
//    beam), and the rest again as LOWTRAN 7's multiple-scattering source forms it from
//    the diffuse fluxes (subroutine TRANS with FLXADD's fluxes: J = omega / pi [F_up
//    (1 - beta) + F_down beta], the diffuse field isotropic in each hemisphere, beta the
//    fraction a layer of asymmetry g backscatters from the vertical), here fed with the
//    discrete-ordinate solution's own fluxes and Henyey-Greenstein's exact beta at
//    mu = 1, beta = (1 - g^2) / (2 g) (1 / sqrt(1 + g^2) - 1 / (1 + g)), g LOWTRAN's
//    COSBAR (the aerosol's g times its share of the scattering).
// 2. In the gas bands (BAND_CM1...): the fitted gas's transmittance on the column's paths
//    by its band model, T = exp(-x^a) with x = C W the path's scaled amount (Curtis-
//    Godson: W = sum of rho ds (P/P0)^n (T0/T)^m), by the exponential sum build_radiance
//    solves with (GasColumn::absorption_terms: a k per term applied to every layer's
//    amount) and by LOWTRAN 7's own 3-term k-distribution of its multiple scattering
//    (w = AA, BB, 1 - AA - BB; k = (1, 0.09, 0.015) CC per unit x;
//    band_model_constants.txt); and on one photon's path down from the sun and up to
//    the sensor, the band model on the summed amounts against the product of the two
//    legs' transmittances (what a source computed without the path's correlation gets).
//
// The deck's first run, the sensor and the sun as build_radiance takes them; the paths
// plane-parallel (GasColumn's). Units: wavenumber cm-1, radiance W cm-2 sr-1 um-1 per
// unit exoatmospheric irradiance (the ratios are what the tables print).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "atmos/column_model.hpp"
#include "atmos/mie_layers.hpp"
#include "atmos/single_scatter.hpp"
#include "atmos_table/stream_choice.hpp"
#include "io/cdk.hpp"
#include "rt/discrete_ordinates.hpp"

using namespace sigchain;
using namespace sigchain::atmos;
using namespace sigchain::atmos_table;  // phase_moments(streams)

namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kPi = std::numbers::pi;
const char* kGasNames[] = {"H2O", "CO2", "O3",  "N2O", "CO",  "CH4",
                           "O2",  "NO",  "SO2", "NO2", "NH3", "HNO3"};

// --- 1. the window: LOWTRAN 7's multiple-scattering source from exact fluxes -----------

// Henyey-Greenstein's fraction scattered into the other hemisphere from the vertical:
// its phase function (1 - g^2) / (1 + g^2 - 2 g mu)^(3/2) / 2 integrated over mu in [-1, 0].
double backscatter_fraction(double g) {
    if (std::abs(g) < 1e-6) return 0.5;
    return (1 - g * g) / (2 * g) * (1 / std::sqrt(1 + g * g) - 1 / (1 + g));
}

void window(const ColumnModel& column, double nu, double mu0) {
    const std::vector<LayerOptics> col = column.layers(nu);
    const std::size_t n = col.size(), sensor = column.sensor_level();
    std::vector<std::size_t> kept(n + 1);
    for (std::size_t k = 0; k <= n; ++k) kept[k] = k;  // every level: no merging
    const int streams = 16, moments = phase_moments(streams);
    const MieOptics mie = mie_optics(column, 1e4 / nu, moments);  // p's exact phase refers to it
    rt::Problem p;
    p.layers = mie_solver_layers(col, kept, mie, moments, &p.exact_phase);
    p.streams = streams;
    p.secondary_correction = true;
    p.beam_flux = 1;
    p.beam_mu0 = mu0;
    p.umu = {1.0};
    p.phi_deg = {0.0};
    p.azimuth_mean = true;
    double t = 0;  // every level, top first
    p.utau.push_back(0);
    for (const rt::Layer& l : p.layers) p.utau.push_back(t += l.tau);
    const rt::Result full = rt::solve(p);
    const rt::Result single = single_scattering(p);
    const std::size_t at = n - sensor;  // the sensor's level in utau
    const double total = full.levels[at].intensity[0], ss = single.levels[at].intensity[0];
    // LOWTRAN 7's source, layer by layer below the sensor (layer k bottom first is the
    // solver's n - 1 - k, between utau n - 1 - k and n - k), attenuated to the sensor:
    // the formal solution along mu = 1, J (1 - exp(-tau)) exp(-tau above, to the sensor).
    double lt = 0;
    for (std::size_t k = 0; k < sensor; ++k) {
        const std::size_t s = n - 1 - k;
        const rt::Layer& l = p.layers[s];
        const LayerOptics& o = col[k];
        const double aer = o.tau_aerosol * o.ssa_aerosol;
        const double g = aer + o.tau_rayleigh > 0 ? o.g_aerosol * aer / (aer + o.tau_rayleigh) : 0;
        const double beta = backscatter_fraction(g);
        const rt::LevelResult &top = full.levels[s], &bottom = full.levels[s + 1];
        const double up = (top.diffuse_up + bottom.diffuse_up) / 2;
        const double down = (top.diffuse_down + bottom.diffuse_down) / 2;
        const double j = l.ssa / kPi * (up * (1 - beta) + down * beta);
        lt += j * -std::expm1(-l.tau) * std::exp(-(p.utau[s] - p.utau[at]));
    }
    std::printf("window %.0f cm-1 (%.4f um), nadir path radiance at the sensor per unit Es:\n", nu,
                1e4 / nu);
    std::printf("  single scattering %.5e\n", ss);
    std::printf("  multiple scattering (discrete ordinates, 16 streams) %.5e\n", total - ss);
    std::printf("  multiple scattering, LOWTRAN 7's source from the same fluxes %.5e (%.3f)\n", lt,
                lt / (total - ss));
    std::printf("  diffuse fluxes per unit mu0 Es, level: up, down\n");
    std::printf("    %9s %.5f %.5f\n", "top", full.levels[0].diffuse_up / mu0, 0.0);
    for (std::size_t k = sensor + 1; k-- > 0;)
        std::printf("    %6.2f km %.5f %.5f\n", column.profile().z_km[k],
                    full.levels[n - k].diffuse_up / mu0, full.levels[n - k].diffuse_down / mu0);
}

// --- 2. the gas bands: layer and path transmittances ------------------------------------

struct BandConstants {
    double a = 1, w[3] = {1, 0, 0}, cc = 0;
};

// The band of `gas` at nu in band_model_constants.txt (its '#' header says the columns).
BandConstants band_constants(const std::string& data_dir, int gas, double nu) {
    std::ifstream in(data_dir + "/atmosphere/lowtran7/band_model_constants.txt");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        std::string name, ranges;
        int id = 0;
        double a, n, m, w1, w2, w3, cc;
        if (!(f >> name >> id >> a >> n >> m >> w1 >> w2 >> w3 >> cc >> ranges)) continue;
        if (name != kGasNames[gas]) continue;
        std::istringstream r(ranges);
        std::string range;
        while (std::getline(r, range, ';')) {
            const auto dash = range.find('-');
            if (nu >= std::stod(range.substr(0, dash)) && nu <= std::stod(range.substr(dash + 1)))
                return {a, {w1, w2, w3}, cc};
        }
    }
    std::fprintf(stderr, "atmosphere_split: no band of %s at %g cm-1\n", kGasNames[gas], nu);
    std::exit(1);
}

// LOWTRAN 7's 3-term k-distribution at scaled amount x (FLXADD: FAC 1, 0.09, 0.015).
double three_term(const BandConstants& b, double x) {
    const double f[3] = {1.0, 0.09, 0.015};
    double t = 0;
    for (int j = 0; j < 3; ++j) t += b.w[j] * std::exp(-f[j] * b.cc * x);
    return t;
}

struct Path {
    std::string name;
    std::size_t lo, hi;  // levels
    double air_mass;
};

void band(const ColumnModel& column, const GasColumn& gases, const std::string& data_dir, double nu,
          double mu0) {
    const GasColumn::Terms terms =
        gases.absorption_terms(nu, ColumnModel::kGasPathFactor, ColumnModel::kGasFitTolerance, 12);
    if (terms.gas < 0) {
        std::printf("band %.0f cm-1: no gas needs an exponential sum\n", nu);
        return;
    }
    if (terms.gas2 >= 0) {
        std::printf("band %.0f cm-1: %s and %s fitted as a pair (not tabulated here)\n", nu,
                    kGasNames[terms.gas], kGasNames[terms.gas2]);
        return;
    }
    const Gas gas = static_cast<Gas>(terms.gas);
    const BandConstants b = band_constants(data_dir, terms.gas, nu);
    const std::size_t top = column.profile().size() - 1, sensor = column.sensor_level();
    auto band_t = [&](const Path& p) {
        return gases.band_transmittance(gas, nu, p.lo, p.hi, 1 / p.air_mass);
    };
    auto x_of = [&](double t) { return std::pow(-std::log(t), 1 / b.a); };
    auto sum_t = [&](const std::vector<Path>& legs) {
        double t = 0;
        for (std::size_t i = 0; i < terms.weight.size(); ++i) {
            double d = 0;
            for (const Path& p : legs)
                for (std::size_t k = p.lo; k < p.hi; ++k)
                    d += p.air_mass * terms.fitted_depth[i][k];
            t += terms.weight[i] * std::exp(-d);
        }
        return t;
    };
    std::printf("band %.0f cm-1 (%.4f um): %s, a %.4f, %zu terms\n", nu, 1e4 / nu,
                kGasNames[terms.gas], b.a, terms.weight.size());
    std::printf("  %-34s %10s %9s %9s %9s\n", "path", "x = C W", "band", "exp sum", "3-term");
    std::vector<Path> paths;
    const Profile& prof = column.profile();
    for (std::size_t k = 0; k < sensor; ++k) {
        char name[64];
        std::snprintf(name, sizeof name, "layer %.2f-%.2f km", prof.z_km[k], prof.z_km[k + 1]);
        paths.push_back({name, k, k + 1, 1});
    }
    paths.push_back({"sensor to ground (view)", 0, sensor, 1});
    paths.push_back({"top to sensor", sensor, top, 1});
    paths.push_back({"top to ground at the sun's zenith", 0, top, 1 / mu0});
    paths.push_back({"20 vertical columns", 0, top, ColumnModel::kGasPathFactor});
    for (const Path& p : paths) {
        const double t = band_t(p), x = x_of(t);
        std::printf("  %-34s %10.4g %9.4f %9.4f %9.4f\n", p.name.c_str(), x, t, sum_t({p}),
                    three_term(b, x));
    }
    // One photon's path: down from the sun to the ground, up to the sensor.
    const Path sun{"", 0, top, 1 / mu0}, view{"", 0, sensor, 1};
    const double xs = x_of(band_t(sun)), xv = x_of(band_t(view));
    std::printf("  %-34s %10.4g %9.4f %9.4f %9.4f\n", "sun to ground to sensor", xs + xv,
                std::exp(-std::pow(xs + xv, b.a)), sum_t({sun, view}), three_term(b, xs + xv));
    std::printf("  %-34s %10s %9.4f %9.4f %9.4f\n", "  the two legs' product", "",
                band_t(sun) * band_t(view), sum_t({sun}) * sum_t({view}),
                three_term(b, xs) * three_term(b, xv));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 7) {
        std::fprintf(stderr,
                     "usage: atmosphere_split DATA_DIR CDK SENSOR_KM SUN_ZENITH_DEG WINDOW_CM1 "
                     "BAND_CM1...\n");
        return 2;
    }
    try {
        const std::string data_dir = argv[1];
        const io::Cdk deck = io::read_cdk_file(argv[2]);
        ColumnOptions o;
        o.data_dir = data_dir;
        const ColumnModel column(deck.runs.front(), std::stod(argv[3]), o);
        const double mu0 = std::cos(std::stod(argv[4]) * kDeg);
        window(column, std::stod(argv[5]), mu0);
        const GasTables tables = GasTables::load(data_dir);
        const GasColumn gases(tables, column.profile());
        for (int i = 6; i < argc; ++i) band(column, gases, data_dir, std::stod(argv[i]), mu0);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "atmosphere_split: %s\n", e.what());
        return 1;
    }
    return 0;
}
