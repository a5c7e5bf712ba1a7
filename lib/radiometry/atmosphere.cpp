// The atmosphere of a render: the .rad tables of every band merged on one spectral
// grid; sun, path terms by view angle and the downwelled sky hemisphere (White (1996), section 3.4;
// rad(5); atmosphere.hpp).
#include "radiometry/atmosphere.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "radiometry/atmosphere_data.hpp"

namespace sigchain::radiometry {

namespace {

// Two files' sun positions agree when within this (deg; atmosphere.hpp).
constexpr double kSunTolerance_deg = 0.01;
// Two files' view angles or sky-cell centres agree when within this (deg): the .rad
// grids are printed with at least 6 significant digits.
constexpr double kGridTolerance_deg = 1e-6;

}  // namespace

namespace {

std::string stem_of(const std::string& file) { return std::filesystem::path(file).stem().string(); }

double azimuth_difference_deg(double a, double b) {
    double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360 - d);
}

// The grids of `rad` (file `file`) against those of the first file. Errors name the
// file only: a disagreement between two files belongs to no line of either.
void check_same_grids(const io::Rad& first, const std::string& first_file, const io::Rad& rad,
                      const std::string& file) {
    auto fail = [&](const std::string& what) {
        throw DataError({file, 0}, what + " " + first_file);
    };
    if (rad.views.size() != first.views.size()) fail("view angles differ from those of");
    for (std::size_t v = 0; v < rad.views.size(); ++v)
        if (std::abs(rad.views[v].view_angle_deg - first.views[v].view_angle_deg) >
            kGridTolerance_deg)
            fail("view angles differ from those of");
    if (rad.sky.has_value() != first.sky.has_value())
        throw DataError({file, 0}, std::string(rad.sky ? "has" : "has no") +
                                       " SIGCHAIN_RAD block (sun and sky), unlike " + first_file);
    if (!rad.sky) return;
    const io::RadSky &a = *first.sky, &b = *rad.sky;
    if (std::abs(a.sun_zenith_deg - b.sun_zenith_deg) > kSunTolerance_deg ||
        azimuth_difference_deg(a.sun_azimuth_deg, b.sun_azimuth_deg) > kSunTolerance_deg)
        fail("sun position differs from that of");
    if (a.zenith_count != b.zenith_count || a.azimuth_count != b.azimuth_count ||
        a.cells.size() != b.cells.size())
        fail("sky hemisphere grid differs from that of");
    for (std::size_t c = 0; c < a.cells.size(); ++c)
        if (std::abs(a.cells[c].zenith_deg - b.cells[c].zenith_deg) > kGridTolerance_deg ||
            std::abs(a.cells[c].azimuth_deg - b.cells[c].azimuth_deg) > kGridTolerance_deg)
            fail("sky hemisphere grid differs from that of");
}

// The tables' sizes and order. parse_rad checks these at their lines as it reads; here
// they guard a Rad made in memory (uniform_rad, tests), which has no lines: the errors
// name the file only.
void check_shape(const io::Rad& rad, const std::string& file) {
    if (rad.samples.empty()) throw DataError({file, 0}, "no spectral samples");
    if (rad.views.empty()) throw DataError({file, 0}, "no view angles");
    for (const auto& v : rad.views)
        if (v.path.size() != rad.samples.size())
            throw DataError({file, 0}, "a view angle has " + std::to_string(v.path.size()) +
                                           " path samples for " +
                                           std::to_string(rad.samples.size()) +
                                           " spectral samples");
    for (std::size_t v = 1; v < rad.views.size(); ++v)
        if (!(rad.views[v].view_angle_deg > rad.views[v - 1].view_angle_deg))
            throw DataError({file, 0}, "view angles are not increasing");
    if (!rad.sky) return;
    const io::RadSky& s = *rad.sky;
    if (s.zenith_count < 1 || s.azimuth_count < 1 ||
        s.cells.size() != static_cast<std::size_t>(s.zenith_count * s.azimuth_count))
        throw DataError({file, 0}, "sky hemisphere: cell count is not rings x cells per ring");
    for (const auto& c : s.cells)
        if (c.scattered_radiance.size() != rad.samples.size() ||
            c.emitted_radiance.size() != rad.samples.size())
            throw DataError({file, 0},
                            "sky hemisphere: a cell's radiances do not match the "
                            "spectral samples");
}

}  // namespace

