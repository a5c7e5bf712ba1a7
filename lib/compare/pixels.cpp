// Pixel-by-pixel comparison of co-registered images (compare --pixelwise).
#include <algorithm>
#include <cmath>

#include "compare/compare.hpp"
#include "core/error.hpp"

namespace sigchain::compare {

namespace {

// Running sums of the differences d = synthetic - reference.
struct Sums {
    double d = 0, d2 = 0, max_abs = 0, relative = 0;
    long n = 0, relative_n = 0;

    void add(double syn, double ref) {
        double diff = syn - ref;
        d += diff;
        d2 += diff * diff;
        max_abs = std::max(max_abs, std::fabs(diff));
        ++n;
        if (ref != 0) {
            relative += std::fabs(diff) / std::fabs(ref);
            ++relative_n;
        }
    }
    void fill(PixelBand& band) const {
        band.rms = std::sqrt(d2 / static_cast<double>(n));
        band.bias = d / static_cast<double>(n);
        band.max_abs = max_abs;
        band.mean_relative = relative_n > 0 ? relative / static_cast<double>(relative_n) : 0.0;
        band.relative_pixels = relative_n;
    }
};

}  // namespace

PixelComparison compare_pixels(const NamedImage& synthetic, const NamedImage& reference,
                               const BandMap& map) {
    const auto& syn = *synthetic.image;
    const auto& ref = *reference.image;
    if (syn.rows != ref.rows || syn.columns != ref.columns)  // rasters have no lines
        throw DataError({reference.path, 0}, "size mismatch: " + std::to_string(ref.rows) +
                                                 " rows, " + std::to_string(ref.columns) +
                                                 " columns, but " + synthetic.path + " has " +
                                                 std::to_string(syn.rows) + " rows, " +
                                                 std::to_string(syn.columns) + " columns");
    auto pairs = band_pairs(map, syn.channels, ref.channels);
    require_no_nan_pixels(synthetic);  // also rejects empty images (no division by 0 below)
    require_no_nan_pixels(reference);
    PixelComparison out{synthetic.path, reference.path, syn.rows, syn.columns, {}, {}};
    out.error_map.rows = syn.rows;
    out.error_map.columns = syn.columns;
    out.error_map.channels = static_cast<int>(pairs.size());
    out.error_map.units = syn.units == ref.units ? syn.units : "";
    out.error_map.data.reserve(pairs.size() * syn.plane_size());
    Sums all;
    for (auto [s, r] : pairs) {
        Sums sums;
        for (long row = 0; row < syn.rows; ++row)
            for (long col = 0; col < syn.columns; ++col) {
                double a = syn.at(s, row, col), b = ref.at(r, row, col);
                sums.add(a, b);
                all.add(a, b);
                out.error_map.data.push_back(static_cast<float>(a - b));
            }
        PixelBand band{std::to_string(s + 1), s + 1, r + 1};
        sums.fill(band);
        out.bands.push_back(band);
        out.error_map.channel_names.push_back("synthetic " + std::to_string(s + 1) +
                                              " - reference " + std::to_string(r + 1));
    }
    if (pairs.size() > 1) {
        PixelBand band{"all", 0, 0};
        all.fill(band);
        out.bands.push_back(band);
    }
    return out;
}

}  // namespace sigchain::compare
