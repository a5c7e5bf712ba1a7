// .sen sensor band file (White (1996), fig. 4.42; man sen(5)): the relative spectral response,
// gain and bias of one sensor band.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// digital count = gain * band radiance + bias (sensorize(1)); one relative response
// (unitless, >= 0; White's (1996) are fractions) per spectral sample of the matching .rad
// band, in that band's order.
struct Sen {
    double gain = 1;               // > 0, counts per unit band radiance
    double bias = 0;               // counts
    std::vector<double> response;  // at least 1 value

    bool operator==(const Sen&) const = default;
};

inline constexpr long kSenMaxSamples = 1000000;

Sen parse_sen(const TextInput& in);
// The legacy layout: count, gain, bias, one response per line, no comments.
void write_sen(std::ostream& out, const Sen& sen);
inline Sen read_sen_file(const std::string& path) { return parse_sen(TextInput::from_file(path)); }
FormatHandler sen_format();

}  // namespace sigchain::io
