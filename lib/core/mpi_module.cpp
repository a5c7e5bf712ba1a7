// MPI through its C interface (Open MPI's libmpi; the C++ bindings are gone since
// MPI 3), built as the shared module sigchain_mpi and loaded by lib/core/mpi.cpp when a
// Session starts (mpi_module.hpp says why). Links MPI and no sigchain library.
#include <mpi.h>

#include "core/mpi_module.hpp"

namespace sigchain::mpi_module {
namespace {

// false and "WHAT: MPI's text" unless `status` is MPI_SUCCESS.
bool check(int status, const char* what, std::string& message) {
    if (status == MPI_SUCCESS) return true;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(status, text, &length);
    message = std::string(what) + ": " + std::string(text, length);
    return false;
}

bool init(int& rank, int& size, std::string& message) {
    int provided = 0;
    if (!check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided),
               "MPI_Init_thread", message))
        return false;
    // Errors are returned, not fatal, so that they become IoErrors with a message.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return true;
}

void finalize() { MPI_Finalize(); }

bool send(int to, int tag, const void* data, int count, std::string& message) {
    return check(MPI_Send(data, count, MPI_BYTE, to, tag, MPI_COMM_WORLD), "MPI_Send", message);
}

bool describe(const MPI_Status& probe, Pending& pending, std::string& message) {
    pending.source = probe.MPI_SOURCE;
    pending.tag = probe.MPI_TAG;
    return check(MPI_Get_count(&probe, MPI_BYTE, &pending.count), "MPI_Get_count", message);
}

bool iprobe(int tag, bool& ready, Pending& pending, std::string& message) {
    int flag = 0;
    MPI_Status probe;
    if (!check(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &probe), "MPI_Iprobe",
               message))
        return false;
    ready = flag != 0;
    return !ready || describe(probe, pending, message);
}

bool probe(int from, int tag, Pending& pending, std::string& message) {
    MPI_Status probe;
    return check(MPI_Probe(from, tag, MPI_COMM_WORLD, &probe), "MPI_Probe", message) &&
           describe(probe, pending, message);
}

bool receive(const Pending& pending, void* data, std::string& message) {
    return check(MPI_Recv(data, pending.count, MPI_BYTE, pending.source, pending.tag,
                          MPI_COMM_WORLD, MPI_STATUS_IGNORE),
                 "MPI_Recv", message);
}

constexpr Api kApi{sizeof(Api), kApiVersion, init, finalize, send, iprobe, probe, receive};

}  // namespace
}  // namespace sigchain::mpi_module

extern "C" __attribute__((visibility("default"))) const sigchain::mpi_module::Api*
sigchain_mpi_api() {
    return &sigchain::mpi_module::kApi;
}
