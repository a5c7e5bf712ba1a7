// The warning a black radiance cube deserves, whatever -q says.
#pragma once

#include <cstddef>
#include <string>

#include "core/report.hpp"
#include "image/image.hpp"

namespace sigchain::trace {

// The radiance at or below which a whole cube is called black, W cm-2 sr-1 um-1: five
// orders below the noise-equivalent radiance of any sensor sigchain models (about
// 1e-7), so nothing a camera could record.
inline constexpr float kBlackRadiance = 1e-12f;

// Reporter::alarm (shown even with -q: a script must not take a black cube for a
// render) when no value of `radiance` exceeds kBlackRadiance in magnitude; `path` names
// the cube in the message.
void alarm_if_black(const image::Image& radiance, const std::string& path,
                    const Reporter& reporter);
// The same from the largest magnitude of a cube's values, found as its rows went by
// (largest_magnitude), for a cube of `values` values (none: no alarm).
void alarm_if_black(float largest, std::size_t values, const std::string& path,
                    const Reporter& reporter);
// The largest magnitude among rows [first_row, first_row + rows) of every channel of
// `image`, or `so_far` when larger.
float largest_magnitude(const image::Image& image, long first_row, long rows, float so_far = 0);

}  // namespace sigchain::trace
