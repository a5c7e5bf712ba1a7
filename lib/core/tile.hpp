// One of N equal parts of a range of items (--tile K/N: rows of trace's image), and the
// rule that rounds it: part K of N of `count` items is [floor((K-1) count / N),
// floor(K count / N)), so the parts are contiguous, cover the range once, and differ in
// size by at most one item (a part of no item when N > count). Header only.
#pragma once

#include <string>
#include <utility>

namespace sigchain {

struct Tile {
    long index = 1;  // K, 1 to count
    long count = 1;  // N, 1 or more

    // [begin, end) of the part within [0, items).
    std::pair<long, long> range(long items) const {
        // 128-bit products: K * items overflows a long only for absurd sizes, but must not.
        const auto begin = static_cast<long>((__int128)(index - 1) * items / count);
        const auto end = static_cast<long>((__int128)index * items / count);
        return {begin, end};
    }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

}  // namespace sigchain
