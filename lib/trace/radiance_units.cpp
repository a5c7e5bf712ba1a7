// trace --radiance-units W/m2/sr/um (radiance_units.hpp).
#include "trace/radiance_units.hpp"

#include <string>

namespace sigchain::trace {

namespace {

// Rows [first_row, first_row + rows) of channel c of `image`, times 1e4 (1 W cm-2 =
// 1e4 W m-2); with `sentinel`, -1 ("fewer than two samples") stays.
void scale_rows(image::Image& image, int c, long first_row, long rows, bool sentinel) {
    constexpr float kCm2PerM2 = 1e4f;
    float* v = &image.at(c, first_row, 0);
    const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(image.columns);
    for (std::size_t p = 0; p < n; ++p)
        if (!(sentinel && v[p] == -1.0f)) v[p] *= kCm2PerM2;
}

}  // namespace

void rows_to_si_units(image::Image& cube, image::Image& truth, long first_row, long rows) {
    if (rows <= 0) return;
    for (int c = 0; c < cube.channels; ++c) scale_rows(cube, c, first_row, rows, false);
    const int named = static_cast<int>(truth.channel_names.size());
    for (int c = 0; c < truth.channels && c < named; ++c) {
        const std::string& n = truth.channel_names[c];
        const bool sentinel = n.rfind("standard_error_", 0) == 0;  // -1: fewer than 2 samples
        bool radiance = sentinel;
        for (const char* q : {"solar_", "downwelled_", "upwelled_", "uncertainty_"})
            radiance = radiance || n.rfind(q, 0) == 0;
        if (radiance) scale_rows(truth, c, first_row, rows, sentinel);
    }
}

void to_si_units(image::Image& cube, image::Image& truth) {
    rows_to_si_units(cube, truth, 0, cube.rows);
    cube.units = kSiRadianceUnits;
}

}  // namespace sigchain::trace
