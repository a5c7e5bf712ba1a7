// Tests for atomic output: nothing appears until commit, nothing is left on failure.
#include "core/output.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

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
