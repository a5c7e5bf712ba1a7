// The one parallel loop of sigchain: every tool that spreads independent work items
// (image rows, facets, spectral samples) over threads calls parallel_for.
//
// Results never depend on the thread count as long as the body computes item i from
// i alone (its seeds, its inputs) and writes only item i's outputs; per-thread
// scratch space is indexed by the worker number the body receives. Built on oneTBB
// (Debian's libtbb, which Embree uses too): an arena of `threads` slots, dynamic
// work stealing over the index range.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace sigchain {

struct ParallelOptions {
    unsigned threads = 0;  // 0: every core the process may use
    // Called now and then with (items done, items in all), never by two threads at
    // once; last with (count, count) when the loop completes. May be empty.
    std::function<void(long done, long total)> progress;
};

// Threads parallel_for uses for `count` items: opt.threads (0: the cores the
// process may use), at most `count`, at least 1. Workers are numbered 0 to this-1.
unsigned parallel_workers(long count, const ParallelOptions& opt);

// Calls body(i, worker) once for every i in [0, count). `worker` is in
// [0, parallel_workers(count, opt)) and is never used by two calls at once. The first
// exception a body throws stops the loop (items not started are not run) and is
// rethrown on the calling thread. With one worker the items run in order on the
// calling thread.
void parallel_for(long count, const ParallelOptions& opt,
                  const std::function<void(long i, unsigned worker)>& body);

// parallel_for whose items are started in increasing order, each at most `window` items
// past the first not yet passed on, and passed on in order as they complete:
// done(first, n) is called for items [first, first + n) once every item up to
// first + n - 1 is complete, the calls in order, one at a time, from whichever worker
// completed the last of them while the others go on with later items. A range holds
// window / 4 items at least (fewer only when it ends the loop or the ring) and never
// crosses a multiple of `window`, so that item i may keep its result in slot
// i % window of a ring of `window` slots (clamped to [1, count]) until it is passed
// on. body(i, worker) must compute item i from i alone, as for parallel_for; with one
// worker, items and done() run in order on the calling thread. The first exception
// of a body or of done() stops the loop and is rethrown; done() is not called again.
// opt.progress counts the items whose body has returned.
void parallel_for_ordered(long count, long window, const ParallelOptions& opt,
                          const std::function<void(long i, unsigned worker)>& body,
                          const std::function<void(long first, long n)>& done);

// Per-worker state made on a worker's first item: `WorkerStates<T> s(workers)`, then
// `T& t = s.get(worker, [&] { return T(...); })` in the body; after the loop,
// s.each(...) visits the states that were made, in worker order.
template <class T>
class WorkerStates {
public:
    explicit WorkerStates(unsigned workers) : m_states(workers) {}
    template <class Make>
    T& get(unsigned worker, Make&& make) {
        auto& slot = m_states[worker];
        if (!slot) slot.emplace(make());
        return *slot;
    }
    template <class Visit>
    void each(Visit&& visit) {
        for (auto& slot : m_states)
            if (slot) visit(*slot);
    }

private:
    std::vector<std::optional<T>> m_states;
};

}  // namespace sigchain
