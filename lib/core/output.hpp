// Atomic file output: a private temporary beside the target, then rename; "-" is
// standard output. Temporaries are removed on an error and on SIGTERM, SIGINT or SIGHUP.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace sigchain {

// An output file that appears only when complete. Write through stream(), then call
// commit(); if the object is destroyed without commit() (an exception, a failed
// check), the temporary file is removed and the target is left untouched.
// For path "-", stream() is std::cout and commit() flushes it.
// The temporary is TARGET.tmp.XXXXXX in the target's folder, a name no other process
// can predict, created with O_CREAT|O_EXCL|O_NOFOLLOW (never through a planted
// symbolic link), mode 0666 less the umask as any new file. It is held under flock(2)
// while the run lasts; a new output first removes the TARGET.tmp.XXXXXX files and
// folders no run holds (what a SIGKILL left).
class AtomicOutput {
public:
    explicit AtomicOutput(std::string path);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    std::ostream& stream();
    // Flushes, checks for write errors, renames into place. Throws IoError.
    void commit();
    // Flushes and closes the temporary, checking for write errors (commit_together).
    void finish();
    const std::string& path() const { return m_path; }
    // Temporary file name (empty for "-"); exposed for tests.
    const std::string& temp_path() const { return m_temp; }

private:
    friend void commit_together(const std::vector<AtomicOutput*>& outputs);
    std::string m_path;
    std::string m_temp;
    int m_fd = -1;
    int m_lock = -1;  // the same open file, under flock(2) while this object lives
    int m_slot = -1;  // in the signal handler's list of temporaries
    std::unique_ptr<std::streambuf> m_buffer;
    std::unique_ptr<std::ostream> m_stream;
    bool m_committed = false;
};

// Convenience: write a whole file atomically with `writer`.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer);

// A private temporary folder beside `target` (TARGET.tmp.XXXXXX, made by mkdtemp, mode
// 0700) for writers that open their files themselves (GDAL, OpenImageIO): they write
// inside it, where no other user can plant a link, and commit_moves renames the
// results out. Removed with what it holds on destruction and on a signal.
class TempDir {
public:
    explicit TempDir(const std::string& target);
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return m_path; }
    // `name` inside the folder.
    std::string file(const std::string& name) const { return m_path + "/" + name; }

private:
    std::string m_path;
    int m_slot = -1;
    int m_lock = -1;  // the folder, open under flock(2) while the run lasts
};

// One finished temporary and the name it takes.
struct Move {
    std::string temp;
    std::string target;
};

// Renames every temp onto its target as one output (cube(5), sigchain(7) OUTPUTS).
// One file is renamed over its target (atomic). Several files (an ENVI .img and .hdr,
// build_radiance's bands) are committed so that no interruption, even SIGKILL or a
// power cut, leaves new and old files side by side: the existing targets are first
// moved aside (renamed to TARGET.tmp.XXXXXX), the last one given first, then the temps
// are renamed in the order given, then the old files removed. The last file should be
// the one that makes the set readable (an ENVI header, the .odb naming the .gdb
// files): it goes first and comes back last, so a kill in between leaves an incomplete
// set that readers reject as missing, never a mixed one. A rename that fails puts the
// old files back (a failed run leaves the previous outputs as they were; where even
// that fails, the error names the file that holds each). SIGTERM, SIGINT and SIGHUP
// are held off while this runs. Throws IoError.
void commit_moves(const std::vector<Move>& moves);

// Finishes each output and commits them as one (commit_moves), in the order given.
void commit_together(const std::vector<AtomicOutput*>& outputs);

// Installs the handler of SIGTERM, SIGINT and SIGHUP that removes the run's
// temporaries (files and folders registered above) and exits with status 128 +
// the signal number; a SIGHUP inherited as ignored (nohup) stays ignored. Cli::run
// calls it; calling it again does nothing.
void install_output_signal_handlers();

// Whether two paths name the same file: the same device and inode when both exist,
// else the same path once made absolute and normal (symbolic links resolved where
// they exist).
bool same_file(const std::string& a, const std::string& b);

// UsageError "OUTPUT: is also the input INPUT (refusing to overwrite an input)" when
// an output names one of the same run's inputs; "-" (standard streams) and empty
// names are ignored.
void require_outputs_distinct(const std::vector<std::string>& outputs,
                              const std::vector<std::string>& inputs);

}  // namespace sigchain
