// The farm over MPI (farm.hpp): rank 0 hands out parts one at a time and gathers
// their bytes; the other ranks compute them.
#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/mpi.hpp"

namespace sigchain {

namespace {

constexpr int kTagResult = 1;  // worker -> rank 0: a computed part (or, empty, a request)
constexpr int kTagWork = 2;    // rank 0 -> worker: the next part's items (empty: stop)

// MPI for the farm's life. On the way out of an error MPI is not finalised (that
// would wait for the other ranks): the process exits with its error and the launcher
// ends the job.
class Session {
public:
    Session() : m_session(std::make_unique<mpi::Session>()) {}
    ~Session() {
        if (std::uncaught_exceptions() > 0) (void)m_session.release();
    }
    const mpi::Session& get() const { return *m_session; }

private:
    std::unique_ptr<mpi::Session> m_session;
};

// Test hook, not documented for users: SIGCHAIN_TEST_KILL_WORKER_AFTER_TILES=N makes a
// worker raise SIGKILL once it has sent N parts (tests/cli/mpi.bats: a killed worker
// fails the run cleanly).
void kill_hook(long sent) {
    static const long after = [] {
        const char* v = std::getenv("SIGCHAIN_TEST_KILL_WORKER_AFTER_TILES");
        return v && *v ? std::atol(v) : -1L;
    }();
    if (after >= 0 && sent >= after) std::raise(SIGKILL);
}

// A part's message: [begin, end) as two int64, then its bytes.
void send_part(int to, int tag, long begin, long end, const FarmBytes& bytes) {
    FarmBytes m(16 + bytes.size());
    const std::int64_t range[2] = {begin, end};
    std::memcpy(m.data(), range, 16);
    if (!bytes.empty()) std::memcpy(m.data() + 16, bytes.data(), bytes.size());
    mpi::send(to, tag, m.data(), m.size());
}

void read_range(const mpi::Message& m, long& begin, long& end) {
    if (m.bytes.size() < 16) throw IoError("MPI: a malformed farm message");
    std::int64_t range[2];
    std::memcpy(range, m.bytes.data(), 16);
    begin = static_cast<long>(range[0]);
    end = static_cast<long>(range[1]);
}

std::atomic<bool> g_working{false};  // farm_worker_working()

void work(const FarmJob& job) {
    g_working = true;
    send_part(0, kTagResult, 0, 0, {});  // a request
    for (long sent = 1;; ++sent) {
        long begin = 0, end = 0;
        read_range(mpi::receive(0, kTagWork), begin, end);
        if (begin == end) return;
        send_part(0, kTagResult, begin, end, job.compute(begin, end));
        kill_hook(sent);
    }
}

void lead(const FarmJob& job, int size) {
    long next = 0, outstanding = 0;
    auto assign = [&](int worker) {
        long begin = 0, end = 0;
        if (next < job.parts) {
            begin = static_cast<long>((__int128)next * job.items / job.parts);
            end = static_cast<long>((__int128)(next + 1) * job.items / job.parts);
            ++next;
            ++outstanding;
        }
        send_part(worker, kTagWork, begin, end, {});
    };
    for (int w = 1; w < size; ++w) assign(mpi::receive_any(kTagResult).source);
    if (job.meanwhile) job.meanwhile();
    while (outstanding > 0) {
        mpi::Message m = mpi::receive_any(kTagResult);
        long begin = 0, end = 0;
        read_range(m, begin, end);
        if (begin < 0 || end <= begin || end > job.items)
            throw IoError("MPI: a part " + std::to_string(begin) + ":" + std::to_string(end) +
                          " outside the job's " + std::to_string(job.items) + " items");
        m.bytes.erase(m.bytes.begin(), m.bytes.begin() + 16);
        job.gather(begin, end, m.bytes);
        --outstanding;
        assign(m.source);
    }
}

}  // namespace

bool farm_available() { return mpi::launched() && mpi::launched_size() > 1; }
bool farm_worker() { return farm_available() && mpi::launched_rank() > 0; }
bool farm_worker_working() { return g_working; }
int farm_rank() { return farm_available() ? mpi::launched_rank() : 0; }
int farm_workers() { return farm_available() ? mpi::launched_size() - 1 : 0; }

FarmRole run_farm(const FarmJob& job) {
    if (!farm_available()) return FarmRole::Alone;
    Session session;
    if (session.get().rank() != 0) {
        work(job);
        return FarmRole::Worker;
    }
    lead(job, session.get().size());
    return FarmRole::Lead;
}

}  // namespace sigchain
