// Control-point comparison: band mapping, point sampling, ranks, RMS, ROC, statistics.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "compare/compare.hpp"
#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::compare {

namespace {

std::string size_text(const image::Image& img) {
    return std::to_string(img.rows) + " rows, " + std::to_string(img.columns) + " columns";
}

std::vector<double> band_values(const image::Image& img, int channel) {
    const float* p = img.data.data() + static_cast<std::size_t>(channel) * img.plane_size();
    return std::vector<double>(p, p + img.plane_size());
}

// Per-pixel mean of the given bands: the "combined" band.
std::vector<double> combined_values(const image::Image& img, const std::vector<int>& channels) {
    std::vector<double> sum(img.plane_size(), 0.0);
    for (int c : channels) {
        auto v = band_values(img, c);
        for (std::size_t i = 0; i < v.size(); ++i) sum[i] += v[i];
    }
    for (double& s : sum) s /= static_cast<double>(channels.size());
    return sum;
}

void fill_whole_image(Side& side, const std::vector<double>& pixels) {
    side.mean = stats::mean(pixels);
    side.std = stats::population_std(pixels);
    side.median = stats::median(pixels);
}

// All control-point values equal: the ranks have no spread and rho is undefined. A
// condition of all the points together, so the error names the .cpt without a line.
void require_spread(const std::vector<double>& values, const std::string& band,
                    const std::string& image, const std::string& cpt_path) {
    for (double v : values)
        if (v != values.front()) return;
    throw DataError({cpt_path, 0}, band + ": every control point of " + image + " has the value " +
                                       format_number(values.front()) +
                                       ": the rank-order correlation is undefined");
}

// Ranks, RMS, bias and ROC of one band whose point values are filled in, then the
// whole-image statistics and histograms. A statistic left undefined (StatsError)
// becomes a DataError naming the band and the .cpt: it concerns all the points
// together, so no line.
void finish_band(BandComparison& band, const std::vector<double>& syn_pixels,
                 const std::vector<double>& ref_pixels, int bins, const PointComparison& cmp) {
    const std::string& cpt_path = cmp.cpt_path;
    std::string label = band.name == "combined" ? band.name : "band " + band.name;
    require_spread(band.synthetic.values, label, cmp.synthetic_path, cpt_path);
    require_spread(band.reference.values, label, cmp.reference_path, cpt_path);
    try {
        band.synthetic.ranks = stats::average_ranks(band.synthetic.values);
        band.reference.ranks = stats::average_ranks(band.reference.values);
        band.rms = stats::rms_difference(band.synthetic.values, band.reference.values);
        band.bias = stats::bias(band.synthetic.values, band.reference.values);
        band.roc = stats::rank_order_correlation(band.synthetic.values, band.reference.values);
    } catch (const stats::StatsError& e) {
        throw DataError({cpt_path, 0}, label + ": " + e.what());
    }
    fill_whole_image(band.synthetic, syn_pixels);
    fill_whole_image(band.reference, ref_pixels);
    std::vector<std::span<const double>> both{syn_pixels, ref_pixels};
    auto range = stats::common_range(both);
    band.synthetic.histogram = stats::histogram(syn_pixels, range, bins);
    band.reference.histogram = stats::histogram(ref_pixels, range, bins);
}

}  // namespace

BandMap parse_band_map(const std::string& text) {
    BandMap map;
    for (auto field : split_fields(text, true)) {
        long band = 0;
        try {
            band = parse_long(field, {"--bands", 0}, "a band number");
        } catch (const DataError&) {
            band = 0;
        }
        if (band < 1 || band > 100000)
            throw UsageError("--bands: expected band numbers from 1, found " + quoted(field));
        map.push_back(static_cast<int>(band));
    }
    if (map.empty()) throw UsageError("--bands: expected a list such as 3,2,1");
    return map;
}

std::vector<std::pair<int, int>> band_pairs(const BandMap& map, int synthetic_channels,
                                            int reference_channels) {
    std::vector<std::pair<int, int>> pairs;
    if (map.empty()) {
        if (synthetic_channels != reference_channels)
            throw UsageError("the synthetic image has " + std::to_string(synthetic_channels) +
                             " bands and the reference " + std::to_string(reference_channels) +
                             ": give --bands");
        for (int c = 0; c < synthetic_channels; ++c) pairs.emplace_back(c, c);
        return pairs;
    }
    if (static_cast<int>(map.size()) > synthetic_channels)
        throw UsageError("--bands lists " + std::to_string(map.size()) +
                         " bands but the synthetic image has " +
                         std::to_string(synthetic_channels));
    for (std::size_t i = 0; i < map.size(); ++i) {
        if (map[i] > reference_channels)
            throw UsageError("--bands: reference band " + std::to_string(map[i]) +
                             " does not exist (the reference image has " +
                             std::to_string(reference_channels) + ")");
        pairs.emplace_back(static_cast<int>(i), map[i] - 1);
    }
    return pairs;
}

