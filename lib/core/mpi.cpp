// MPI through its C interface (Open MPI's libmpi; the C++ bindings are gone since MPI 3).
#include "core/mpi.hpp"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <thread>

#include "core/error.hpp"

namespace sigchain::mpi {

namespace {

// The first of the launchers' variables that is set, as an integer; -1 when none is.
int env_int(std::initializer_list<const char*> names) {
    for (const char* name : names)
        if (const char* v = std::getenv(name); v && *v) return std::atoi(v);
    return -1;
}

void check(int status, const char* what) {
    if (status == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(status, text, &length);
    throw IoError(std::string("MPI: ") + what + ": " + std::string(text, length));
}

Message take(const MPI_Status& probe) {
    Message m;
    m.source = probe.MPI_SOURCE;
    m.tag = probe.MPI_TAG;
    int count = 0;
    check(MPI_Get_count(&probe, MPI_BYTE, &count), "MPI_Get_count");
    m.bytes.resize(static_cast<std::size_t>(count));
    check(MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE),
          "MPI_Recv");
    return m;
}

}  // namespace

// Open MPI's mpirun: OMPI_COMM_WORLD_SIZE and _RANK; MPICH's Hydra: PMI_SIZE and PMI_RANK.
int launched_size() {
    const int n = env_int({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"});
    return n > 0 ? n : 1;
}

int launched_rank() {
    const int r = env_int({"OMPI_COMM_WORLD_RANK", "PMI_RANK"});
    return r > 0 ? r : 0;
}

bool launched() { return env_int({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) > 0; }

Session::Session() {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    // Errors are returned, not fatal, so that they become IoErrors with a message.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
}

Session::~Session() { MPI_Finalize(); }

void send(int to, int tag, const void* data, std::size_t bytes) {
    if (bytes > static_cast<std::size_t>(INT_MAX))
        throw IoError("MPI: a message of " + std::to_string(bytes) +
                      " bytes exceeds the 2^31 - 1 of one message");
    check(MPI_Send(data, static_cast<int>(bytes), MPI_BYTE, to, tag, MPI_COMM_WORLD), "MPI_Send");
}

Message receive_any(int tag) {
    for (;;) {
        int ready = 0;
        MPI_Status probe;
        check(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &ready, &probe), "MPI_Iprobe");
        if (ready) return take(probe);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

Message receive(int from, int tag) {
    MPI_Status probe;
    check(MPI_Probe(from, tag, MPI_COMM_WORLD, &probe), "MPI_Probe");
    return take(probe);
}

}  // namespace sigchain::mpi
