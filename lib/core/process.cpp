// Running an external program with posix_spawnp and a pipe (see process.hpp).
#include "core/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/error.hpp"

extern char** environ;

namespace sigchain {

std::string run_and_capture(const std::vector<std::string>& argv, const std::string& hint) {
    if (argv.empty()) throw IoError("run_and_capture: no program");
    const std::string& name = argv.front();
    auto fail = [&](const std::string& why) -> IoError {
        return IoError(name + ": " + why + (hint.empty() ? "" : " (" + hint + ")"));
    };
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw fail(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    int rc = ::posix_spawnp(&pid, name.c_str(), &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (rc != 0) {
        ::close(fds[0]);
        throw fail(std::string("cannot run: ") + std::strerror(rc));
    }
    std::string out;
    char buf[65536];
    for (;;) {
        ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n > 0) {
            out.append(buf, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) throw fail("killed by signal " + std::to_string(WTERMSIG(status)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        // posix_spawnp reports a missing program as exit 127 of the child on glibc.
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127) throw fail("not found");
        throw fail("failed with exit status " + std::to_string(WEXITSTATUS(status)));
    }
    return out;
}

double usable_memory_bytes() {
    double bytes =
        static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
    struct rlimit limit {};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
    return bytes;
}

}  // namespace sigchain
