// Tile::range (--tile K/N) and the SHA-256 digests of a part's inputs.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "core/digest.hpp"
#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/tile.hpp"

namespace sigchain {
namespace {

TEST(Tile, PartsCoverTheRowsOnceInOrder) {
    for (long rows : {1L, 2L, 7L, 16L, 100L, 1001L}) {
        for (long n = 1; n <= 12; ++n) {
            long next = 0;
            for (long k = 1; k <= n; ++k) {
                const auto [begin, end] = Tile{k, n}.range(rows);
                EXPECT_EQ(begin, next) << rows << " rows, " << k << "/" << n;
                // Sizes differ by at most one: floor(rows / n) or one more.
                EXPECT_TRUE(end - begin == rows / n || end - begin == rows / n + 1);
                next = end;
            }
            EXPECT_EQ(next, rows);
        }
    }
}

TEST(Tile, RoundingIsTheDocumentedFloor) {
    // trace(1): 16 rows in 3 tiles are 0:5, 5:10, 10:16 (floor((K-1) R / N)).
    EXPECT_EQ(Tile({1, 3}).range(16), std::make_pair(0L, 5L));
    EXPECT_EQ(Tile({2, 3}).range(16), std::make_pair(5L, 10L));
    EXPECT_EQ(Tile({3, 3}).range(16), std::make_pair(10L, 16L));
    EXPECT_EQ(Tile({2, 3}).text(), "2/3");
    // More tiles than rows: some hold none.
    EXPECT_EQ(Tile({1, 3}).range(2), std::make_pair(0L, 0L));
    // No overflow for huge counts: K * R would overflow 64 bits.
    const long big = 4'000'000'000'000'000'000L;
    EXPECT_EQ(Tile({999999, 1000000}).range(big).second, big / 1000000 * 999999);
}

// The farm's part rule (trace(1), MPI): 4 parts per worker, more when a part's bytes
// would pass the message limit, at most one per item, at least one.
TEST(FarmParts, FourPerWorkerWithinTheItems) {
    EXPECT_EQ(farm_parts(16, 2, 100), 8);      // the -np 3 case of tests/cli/mpi.bats
    EXPECT_EQ(farm_parts(16, 5, 100), 16);     // 20 wanted, 16 rows
    EXPECT_EQ(farm_parts(6, 2, 24), 6);        // therm: 6 facets
    EXPECT_EQ(farm_parts(1000, 0, 100), 4);    // no worker counts as one
    EXPECT_EQ(farm_parts(0, 3, 100), 1);
    // 1000 rows of 10 MB: 10 GB in parts of at most 1 GiB -> 10 parts, not 4.
    EXPECT_EQ(farm_parts(1000, 1, 1e7), 10);
    EXPECT_EQ(farm_parts(1000, 1, 1e7, 1e8), 100);
    // A single row above the limit still makes one part per row.
    EXPECT_EQ(farm_parts(3, 1, 2e9), 3);
}

TEST(Digest, KnownSha256Values) {
    // FIPS 180-2 examples: SHA-256("abc") and of the empty message.
    EXPECT_EQ(sha256_text("abc"),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256_text(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Digest, FilesByContentAndOrder) {
    const std::string a = ::testing::TempDir() + "/digest_a.txt",
                      b = ::testing::TempDir() + "/digest_b.txt";
    std::ofstream(a) << "abc";
    std::ofstream(b) << "abd";
    EXPECT_EQ(sha256_file(a), sha256_text("abc"));
    EXPECT_EQ(sha256_files({a, b}), sha256_text(sha256_text("abc") + "\n" +
                                                sha256_text("abd") + "\n"));
    EXPECT_NE(sha256_files({a, b}), sha256_files({b, a}));
    EXPECT_THROW(sha256_file(a + ".missing"), IoError);
    std::remove(a.c_str());
    std::remove(b.c_str());
}

}  // namespace
}  // namespace sigchain
