// Atomic file output: private temporaries, renames that never mix old and new files,
// and their removal on a signal.
#include "core/output.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>

#include "core/error.hpp"

namespace sigchain {

namespace {

// ---- The registry of the run's temporaries, read by the signal handler ----
// A fixed table (no allocation in the handler): each slot is free, being filled, a
// file or a folder; the handler reads only slots whose state says the name is whole.
constexpr int kSlots = 1024;
constexpr std::size_t kPathMax = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kFile = 2, kFolder = 3 };
struct Slot {
    std::atomic<int> state{kFree};
    char path[kPathMax]{};
};
// constinit: zero in .bss, with no start-up loop touching all of its 4 MB (a page fault
// per 4 kB: build_radiance --version took 7 ms with it, 4 ms without).
constinit Slot g_slots[kSlots];

int register_temp(const std::string& path, SlotState kind) {
    if (path.size() + 1 > kPathMax) throw IoError(path + ": temporary name too long");
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!g_slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
        g_slots[i].state.store(kind);
        return i;
    }
    throw IoError(path + ": more than " + std::to_string(kSlots) + " temporaries at once");
}

void unregister_temp(int slot) {
    if (slot >= 0) g_slots[slot].state.store(kFree);
}

// Removes a folder's entries and the folder, with system calls only (async-signal-safe).
void remove_folder_raw(const char* path) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
        alignas(8) char buffer[4096];
        for (;;) {
            const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
            if (n <= 0) break;
            for (long at = 0; at < n;) {
                // struct linux_dirent64: ino (8), off (8), reclen (2), type (1), name.
                unsigned short reclen;
                std::memcpy(&reclen, buffer + at + 16, sizeof reclen);
                const char* name = buffer + at + 19;
                if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0)
                    ::unlinkat(fd, name, 0);
                at += reclen;
            }
        }
        ::close(fd);
    }
    ::rmdir(path);
}

void remove_registered_temps() {
    for (auto& slot : g_slots) {
        const int state = slot.state.load();
        if (state == kFile)
            ::unlink(slot.path);
        else if (state == kFolder)
            remove_folder_raw(slot.path);
    }
}

// ---- Signals: remove the temporaries and exit 128 + N, but never mid-commit ----
enum RunState : int { kRunning = 0, kCommitting = 1, kDying = 2 };
std::atomic<int> g_run_state{kRunning};
std::atomic<int> g_pending_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

extern "C" void on_terminating_signal(int sig) {
    int expected = kRunning;
    if (g_run_state.compare_exchange_strong(expected, kDying)) {
        remove_registered_temps();
        ::_exit(128 + sig);
    }
    // A commit is under way: it finishes, then raises the signal again.
    if (expected == kCommitting) g_pending_signal.store(sig);
}

// Marks a commit: the handler defers signals until it ends.
class CommitSection {
public:
    CommitSection() {
        int expected = kRunning;
        while (!g_run_state.compare_exchange_weak(expected, kCommitting)) {
            if (expected == kDying)
                for (;;) ::pause();  // the handler is cleaning up and exits
            expected = kRunning;
            std::this_thread::yield();  // another thread commits
        }
    }
    ~CommitSection() {
        const int sig = g_pending_signal.exchange(0);
        g_run_state.store(kRunning);
        if (sig != 0) ::raise(sig);
    }
    CommitSection(const CommitSection&) = delete;
    CommitSection& operator=(const CommitSection&) = delete;
};

// Holds SIGTERM, SIGINT and SIGHUP off in this thread while a temporary is created and
// registered: a signal arriving between the two would otherwise find a file or folder
// the handler does not know of, and leave it behind. A signal that came meanwhile is
// delivered when the mask is restored, with the temporary registered.
class SignalHold {
public:
    SignalHold() {
        sigset_t set;
        sigemptyset(&set);
        for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaddset(&set, sig);
        ::pthread_sigmask(SIG_BLOCK, &set, &m_old);
    }
    ~SignalHold() { ::pthread_sigmask(SIG_SETMASK, &m_old, nullptr); }
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;

private:
    sigset_t m_old;
};

