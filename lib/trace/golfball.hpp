// The "golf ball" secondary-ray pattern of White (1996), section 5.2.3 (figs 5.24-5.27): 61 cells
// over the hemisphere above a facet, 37 of solid angle 2 pi / 49 and 24 horizon cells
// of half that, plus three specular-lobe matrices that split the cells about the
// mirror direction into smaller ones of exact solid angle.
//
// Geometry (ours; White (1996) gives only the counts): rings of cells between zenith
// angles whose cosines are exact, so every cell's solid angle is exact:
//   ring 0: 1 cap cell,              cos theta in [48/49, 1]
//   ring 1: 6 cells of 60 deg,       cos theta in [42/49, 48/49]
//   ring 2: 12 cells of 30 deg,      cos theta in [30/49, 42/49]
//   ring 3: 18 cells of 20 deg,      cos theta in [12/49, 30/49]
//   ring 4: 24 horizon cells, 15 deg, cos theta in [0, 12/49]   (half size)
// (solid angle of a ring = 2 pi * delta cos; 1 + 6 + 12 + 18 full cells and 24 half
// cells: 49 full cells of 2 pi / 49 sr). Cell j of a ring with n cells is centred at
// azimuth j * 360 / n (local frame, azimuth 0 = the specular azimuth once rotated),
// its ray at the cell's mid-cos and mid-azimuth (the cap's at the zenith).
//
// Matrices (White (1996): "centred about zenith angles of 0, 22.5 and 45 degrees"),
// each seven cells, each of which is split into 7 rays of 1/7 of its solid angle
// (the 103 rays of White (1996) = 61 - 7 + 49):
//   matrix 1: the cap and ring 1 (centre zenith 0)
//   matrix 2: ring-1 cell 0 (zenith 23.3), the cap, ring-1 cells +-1, ring-2 cells 0, +-1
//   matrix 3: ring-2 cell 0 (zenith 42.7), ring-1 cell 0, ring-2 cells +-1,
//             ring-3 cells 0, +-1
// A rectangular cell (cos range x azimuth range) is split into three zenith bands of
// 2/7, 3/7, 2/7 of its cos range cut into 2, 3, 2 equal azimuth pieces (a hexagon
// with its centre); the cap into an inner cap of 1/7 and six 60-degree sectors.
// Choice by the specular angle (White (1996), section 5.2.3): > 33.75 deg matrix 3, > 11.25 matrix 2,
// else matrix 1.
#pragma once

#include <array>
#include <vector>

namespace sigchain::trace {

struct GolfRay {
    double cos_theta = 1, sin_theta = 0;  // ray direction (local frame, z = normal)
    double cos_phi = 1, sin_phi = 0;      // azimuth from local x, counter-clockwise
    double solid_angle_sr = 0;            // exact solid angle of the ray's cell
    double projected_sr = 0;              // exact integral of cos theta over the cell
    int cell = 0;                         // index of the golf-ball cell it belongs to
    // The region the ray stands for (cos theta and azimuth ranges, azimuth in radians
    // before the rotation to the mirror azimuth): the jittered golf ball draws its
    // ray inside it (render.cpp).
    double cos_lo = 0, cos_hi = 1, phi_lo = 0, phi_hi = 0;
};

// Cell edges: cos theta in [cos_lo, cos_hi], azimuth in [phi_lo, phi_hi] (radians);
// a cap has the full azimuth range.
struct GolfCell {
    double cos_lo = 0, cos_hi = 1, phi_lo = 0, phi_hi = 0;
    int ring = 0, index = 0;
};

// The 61 cells, ring by ring.
const std::vector<GolfCell>& golfball_cells();
// Rays of matrix 1, 2 or 3 (0: the 61 plain cells, one ray each).
const std::vector<GolfRay>& golfball_rays(int matrix);
// Matrix for a specular angle (deg, angle of the mirror direction from the normal).
int golfball_matrix(double specular_angle_deg);

}  // namespace sigchain::trace
