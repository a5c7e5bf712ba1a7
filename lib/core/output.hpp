// Atomic file output: write FILE.tmp.PID, then rename; "-" is standard output.
#pragma once

#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace sigchain {

// An output file that appears only when complete. Write through stream(), then call
// commit(); if the object is destroyed without commit() (an exception, a failed
// check), the temporary file is removed and the target is left untouched.
// For path "-", stream() is std::cout and commit() flushes it.
class AtomicOutput {
public:
    explicit AtomicOutput(std::string path);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    std::ostream& stream();
    // Flushes, checks for write errors, renames into place. Throws IoError.
    void commit();
    const std::string& path() const { return m_path; }
    // Temporary file name (empty for "-"); exposed for tests.
    const std::string& temp_path() const { return m_temp; }

private:
    std::string m_path;
    std::string m_temp;
    std::ofstream m_file;
    bool m_committed = false;
};

// Convenience: write a whole file atomically with `writer`.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer);

}  // namespace sigchain
