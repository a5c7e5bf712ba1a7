// A number a unit test measured, recorded for the documents generated from the tests'
// JSON output (scripts/accuracy: docs/accuracy.md).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace sigchain::unit {

// GoogleTest's RecordProperty with 10 significant digits (std::to_string's six
// decimals lose small errors such as 5e-8): the documents print fewer, and their
// staleness check compares runs to a relative 1e-6 (tests/cli/accuracy_doc.bats).
inline void record(const std::string& key, double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    ::testing::Test::RecordProperty(key, text);
}

}  // namespace sigchain::unit
