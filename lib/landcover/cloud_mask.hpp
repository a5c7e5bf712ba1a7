// Cloud and cloud-shadow masks of one image: clouds by a pixel test, shadows where the
// clouds' outlines, cast away from the sun from a range of cloud heights, fall on dark
// pixels. The mask only removes pixels from a comparison or a fit; it changes no value.
// Thread-safety: free functions on value types.
#pragma once

#include <string>
#include <vector>

#include "landcover/rules.hpp"

namespace sigchain::landcover {

inline constexpr int kMaskClear = 0;
inline constexpr int kMaskCloud = 1;
inline constexpr int kMaskShadow = 2;

struct CloudMaskRequest {
    std::vector<Term> cloud;        // a pixel is cloud when every term holds
    std::vector<Term> dark;         // a shadow candidate is shadow when every term holds
    double sun_elevation_deg = 45;  // of the image's acquisition
    double sun_azimuth_deg = 180;   // clockwise from north
    double min_height_m = 500;      // cloud heights above the ground tried
    double max_height_m = 3000;
    double pixel_m = 30;            // ground size of a pixel (north-up grid)
    int buffer_px = 2;              // both masks grown by this many pixels (a square)
};

// The mask (rows x columns, row-major): kMaskCloud, kMaskShadow or kMaskClear.
// Shadow candidates are the cloud pixels moved by h / tan(elevation) away from the sun
// (azimuth + 180 deg; grid north taken as true north) for every h from min to max in
// steps of one pixel's length of displacement.
std::vector<int> cloud_mask(const std::vector<const geo::GeoRaster*>& images,
                            const CloudMaskRequest& request);

// Grows the pixels equal to `value` by `radius` pixels (a square window) over pixels
// that are kMaskClear.
void grow(std::vector<int>& mask, long rows, long columns, int value, int radius);

}  // namespace sigchain::landcover
