// alarm_if_black (black_cube.hpp).
#include "trace/black_cube.hpp"

#include <algorithm>
#include <cmath>

#include "core/text.hpp"

namespace sigchain::trace {

void alarm_if_black(const image::Image& radiance, const std::string& path,
                    const Reporter& reporter) {
    if (radiance.data.empty()) return;
    float largest = 0;
    for (float v : radiance.data) largest = std::max(largest, std::abs(v));
    if (largest > kBlackRadiance) return;
    reporter.alarm(path + ": the image is black: its largest radiance is " +
                   format_number(largest) +
                   " W cm-2 sr-1 um-1, nothing a sensor records (a visibility near 0 km in the "
                   ".rad tables, the sun below the horizon, every material black?)");
}

}  // namespace sigchain::trace
