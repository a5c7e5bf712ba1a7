// Atomic file output.
#include "core/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "core/error.hpp"

namespace sigchain {

AtomicOutput::AtomicOutput(std::string path) : m_path(std::move(path)) {
    if (m_path == "-") return;
    m_temp = m_path + ".tmp." + std::to_string(::getpid());
    m_file.open(m_temp, std::ios::binary | std::ios::trunc);
    if (!m_file) throw IoError(m_path + ": cannot create: " + std::strerror(errno));
}

AtomicOutput::~AtomicOutput() {
    if (m_committed || m_temp.empty()) return;
    m_file.close();
    std::remove(m_temp.c_str());
}

std::ostream& AtomicOutput::stream() {
    if (m_path == "-") return std::cout;
    return m_file;
}

void AtomicOutput::commit() {
    if (m_path == "-") {
        std::cout.flush();
        if (!std::cout) throw IoError("<stdout>: write error");
        m_committed = true;
        return;
    }
    m_file.flush();
    if (!m_file) throw IoError(m_path + ": write error");
    m_file.close();
    if (std::rename(m_temp.c_str(), m_path.c_str()) != 0)
        throw IoError(m_path + ": cannot rename from " + m_temp + ": " + std::strerror(errno));
    m_committed = true;
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer) {
    AtomicOutput out(path);
    writer(out.stream());
    out.commit();
}

}  // namespace sigchain