// The UPWELLED grids of every band merged on the spectral grid, when all files have
// one and the grids agree; none when no file has one. The errors compare whole grids
// (or re-check a Rad made in memory, as check_shape), so they name the file only.
void Atmosphere::Data::load_upwelled(const std::vector<io::Rad>& rads,
                                     const std::vector<std::string>& files) {
    Data& d = *this;
    const auto& first = rads[0].sky->upwelled;
    for (std::size_t b = 0; b < rads.size(); ++b) {
        const auto& up = rads[b].sky->upwelled;
        if (up.has_value() != first.has_value())
            throw DataError({files[b], 0}, std::string("UPWELLED grid ") +
                                               (up ? "present" : "missing") + ", unlike in " +
                                               files[0]);
        if (!up) continue;
        if (up->zenith_count < 1 || up->azimuth_count < 1 ||
            up->cells.size() != static_cast<std::size_t>(up->zenith_count * up->azimuth_count))
            throw DataError({files[b], 0}, "UPWELLED grid: cell count is not rings x cells");
        bool same =
            up->zenith_count == first->zenith_count && up->azimuth_count == first->azimuth_count;
        for (std::size_t c = 0; same && c < up->cells.size(); ++c)
            same = std::abs(up->cells[c].view_zenith_deg - first->cells[c].view_zenith_deg) <=
                       kGridTolerance_deg &&
                   std::abs(up->cells[c].azimuth_deg - first->cells[c].azimuth_deg) <=
                       kGridTolerance_deg;
        if (!same) throw DataError({files[b], 0}, "UPWELLED grid differs from that of " + files[0]);
        for (const auto& c : up->cells)
            if (c.scattered_radiance.size() != rads[b].samples.size() ||
                c.emitted_radiance.size() != rads[b].samples.size())
                throw DataError({files[b], 0},
                                "UPWELLED grid: a cell's radiances do not match the spectral "
                                "samples");
    }
    if (!first) return;
    const auto za = static_cast<std::size_t>(first->azimuth_count);
    for (long r = 0; r < first->zenith_count; ++r)
        d.up_zenith_deg.push_back(first->cells[static_cast<std::size_t>(r) * za].view_zenith_deg);
    for (std::size_t a = 0; a < za; ++a) d.up_azimuth_deg.push_back(first->cells[a].azimuth_deg);
    const std::size_t n = d.grid.size();
    d.up_scattered.assign(first->cells.size() * n, 0.0);
    d.up_emitted.assign(first->cells.size() * n, 0.0);
    for (std::size_t c = 0; c < first->cells.size(); ++c) {
        std::size_t k = 0;
        for (const auto& rad : rads) {
            const auto& cell = rad.sky->upwelled->cells[c];
            for (std::size_t s = 0; s < cell.scattered_radiance.size(); ++s, ++k) {
                d.up_scattered[c * n + k] = cell.scattered_radiance[s];
                d.up_emitted[c * n + k] = cell.emitted_radiance[s];
            }
        }
    }
    d.has_upwelled = true;
}

// Ring edges halfway between ring centres, the first at 0 and the last at 90 deg;
// azimuth edges halfway between column centres, wrapping round north.
void Atmosphere::Data::build_sky_grid(const io::RadSky& sky) {
    Data& d = *this;
    d.rings = static_cast<int>(sky.zenith_count);
    d.columns = static_cast<int>(sky.azimuth_count);
    std::vector<double> zc(d.rings), ac(d.columns);
    for (int r = 0; r < d.rings; ++r) zc[r] = sky.cells[r * d.columns].zenith_deg;
    for (int c = 0; c < d.columns; ++c) ac[c] = sky.cells[c].azimuth_deg;
    d.ring_edges_deg.assign(d.rings + 1, 0.0);
    for (int r = 1; r < d.rings; ++r) d.ring_edges_deg[r] = 0.5 * (zc[r - 1] + zc[r]);
    d.ring_edges_deg[d.rings] = 90;
    d.azimuth_hi_deg.resize(d.columns);
    for (int c = 0; c < d.columns; ++c) {
        double next = c + 1 < d.columns ? ac[c + 1] : ac[0] + 360;
        d.azimuth_hi_deg[c] = 0.5 * (ac[c] + next);
    }
    for (int r = 1; r < d.rings; ++r)
        d.ring_cos_edges.push_back(std::cos(d.ring_edges_deg[r] * kRadPerDeg));
    d.uniform_azimuth_step_deg = 360.0 / d.columns;
    for (int c = 0; c < d.columns; ++c) {
        double lo = c > 0 ? d.azimuth_hi_deg[c - 1] : d.azimuth_hi_deg.back() - 360;
        if (std::abs(d.azimuth_hi_deg[c] - lo - 360.0 / d.columns) > 1e-9)
            d.uniform_azimuth_step_deg = 0;
    }
}