// Test hook, not documented for users: SIGCHAIN_TEST_KILL_AT_RENAME=N[:SIG] raises
// SIGKILL (or SIG: TERM, INT or HUP) before the N-th file operation (removal of an old
// target, or rename) of the run's commits; N = 0 raises it as the first commit starts,
// its temporaries written and nothing renamed. tests/robustness/outputs.bats checks
// every intermediate state with it.
struct KillHook {
    long at = -1;
    int sig = SIGKILL;
};

const KillHook& kill_hook() {
    static const KillHook hook = [] {
        KillHook h;
        const char* text = std::getenv("SIGCHAIN_TEST_KILL_AT_RENAME");
        if (!text || !*text) return h;
        h.at = std::atol(text);
        if (const char* colon = std::strchr(text, ':')) {
            const std::string name(colon + 1);
            h.sig = name == "TERM" ? SIGTERM : name == "INT" ? SIGINT : name == "HUP" ? SIGHUP
                                                                                      : SIGKILL;
        }
        return h;
    }();
    return hook;
}

void test_kill_point() {
    static std::atomic<long> count{0};
    const KillHook& hook = kill_hook();
    if (hook.at > 0 && ++count == hook.at) ::raise(hook.sig);
}

void test_kill_at_start() {
    static std::atomic<bool> started{false};
    if (kill_hook().at == 0 && !started.exchange(true)) ::raise(kill_hook().sig);
}

// The permissions of a new file (0666 less the umask), which mkostemp's 0600 lacks.
mode_t new_file_mode() {
    static const mode_t mode = [] {
        const mode_t mask = ::umask(022);
        ::umask(mask);
        return static_cast<mode_t>(0666 & ~mask);
    }();
    return mode;
}

// A streambuf writing to a file descriptor; records the first write error.
class FdBuffer final : public std::streambuf {
public:
    explicit FdBuffer(int fd) : m_fd(fd) { setp(m_buffer, m_buffer + sizeof m_buffer); }
    ~FdBuffer() override = default;
    int error() const { return m_errno; }

protected:
    int_type overflow(int_type ch) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const char* p = pbase();
        while (p < pptr()) {
            const ssize_t n = ::write(m_fd, p, static_cast<std::size_t>(pptr() - p));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                m_errno = n < 0 ? errno : EIO;
                return false;
            }
            p += n;
        }
        setp(m_buffer, m_buffer + sizeof m_buffer);
        return true;
    }
    int m_fd;
    int m_errno = 0;
    char m_buffer[1 << 16];
};

std::string errno_text(int e) { return std::strerror(e); }

// Whether `name` is `base` + ".tmp." + six letters or digits (a temporary's name).
bool is_temp_name_of(const char* name, const std::string& base) {
    const std::size_t n = std::strlen(name);
    if (n != base.size() + 11 || std::strncmp(name, base.c_str(), base.size()) != 0 ||
        std::strncmp(name + base.size(), ".tmp.", 5) != 0)
        return false;
    for (std::size_t i = base.size() + 5; i < n; ++i)
        if (!std::isalnum(static_cast<unsigned char>(name[i]))) return false;
    return true;
}

// Removes the temporaries a killed run left beside `target` (SIGKILL runs no handler):
// every TARGET.tmp.XXXXXX file or folder of this user that no live run holds locked
// (each run holds its own temporaries under flock(2) until it ends). Symbolic links and
// other users' files are left alone; failures are ignored (a temporary is only litter).
void remove_stale_temps(const std::string& target) {
    const std::filesystem::path t(target);
    const std::string base = t.filename().string();
    const std::string folder = t.has_parent_path() ? t.parent_path().string() : ".";
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    const int dfd = ::dirfd(dir);
    while (const dirent* e = ::readdir(dir)) {
        if (!is_temp_name_of(e->d_name, base)) continue;
        struct stat st {};
        if (::fstatat(dfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || st.st_uid != ::getuid())
            continue;
        const bool is_dir = S_ISDIR(st.st_mode);
        if (!is_dir && !S_ISREG(st.st_mode)) continue;
        const int fd = ::openat(dfd, e->d_name,
                                O_RDONLY | O_NOFOLLOW | O_CLOEXEC | (is_dir ? O_DIRECTORY : 0));
        if (fd < 0) continue;
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {  // no run holds it: its run is dead
            if (is_dir)
                remove_folder_raw((folder + "/" + e->d_name).c_str());
            else
                ::unlinkat(dfd, e->d_name, 0);
        }
        ::close(fd);
    }
    ::closedir(dir);
}

}  // namespace

