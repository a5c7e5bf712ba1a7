#include "landcover/preview.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace sigchain::landcover {

image::Image side_by_side(const image::Image& synthetic, const image::Image& reference,
                          const std::array<int, 3>& bands, long gap) {
    if (synthetic.rows != reference.rows || synthetic.columns != reference.columns)
        throw Error("side-by-side preview: the images differ in size (" +
                    std::to_string(synthetic.rows) + " x " + std::to_string(synthetic.columns) +
                    " and " + std::to_string(reference.rows) + " x " +
                    std::to_string(reference.columns) + ")");
    for (int b : bands)
        if (b < 1 || b > synthetic.channels || b > reference.channels)
            throw Error("side-by-side preview: no band " + std::to_string(b) + " in both images");
    const long cols = synthetic.columns;
    image::Image out(synthetic.rows, 2 * cols + gap, 3, 255.0f);
    for (int c = 0; c < 3; ++c)
        for (long r = 0; r < synthetic.rows; ++r)
            for (long x = 0; x < cols; ++x) {
                auto count = [](float v) { return std::round(std::clamp(v, 0.0f, 255.0f)); };
                out.at(c, r, x) = count(synthetic.at(bands[c] - 1, r, x));
                out.at(c, r, cols + gap + x) = count(reference.at(bands[c] - 1, r, x));
            }
    return out;
}

}  // namespace sigchain::landcover
