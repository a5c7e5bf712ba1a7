// A side-by-side preview of a synthetic image and its reference (the demo shows the
// Olinda render beside the real Landsat image).
#pragma once

#include <array>

#include "image/image.hpp"

namespace sigchain::landcover {

// An 8-bit RGB image: `synthetic` on the left, `reference` on the right, `gap` white
// columns between them. `bands` are the 1-based channels shown as red, green and blue
// (the same in both images). Values are clamped to [0, 255] and rounded. Throws
// sigchain::Error when the images differ in size or a band is missing.
image::Image side_by_side(const image::Image& synthetic, const image::Image& reference,
                          const std::array<int, 3>& bands, long gap = 8);

}  // namespace sigchain::landcover
