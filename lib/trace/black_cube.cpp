// alarm_if_black (black_cube.hpp).
#include "trace/black_cube.hpp"

#include <algorithm>
#include <cmath>

#include "core/text.hpp"

namespace sigchain::trace {

float largest_magnitude(const image::Image& image, long first_row, long rows, float so_far) {
    const std::size_t n = static_cast<std::size_t>(std::max(0L, rows)) *
                          static_cast<std::size_t>(image.columns);
    for (int c = 0; c < image.channels && n > 0; ++c) {
        const float* v = &image.data[(static_cast<std::size_t>(c) * image.rows + first_row) *
                                     image.columns];
        for (std::size_t p = 0; p < n; ++p) so_far = std::max(so_far, std::abs(v[p]));
    }
    return so_far;
}

void alarm_if_black(const image::Image& radiance, const std::string& path,
                    const Reporter& reporter) {
    alarm_if_black(largest_magnitude(radiance, 0, radiance.rows), radiance.data.size(), path,
                   reporter);
}

void alarm_if_black(float largest, std::size_t values, const std::string& path,
                    const Reporter& reporter) {
    if (values == 0) return;
    if (largest > kBlackRadiance) return;
    reporter.alarm(path + ": the image is black: its largest radiance is " +
                   format_number(largest) +
                   " W cm-2 sr-1 um-1, nothing a sensor records (a visibility near 0 km in the "
                   ".rad tables, the sun below the horizon, every material black?)");
}

}  // namespace sigchain::trace
