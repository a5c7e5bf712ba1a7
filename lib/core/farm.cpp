// The farm's part rule, shared by the builds with and without MPI.
#include "core/farm.hpp"

#include <algorithm>
#include <cmath>

namespace sigchain {

long farm_parts(long items, long workers, double bytes_per_item, double max_part_bytes) {
    constexpr long kPartsPerWorker = 4;
    long parts = kPartsPerWorker * std::max(1L, workers);
    const double by_size = std::ceil(static_cast<double>(items) * bytes_per_item / max_part_bytes);
    if (by_size > static_cast<double>(parts)) parts = static_cast<long>(std::min(by_size, 1e15));
    return std::clamp(parts, 1L, std::max(1L, items));
}

}  // namespace sigchain
