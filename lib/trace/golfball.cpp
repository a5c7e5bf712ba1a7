// The golf-ball secondary-ray pattern (White (1996), section 5.2.3); geometry in golfball.hpp.
#include "trace/golfball.hpp"

#include <cmath>
#include <algorithm>
#include <utility>

namespace sigchain::trace {
namespace {

constexpr int kRingCells[5] = {1, 6, 12, 18, 24};
// cos theta at the lower (outer) edge of each ring: cumulative full cells / 49.
constexpr double kRingCosLo[5] = {48.0 / 49, 42.0 / 49, 30.0 / 49, 12.0 / 49, 0.0};

std::vector<GolfCell> make_cells() {
    std::vector<GolfCell> cells;
    double cos_hi = 1;
    for (int ring = 0; ring < 5; ++ring) {
        int n = kRingCells[ring];
        double width = 2 * M_PI / n;
        for (int j = 0; j < n; ++j) {
            GolfCell c;
            c.cos_lo = kRingCosLo[ring];
            c.cos_hi = cos_hi;
            c.phi_lo = ring == 0 ? -M_PI : j * width - width / 2;
            c.phi_hi = ring == 0 ? M_PI : j * width + width / 2;
            c.ring = ring;
            c.index = j;
            cells.push_back(c);
        }
        cos_hi = kRingCosLo[ring];
    }
    return cells;
}

// A ray at the mid-cos, mid-azimuth of the region (cos_lo..cos_hi, phi_lo..phi_hi),
// or at the zenith for a cap (cos_hi == 1 with the full azimuth range).
// Solid angle = dphi * dcos; projected = dphi * (cos_hi^2 - cos_lo^2) / 2.
GolfRay region_ray(double cos_lo, double cos_hi, double phi_lo, double phi_hi, int cell) {
    GolfRay r;
    bool cap = cos_hi == 1 && phi_hi - phi_lo >= 2 * M_PI - 1e-12;
    r.cos_theta = cap ? 1.0 : 0.5 * (cos_lo + cos_hi);
    r.sin_theta = std::sqrt(std::max(0.0, 1 - r.cos_theta * r.cos_theta));
    double phi = cap ? 0.0 : 0.5 * (phi_lo + phi_hi);
    r.cos_phi = std::cos(phi);
    r.sin_phi = std::sin(phi);
    r.solid_angle_sr = (phi_hi - phi_lo) * (cos_hi - cos_lo);
    r.projected_sr = (phi_hi - phi_lo) * (cos_hi * cos_hi - cos_lo * cos_lo) / 2;
    r.cell = cell;
    r.cos_lo = cos_lo;
    r.cos_hi = cos_hi;
    r.phi_lo = phi_lo;
    r.phi_hi = phi_hi;
    return r;
}

// Seven rays of 1/7 of the cell's solid angle each (header: hexagon split).
void split_cell(const GolfCell& c, int cell, std::vector<GolfRay>& out) {
    double dcos = c.cos_hi - c.cos_lo;
    if (c.ring == 0) {
        double inner = c.cos_hi - dcos / 7;
        out.push_back(region_ray(inner, c.cos_hi, c.phi_lo, c.phi_hi, cell));
        double width = 2 * M_PI / 6;
        for (int j = 0; j < 6; ++j)
            out.push_back(region_ray(c.cos_lo, inner, j * width - width / 2,
                                     j * width + width / 2, cell));
        return;
    }
    constexpr int pieces[3] = {2, 3, 2};
    double hi = c.cos_hi;
    for (int band = 0; band < 3; ++band) {
        double lo = band == 2 ? c.cos_lo : hi - dcos * pieces[band] / 7;
        double width = (c.phi_hi - c.phi_lo) / pieces[band];
        for (int j = 0; j < pieces[band]; ++j)
            out.push_back(region_ray(lo, hi, c.phi_lo + j * width, c.phi_lo + (j + 1) * width,
                                     cell));
        hi = lo;
    }
}

int cell_index(int ring, int j) {
    int first = 0;
    for (int r = 0; r < ring; ++r) first += kRingCells[r];
    int n = kRingCells[ring];
    return first + ((j % n) + n) % n;
}

std::vector<int> matrix_cells(int matrix) {
    switch (matrix) {
    case 1:
        return {cell_index(0, 0), cell_index(1, 0), cell_index(1, 1), cell_index(1, 2),
                cell_index(1, 3), cell_index(1, 4), cell_index(1, 5)};
    case 2:
        return {cell_index(1, 0), cell_index(0, 0), cell_index(1, 1), cell_index(1, -1),
                cell_index(2, 0), cell_index(2, 1), cell_index(2, -1)};
    case 3:
        return {cell_index(2, 0), cell_index(1, 0), cell_index(2, 1), cell_index(2, -1),
                cell_index(3, 0), cell_index(3, 1), cell_index(3, -1)};
    default:
        return {};
    }
}

std::vector<GolfRay> make_rays(int matrix) {
    const auto& cells = golfball_cells();
    std::vector<int> split = matrix_cells(matrix);
    std::vector<GolfRay> rays;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const GolfCell& c = cells[i];
        bool is_split = false;
        for (int s : split) is_split = is_split || s == static_cast<int>(i);
        if (is_split)
            split_cell(c, static_cast<int>(i), rays);
        else
            rays.push_back(region_ray(c.cos_lo, c.cos_hi, c.phi_lo, c.phi_hi,
                                      static_cast<int>(i)));
    }
    return rays;
}

}  // namespace

const std::vector<GolfCell>& golfball_cells() {
    static const std::vector<GolfCell> cells = make_cells();
    return cells;
}

const std::vector<GolfRay>& golfball_rays(int matrix) {
    static const std::array<std::vector<GolfRay>, 4> rays = {make_rays(0), make_rays(1),
                                                              make_rays(2), make_rays(3)};
    return rays.at(static_cast<std::size_t>(matrix));
}

int golfball_matrix(double specular_angle_deg) {
    // White (1996), section 5.2.3: |phi_rps - phi_fn| > 33.75 -> matrix 3, > 11.25 ->
    // matrix 2, else 1.
    double a = std::abs(specular_angle_deg);
    if (a > 33.75) return 3;
    if (a > 11.25) return 2;
    return 1;
}

}  // namespace sigchain::trace
