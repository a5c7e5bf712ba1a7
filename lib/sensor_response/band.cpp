// Band-effective radiance and digital counts (White (1996), section 3.2; sen(5)).
#include "sensor_response/band.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace sigchain::sensor_response {

std::vector<BandSamples> group_bands(const std::vector<io::Sen>& sens,
                                     const std::vector<std::string>& sen_paths, int cube_bands,
                                     const std::string& cube_path) {
    std::vector<BandSamples> groups;
    int first = 0;
    for (std::size_t i = 0; i < sens.size(); ++i) {
        const int count = static_cast<int>(sens[i].response.size());
        if (first + count > cube_bands)
            throw DataError({sen_paths[i], 1}, std::to_string(count) + " response samples, but " +
                                                   cube_path + " has " +
                                                   std::to_string(cube_bands - first) +
                                                   " bands left for this band (" +
                                                   std::to_string(cube_bands) + " in all)");
        groups.push_back({first, count});
        first += count;
    }
    if (first != cube_bands)  // the cube is a binary raster: no line
        throw DataError({cube_path, 0}, std::to_string(cube_bands) +
                                            " bands, but the .sen files (" + sen_paths.front() +
                                            (sens.size() > 1 ? " ..." : "") + ") have " +
                                            std::to_string(first) + " response samples in all");
    return groups;
}

std::vector<double> sample_widths_um(const std::vector<double>& wavelength_um, int count) {
    const std::size_t n = wavelength_um.size();
    if (n < 2) return std::vector<double>(count, 1.0);
    std::vector<double> widths(n);
    // Midpoint rule: sample i stands for the bin from halfway to its previous sample to
    // halfway to its next, (λ[i+1] - λ[i-1]) / 2; an end bin is one neighbouring interval.
    for (std::size_t i = 0; i < n; ++i) {
        if (i == 0)
            widths[i] = std::abs(wavelength_um[1] - wavelength_um[0]);
        else if (i + 1 == n)
            widths[i] = std::abs(wavelength_um[n - 1] - wavelength_um[n - 2]);
        else
            widths[i] = std::abs(wavelength_um[i + 1] - wavelength_um[i - 1]) / 2;
    }
    return widths;
}

double centre_wavelength_um(const std::vector<double>& wavelength_um,
                            const std::vector<double>& response,
                            const std::vector<double>& widths_um) {
    const std::size_t n = wavelength_um.size();
    double weighted = 0, weight = 0;
    for (std::size_t i = 0; i < n && i < response.size() && i < widths_um.size(); ++i) {
        weighted += response[i] * wavelength_um[i] * widths_um[i];
        weight += response[i] * widths_um[i];
    }
    if (!(weight > 0)) return std::numeric_limits<double>::quiet_NaN();
    return weighted / weight;
}

double fwhm_um(const std::vector<double>& wl, const std::vector<double>& r) {
    const std::size_t n = wl.size();
    if (n < 2 || r.size() != n) return std::numeric_limits<double>::quiet_NaN();
    const double peak = *std::max_element(r.begin(), r.end());
    if (!(peak > 0)) return std::numeric_limits<double>::quiet_NaN();
    const double half = peak / 2;
    std::size_t first = 0, last = n - 1;
    while (r[first] < half) ++first;
    while (r[last] < half) --last;
    // Signed arithmetic throughout: descending wavelengths give a negative span.
    double lower = wl[0] - (wl[1] - wl[0]) / 2;
    if (first > 0) {
        const double t = (half - r[first - 1]) / (r[first] - r[first - 1]);
        lower = wl[first - 1] + t * (wl[first] - wl[first - 1]);
    }
    double upper = wl[n - 1] + (wl[n - 1] - wl[n - 2]) / 2;
    if (last + 1 < n) {
        const double t = (r[last] - half) / (r[last] - r[last + 1]);
        upper = wl[last] + t * (wl[last + 1] - wl[last]);
    }
    return std::abs(upper - lower);
}

std::vector<float> band_radiance(const image::Image& cube, BandSamples samples,
                                 const std::vector<double>& response,
                                 const std::vector<double>& widths_um,
                                 const std::string& sen_path) {
    const std::size_t plane = cube.plane_size();
    std::vector<double> sum(plane, 0.0);
    double weight_sum = 0;
    for (int k = 0; k < samples.count; ++k) {
        // White (1996), section 3.2: L̄ = Σ R·L·Δλ / Σ R·Δλ (the normalised response
        // R̄ = R / Σ R·Δλ).
        const double w = response[k] * widths_um[k];
        weight_sum += w;
        const float* band = cube.data.data() + (samples.first + k) * plane;
        for (std::size_t p = 0; p < plane; ++p) sum[p] += w * band[p];
    }
    if (!(weight_sum > 0))  // a sum over all the .sen's responses: no single line
        throw DataError({sen_path, 0}, "the response integrates to zero over the band's samples");
    std::vector<float> out(plane);
    for (std::size_t p = 0; p < plane; ++p) out[p] = static_cast<float>(sum[p] / weight_sum);
    return out;
}

double max_count(int bits) { return std::ldexp(1.0, bits) - 1; }

ClipCount quantise(std::vector<float>& counts, int bits) {
    const float top = static_cast<float>(max_count(bits));
    ClipCount clipped;
    for (float& v : counts) {
        v = std::round(v);
        if (v < 0 || std::isnan(v)) {  // a NaN radiance has no count: the floor
            v = 0;
            ++clipped.low;
        } else if (v > top) {
            v = top;
            ++clipped.high;
        }
    }
    return clipped;
}

void apply_gain_bias(std::vector<float>& values, double gain, double bias) {
    for (float& v : values) v = static_cast<float>(gain * v + bias);
}

}  // namespace sigchain::sensor_response
