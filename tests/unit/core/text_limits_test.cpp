// Tests for the limits TextInput enforces while reading (sigchain(7), Text files):
// directories, NUL bytes, over-long lines, over-large files, and special files.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/text.hpp"

using namespace sigchain;

namespace {

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

std::string scratch(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("sigchain_text_limits_" + std::to_string(getpid()) + "_" + name))
        .string();
}

}  // namespace

TEST(TextLimits, DirectoryIsNamed) {
    std::string dir = scratch("dir");
    std::filesystem::create_directory(dir);
    EXPECT_EQ(error_of([&] { TextInput::from_file(dir); }),
              dir + ": is a directory; expected a file");
    std::filesystem::remove(dir);
}

TEST(TextLimits, DevZeroIsBinaryAtLineOne) {
    EXPECT_EQ(error_of([] { TextInput::from_file("/dev/zero"); }),
              "/dev/zero:1: binary data (NUL byte); expected a text file");
}

TEST(TextLimits, DevNullIsEmpty) { EXPECT_EQ(TextInput::from_file("/dev/null").text(), ""); }

TEST(TextLimits, NulByteAtItsLine) {
    std::istringstream in(std::string("a\nb\nc\0d\n", 8));
    EXPECT_EQ(error_of([&] { TextInput::from_stream(in, "s.txt"); }),
              "s.txt:3: binary data (NUL byte); expected a text file");
}

// The limits hold across chunk boundaries: a line of exactly max_line bytes passes,
// one more byte fails at its line, whatever the 64 KiB chunks cut.
TEST(TextLimits, LineLengthAcrossChunks) {
    TextLimits limits;
    limits.max_line = 100000;
    std::string ok = "x\n" + std::string(100000, 'a') + "\n";
    std::istringstream good(ok);
    EXPECT_EQ(TextInput::from_stream(good, "g", limits).text(), ok);
    std::istringstream bad("x\n" + std::string(100001, 'a') + "\n");
    EXPECT_EQ(error_of([&] { TextInput::from_stream(bad, "b", limits); }),
              "b:2: line longer than 100000 bytes (the limit of a text line, sigchain(7)); "
              "expected a text file");
}

TEST(TextLimits, FileSize) {
    TextLimits limits;
    limits.max_bytes = 1000;
    std::string text;
    for (int i = 0; i < 200; ++i) text += "1 2\n";  // 800 bytes: within
    std::istringstream good(text);
    EXPECT_EQ(TextInput::from_stream(good, "g", limits).text(), text);
    std::istringstream bad(text + text);
    EXPECT_EQ(error_of([&] { TextInput::from_stream(bad, "b", limits); }).rfind("b:", 0), 0u);
    // A regular file over the limit is refused from its size, before reading.
    std::string path = scratch("big");
    std::ofstream(path) << text << text;
    EXPECT_EQ(error_of([&] { TextInput::from_file(path, limits); }),
              path + ": file of 1600 bytes, larger than 1000 (the limit of a text file, "
                     "sigchain(7))");
    std::filesystem::remove(path);
}

TEST(TextLimits, FifoIsReadToItsEnd) {
    std::string path = scratch("fifo");
    ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs("1 2 3\n4 5 6\n", f);
        std::fclose(f);
        _exit(0);
    }
    EXPECT_EQ(TextInput::from_file(path).text(), "1 2 3\n4 5 6\n");
    std::filesystem::remove(path);
}