// ---- AtomicOutput ----

AtomicOutput::AtomicOutput(std::string path) : m_path(std::move(path)) {
    if (m_path == "-") return;
    remove_stale_temps(m_path);
    const SignalHold hold;
    std::string name = m_path + ".tmp.XXXXXX";
    m_fd = ::mkostemp(name.data(), O_NOFOLLOW | O_CLOEXEC);
    if (m_fd < 0) throw IoError(m_path + ": cannot create: " + errno_text(errno));
    // Locked while this object lives (remove_stale_temps): through a second descriptor
    // of the same open file, so that finish() can close the first and check its error.
    ::flock(m_fd, LOCK_EX | LOCK_NB);
    m_lock = ::fcntl(m_fd, F_DUPFD_CLOEXEC, 0);
    m_temp = name;
    try {
        m_slot = register_temp(m_temp, kFile);
    } catch (...) {
        ::close(m_fd);
        ::unlink(m_temp.c_str());
        throw;
    }
    ::fchmod(m_fd, new_file_mode());
    m_buffer = std::make_unique<FdBuffer>(m_fd);
    m_stream = std::make_unique<std::ostream>(m_buffer.get());
}

AtomicOutput::~AtomicOutput() {
    if (m_fd >= 0) ::close(m_fd);
    if (!m_committed && !m_temp.empty()) ::unlink(m_temp.c_str());
    if (m_lock >= 0) ::close(m_lock);
    unregister_temp(m_slot);
}

std::ostream& AtomicOutput::stream() {
    if (m_path == "-") return std::cout;
    return *m_stream;
}

void AtomicOutput::finish() {
    if (m_path == "-") {
        std::cout.flush();
        if (!std::cout) throw IoError("<stdout>: write error");
        return;
    }
    if (m_fd < 0) return;  // already finished
    m_stream->flush();
    const int e = static_cast<FdBuffer*>(m_buffer.get())->error();
    if (!*m_stream || e != 0) throw IoError(m_path + ": write error: " + errno_text(e ? e : EIO));
    const int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0) throw IoError(m_path + ": write error: " + errno_text(errno));
}

void AtomicOutput::commit() { commit_together({this}); }

void commit_together(const std::vector<AtomicOutput*>& outputs) {
    std::vector<Move> moves;
    for (AtomicOutput* out : outputs) {
        out->finish();
        if (out->m_path != "-") moves.push_back({out->m_temp, out->m_path});
    }
    if (!moves.empty()) commit_moves(moves);
    for (AtomicOutput* out : outputs) out->m_committed = true;
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer) {
    AtomicOutput out(path);
    writer(out.stream());
    out.commit();
}

// ---- TempDir ----

