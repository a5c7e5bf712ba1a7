// The SIGCHAIN_RAD block of a .rad (rad(5)): the sun, the sky hemisphere, the upwelled
// grid and the coupling terms after the legacy tables. Internal to lib/io (rad.cpp
// calls it).
#pragma once

#include <ostream>

#include "core/text.hpp"
#include "io/rad.hpp"

namespace sigchain::io {

// Reads the block from its SIGCHAIN_RAD line (the cursor's next line) to the end of
// the input, for `rad`'s samples and views (already read). Throws DataError at the
// offending line.
RadSky read_sky_block(LineCursor& c, const Rad& rad);
// Writes the block, the coupling terms included.
void write_sky_block(std::ostream& out, const Rad& rad);

}  // namespace sigchain::io
