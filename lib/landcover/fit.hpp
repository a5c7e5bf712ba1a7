// Control points on a class map and the least-squares fit of each class's reflectance
// scale to a reference image (White (1996), section 3.5/4.5 validation with a held-out half).
// Thread-safety: free functions on value types.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace sigchain::landcover {

struct ClassPoint {
    int cls = 0;       // class number
    long row = 0;      // 0-based pixel row of the class map
    long column = 0;   // 0-based pixel column
    bool fit = false;  // true: fit half; false: held-out half
};

// Up to `per_class` points of each class 1..class_count on a fixed pseudo-random pattern:
// std::mt19937(seed) draws pixel indices (raw output modulo the pixel count; the
// engine's sequence is fixed by the C++ standard) and a pixel is taken when it lies at
// least `margin` pixels inside the map, every pixel within `half_window` of it (a square)
// has its class, `other` (if not empty, same size) agrees at the pixel, and the class
// still needs points. Points of a class alternate fit, held-out, fit, ... in the order
// drawn. At most `max_draws` draws.
std::vector<ClassPoint> pick_control_points(const std::vector<int>& classes, long rows,
                                            long columns, const std::vector<int>& other,
                                            int class_count, int per_class, std::uint32_t seed,
                                            long margin, long half_window,
                                            long max_draws = 10'000'000);

// The scale s of a material's reflectance that best matches a reference in the least-
// squares sense, when each synthetic value is linear in the reflectance:
//   synthetic(s) = dark + s * (base - dark),
// dark the value rendered with reflectance 0 (path radiance only) and base the value
// with the unscaled reflectance. Minimises sum (dark + s (base - dark) - reference)^2:
//   s = sum (base - dark)(reference - dark) / sum (base - dark)^2.
// `what` names the values at `where` (the control points' file) in a DataError "WHERE:
// WHAT: no control points" for no values, or "...: the base image equals the dark image
// at every control point" (s undetermined). Unequal sizes are the caller's bug
// (std::invalid_argument).
double fit_reflectance_scale(const std::vector<double>& dark, const std::vector<double>& base,
                             const std::vector<double>& reference, const SourceLocation& where,
                             const std::string& what);

}  // namespace sigchain::landcover
