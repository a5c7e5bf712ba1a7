// The tile rule shared by the builds with and without MPI.
#include "trace/distributed.hpp"

#include <algorithm>
#include <cmath>

namespace sigchain::trace {

long farm_tiles(long rows, long workers, double bytes_per_row, double max_tile_bytes) {
    constexpr long kTilesPerWorker = 4;
    long tiles = kTilesPerWorker * std::max(1L, workers);
    const double by_size = std::ceil(static_cast<double>(rows) * bytes_per_row / max_tile_bytes);
    if (by_size > static_cast<double>(tiles)) tiles = static_cast<long>(std::min(by_size, 1e15));
    return std::clamp(tiles, 1L, std::max(1L, rows));
}

}  // namespace sigchain::trace
