// Two-gray-card calibration (White (1996), section 4.2.4): the gain and bias that map two rendered cards'
// band radiances to their target digital counts.
#pragma once

#include <string>
#include <vector>

namespace sigchain::sensor_response {

// A pixel box, 0-based, inclusive: rows row0..row1, columns column0..column1.
struct PixelBox {
    long row0 = 0, column0 = 0, row1 = 0, column1 = 0;
};

// Parses "ROW0,COL0,ROW1,COL1" (throws UsageError naming `option`).
PixelBox parse_box(const std::string& text, const std::string& option);

// The mean of a plane (rows x columns) over a box; throws UsageError naming `option`
// when the box is empty or reaches outside the image.
double box_mean(const std::vector<float>& plane, long rows, long columns, const PixelBox& box,
                const std::string& option);

struct GainBias {
    double gain = 1;  // counts per radiance unit
    double bias = 0;  // counts
};

// Solves count = gain * L + bias through the two points (L1, count1), (L2, count2):
// gain = (count1 - count2) / (L1 - L2), bias = count1 - gain * L1. Throws DataError at
// `where_file` when L1 = L2 or the gain is not positive (sen(5) requires gain > 0).
GainBias solve_gain_bias(double radiance1, double count1, double radiance2, double count2,
                         const std::string& where_file);

}  // namespace sigchain::sensor_response
