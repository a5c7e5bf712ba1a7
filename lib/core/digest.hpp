// SHA-256 digests of files and text (OpenSSL's libcrypto): the inputs of a part of a
// render, recorded so that a merge can refuse parts made from other inputs (cube(5), Parts).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace sigchain {

// A SHA-256 of bytes given in pieces: add() them in order, then hex() once. The
// pieces' boundaries do not matter (what a writer of rows and a reader of other row
// blocks must agree on). Not thread-safe; movable.
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(Sha256&&) noexcept;
    Sha256& operator=(Sha256&&) noexcept;
    void add(const void* data, std::size_t size);
    // The digest of everything added, 64 lowercase hex digits; the object is spent.
    std::string hex();

private:
    struct Context;
    std::unique_ptr<Context> m_context;
};

// The SHA-256 of a file's bytes, 64 lowercase hex digits. IoError naming `path` when it
// cannot be read.
std::string sha256_file(const std::string& path);
// The SHA-256 of `text`'s bytes, 64 lowercase hex digits.
std::string sha256_text(const std::string& text);
// One digest of a list of files: the SHA-256 of their digests, one per line, in order.
std::string sha256_files(const std::vector<std::string>& paths);

}  // namespace sigchain