// The spectral grid: the samples of every band in file order, each band named by its
// file's stem, with Es * tau1 per sample.
void Atmosphere::Data::merge_spectra(const std::vector<io::Rad>& rads,
                                     const std::vector<std::string>& files) {
    for (std::size_t b = 0; b < rads.size(); ++b) {
        grid.band_names.push_back(stem_of(files[b]));
        for (const auto& s : rads[b].samples) {
            grid.wavelength_um.push_back(s.wavelength_um);
            grid.band_of_sample.push_back(static_cast<int>(b));
            es.push_back(s.solar_irradiance);
            es_tau1.push_back(s.solar_irradiance * s.sun_transmission);
        }
    }
}

// The path terms of every view angle, the bands' samples side by side.
void Atmosphere::Data::merge_views(const std::vector<io::Rad>& rads) {
    const std::size_t n = grid.size();
    const auto& views = rads[0].views;
    std::size_t nv = views.size();
    tau2.resize(nv * n), scattered.resize(nv * n), emitted.resize(nv * n);
    for (std::size_t v = 0; v < nv; ++v) {
        view_angles_deg.push_back(views[v].view_angle_deg);
        range_km.push_back(views[v].range_km);
        std::size_t k = 0;
        for (const auto& rad : rads)
            for (const auto& p : rad.views[v].path) {
                tau2[v * n + k] = p.transmission;
                scattered[v * n + k] = p.scattered_radiance;
                emitted[v * n + k] = p.emitted_radiance;
                ++k;
            }
    }
}

// Sky cell `c` of the first file's grid with the radiances of every band, its edges,
// exact solid angle and direction; adds its share to the horizontal irradiances.
SkyCell Atmosphere::Data::merge_sky_cell(const std::vector<io::Rad>& rads, std::size_t c) {
    const io::RadSky& sky = *rads[0].sky;
    int r = static_cast<int>(c) / columns, col = static_cast<int>(c) % columns;
    SkyCell cell;
    cell.zenith_deg = sky.cells[c].zenith_deg;
    cell.azimuth_deg = sky.cells[c].azimuth_deg;
    cell.zenith_lo_deg = ring_edges_deg[r];
    cell.zenith_hi_deg = ring_edges_deg[r + 1];
    cell.azimuth_hi_deg = azimuth_hi_deg[col];
    cell.azimuth_lo_deg = col > 0 ? azimuth_hi_deg[col - 1] : azimuth_hi_deg[columns - 1] - 360;
    // The solid angle of the cell's edges, exactly: (cos z_lo - cos z_hi)(a_hi -
    // a_lo), so that lookup (sky_cell), solid angles and irradiance describe one
    // partition of the hemisphere (the file's values agree when its centres lie
    // midway, as build_radiance and uniform_rad write them).
    double c_lo = std::cos(cell.zenith_lo_deg * kRadPerDeg);
    double c_hi = std::cos(cell.zenith_hi_deg * kRadPerDeg);
    cell.solid_angle_sr = (c_lo - c_hi) * (cell.azimuth_hi_deg - cell.azimuth_lo_deg) * kRadPerDeg;
    cell.direction =
        geo::direction_from_degrees(cell.zenith_deg, cell.azimuth_deg);
    for (const auto& rad : rads) {
        const auto& src = rad.sky->cells[c];
        cell.scattered.insert(cell.scattered.end(), src.scattered_radiance.begin(),
                              src.scattered_radiance.end());
        cell.emitted.insert(cell.emitted.end(), src.emitted_radiance.begin(),
                            src.emitted_radiance.end());
    }
    // Int cos(z) d(omega) over the cell = 0.5 (sin^2 z_hi - sin^2 z_lo) (a_hi - a_lo).
    double s_hi = std::sin(cell.zenith_hi_deg * kRadPerDeg);
    double s_lo = std::sin(cell.zenith_lo_deg * kRadPerDeg);
    double projected = 0.5 * (s_hi * s_hi - s_lo * s_lo) *
                       (cell.azimuth_hi_deg - cell.azimuth_lo_deg) * kRadPerDeg;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        sky_irradiance[k] += cell.scattered[k] * projected;
        sky_emitted_irradiance[k] += cell.emitted[k] * projected;
    }
    return cell;
}

