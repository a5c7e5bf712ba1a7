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
#include "trace/render_stream.hpp"

namespace sigchain::trace {

// Renders options' rows and hands them to `sink` in row order (render_stream.hpp), with
// `reporter`'s progress bar ("rendering"): in one process as they complete, held in a
// ring of `ring_rows` rows (render_streamed); over MPI, on rank 0, all at once when
// every tile has arrived, rank 0 holding the whole image. `result` receives the
// statistics (and the ring, or the whole image under MPI). Returns false on an MPI
// worker (rank > 0), which must write nothing. Throws what render() and `sink` throw.
bool render_rows(const RenderInputs& inputs, const RenderOptions& options, long ring_rows,
                 const RowSink& sink, const Reporter& reporter, RenderResult& result);

// Whether this process is an MPI worker (farm_worker: a rank other than 0 of a job of
// more than one rank), known before MPI is set up. Always false without SIGCHAIN_MPI.
bool distributed_worker();

}  // namespace sigchain::trace
