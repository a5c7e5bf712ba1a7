// Where sigchain's reference data (solar spectrum, model atmospheres, LOWTRAN 7
// tables) are read at run time.
#pragma once

#include <string>

namespace sigchain {

// The data directory: `option` when not empty (a tool's --data-dir), else the
// environment variable SIGCHAIN_DATA when set and not empty, else an installed copy's
// PREFIX/share/sigchain/data when the running program is PREFIX/bin/TOOL and that
// folder exists, else the directory fixed at build time (the source tree's data/). Throws IoError when the chosen directory
// does not exist, naming where the choice came from.
std::string data_dir(const std::string& option = {});

}  // namespace sigchain
