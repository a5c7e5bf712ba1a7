// Wall-clock and CPU timing for the plain benchmark programs (bench_trace, bench_therm).
#pragma once

#include <sys/resource.h>

#include <chrono>

namespace sigchain::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU seconds used by the process so far (user + system, every thread): on a shared
// machine, work per CPU second compares runs more fairly than wall-clock time.
inline double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace sigchain::bench
