// The message transport of the farm over MPI ranks (lib/core/farm_mpi.cpp): MPI's
// set-up, byte messages between ranks, and the job's abort. Built only with
// SIGCHAIN_MPI (CMake finds MPI: Open MPI on Debian 12); nothing else includes it.
// MPI itself is loaded only when the first Session starts (mpi_module.hpp).
// Thread-safety: MPI is initialised with MPI_THREAD_FUNNELED, so only the thread that
// made the Session may call these functions (the render's worker threads never do).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sigchain::mpi {

// Whether an MPI launcher started this process: Open MPI's mpirun/mpiexec
// (OMPI_COMM_WORLD_SIZE) or MPICH's Hydra (PMI_SIZE) name the job's size in its
// environment. A process started by hand, or by a direct srun launch under PMIx
// (which sets neither), is not, and runs as it would without MPI.
bool launched();
// This process's rank and the job's size as the launcher's environment gives them
// (before MPI is set up; 0 and 1 when not launched).
int launched_rank();
int launched_size();

// MPI set up for the life of the object (MPI_Init_thread ... MPI_Finalize).
class Session {
public:
    Session();
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;
    int rank() const { return m_rank; }
    int size() const { return m_size; }

private:
    int m_rank = 0, m_size = 1;
};

struct Message {
    int source = -1;
    int tag = -1;
    std::vector<unsigned char> bytes;
};

// Sends `bytes` to rank `to` with `tag` (blocking until the buffer may be reused).
// IoError when MPI fails or the message exceeds 2^31 - 1 bytes.
void send(int to, int tag, const void* data, std::size_t bytes);
// Waits for the next message with `tag` from any rank. Polls every millisecond instead
// of MPI's busy wait, so that a rank that only waits (rank 0 of the farm) leaves the
// cores to the ranks that render.
Message receive_any(int tag);
// Waits (MPI's own way) for the next message with `tag` from rank `from`.
Message receive(int from, int tag);

}  // namespace sigchain::mpi
