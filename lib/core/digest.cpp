// SHA-256 through OpenSSL's EVP interface (libcrypto, Debian's libssl-dev): a well-kept
// implementation rather than one of our own.
#include "core/digest.hpp"

#include <openssl/evp.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/error.hpp"

namespace sigchain {

struct Sha256::Context {
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx{EVP_MD_CTX_new(),
                                                                 &EVP_MD_CTX_free};
    Context() {
        if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
            throw std::runtime_error("cannot set up SHA-256 (OpenSSL)");
    }
    void add(const void* data, std::size_t size) {
        if (EVP_DigestUpdate(ctx.get(), data, size) != 1)
            throw std::runtime_error("SHA-256 update failed (OpenSSL)");
    }
    std::string hex() {
        unsigned char md[EVP_MAX_MD_SIZE];
        unsigned int n = 0;
        if (EVP_DigestFinal_ex(ctx.get(), md, &n) != 1)
            throw std::runtime_error("SHA-256 final failed (OpenSSL)");
        static const char* digits = "0123456789abcdef";
        std::string out;
        for (unsigned int i = 0; i < n; ++i) {
            out += digits[md[i] >> 4];
            out += digits[md[i] & 15];
        }
        return out;
    }
};

Sha256::Sha256() : m_context(std::make_unique<Context>()) {}
Sha256::~Sha256() = default;
Sha256::Sha256(Sha256&&) noexcept = default;
Sha256& Sha256::operator=(Sha256&&) noexcept = default;
void Sha256::add(const void* data, std::size_t size) { m_context->add(data, size); }
std::string Sha256::hex() { return m_context->hex(); }

std::string sha256_file(const std::string& path) {
    std::unique_ptr<std::FILE, decltype(&std::fclose)> f(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!f) throw IoError(path + ": cannot open: " + std::strerror(errno));
    Sha256 d;
    char buf[1 << 16];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f.get())) > 0) d.add(buf, n);
    if (std::ferror(f.get())) throw IoError(path + ": read error");
    return d.hex();
}

std::string sha256_text(const std::string& text) {
    Sha256 d;
    d.add(text.data(), text.size());
    return d.hex();
}

std::string sha256_files(const std::vector<std::string>& paths) {
    std::string list;
    for (const std::string& p : paths) list += sha256_file(p) + "\n";
    return sha256_text(list);
}

}  // namespace sigchain
