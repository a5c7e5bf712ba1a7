// trace --radiance-units W/m2/sr/um (radiance_units.hpp).
#include "trace/radiance_units.hpp"

#include <string>

namespace sigchain::trace {

void to_si_units(image::Image& cube, image::Image& truth) {
    constexpr float kCm2PerM2 = 1e4f;  // W cm-2 -> W m-2
    for (float& v : cube.data) v *= kCm2PerM2;
    cube.units = kSiRadianceUnits;
    const int named = static_cast<int>(truth.channel_names.size());
    for (int c = 0; c < truth.channels && c < named; ++c) {
        const std::string& n = truth.channel_names[c];
        const bool sentinel = n.rfind("standard_error_", 0) == 0;  // -1: fewer than 2 samples
        bool radiance = sentinel;
        for (const char* q : {"solar_", "downwelled_", "upwelled_", "uncertainty_"})
            radiance = radiance || n.rfind(q, 0) == 0;
        if (!radiance) continue;
        float* plane = truth.data.data() + c * truth.plane_size();
        for (std::size_t p = 0; p < truth.plane_size(); ++p)
            if (!(sentinel && plane[p] == -1.0f)) plane[p] *= kCm2PerM2;
    }
}

}  // namespace sigchain::trace
