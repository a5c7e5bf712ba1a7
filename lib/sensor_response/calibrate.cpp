// Two-point gain and bias from two gray cards (White (1996), section 4.2.4).
#include "sensor_response/calibrate.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::sensor_response {

PixelBox parse_box(const std::string& text, const std::string& option) {
    const auto fields = split_fields(text, true);
    if (fields.size() != 4)
        throw UsageError(option + ": expected ROW0,COL0,ROW1,COL1, found '" + text + "'");
    long v[4];
    for (int i = 0; i < 4; ++i) {
        try {
            v[i] = parse_count(fields[i], {option, 0}, "a pixel index");  // an option: no line
        } catch (const DataError&) {
            throw UsageError(option +
                             ": expected ROW0,COL0,ROW1,COL1 (non-negative integers), "
                             "found '" +
                             text + "'");
        }
    }
    return {v[0], v[1], v[2], v[3]};
}

double box_mean(const std::vector<float>& plane, long rows, long columns, const PixelBox& box,
                const std::string& option) {
    if (box.row1 < box.row0 || box.column1 < box.column0)
        throw UsageError(option + ": the box is empty (ROW1 < ROW0 or COL1 < COL0)");
    if (box.row1 >= rows || box.column1 >= columns)
        throw UsageError(option + ": the box reaches outside the " + std::to_string(rows) + "x" +
                         std::to_string(columns) + " image");
    double sum = 0;
    for (long r = box.row0; r <= box.row1; ++r)
        for (long c = box.column0; c <= box.column1; ++c) sum += plane[r * columns + c];
    return sum / static_cast<double>((box.row1 - box.row0 + 1) * (box.column1 - box.column0 + 1));
}

GainBias solve_gain_bias(double radiance1, double count1, double radiance2, double count2,
                         const std::string& where_file) {
    // Two equations count_i = gain * L_i + bias (White (1996), section 4.2.4, two gray cards).
    // The errors name `where_file` only: they concern both cards, not one of its lines.
    if (radiance1 == radiance2)
        throw DataError({where_file, 0},
                        "the two cards have the same band radiance: gain is undefined");
    GainBias gb;
    gb.gain = (count1 - count2) / (radiance1 - radiance2);
    gb.bias = count1 - gb.gain * radiance1;
    if (!(gb.gain > 0) || !std::isfinite(gb.gain))
        throw DataError({where_file, 0}, "the solved gain " + format_number(gb.gain) +
                                             " is not positive (is the brighter card given the "
                                             "higher target?)");
    return gb;
}

}  // namespace sigchain::sensor_response
