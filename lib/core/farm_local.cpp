// The farm of a build without MPI: every job runs in its one process.
#include "core/farm.hpp"

namespace sigchain {

bool farm_available() { return false; }
bool farm_worker() { return false; }
bool farm_worker_working() { return false; }
int farm_rank() { return 0; }
int farm_workers() { return 0; }
FarmRole run_farm(const FarmJob&) { return FarmRole::Alone; }

}  // namespace sigchain
