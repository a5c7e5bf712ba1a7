// Tests for check_ply (lib/scene/ply.cpp): the header and body walk, ASCII and binary.
#include "scene/ply.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::scene;

namespace {

std::string write(const std::string& name, const std::string& bytes) {
    const auto path = std::filesystem::temp_directory_path() / ("sigchain_ply_test_" + name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
}

const std::string kHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

std::string message_of(const std::string& path) {
    try {
        check_ply(path);
    } catch (const DataError& e) {
        return e.what();
    }
    return "";
}

// Little- or big-endian bytes of a float.
std::string bytes_of(float f, bool big) {
    char b[4];
    std::memcpy(b, &f, 4);
    if (big) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
    return std::string(b, 4);
}

}  // namespace

TEST(CheckPly, CountsAWellFormedAsciiFile) {
    const PlyCounts c = check_ply(write("ok.ply", kHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"));
    EXPECT_EQ(c.vertices, 3u);
    EXPECT_EQ(c.faces, 1u);
}

TEST(CheckPly, ReadsCrlfLinesAndRefusesNonFiniteValues) {
    std::string crlf = kHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n";
    for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2))
        crlf.insert(at, "\r");
    EXPECT_EQ(check_ply(write("crlf.ply", crlf)).faces, 1u);
    const std::string p = write("inf.ply", kHeader + "0 0 0\n1 0 inf\n1 1 0\n3 0 1 2\n");
    EXPECT_NE(message_of(p).find("inf.ply:11: vertex 1: property z: 'inf' is not a finite number"),
              std::string::npos)
        << message_of(p);
}

TEST(CheckPly, NamesTheLineOfEachAsciiFault) {
    const std::string p = write("bad.ply", kHeader + "0 0 0\n1 0\n1 1 0\n3 0 1 2\n");
    EXPECT_NE(message_of(p).find("bad.ply:11: vertex 1: too few values"), std::string::npos)
        << message_of(p);
    const std::string q = write("list.ply", kHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1\n");
    EXPECT_NE(message_of(q).find("list.ply:13: face 0: too few values"), std::string::npos)
        << message_of(q);
    const std::string r = write("extra.ply", kHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2 7\n");
    EXPECT_NE(message_of(r).find("face 0: more values than its properties"), std::string::npos);
}

TEST(CheckPly, WalksBinaryBodiesInEitherByteOrder) {
    for (bool big : {false, true}) {
        std::string body;
        for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f}) body += bytes_of(v, big);
        body += std::string("\3", 1);
        for (int i : {0, 1, 2}) {
            const char b[4] = {static_cast<char>(big ? 0 : i), 0, 0, static_cast<char>(big ? i : 0)};
            body += std::string(b, 4);
        }
        std::string header = kHeader;
        header.replace(header.find("ascii"), 5,
                       big ? "binary_big_endian" : "binary_little_endian");
        const PlyCounts c = check_ply(write("bin.ply", header + body));
        EXPECT_EQ(c.faces, 1u);
        // One byte short, one byte over, a NaN coordinate.
        EXPECT_NE(message_of(write("short.ply", header + body.substr(0, body.size() - 1)))
                      .find("the file ends inside face 0 of 1"),
                  std::string::npos);
        EXPECT_NE(message_of(write("long.ply", header + body + "x")).find("1 bytes after"),
                  std::string::npos);
        std::string nan_body = body;
        nan_body.replace(4, 4, bytes_of(std::nanf(""), big));
        // No line in a binary body: the element is named instead.
        EXPECT_NE(message_of(write("nan.ply", header + nan_body))
                      .find("sigchain_ply_test_nan.ply: vertex 0: property y is not finite"),
                  std::string::npos)
            << message_of(write("nan.ply", header + nan_body));
    }
}

TEST(CheckPly, RefusesAHeaderWithoutEndHeader) {
    EXPECT_NE(message_of(write("head.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"))
                  .find("head.ply:3: the header has no end_header line"),
              std::string::npos);
    EXPECT_NE(message_of(write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                           "property quad x\nend_header\n0\n"))
                  .find("type.ply:4: unknown type 'quad'"),
              std::string::npos);
}
