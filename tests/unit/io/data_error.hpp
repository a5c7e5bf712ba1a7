// Test support for the format readers: the DataError message a parse produces.
#pragma once

#include <functional>
#include <string>

#include "core/error.hpp"

namespace sigchain::test {

// Runs `parse` and returns the DataError's what() ("FILE:LINE: message"), or
// "no error" when it parses.
inline std::string data_error_of(const std::function<void()>& parse) {
    try {
        parse();
    } catch (const DataError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace sigchain::test
