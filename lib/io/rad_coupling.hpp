// The COUPLING section of a .rad's SIGCHAIN_RAD block (version 1.2; rad(5)): reader
// and writer, internal to lib/io (rad.cpp calls them).
#pragma once

#include <ostream>

#include "core/text.hpp"
#include "io/rad.hpp"

namespace sigchain::io {

// True when the cursor's next line starts with COUPLING.
bool at_coupling(const LineCursor& c);
// Reads COUPLING, SPHERICAL_ALBEDO, DIFFUSE_DOWN and one DIFFUSE_UP line per view of
// `rad` (its samples and views already read). Throws DataError at the offending line.
RadCoupling read_coupling(LineCursor& c, const Rad& rad);
void write_coupling(std::ostream& out, const RadCoupling& coupling, const Rad& rad);

}  // namespace sigchain::io