Atmosphere Atmosphere::from_rads(const std::vector<io::Rad>& rads,
                                 const std::vector<std::string>& files) {
    if (rads.empty() || rads.size() != files.size())
        throw std::invalid_argument("Atmosphere::from_rads: one file name per .rad, at least one");
    for (std::size_t i = 0; i < rads.size(); ++i) {
        check_shape(rads[i], files[i]);
        if (i > 0) check_same_grids(rads[0], files[0], rads[i], files[i]);
    }
    auto d = std::make_shared<Data>();
    d->merge_spectra(rads, files);
    d->merge_views(rads);
    const std::size_t n = d->grid.size();
    d->sky_irradiance.assign(n, 0.0);
    d->sky_emitted_irradiance.assign(n, 0.0);
    d->sun_at_ground.assign(n, 0.0);
    if (rads[0].sky) {
        const io::RadSky& sky = *rads[0].sky;
        d->has_sky = true;
        d->build_sky_grid(sky);
        for (std::size_t c = 0; c < sky.cells.size(); ++c)
            d->cells.push_back(d->merge_sky_cell(rads, c));
        d->place_sun(sky.sun_zenith_deg, sky.sun_azimuth_deg);
        d->load_upwelled(rads, files);
        d->load_coupling(rads, files);
    }
    Atmosphere a;
    a.m_data = d;
    return a;
}

const SpectralGrid& Atmosphere::grid() const { return m_data->grid; }
geo::Vec3 Atmosphere::sun_direction() const { return m_data->sun_direction; }
bool Atmosphere::sun_up() const { return m_data->sun_up(); }
double Atmosphere::sun_zenith_deg() const { return m_data->sun_zenith_deg; }
double Atmosphere::sun_azimuth_deg() const { return m_data->sun_azimuth_deg; }

std::span<const double> Atmosphere::sun_irradiance_at_ground() const {
    return m_data->sun_at_ground;
}

namespace {

}  // namespace

void Atmosphere::path(double view_angle_deg, std::span<double> tau2, std::span<double> scattered,
                      std::span<double> emitted) const {
    const Data& d = *m_data;
    const std::size_t n = d.grid.size();
    const Bracket b = bracket(d.view_angles_deg, view_angle_deg);
    const std::size_t i = b.k, j = b.next(d.view_angles_deg.size());
    const double f = b.t;
    auto lerp = [&](const std::vector<double>& t, std::span<double> out) {
        if (out.empty()) return;
        if (out.size() != n) throw std::invalid_argument("Atmosphere::path: span size");
        for (std::size_t k = 0; k < n; ++k) out[k] = (1 - f) * t[i * n + k] + f * t[j * n + k];
    };
    lerp(d.tau2, tau2);
    lerp(d.scattered, scattered);
    lerp(d.emitted, emitted);
}

bool Atmosphere::has_upwelled() const { return m_data->has_upwelled; }

void Atmosphere::path(const geo::Vec3& line_of_sight, double view_angle_deg, std::span<double> tau2,
                      std::span<double> scattered, std::span<double> emitted) const {
    const Data& d = *m_data;
    if (!d.has_upwelled) {
        path(view_angle_deg, tau2, scattered, emitted);
        return;
    }
    path(view_angle_deg, tau2, {}, {});
    const std::size_t n = d.grid.size();
    // View zenith off nadir and azimuth of the line of sight (clockwise from north).
    const double len = geo::norm(line_of_sight);
    if (!(len > 0)) throw std::invalid_argument("Atmosphere::path: zero line of sight");
    const double zenith = std::acos(std::clamp(-line_of_sight[2] / len, -1.0, 1.0)) / kRadPerDeg;
    double azimuth = std::atan2(line_of_sight[0], line_of_sight[1]) / kRadPerDeg;
    if (azimuth < 0) azimuth += 360;
    const Bracket bz = bracket(d.up_zenith_deg, zenith);
    const std::size_t i = bz.k, i1 = bz.next(d.up_zenith_deg.size());
    const double f = bz.t;
    // Azimuth nodes are periodic: between the last and the first across north.
    const auto& az = d.up_azimuth_deg;
    const std::size_t na = az.size();
    std::size_t j0 = 0, j1 = 0;
    double g = 0;
    if (na > 1) {
        const auto hi =
            static_cast<std::size_t>(std::upper_bound(az.begin(), az.end(), azimuth) - az.begin());
        if (hi == 0 || hi == na) {  // across north
            j0 = na - 1, j1 = 0;
            const double span = az[0] + 360 - az[na - 1];
            const double x = hi == 0 ? azimuth + 360 : azimuth;
            g = span > 0 ? (x - az[na - 1]) / span : 0;
        } else {
            j0 = hi - 1, j1 = hi;
            g = (azimuth - az[j0]) / (az[j1] - az[j0]);
        }
    }
    auto lerp = [&](const std::vector<double>& t, std::span<double> out) {
        if (out.empty()) return;
        if (out.size() != n) throw std::invalid_argument("Atmosphere::path: span size");
        const std::size_t c00 = (i * na + j0) * n, c01 = (i * na + j1) * n;
        const std::size_t c10 = (i1 * na + j0) * n, c11 = (i1 * na + j1) * n;
        for (std::size_t k = 0; k < n; ++k)
            out[k] = (1 - f) * ((1 - g) * t[c00 + k] + g * t[c01 + k]) +
                     f * ((1 - g) * t[c10 + k] + g * t[c11 + k]);
    };
    lerp(d.up_scattered, scattered);
    lerp(d.up_emitted, emitted);
}

