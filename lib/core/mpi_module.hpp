// The interface between lib/core/mpi.cpp and MPI. Every MPI call is made by a shared
// module (sigchain_mpi, built from mpi_module.cpp, installed in LIBDIR/sigchain/) that
// mpi.cpp opens with dlopen when a Session starts, that is only in a process an MPI
// launcher started. Linked into the tools, Open MPI's 8 shared libraries (libmpi,
// libmpi_cxx, libopen-pal, libopen-rte, hwloc, libevent's two, udev) cost every process
// about 2.5 ms of start-up on Debian 12, when a line of sight takes about 45 ms.
//
// Both sides are built together by the same compiler, so C++ types cross the boundary;
// errors cross as false and a message "MPI_CALL: MPI's text", never as exceptions (the
// module links no sigchain library: it is linked with --no-undefined).
#pragma once

#include <cstdint>
#include <string>

namespace sigchain::mpi_module {

// Raise when Api or the types it passes change: the loader refuses a module built with
// another version or another sizeof(Api).
inline constexpr std::uint32_t kApiVersion = 1;

// A message waiting in MPI_COMM_WORLD: its sender, tag and length in bytes.
struct Pending {
    int source = -1;
    int tag = -1;
    int count = 0;
};

struct Api {
    std::uint32_t size;     // sizeof(Api) in the module
    std::uint32_t version;  // kApiVersion in the module
    // MPI_Init_thread (MPI_THREAD_FUNNELED), errors returned on MPI_COMM_WORLD, this
    // process's rank and the job's size.
    bool (*init)(int& rank, int& size, std::string& message);
    void (*finalize)();
    // MPI_Send of `count` bytes to rank `to` with `tag`.
    bool (*send)(int to, int tag, const void* data, int count, std::string& message);
    // MPI_Iprobe for a message with `tag` from any rank: `ready`, and if so `pending`.
    bool (*iprobe)(int tag, bool& ready, Pending& pending, std::string& message);
    // MPI_Probe: waits for a message with `tag` from rank `from`.
    bool (*probe)(int from, int tag, Pending& pending, std::string& message);
    // MPI_Recv of the message `pending` describes into `data` (pending.count bytes).
    bool (*receive)(const Pending& pending, void* data, std::string& message);
};

}  // namespace sigchain::mpi_module

// The module's one entry point (looked up with dlsym by this name).
extern "C" const sigchain::mpi_module::Api* sigchain_mpi_api();
