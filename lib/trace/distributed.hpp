// The image loop over one process or many: in one process render() does the rows; a
// trace built with SIGCHAIN_MPI and started by mpirun farms row tiles out to
// its ranks instead (core/farm.hpp; trace(1), MPI). Rank 0 hands out tiles dynamically,
// one at a time to whichever worker asks, and gathers them; each worker renders its
// tile with its own threads. A tile's rows are exactly those rows of the whole image
// (render() depends only on the seed and the options), so the gathered cube is
// bit-identical to a one-process render for every rank and thread count.
#pragma once

#include "core/report.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {

// Renders options' rows into `result`, with `reporter`'s progress bar ("rendering").
// Returns false on an MPI worker (rank > 0), which must write nothing: rank 0 alone
// holds the whole result. Throws what render() throws.
bool render_rows(const RenderInputs& inputs, const RenderOptions& options,
                 const Reporter& reporter, RenderResult& result);

// Whether this process is an MPI worker (farm_worker: a rank other than 0 of a job of
// more than one rank), known before MPI is set up. Always false without SIGCHAIN_MPI.
bool distributed_worker();

}  // namespace sigchain::trace
