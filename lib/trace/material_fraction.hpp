// The material_fraction truth layers (trace(1) TRUTH LAYERS): of a pixel's primary
// samples, the fraction that hit each material, the three largest shares kept.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image.hpp"

namespace sigchain::trace {

inline constexpr int kMaterialFractionSlots = 3;
inline constexpr long kMissMaterial = -1;  // the "material" of a sample that hits nothing

// The layer names, in channel order: material_1_id, material_1_fraction, ...,
// material_3_fraction (appended after the other truth layers).
std::vector<std::string> material_fraction_layer_names();

// One pixel's tally of primary samples by material id. Not thread-safe: one per worker.
class MaterialTally {
public:
    void clear() { m_counts.clear(); }
    // A primary sample that hit material `id` (kMissMaterial for a miss).
    void add(long id);
    // Writes the slots into `truth` at channels first, first + 1, ... of pixel (row, col):
    // by decreasing count, ties by increasing id; the fraction is count / samples. An
    // unused slot (fewer than three ids) is id -1 with fraction 0.
    void put(long samples, int first, long row, long col, image::Image& truth) const;

private:
    std::vector<std::pair<long, long>> m_counts;  // (id, count), few entries
};

}  // namespace sigchain::trace