double Atmosphere::range_km(double view_angle_deg) const {
    return interpolate_clamped(m_data->view_angles_deg, m_data->range_km, view_angle_deg);
}

double Atmosphere::min_view_angle_deg() const { return m_data->view_angles_deg.front(); }
double Atmosphere::max_view_angle_deg() const { return m_data->view_angles_deg.back(); }

bool Atmosphere::has_sky() const { return m_data->has_sky; }
const std::vector<SkyCell>& Atmosphere::sky_cells() const { return m_data->cells; }

// Ring by binary search over the cosines of the ring edges (log of <= ~100 rings, no
// acos); column directly on a uniform azimuth grid, else by binary search over the
// azimuth edges after wrapping the azimuth into [lo_0, lo_0 + 360).
int Atmosphere::sky_cell(const geo::Vec3& dir) const {
    const Data& d = *m_data;
    if (!d.has_sky || !(dir[2] > 0)) return -1;
    // Zenith beyond edge r <=> dir.z < cos(edge r): count the edges with cos > dir.z.
    auto rit = std::upper_bound(d.ring_cos_edges.begin(), d.ring_cos_edges.end(), dir[2],
                                [](double z, double edge) { return z >= edge; });
    int ring = static_cast<int>(rit - d.ring_cos_edges.begin());
    if (d.columns == 1) return ring;
    double lo = d.azimuth_hi_deg.back() - 360;
    double azimuth = std::atan2(dir[0], dir[1]) / kRadPerDeg;  // clockwise from north
    while (azimuth < lo) azimuth += 360;
    while (azimuth >= lo + 360) azimuth -= 360;
    int column;
    if (d.uniform_azimuth_step_deg > 0) {
        column =
            std::min(static_cast<int>((azimuth - lo) / d.uniform_azimuth_step_deg), d.columns - 1);
    } else {
        auto ait = std::upper_bound(d.azimuth_hi_deg.begin(), d.azimuth_hi_deg.end() - 1, azimuth);
        column = static_cast<int>(ait - d.azimuth_hi_deg.begin());
    }
    return ring * d.columns + column;
}

void Atmosphere::add_sky_radiance(const geo::Vec3& dir, double weight, std::span<double> out,
                                  bool emitted) const {
    int c = sky_cell(dir);
    if (c < 0) return;
    const SkyCell& cell = m_data->cells[c];
    std::size_t n = std::min(out.size(), cell.scattered.size());
    if (emitted)
        for (std::size_t k = 0; k < n; ++k)
            out[k] += weight * (cell.scattered[k] + cell.emitted[k]);
    else
        for (std::size_t k = 0; k < n; ++k) out[k] += weight * cell.scattered[k];
}

std::span<const double> Atmosphere::sky_irradiance_horizontal() const {
    return m_data->sky_irradiance;
}

std::span<const double> Atmosphere::sky_emitted_irradiance_horizontal() const {
    return m_data->sky_emitted_irradiance;
}

void Atmosphere::set_sun(double zenith_deg, double azimuth_deg) {
    auto d = std::make_shared<Data>(*m_data);
    d->place_sun(zenith_deg, azimuth_deg);
    m_data = d;
}


}  // namespace sigchain::radiometry
