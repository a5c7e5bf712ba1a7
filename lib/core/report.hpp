// What a library run tells its user: warnings, notes, verbose details and progress.
// Library code (trace, therm, build_radiance, ...) reports through a Reporter and
// never writes to a stream itself; lib/cli builds the one a tool uses from its
// command line (-q, -v, --progress), and tests use Reporter (which discards
// everything) or a recording subclass.
#pragma once

#include <functional>
#include <string>

namespace sigchain {

class Reporter {
public:
    virtual ~Reporter() = default;
    // Something the user should know is wrong or approximate ("warning: ..."), shown
    // unless quiet.
    virtual void warn(const std::string& message) const { (void)message; }
    // A warning shown even when quiet: a result that is almost surely not what the user
    // wanted (a whole output zero), which a script running with -q must still see.
    virtual void alarm(const std::string& message) const { warn(message); }
    // A result worth one line (shown unless quiet).
    virtual void note(const std::string& message) const { (void)message; }
    // What was done and what was skipped (shown with -v).
    virtual void info(const std::string& message) const { (void)message; }
    // Whether info() is shown: callers skip building costly messages otherwise.
    virtual bool verbose() const { return false; }
    // Progress of a task of `total` items named `label` ("rendering"): update(done)
    // now and then, finish() at the end (also when an exception ends the task).
    virtual void progress_update(const std::string& label, long done, long total) const {
        (void)label, (void)done, (void)total;
    }
    virtual void progress_finish(const std::string& label) const { (void)label; }
};

// The ParallelOptions::progress callback that draws `label` on `reporter`.
inline std::function<void(long, long)> progress_callback(const Reporter& reporter,
                                                         std::string label) {
    return [&reporter, label = std::move(label)](long done, long total) {
        reporter.progress_update(label, done, total);
    };
}

// Ends the progress line of `label` when it goes out of scope (normally or not).
class ProgressScope {
public:
    ProgressScope(const Reporter& reporter, std::string label)
        : m_reporter(reporter), m_label(std::move(label)) {}
    ~ProgressScope() { m_reporter.progress_finish(m_label); }
    ProgressScope(const ProgressScope&) = delete;
    ProgressScope& operator=(const ProgressScope&) = delete;
    std::function<void(long, long)> callback() const {
        return progress_callback(m_reporter, m_label);
    }

private:
    const Reporter& m_reporter;
    std::string m_label;
};

}  // namespace sigchain
