// Running an external program (gnuplot for compare --plot) without a shell, and the
// memory this process may use.
#pragma once

#include <string>
#include <vector>

namespace sigchain {

// Runs argv[0] (searched on PATH) with the arguments argv[1..], standard input from
// /dev/null and standard error passed through, and returns what it wrote to standard
// output. Throws IoError naming the program when it cannot be started (`hint` is
// appended, e.g. which package provides it), is killed by a signal or exits non-zero.
std::string run_and_capture(const std::vector<std::string>& argv, const std::string& hint = "");

// The memory this process may use (bytes): the physical memory, or the address-space
// limit (ulimit -v) when it is lower.
double usable_memory_bytes();

}  // namespace sigchain
