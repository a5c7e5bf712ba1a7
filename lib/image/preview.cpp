// Previews of multi-band images (sensorize(1), --preview): true colour, or one band in
// grey.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "image/image.hpp"

namespace sigchain::image {
namespace {

// Visible light, um: the bands a true-colour preview may use.
constexpr double kVisibleMinUm = 0.38, kVisibleMaxUm = 0.78;

// The value at `fraction` of the sorted finite values (nearest rank); 0 if none.
double percentile(std::vector<float> values, double fraction) {
    values.erase(
        std::remove_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }),
        values.end());
    if (values.empty()) return 0;
    const auto k = static_cast<std::size_t>(std::lround(fraction * (values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[k];
}

// The stretch of one band: its 2nd and 98th percentiles, or its smallest and largest
// finite values where those coincide (a small object on a uniform background, which
// the percentiles miss); equal ends mean a uniform band.
std::pair<double, double> stretch(const std::vector<float>& values) {
    double lo = percentile(values, 0.02), hi = percentile(values, 0.98);
    if (hi > lo) return {lo, hi};
    lo = INFINITY;
    hi = -INFINITY;
    for (float v : values)
        if (std::isfinite(v)) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v);
    return {lo, hi};
}

}  // namespace

std::vector<int> true_colour_bands(const Image& image, const std::string& path) {
    std::vector<int> visible;
    for (int c = 0; c < static_cast<int>(image.wavelength_um.size()); ++c)
        if (image.wavelength_um[c] >= kVisibleMinUm && image.wavelength_um[c] <= kVisibleMaxUm)
            visible.push_back(c);
    if (visible.size() < 3)
        throw DataError({path, 0},
                        "a true-colour preview needs 3 bands with centres in 0.38-0.78 "
                        "um; the image has " +
                            std::to_string(visible.size()));
    const auto by_wavelength = [&](int a, int b) {
        return image.wavelength_um[a] < image.wavelength_um[b];
    };
    std::sort(visible.begin(), visible.end(), by_wavelength);
    const int blue = visible.front(), red = visible.back();
    // Green: of the bands between, the one nearest 0.55 um (the eye's peak sensitivity).
    int green = visible[1];
    for (std::size_t i = 1; i + 1 < visible.size(); ++i)
        if (std::abs(image.wavelength_um[visible[i]] - 0.55) <
            std::abs(image.wavelength_um[green] - 0.55))
            green = visible[i];
    return {red, green, blue};
}

std::vector<int> preview_bands(const Image& image) {
    int visible = 0;
    for (double w : image.wavelength_um) visible += w >= kVisibleMinUm && w <= kVisibleMaxUm;
    if (visible >= 3) return true_colour_bands(image, "");
    if (image.wavelength_um.empty()) return {0};
    const auto shortest = std::min_element(image.wavelength_um.begin(), image.wavelength_um.end());
    return {static_cast<int>(shortest - image.wavelength_um.begin())};
}

Image true_colour_preview(const Image& image, const std::string& path, bool common) {
    if (image.channels < 1) throw DataError({path, 0}, "a preview needs at least one band");
    const std::vector<int> bands = preview_bands(image);
    const int n = static_cast<int>(bands.size());
    Image rgb(image.rows, image.columns, n);
    rgb.channel_names = n == 3 ? std::vector<std::string>{"R", "G", "B"}
                               : std::vector<std::string>{"grey"};
    const std::size_t plane = image.plane_size();
    std::pair<double, double> pooled{0, 0};
    if (common) {
        std::vector<float> all;
        all.reserve(3 * plane);
        for (int b : bands)
            all.insert(all.end(), image.data.begin() + b * plane, image.data.begin() + (b + 1) * plane);
        pooled = stretch(all);
    }
    for (int o = 0; o < n; ++o) {
        const auto first = image.data.begin() + bands[o] * plane;
        const std::vector<float> values(first, first + plane);
        const auto [lo, hi] = common ? pooled : stretch(values);
        for (std::size_t p = 0; p < plane; ++p) {
            // A uniform band is mid-grey, not black: it has a value, just no contrast.
            const double v = hi > lo ? (values[p] - lo) / (hi - lo) * 255 : 128;
            rgb.data[o * plane + p] =
                std::isfinite(v) ? static_cast<float>(std::lround(std::clamp(v, 0.0, 255.0))) : 0;
        }
    }
    return rgb;
}

}  // namespace sigchain::image
