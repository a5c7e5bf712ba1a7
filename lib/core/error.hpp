// Typed errors with source locations; tools map them to exit codes (lib/cli).
#pragma once

#include <stdexcept>
#include <string>

namespace sigchain {

// Where a value came from: a file name ("-" is shown as "<stdin>") and a 1-based
// line number (0 when the error concerns the whole file).
struct SourceLocation {
    std::string file;
    int line = 0;

    // "file:line" or "file" when line is 0.
    std::string str() const;
};

// Base of every sigchain error. what() is the complete message without the tool name.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bad input data (exit status 1). what() is "FILE:LINE: message".
class DataError : public Error {
public:
    DataError(const SourceLocation& where, const std::string& message);
    const SourceLocation& where() const { return m_where; }
    const std::string& message() const { return m_message; }

private:
    SourceLocation m_where;
    std::string m_message;
};

// A file that cannot be opened, read, written or renamed (exit status 1).
class IoError : public Error {
public:
    using Error::Error;
};

// Bad command-line usage (exit status 2).
class UsageError : public Error {
public:
    using Error::Error;
};

// A requested feature that sigchain does not implement yet (exit status 1).
class NotImplemented : public Error {
public:
    using Error::Error;
};

}  // namespace sigchain
