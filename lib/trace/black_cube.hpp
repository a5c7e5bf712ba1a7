// The warning a black radiance cube deserves, whatever -q says.
#pragma once

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

}  // namespace sigchain::trace
