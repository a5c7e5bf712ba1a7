// The MPI transport (mpi.hpp). MPI itself is called by the module sigchain_mpi
// (mpi_module.cpp), which this file loads when the first Session starts
// (mpi_module.hpp says why); the launcher's environment is read here.
#include "core/mpi.hpp"

#include <chrono>
#include <climits>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "core/module_loader.hpp"
#include "core/mpi_module.hpp"

namespace sigchain::mpi {

namespace {

// The first of the launchers' variables that is set, as an integer; -1 when none is.
int env_int(std::initializer_list<const char*> names) {
    for (const char* name : names)
        if (const char* v = std::getenv(name); v && *v) return std::atoi(v);
    return -1;
}

// The module's functions, loaded once per process (thread-safe); IoError
// "MPI: cannot load the MPI module PATH: REASON" when it cannot be loaded.
const mpi_module::Api& api() {
    static std::once_flag once;
    static LoadedModule<mpi_module::Api> loaded;
    std::call_once(once, [] {
        loaded = load_module<mpi_module::Api>(SIGCHAIN_MPI_MODULE_NAME, "sigchain_mpi_api",
                                              "MPI", mpi_module::kApiVersion);
    });
    if (!loaded.api) throw IoError("MPI: " + loaded.error);
    return *loaded.api;
}

// IoError "MPI: MPI_CALL: MPI's text" unless `ok`.
void check(bool ok, const std::string& message) {
    if (!ok) throw IoError("MPI: " + message);
}

Message take(const mpi_module::Pending& pending) {
    Message m;
    m.source = pending.source;
    m.tag = pending.tag;
    m.bytes.resize(static_cast<std::size_t>(pending.count));
    std::string message;
    check(api().receive(pending, m.bytes.data(), message), message);
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
    std::string message;
    check(api().init(m_rank, m_size, message), message);
}

// Only a Session whose constructor returned is destroyed: the module is loaded.
Session::~Session() { api().finalize(); }

void send(int to, int tag, const void* data, std::size_t bytes) {
    if (bytes > static_cast<std::size_t>(INT_MAX))
        throw IoError("MPI: a message of " + std::to_string(bytes) +
                      " bytes exceeds the 2^31 - 1 of one message");
    std::string message;
    check(api().send(to, tag, data, static_cast<int>(bytes), message), message);
}

Message receive_any(int tag) {
    for (;;) {
        bool ready = false;
        mpi_module::Pending pending;
        std::string message;
        check(api().iprobe(tag, ready, pending, message), message);
        if (ready) return take(pending);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

Message receive(int from, int tag) {
    mpi_module::Pending pending;
    std::string message;
    check(api().probe(from, tag, pending, message), message);
    return take(pending);
}

}  // namespace sigchain::mpi
