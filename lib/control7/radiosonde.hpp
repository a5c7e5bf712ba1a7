// Radiosonde soundings (.rsd) as control7 puts them in the card deck: missing dew
// points filled (White (1996), section 4.2.3.4) and the levels as CARD 2C1 layers.
#pragma once

#include <string>

#include "core/error.hpp"
#include "io/cdk.hpp"
#include "io/rsd.hpp"

namespace sigchain::control7 {

// White (1996), section 4.2.3.4: a missing (-999) dew point above the last valid one gets the
// last valid dew-point depression (T - Td) applied to its level's temperature; below the
// first valid one, the first valid depression; between valid ones, the depression
// interpolated linearly in altitude. Throws DataError (naming `where`) if a level has no
// temperature or no level has a dew point.
io::Rsd fill_missing_dew_points(const io::Rsd& rsd, const SourceLocation& where);

// The lowest `levels` levels as LOWTRAN 7 CARD 2C1 layers: altitude (km), pressure (mb,
// JCHAR A), temperature (C, B), H2O as dew point (C, G); CO2 and O3 0 (model default).
// `rsd` must have its dew points filled.
io::CdkProfile radiosonde_profile(const io::Rsd& rsd, int levels, const std::string& title);

}  // namespace sigchain::control7
