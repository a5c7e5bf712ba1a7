// The material_fraction truth layers: per-pixel tallies of primary samples by material
// (material_fraction.hpp).
#include "trace/material_fraction.hpp"

#include <algorithm>

namespace sigchain::trace {

std::vector<std::string> material_fraction_layer_names() {
    std::vector<std::string> names;
    for (int k = 1; k <= kMaterialFractionSlots; ++k) {
        names.push_back("material_" + std::to_string(k) + "_id");
        names.push_back("material_" + std::to_string(k) + "_fraction");
    }
    return names;
}

void MaterialTally::add(long id) {
    for (auto& [key, count] : m_counts)
        if (key == id) {
            ++count;
            return;
        }
    m_counts.emplace_back(id, 1);
}

void MaterialTally::put(long samples, int first, long row, long col, image::Image& truth) const {
    std::vector<std::pair<long, long>> order = m_counts;
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    for (int k = 0; k < kMaterialFractionSlots; ++k) {
        bool used = static_cast<std::size_t>(k) < order.size() && samples > 0;
        double id = used ? static_cast<double>(order[k].first) : -1.0;
        double fraction =
            used ? static_cast<double>(order[k].second) / static_cast<double>(samples) : 0.0;
        truth.at(first + 2 * k, row, col) = static_cast<float>(id);
        truth.at(first + 2 * k + 1, row, col) = static_cast<float>(fraction);
    }
}

}  // namespace sigchain::trace
