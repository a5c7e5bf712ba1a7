// Tests for atomic output: nothing appears until commit, nothing is left on failure or
// a signal, no planted link is followed, a set of files is replaced as one.
#include "core/output.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"

using namespace sigchain;
namespace fs = std::filesystem;

TEST(AtomicOutput, AppearsOnlyOnCommit) {
    fs::path dir = fs::temp_directory_path() / ("sigchain_out_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string target = (dir / "a.txt").string();
    {
        AtomicOutput out(target);
        out.stream() << "hello\n";
        EXPECT_FALSE(fs::exists(target));
        EXPECT_TRUE(fs::exists(out.temp_path()));
        out.commit();
    }
    EXPECT_TRUE(fs::exists(target));
    std::string temp;
    {
        AtomicOutput out((dir / "b.txt").string());
        out.stream() << "half";
        temp = out.temp_path();
    }  // destroyed without commit: as after an exception
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
    EXPECT_FALSE(fs::exists(temp));
    fs::remove_all(dir);
}

namespace {

// A fresh folder for one test.
fs::path scratch(const std::string& name) {
    fs::path dir = fs::temp_directory_path() /
                   ("sigchain_out_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void spit(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST(AtomicOutput, TemporaryNameIsUnpredictableAndBesideTheTarget) {
    const fs::path dir = scratch("names");
    const std::string target = (dir / "a.txt").string();
    AtomicOutput one(target), two(target);
    // TARGET.tmp.XXXXXX: six characters chosen by mkostemp, not the process id.
    for (const std::string& t : {one.temp_path(), two.temp_path()}) {
        EXPECT_EQ(t.rfind(target + ".tmp.", 0), 0u) << t;
        EXPECT_EQ(t.size(), target.size() + 11) << t;
        EXPECT_NE(t, target + ".tmp." + std::to_string(::getpid()));
    }
    EXPECT_NE(one.temp_path(), two.temp_path());
    fs::remove_all(dir);
}

TEST(AtomicOutput, NeverWritesThroughAPlantedLink) {
    // The old predictable name, planted as a link to a victim, is left alone and the
    // victim keeps its content.
    const fs::path dir = scratch("symlink");
    const fs::path victim = dir / "victim";
    spit(victim, "precious\n");
    const std::string target = (dir / "out.txt").string();
    fs::create_symlink(victim, target + ".tmp." + std::to_string(::getpid()));
    write_atomically(target, [](std::ostream& o) { o << "new\n"; });
    EXPECT_EQ(slurp(victim), "precious\n");
    EXPECT_EQ(slurp(target), "new\n");
    EXPECT_TRUE(fs::is_symlink(target + ".tmp." + std::to_string(::getpid())));
    fs::remove_all(dir);
}

TEST(AtomicOutput, NewFilesHaveTheUmasksMode) {
    const fs::path dir = scratch("mode");
    const mode_t old = ::umask(022);
    write_atomically((dir / "m").string(), [](std::ostream& o) { o << "x"; });
    ::umask(old);
    // mkostemp makes 0600; a tool's output is 0666 less the umask like any new file.
    EXPECT_EQ(fs::status(dir / "m").permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                  fs::perms::others_read);
    fs::remove_all(dir);
}

TEST(TempDir, IsPrivateAndRemovedWithItsFiles) {
    const fs::path dir = scratch("tempdir");
    std::string path;
    {
        TempDir t((dir / "cube.img").string());
        path = t.path();
        EXPECT_EQ(path.rfind((dir / "cube.img").string() + ".tmp.", 0), 0u);
        EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, fs::perms::owner_all);
        spit(t.file("cube.img"), "data");
        spit(t.file("cube.hdr"), "ENVI");
    }
    EXPECT_FALSE(fs::exists(path));
    fs::remove_all(dir);
}

TEST(CommitMoves, ReplacesASetWithTheKeyFileLast) {
    const fs::path dir = scratch("moves");
    spit(dir / "c.img", "old img");
    spit(dir / "c.hdr", "old hdr");
    {
        TempDir t((dir / "c.img").string());
        spit(t.file("c.img"), "new img");
        spit(t.file("c.hdr"), "new hdr");
        commit_moves({{t.file("c.img"), (dir / "c.img").string()},
                      {t.file("c.hdr"), (dir / "c.hdr").string()}});
    }
    EXPECT_EQ(slurp(dir / "c.img"), "new img");
    EXPECT_EQ(slurp(dir / "c.hdr"), "new hdr");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
    fs::remove_all(dir);
}

TEST(CommitMoves, AFailedRenamePutsTheOldSetBack) {
    const fs::path dir = scratch("moves_back");
    spit(dir / "c.img", "old img");
    spit(dir / "c.hdr", "old hdr");
    {
        TempDir t((dir / "c.img").string());
        spit(t.file("c.img"), "new img");
        // The header's temporary is missing: its rename fails after the data's.
        EXPECT_THROW(commit_moves({{t.file("c.img"), (dir / "c.img").string()},
                                   {t.file("c.hdr"), (dir / "c.hdr").string()}}),
                     IoError);
    }
    EXPECT_EQ(slurp(dir / "c.img"), "old img");
    EXPECT_EQ(slurp(dir / "c.hdr"), "old hdr");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
    fs::remove_all(dir);
}

TEST(AtomicOutput, RemovesWhatAKilledRunLeftButNotALiveRunsTemporaries) {
    const fs::path dir = scratch("stale");
    const std::string target = (dir / "out.txt").string();
    spit(target + ".tmp.AbC123", "a killed run's file");
    fs::create_directory(target + ".tmp.dEf456");
    spit(target + ".tmp.dEf456/out.txt", "a killed run's folder");
    spit(target + ".tmp.short", "not a temporary's name");
    {
        AtomicOutput live(target);  // removes the two leftovers, holds its own
        const std::string mine = live.temp_path();
        AtomicOutput other(target);  // a second writer leaves the first's alone
        EXPECT_TRUE(fs::exists(mine));
        EXPECT_FALSE(fs::exists(target + ".tmp.AbC123"));
        EXPECT_FALSE(fs::exists(target + ".tmp.dEf456"));
        EXPECT_TRUE(fs::exists(target + ".tmp.short"));
        TempDir folder(target);  // nor does a folder
        EXPECT_TRUE(fs::exists(mine));
        EXPECT_TRUE(fs::exists(other.temp_path()));
    }
    fs::remove_all(dir);
}

TEST(CommitTogether, WritesEveryFileOrNone) {
    const fs::path dir = scratch("together");
    spit(dir / "b1", "old 1");
    spit(dir / "b2", "old 2");
    {
        AtomicOutput a((dir / "b1").string()), b((dir / "b2").string());
        a.stream() << "new 1";
        b.stream() << "new 2";
        commit_together({&a, &b});
    }
    EXPECT_EQ(slurp(dir / "b1"), "new 1");
    EXPECT_EQ(slurp(dir / "b2"), "new 2");
    {
        AtomicOutput a((dir / "b1").string()), b((dir / "b2").string());
        a.stream() << "newer 1";
    }  // abandoned (an exception): both old files stay, no temporary is left
    EXPECT_EQ(slurp(dir / "b1"), "new 1");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
    fs::remove_all(dir);
}

// In a child process: a temporary file and folder in `dir`, then `sig` raised.
int status_after_signal(const fs::path& dir, int sig) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        install_output_signal_handlers();
        AtomicOutput out((dir / "f").string());
        out.stream() << "half" << std::flush;
        TempDir folder((dir / "g").string());
        spit(folder.file("g"), "half");
        ::raise(sig);
        ::_exit(0);  // not reached: the handler exits
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

TEST(SignalHandler, RemovesTheRunsTemporariesAndExits128PlusN) {
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
        const fs::path dir = scratch("signal");
        const int status = status_after_signal(dir, sig);
        ASSERT_TRUE(WIFEXITED(status)) << sig;
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
        EXPECT_TRUE(fs::is_empty(dir)) << "signal " << sig << " left a temporary";
        fs::remove_all(dir);
    }
}

TEST(SameFile, ByInodeWhenTheyExistElseByPath) {
    const fs::path dir = scratch("same");
    spit(dir / "a", "x");
    fs::create_hard_link(dir / "a", dir / "hard");
    fs::create_symlink(dir / "a", dir / "soft");
    EXPECT_TRUE(same_file((dir / "a").string(), (dir / "hard").string()));
    EXPECT_TRUE(same_file((dir / "a").string(), (dir / "soft").string()));
    EXPECT_TRUE(same_file((dir / "a").string(), (dir / "." / "a").string()));
    EXPECT_TRUE(same_file((dir / "new").string(), (dir / "x" / ".." / "new").string()));
    spit(dir / "b", "x");
    EXPECT_FALSE(same_file((dir / "a").string(), (dir / "b").string()));
    EXPECT_FALSE(same_file((dir / "a").string(), (dir / "new").string()));
    EXPECT_THROW(require_outputs_distinct({(dir / "soft").string()}, {(dir / "a").string()}),
                 UsageError);
    EXPECT_NO_THROW(require_outputs_distinct({"-", (dir / "b").string()}, {"-", (dir / "a").string()}));
    fs::remove_all(dir);
}
