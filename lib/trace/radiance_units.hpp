// The radiance unit of trace's outputs (cube(5)): by default W cm-2 sr-1 um-1, the unit
// of the big equation in White (1996), section 3.2, and of LOWTRAN 7; W m-2 sr-1 um-1,
// the unit remote-sensing products use, with --radiance-units W/m2/sr/um.
#pragma once

#include "image/image.hpp"

namespace sigchain::trace {

inline constexpr const char* kRadianceUnits = "W cm-2 sr-1 um-1";
inline constexpr const char* kSiRadianceUnits = "W m-2 sr-1 um-1";

// The cube's radiance and the truth cube's radiance layers (solar_, downwelled_,
// upwelled_, standard_error_ but its -1 "fewer than two samples", uncertainty_) times
// 1e4 (1 W cm-2 = 1e4 W m-2), the cube's units set to kSiRadianceUnits; reflectance,
// transmission and the geometric layers as they are. `truth` may be empty.
void to_si_units(image::Image& cube, image::Image& truth);
// The same for the values of rows [first_row, first_row + rows) of both images alone
// (a render's rows as they are written; the units are the header's).
void rows_to_si_units(image::Image& cube, image::Image& truth, long first_row, long rows);

}  // namespace sigchain::trace