// Errors name the image without a line: it is a raster, not a text file of records.
void require_no_nan_pixels(const NamedImage& img) {
    const auto& im = *img.image;
    if (im.data.empty()) throw DataError({img.path, 0}, "empty image (no pixels)");
    for (std::size_t i = 0; i < im.data.size(); ++i)
        if (std::isnan(im.data[i])) {
            std::size_t plane = im.plane_size();
            long r = static_cast<long>((i % plane) / im.columns);
            long c = static_cast<long>(i % plane % im.columns);
            throw DataError({img.path, 0}, "NaN pixel at band " + std::to_string(i / plane + 1) +
                                               ", row " + std::to_string(r) + ", column " +
                                               std::to_string(c));
        }
}

double control_point_value(const image::Image& img, int channel, double row, double column,
                           double radius_px, const SourceLocation& where, const std::string& what) {
    // Nearest pixel centre; halves round up (std::floor(x + 0.5)).
    long r0 = static_cast<long>(std::floor(row + 0.5));
    long c0 = static_cast<long>(std::floor(column + 0.5));
    if (r0 < 0 || c0 < 0 || r0 >= img.rows || c0 >= img.columns)
        throw DataError(where, what + " at row " + format_number(row) + ", column " +
                                   format_number(column) + " lies outside the image (" +
                                   size_text(img) + ")");
    double sum = 0;
    long count = 0;
    long r_lo = std::max(0L, static_cast<long>(std::ceil(row - radius_px)));
    long r_hi = std::min(img.rows - 1, static_cast<long>(std::floor(row + radius_px)));
    long c_lo = std::max(0L, static_cast<long>(std::ceil(column - radius_px)));
    long c_hi = std::min(img.columns - 1, static_cast<long>(std::floor(column + radius_px)));
    for (long r = r_lo; r <= r_hi; ++r)
        for (long c = c_lo; c <= c_hi; ++c) {
            double dr = static_cast<double>(r) - row, dc = static_cast<double>(c) - column;
            if (dr * dr + dc * dc > radius_px * radius_px) continue;
            sum += img.at(channel, r, c);
            ++count;
        }
    if (count == 0) return img.at(channel, r0, c0);
    return sum / static_cast<double>(count);
}

PointComparison compare_points(const NamedImage& synthetic, const NamedImage& reference,
                               const io::Cpt& cpt, const std::string& cpt_path, const BandMap& map,
                               int histogram_bins) {
    const auto& syn = *synthetic.image;
    const auto& ref = *reference.image;
    auto pairs = band_pairs(map, syn.channels, ref.channels);
    if (cpt.points.size() < 2)  // a condition of the whole .cpt: no line
        throw DataError({cpt_path, 0}, "only " + std::to_string(cpt.points.size()) +
                                           " control point: the rank-order correlation "
                                           "needs at least 2");
    require_no_nan_pixels(synthetic);
    require_no_nan_pixels(reference);
    PointComparison out{synthetic.path, reference.path, cpt_path, syn.rows, syn.columns,
                        ref.rows,       ref.columns,    {},       {}};
    for (const auto& p : cpt.points) out.point_names.push_back(p.name);

    std::vector<int> syn_channels, ref_channels;
    for (auto [s, r] : pairs) {
        BandComparison band;
        band.name = std::to_string(s + 1);
        band.synthetic_band = s + 1;
        band.reference_band = r + 1;
        for (const auto& p : cpt.points) {
            SourceLocation at{cpt_path, p.line};
            band.synthetic.values.push_back(
                control_point_value(syn, s, p.synthetic_row, p.synthetic_column, p.radius_px, at,
                                    "control point '" + p.name + "' of " + synthetic.path));
            band.reference.values.push_back(
                control_point_value(ref, r, p.reference_row, p.reference_column, p.radius_px, at,
                                    "control point '" + p.name + "' of " + reference.path));
        }
        finish_band(band, band_values(syn, s), band_values(ref, r), histogram_bins, out);
        out.bands.push_back(std::move(band));
        syn_channels.push_back(s);
        ref_channels.push_back(r);
    }
    if (pairs.size() > 1) {
        BandComparison combined;
        combined.name = "combined";
        std::size_t n = cpt.points.size();
        combined.synthetic.values.assign(n, 0.0);
        combined.reference.values.assign(n, 0.0);
        for (std::size_t b = 0; b < pairs.size(); ++b)
            for (std::size_t i = 0; i < n; ++i) {
                combined.synthetic.values[i] += out.bands[b].synthetic.values[i];
                combined.reference.values[i] += out.bands[b].reference.values[i];
            }
        // Sum first, divide once, as combined_values does: equal inputs stay equal.
        for (std::size_t i = 0; i < n; ++i) {
            combined.synthetic.values[i] /= static_cast<double>(pairs.size());
            combined.reference.values[i] /= static_cast<double>(pairs.size());
        }
        finish_band(combined, combined_values(syn, syn_channels),
                    combined_values(ref, ref_channels), histogram_bins, out);
        out.bands.push_back(std::move(combined));
    }
    return out;
}

}  // namespace sigchain::compare
