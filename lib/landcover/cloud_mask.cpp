// Cloud and cloud-shadow masks: a pixel test for clouds, their cast outlines for shadows.
#include "landcover/cloud_mask.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/numeric.hpp"

namespace sigchain::landcover {

namespace {

bool all_hold(const std::vector<Term>& terms, const std::vector<double>& px) {
    return std::all_of(terms.begin(), terms.end(), [&](const Term& t) { return t.holds(px); });
}

}  // namespace

void grow(std::vector<int>& mask, long rows, long columns, int value, int radius) {
    const std::vector<int> src = mask;
    for (long r = 0; r < rows; ++r)
        for (long c = 0; c < columns; ++c) {
            if (src[r * columns + c] != value) continue;
            for (long rr = std::max(0L, r - radius); rr <= std::min(rows - 1, r + radius); ++rr)
                for (long cc = std::max(0L, c - radius); cc <= std::min(columns - 1, c + radius);
                     ++cc)
                    if (mask[rr * columns + cc] == kMaskClear) mask[rr * columns + cc] = value;
        }
}

std::vector<int> cloud_mask(const std::vector<const geo::GeoRaster*>& images,
                            const CloudMaskRequest& rq) {
    if (images.empty()) throw std::invalid_argument("cloud_mask: no image");
    if (!(rq.sun_elevation_deg > 0 && rq.sun_elevation_deg <= 90) ||
        !(rq.min_height_m >= 0 && rq.max_height_m >= rq.min_height_m) || !(rq.pixel_m > 0))
        throw std::invalid_argument("cloud_mask: bad sun, heights or pixel size");
    const long rows = images[0]->rows, columns = images[0]->columns;
    std::vector<int> cloud(static_cast<std::size_t>(rows) * columns, kMaskClear);
    std::vector<char> dark(cloud.size(), 0);
    for (long r = 0; r < rows; ++r)
        for (long c = 0; c < columns; ++c) {
            const auto px = stacked_pixel(images, r, c);
            if (all_hold(rq.cloud, px)) cloud[r * columns + c] = kMaskCloud;
            dark[r * columns + c] = all_hold(rq.dark, px) ? 1 : 0;
        }
    // Shadow of a cloud at height h: h / tan(elevation) from it, away from the sun.
    const double away = (rq.sun_azimuth_deg + 180) * kRadPerDeg;
    const double east = std::sin(away), north = std::cos(away);
    const double per_m =
        1 / std::tan(rq.sun_elevation_deg * kRadPerDeg);  // displacement per m of h
    const double step_h = rq.pixel_m / per_m;  // one pixel of displacement
    std::vector<int> mask = cloud;
    for (double h = rq.min_height_m; h <= rq.max_height_m + 1e-9; h += step_h) {
        const double d_px = h * per_m / rq.pixel_m;
        const long dc = std::lround(east * d_px), dr = std::lround(-north * d_px);
        for (long r = 0; r < rows; ++r)
            for (long c = 0; c < columns; ++c) {
                if (cloud[r * columns + c] != kMaskCloud) continue;
                const long rr = r + dr, cc = c + dc;
                if (rr < 0 || cc < 0 || rr >= rows || cc >= columns) continue;
                const std::size_t i = static_cast<std::size_t>(rr) * columns + cc;
                if (mask[i] == kMaskClear && dark[i]) mask[i] = kMaskShadow;
            }
    }
    grow(mask, rows, columns, kMaskCloud, rq.buffer_px);
    grow(mask, rows, columns, kMaskShadow, rq.buffer_px);
    return mask;
}

}  // namespace sigchain::landcover
