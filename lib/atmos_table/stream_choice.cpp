// build_radiance --streams auto (see stream_choice.hpp).
#include "atmos_table/stream_choice.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace sigchain::atmos_table {

namespace {

// Aerosol phase moments beyond the streams for the Nakajima-Tanaka correction: g^k of
// Henyey-Greenstein falls below 1e-5 by k = 32 for g <= 0.7 (LOWTRAN's aerosols). With
// IPH 2 the TMS correction uses the Mie functions themselves (mie_layers.hpp); the
// moments serve delta-M (moment `streams`) and the IMS correction's forward peak.
constexpr int kPhaseMoments = 32;

// An entry is compared with the larger of its reference and this fraction of the
// largest reference entry of its table.
constexpr double kTableFloor = 1e-3;

// N's error from the difference d between N and 2N streams: with an error falling as
// N^-p, N's is d / (1 - 2^-p); p = 1, the slowest the tests' decks show (a clear
// column: 0.59 % between 4 and 8 streams, 0.35 % between 12 and 24; 4 streams are
// then 1.4 % from 32), gives 2 d.
constexpr double kErrorPerDifference = 2;

// The largest relative difference over one table (a and b of one length).
double table_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double largest = 0;
    for (double v : b) largest = std::max(largest, std::abs(v));
    if (!(largest > 0)) return 0;  // nothing in this table (e.g. no emission)
    const double floor = kTableFloor * largest;
    double worst = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), floor));
    return worst;
}

// The sample's radiance tables, each as one series.
std::vector<std::vector<double>> radiance_tables(const SampleResult& r) {
    std::vector<double> scattered, emitted;
    for (const auto& p : r.path) {
        scattered.push_back(p.scattered_radiance);
        emitted.push_back(p.emitted_radiance);
    }
    return {scattered, emitted, r.ls, r.le, r.us, r.ue};
}

// The coupling terms (rt/coupling.hpp), each through the radiance it changes: the
// ground's reflected radiance goes as 1 / (1 - rho S), whose relative change is at
// most |dS| / (1 - S) for any ground reflectance rho <= 1; the ground's irradiance as
// the sun's direct plus diffuse transmittance (tau1 + t_d_down), the ground's radiance
// at the sensor as the path's direct plus diffuse transmittance (tau2 + t_d_up).
double coupling_difference(const SampleResult& a, const SampleResult& b) {
    auto rel = [](double x, double ref, double scale) {
        return scale > 0 ? std::abs(x - ref) / scale : 0.0;
    };
    double worst = rel(a.spherical_albedo, b.spherical_albedo, 1 - b.spherical_albedo);
    worst = std::max(
        worst, rel(a.diffuse_down, b.diffuse_down, b.sample.sun_transmission + b.diffuse_down));
    for (std::size_t v = 0; v < a.diffuse_up.size() && v < b.diffuse_up.size(); ++v)
        worst = std::max(
            worst, rel(a.diffuse_up[v], b.diffuse_up[v], b.path[v].transmission + b.diffuse_up[v]));
    return worst;
}

// The probes solved at `streams` (the setup's options copied with them), each with one
// equivalent gas depth (max_gas_terms 1): the difference between N and 2N streams is the
// error of the scattering, which a sample's exponential-sum terms share, and one depth
// is one column solve where the terms are several (2.2 per Hawkeye sample). A probe's
// preparation (its column, Mie functions and gas depth) serves every order with the
// same phase moments (every order up to kPhaseMoments): preps[p] is kept or remade.
std::vector<SampleResult> solve_probes(const SampleSetup& base, const std::vector<double>& probes,
                                       int streams, std::vector<SamplePrep>& preps) {
    RadianceOptions o = base.options;
    o.streams = streams;
    o.max_gas_terms = 1;
    SampleSetup s{base.column,
                  base.dirs,
                  base.solar,
                  o,
                  base.views_deg,
                  base.mu0,
                  base.sun_up,
                  base.distance_factor,
                  phase_moments(streams),
                  base.deck,
                  base.mie};
    preps.resize(probes.size());
    std::vector<SampleResult> out;
    for (std::size_t p = 0; p < probes.size(); ++p) {
        if (preps[p].moments != s.moments || preps[p].nu != probes[p])
            preps[p] = prepare_sample(s, probes[p]);
        out.push_back(solve_sample(s, preps[p]));
    }
    return out;
}

}  // namespace

int phase_moments(int streams) { return std::max(streams, kPhaseMoments); }

std::vector<double> probe_wavenumbers(const atmos::ColumnModel& column, const io::SndBand& band) {
    const long n = band.sample_count();
    auto nu = [&](long s) { return band.wavenumber_cm1(s); };
    std::vector<double> probes{nu((n - 1) / 2)};
    long most = 0;
    double most_tau = -1;
    for (long s = 0; s < n; ++s) {
        const double tau = column.scattering_optical_depth(nu(s));
        if (tau > most_tau) {
            most_tau = tau;
            most = s;
        }
    }
    if (most != (n - 1) / 2) probes.push_back(nu(most));
    return probes;
}

double table_difference(const SampleResult& a, const SampleResult& b) {
    const auto ta = radiance_tables(a), tb = radiance_tables(b);
    double worst = coupling_difference(a, b);
    for (std::size_t t = 0; t < ta.size(); ++t)
        worst = std::max(worst, table_difference(ta[t], tb[t]));
    return worst;
}

StreamChoice choose_streams(const SampleSetup& setup, const std::vector<double>& probes,
                            double tolerance) {
    std::map<int, std::vector<SampleResult>> solved;  // per order, per probe
    std::vector<SamplePrep> preps;
    auto at = [&](int streams) -> const std::vector<SampleResult>& {
        auto it = solved.find(streams);
        if (it == solved.end())
            it = solved.emplace(streams, solve_probes(setup, probes, streams, preps)).first;
        return it->second;
    };
    StreamChoice choice;
    choice.probe_wavenumbers = probes;
    for (int n : kStreamCandidates) {
        const auto& low = at(n);
        const auto& high = at(2 * n);
        double worst = 0;
        for (std::size_t p = 0; p < probes.size(); ++p)
            worst = std::max(worst, table_difference(low[p], high[p]));
        choice.streams = n;
        choice.check_streams = 2 * n;
        choice.estimated_error = kErrorPerDifference * worst;
        choice.within_tolerance = choice.estimated_error <= tolerance;
        if (choice.within_tolerance) break;
        solved.erase(n);  // no longer needed: the next comparisons are of higher orders
    }
    return choice;
}

}  // namespace sigchain::atmos_table
