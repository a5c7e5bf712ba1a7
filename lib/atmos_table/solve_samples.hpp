// build_radiance's spectral samples solved in parallel: on worker threads, and under
// mpirun in parts farmed out to the ranks (core/farm.hpp). Internal to lib/atmos_table.
#pragma once

#include <cstddef>
#include <vector>

#include "atmos_table/radiance_sample.hpp"
#include "core/report.hpp"

namespace sigchain::atmos_table {

// Every sample is independent: solved on worker threads, each writing its own slot;
// under mpirun parts of the samples go to the ranks (core/farm.hpp), gathered on rank 0.
// Returns false on an MPI worker, which has no results.
// Sample i is solved with setups[setup_of[i]] (its band's streams).
bool solve_samples(const std::vector<SampleSetup>& setups, const std::vector<std::size_t>& setup_of,
                   const std::vector<double>& nus, const Reporter& reporter,
                   std::vector<SampleResult>& results);

}  // namespace sigchain::atmos_table
