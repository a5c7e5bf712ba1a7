// A farm of parts of a job over MPI ranks (trace(1), MPI; therm(1), MPI): under an MPI
// launcher with more than one rank (a SIGCHAIN_MPI build), rank 0 hands out parts of
// [0, items) one at a time to whichever worker (rank 1 to N - 1) asks, and gathers
// what each computed; otherwise nothing runs and the caller computes in its one
// process. Part p of P is [floor(p items / P), floor((p + 1) items / P)). The parts'
// results go as bytes, so a tool's output does not depend on how the work was split
// as long as each item's result depends on the item alone. Call it from the thread
// that runs main (MPI is set up MPI_THREAD_FUNNELED); compute and gather may use
// parallel_for inside.
#pragma once

#include <functional>
#include <vector>

namespace sigchain {

using FarmBytes = std::vector<unsigned char>;

struct FarmJob {
    long items = 0;  // [0, items): rows, facets, ...
    long parts = 1;  // 1 to items (farm_parts)
    // On a worker: the result of items [begin, end).
    std::function<FarmBytes(long begin, long end)> compute;
    // On rank 0: a part's result, in the order the parts arrive.
    std::function<void(long begin, long end, const FarmBytes& bytes)> gather;
    // On rank 0, once the first parts are handed out (may be empty): work of its own.
    std::function<void()> meanwhile;
};

enum class FarmRole { Alone, Lead, Worker };

// Whether run_farm would farm: an MPI build started by a launcher with 2 or more ranks
// (its environment: OMPI_COMM_WORLD_SIZE, PMI_SIZE). Always false without SIGCHAIN_MPI.
bool farm_available();
// Whether this process is a worker of such a farm (rank > 0), before MPI is set up:
// workers read the inputs but report nothing and write nothing.
bool farm_worker();
// Whether this worker has begun its parts. Before that, an error (a bad input) is most
// often one every rank meets the same way, so a worker reports it late and rank 0's is
// the one seen (Cli::run): N ranks printing one message at once interleaved it
// ("thermtherm: ...").
bool farm_worker_working();
// This process's rank under the launcher (0 when not farm_available()).
int farm_rank();
// The workers of the farm (ranks - 1); 0 when not farm_available().
int farm_workers();

// Runs `job` over the ranks when farm_available() and returns Lead on rank 0 (every
// part gathered) or Worker elsewhere (the caller writes nothing); Alone otherwise,
// having run nothing. A rank that fails never finishes MPI (that would wait for the
// others): its error propagates, the process exits, and the launcher ends the job
// (Open MPI's mpirun aborts every rank), so that rank 0 writes nothing. IoError for
// MPI's own failures.
FarmRole run_farm(const FarmJob& job);

// The parts of a farm of `items` over `workers` workers: 4 per worker, so that a slow
// part is balanced by the others; more when a part's result would exceed
// `max_part_bytes` (one message: 1 GiB keeps well under MPI's 2^31 - 1 bytes); at most
// one per item, at least 1.
long farm_parts(long items, long workers, double bytes_per_item,
                double max_part_bytes = 1024.0 * 1024.0 * 1024.0);

}  // namespace sigchain
