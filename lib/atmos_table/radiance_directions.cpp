// The directions of build_radiance's tables (see radiance_directions.hpp).
#include "atmos_table/radiance_directions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/numeric.hpp"

namespace sigchain::atmos_table {

namespace {

std::size_t index_of(const std::vector<double>& v, double x) {
    return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
}

void sort_unique(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

// A sky subsample before the solver's direction lists are sorted.
struct Pending {
    double mu, phi, weight;
};

// Views: the light reaching the sensor travels up, opposite to the line of sight. A
// positive view angle looks along view_azimuth, so the light travels toward
// view_azimuth + 180; the sun's beam travels toward sun_azimuth + 180 (phi is the
// solver's azimuth of propagation relative to the beam's).
struct ViewGeometry {
    double view_azimuth_deg, sun_azimuth_deg;
    double mu(double v) const { return std::cos(std::abs(v) * kRadPerDeg); }
    double phi(double v) const {
        return wrap_degrees(view_azimuth_deg + (v < 0 ? 180.0 : 0.0) - sun_azimuth_deg);
    }
};

// Azimuths of a sky cell that spans the whole ring: a degree apart, so that every
// Fourier mode the solver has (fewer than 360) averages to 0 over them and the
// corrections' aureole is resolved, as in the azimuth-mean solve; n of them would
// alias modes n, 2n, ... into the ring's mean (17 % too bright at 0.45 um with n = 4).
constexpr int kRingAzimuths = 360;

// The subsamples of the sky cell [z0, z1] x [a0, a0 + da]: equal steps in cos(zenith)
// and azimuth, so equal solid angles (n x n; n x kRingAzimuths for a whole ring unless
// the solver gives azimuthal means, the same at every azimuth). A cell at azimuth A
// sends light travelling toward A + 180, down.
std::vector<Pending> cell_subsamples(Directions& d, double z0, double z1, double a0, double da,
                                     int n, double sun_azimuth_deg) {
    std::vector<Pending> subs;
    const int na = da >= 360 && !d.azimuth_means_only ? std::max(n, kRingAzimuths) : n;
    for (int p = 0; p < n; ++p) {
        const double c0 = std::cos(z0 * kRadPerDeg), c1 = std::cos(z1 * kRadPerDeg);
        const double mu = c0 + (c1 - c0) * (p + 0.5) / n;
        for (int q = 0; q < na; ++q) {
            const double a = a0 + da * (q + 0.5) / na;
            subs.push_back({-mu, wrap_degrees(a - sun_azimuth_deg), 1.0 / (n * na)});
            d.umu.push_back(-mu);
            d.phi.push_back(wrap_degrees(a - sun_azimuth_deg));
        }
    }
    return subs;
}

// The sky cells (ring by ring, azimuth within a ring; d.zenith_count x d.azimuth_count)
// and their subsamples.
std::vector<std::vector<Pending>> add_sky(Directions& d, double sun_azimuth_deg,
                                          const RadianceOptions& o) {
    const double dz = 90.0 / static_cast<double>(d.zenith_count);
    const double da = 360.0 / static_cast<double>(d.azimuth_count);
    const int n = std::max(1, o.sky_subsamples);
    std::vector<std::vector<Pending>> pending;
    for (long i = 0; i < d.zenith_count; ++i) {
        const double z0 = i * dz, z1 = (i + 1) * dz;
        for (long j = 0; j < d.azimuth_count; ++j) {
            const double a0 = j * da;
            io::RadSkyCell cell;
            cell.zenith_deg = z0 + dz / 2;
            cell.azimuth_deg = a0 + da / 2;
            cell.solid_angle_sr =
                (std::cos(z0 * kRadPerDeg) - std::cos(z1 * kRadPerDeg)) * da * kRadPerDeg;
            d.cells.push_back(cell);
            pending.push_back(cell_subsamples(d, z0, z1, a0, da, n, sun_azimuth_deg));
        }
    }
    return pending;
}

// The upwelled grid: a line of sight at azimuth A carries light travelling toward
// A + 180, up.
void add_upwelled(Directions& d, const std::vector<double>& view_angles_deg, double sun_azimuth_deg,
                  const RadianceOptions& o) {
    for (double v : view_angles_deg) d.up_zenith_deg.push_back(std::abs(v));
    sort_unique(d.up_zenith_deg);
    const long up_cells = std::lround(360.0 / o.upwelled_azimuth_step_deg);
    for (long j = 0; j < up_cells; ++j) {
        const double a = 360.0 * static_cast<double>(j) / static_cast<double>(up_cells);
        d.up_azimuth_deg.push_back(a);
        d.phi.push_back(wrap_degrees(a - sun_azimuth_deg));
    }
}

// Where every view, upwelled node and sky subsample lands in the sorted lists.
void index_directions(Directions& d, const std::vector<double>& view_angles_deg,
                      const ViewGeometry& view, const std::vector<std::vector<Pending>>& pending) {
    for (double z : d.up_zenith_deg) d.up_mu.push_back(index_of(d.umu, std::cos(z * kRadPerDeg)));
    for (double a : d.up_azimuth_deg)
        d.up_phi.push_back(index_of(d.phi, wrap_degrees(a - view.sun_azimuth_deg)));
    for (double v : view_angles_deg) {
        d.view_mu.push_back(index_of(d.umu, view.mu(v)));
        d.view_phi.push_back(index_of(d.phi, view.phi(v)));
    }
    for (const auto& subs : pending) {
        std::vector<Directions::Sub> s;
        for (const auto& p : subs)
            s.push_back({index_of(d.umu, p.mu), index_of(d.phi, p.phi), p.weight});
        d.sky.push_back(std::move(s));
    }
}

}  // namespace

double wrap_degrees(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

Directions directions(const std::vector<double>& view_angles_deg, double view_azimuth_deg,
                      double sun_azimuth_deg, const RadianceOptions& o) {
    Directions d;
    const ViewGeometry view{view_azimuth_deg, sun_azimuth_deg};
    for (double v : view_angles_deg) {
        d.umu.push_back(view.mu(v));
        d.phi.push_back(view.phi(v));
    }
    // Only means over azimuth: every sky cell a whole ring and every view at nadir.
    const bool nadir = std::all_of(view_angles_deg.begin(), view_angles_deg.end(),
                                   [](double v) { return v == 0; });
    d.zenith_count = std::lround(90.0 / o.sky_zenith_step_deg);
    d.azimuth_count = std::lround(360.0 / o.sky_azimuth_step_deg);
    d.azimuth_means_only = d.azimuth_count == 1 && nadir;
    const auto pending = add_sky(d, sun_azimuth_deg, o);
    add_upwelled(d, view_angles_deg, sun_azimuth_deg, o);
    sort_unique(d.umu);
    sort_unique(d.phi);
    index_directions(d, view_angles_deg, view, pending);
    return d;
}

}  // namespace sigchain::atmos_table
