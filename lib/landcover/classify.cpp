// Rule-based land-cover classification of ETM+ digital numbers, and majority resampling.
#include "landcover/classify.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace sigchain::landcover {

const char* class_name(LandCover c) {
    switch (c) {
        case LandCover::Water:
            return "water";
        case LandCover::Vegetation:
            return "vegetation";
        case LandCover::Urban:
            return "urban";
        case LandCover::Sand:
            return "sand";
    }
    return "?";
}

LandCover classify_pixel(const EtmPixel& p, const Rule& rule) {
    if (p.nir < rule.water_nir_max && p.swir1 < rule.water_swir_max) return LandCover::Water;
    const double sum = p.nir + p.red;
    // NDVI (Rouse et al. 1974) on digital numbers.
    const double ndvi = sum > 0 ? (p.nir - p.red) / sum : 0.0;
    if (ndvi >= rule.vegetation_ndvi_min) return LandCover::Vegetation;
    if (p.red >= rule.sand_red_min) return LandCover::Sand;
    return LandCover::Urban;
}

std::vector<int> classify_raster(const geo::GeoRaster& etm, const Rule& rule,
                                 const std::string& path) {
    // A raster has no lines: the error names the file alone.
    if (etm.bands < 5)
        throw DataError({path, 0},
                        "classification needs ETM+ bands 1-5, found " + std::to_string(etm.bands));
    std::vector<int> out(static_cast<std::size_t>(etm.rows) * etm.columns);
    for (long r = 0; r < etm.rows; ++r)
        for (long c = 0; c < etm.columns; ++c) {
            const EtmPixel p{etm.at(0, r, c), etm.at(1, r, c), etm.at(2, r, c), etm.at(3, r, c),
                             etm.at(4, r, c)};
            out[r * etm.columns + c] = static_cast<int>(classify_pixel(p, rule));
        }
    return out;
}

std::array<double, kClassCount> class_fractions(const std::vector<int>& classes) {
    std::array<double, kClassCount> f{};
    for (int k : classes)
        if (k >= 1 && k <= kClassCount) f[k - 1] += 1;
    for (double& v : f) v = classes.empty() ? 0.0 : v / classes.size();
    return f;
}

namespace {

// Source pixel index range [lo, hi) whose centres lie in [a, b) along one axis, where
// centre i is at origin + step * (i + 0.5); a and b in CRS units, step may be negative.
std::pair<long, long> centres_in(double a, double b, double origin, double step, long n) {
    double ia = (a - origin) / step - 0.5;
    double ib = (b - origin) / step - 0.5;
    if (ia > ib) std::swap(ia, ib);
    const long lo = std::max(0L, static_cast<long>(std::ceil(ia)));
    const long hi = std::min(n, static_cast<long>(std::ceil(ib)));
    return {lo, hi};
}

long nearest_index(double x, double origin, double step, long n) {
    const long i = static_cast<long>(std::floor((x - origin) / step));
    return std::clamp(i, 0L, n - 1);
}

}  // namespace

std::vector<int> majority_on_dem_blocks(const std::vector<int>& src_classes, long src_rows,
                                        long src_columns, const std::array<double, 6>& src_gt,
                                        long dst_rows, long dst_columns,
                                        const std::array<double, 6>& dst_gt) {
    std::vector<int> out(static_cast<std::size_t>(dst_rows) * dst_columns);
    for (long r = 0; r < dst_rows; ++r)
        for (long c = 0; c < dst_columns; ++c) {
            // DEM cell centres (r, c) and (r+1, c+1) bound the block.
            const double x0 = dst_gt[0] + dst_gt[1] * (c + 0.5);
            const double x1 = x0 + dst_gt[1];
            const double y0 = dst_gt[3] + dst_gt[5] * (r + 0.5);
            const double y1 = y0 + dst_gt[5];
            const auto [c_lo, c_hi] = centres_in(x0, x1, src_gt[0], src_gt[1], src_columns);
            const auto [r_lo, r_hi] = centres_in(y0, y1, src_gt[3], src_gt[5], src_rows);
            std::array<long, kClassCount + 1> count{};
            for (long sr = r_lo; sr < r_hi; ++sr)
                for (long sc = c_lo; sc < c_hi; ++sc) {
                    const int k = src_classes[sr * src_columns + sc];
                    if (k >= 1 && k <= kClassCount) ++count[k];
                }
            int best = 0;
            for (int k = 1; k <= kClassCount; ++k)
                if (count[k] > count[best]) best = k;
            if (best == 0) {
                const long sr = nearest_index(0.5 * (y0 + y1), src_gt[3], src_gt[5], src_rows);
                const long sc = nearest_index(0.5 * (x0 + x1), src_gt[0], src_gt[1], src_columns);
                best = src_classes[sr * src_columns + sc];
            }
            out[r * dst_columns + c] = best;
        }
    return out;
}

}  // namespace sigchain::landcover