TempDir::TempDir(const std::string& target) {
    remove_stale_temps(target);
    const SignalHold hold;
    std::string name = target + ".tmp.XXXXXX";
    if (!::mkdtemp(name.data())) throw IoError(target + ": cannot create: " + errno_text(errno));
    m_path = name;
    // Held open and locked until the run ends, so that no other run takes it for litter.
    m_lock = ::open(m_path.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (m_lock >= 0) ::flock(m_lock, LOCK_EX | LOCK_NB);
    try {
        m_slot = register_temp(m_path, kFolder);
    } catch (...) {
        ::rmdir(m_path.c_str());
        throw;
    }
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
    if (m_lock >= 0) ::close(m_lock);
    unregister_temp(m_slot);
}

// ---- Commits ----

void commit_moves(const std::vector<Move>& moves) {
    test_kill_at_start();
    CommitSection section;
    if (moves.size() == 1) {
        test_kill_point();
        if (std::rename(moves[0].temp.c_str(), moves[0].target.c_str()) != 0)
            throw IoError(moves[0].target + ": cannot rename from " + moves[0].temp + ": " +
                          errno_text(errno));
        return;
    }
    // The old set goes first, so that no prefix of the renames leaves old and new
    // files together (output.hpp). It is moved aside, not removed, so that a rename that
    // fails (EXDEV, EIO, a full directory) puts it back: a failed run leaves the
    // previous outputs as they were.
    struct Aside {
        std::string target, backup;
    };
    std::vector<Aside> aside;
    std::vector<std::string> renamed;  // targets that hold a new file
    const auto undo = [&](const std::string& why) {
        std::string kept;
        for (auto t = renamed.rbegin(); t != renamed.rend(); ++t) ::unlink(t->c_str());
        for (auto a = aside.rbegin(); a != aside.rend(); ++a)
            if (std::rename(a->backup.c_str(), a->target.c_str()) != 0)
                kept += "; the previous " + a->target + " is kept as " + a->backup;
        throw IoError(why + kept);
    };
    for (const Move& m : moves) remove_stale_temps(m.target);  // a killed commit's
    for (auto m = moves.rbegin(); m != moves.rend(); ++m) {  // the last (the key) first
        struct stat st {};
        if (::lstat(m->target.c_str(), &st) != 0) continue;
        test_kill_point();
        // A name no other process can take, then the old file renamed over it.
        std::string backup = m->target + ".tmp.XXXXXX";
        const int fd = ::mkostemp(backup.data(), O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) undo(m->target + ": cannot replace: " + errno_text(errno));
        ::close(fd);
        if (std::rename(m->target.c_str(), backup.c_str()) != 0) {
            const int e = errno;
            ::unlink(backup.c_str());
            undo(m->target + ": cannot replace: " + errno_text(e));
        }
        aside.push_back({m->target, backup});
    }
    for (const Move& m : moves) {
        test_kill_point();
        if (std::rename(m.temp.c_str(), m.target.c_str()) != 0)
            undo(m.target + ": cannot rename from " + m.temp + ": " + errno_text(errno));
        renamed.push_back(m.target);
    }
    for (const Aside& a : aside) ::unlink(a.backup.c_str());
}

void install_output_signal_handlers() {
    static const bool installed = [] {
        new_file_mode();  // read the umask now, before any thread starts
        struct sigaction action {};
        action.sa_handler = on_terminating_signal;
        sigemptyset(&action.sa_mask);
        for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaddset(&action.sa_mask, sig);
        for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
            // A hangup the process inherited as ignored stays ignored (nohup(1)): the
            // user asked for the run to outlive its terminal.
            struct sigaction inherited {};
            if (sig == SIGHUP && ::sigaction(sig, nullptr, &inherited) == 0 &&
                inherited.sa_handler == SIG_IGN)
                continue;
            ::sigaction(sig, &action, nullptr);
        }
        return true;
    }();
    (void)installed;
}

// ---- Outputs that are inputs ----

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    std::error_code ea, eb;
    const auto ca = std::filesystem::weakly_canonical(a, ea);
    const auto cb = std::filesystem::weakly_canonical(b, eb);
    if (ea || eb) return std::filesystem::absolute(a).lexically_normal() ==
                         std::filesystem::absolute(b).lexically_normal();
    return ca == cb;
}

void require_outputs_distinct(const std::vector<std::string>& outputs,
                              const std::vector<std::string>& inputs) {
    for (const std::string& out : outputs) {
        if (out.empty() || out == "-") continue;
        for (const std::string& in : inputs) {
            if (in.empty() || in == "-") continue;
            if (same_file(out, in))
                throw UsageError(out + ": is also the input " + in +
                                 " (refusing to overwrite an input)");
        }
    }
}

}  // namespace sigchain
