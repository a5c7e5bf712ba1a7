// Error types with source locations.
#include "core/error.hpp"

namespace sigchain {

std::string SourceLocation::str() const {
    std::string name = file == "-" ? std::string("<stdin>") : file;
    return line > 0 ? name + ":" + std::to_string(line) : name;
}

DataError::DataError(const SourceLocation& where, const std::string& message)
    : Error(where.str() + ": " + message), m_where(where), m_message(message) {}

}  // namespace sigchain
