// Per-thread spectral scratch of the renderer: a stack of n-sample buffers, grown on
// first use only, released in scope order (ArenaScope). Not thread-safe: one per
// Tracer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace sigchain::trace {

class Arena {
public:
    explicit Arena(std::size_t n) : m_n(n) {}
    // A zeroed buffer of n values, valid until the enclosing ArenaScope ends.
    double* take() {
        if (m_top == m_blocks.size()) m_blocks.push_back(std::make_unique<double[]>(m_n));
        double* p = m_blocks[m_top++].get();
        std::fill(p, p + m_n, 0.0);
        return p;
    }
    std::size_t mark() const { return m_top; }
    void release(std::size_t mark) { m_top = mark; }

private:
    std::size_t m_n;
    std::vector<std::unique_ptr<double[]>> m_blocks;
    std::size_t m_top = 0;
};

// Gives back every buffer taken since its construction when it goes out of scope.
struct ArenaScope {
    Arena& arena;
    std::size_t mark;
    explicit ArenaScope(Arena& a) : arena(a), mark(a.mark()) {}
    ~ArenaScope() { arena.release(mark); }
};

}  // namespace sigchain::trace
