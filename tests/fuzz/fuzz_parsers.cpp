// libFuzzer harness for every text parser in the format registry (run by `make fuzz`).
//
// Input layout: the first byte picks the format (its index in io::formats(), modulo
// the number of formats); the remaining bytes are the file text. For each input the
// harness parses the text (handler.check), writes its canonical form
// (handler.rewrite), and then checks the writer's contract: the canonical text parses
// again and rewriting it gives the same text (sigchain-check(1), --rewrite).
//
// Expected for bad input: a sigchain::Error (DataError, IoError, ...), which is
// caught. Everything else is a finding: any other exception (libFuzzer reports it
// as "deadly signal" after std::terminate), a crash, a sanitizer report, a timeout,
// an out-of-memory, or a broken round trip (reported on stderr, then abort()).
//
// `fuzz_parsers --list-formats` prints the format extensions in index order, one
// per line, and exits; scripts/fuzz uses it to prefix the seed corpus.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/text.hpp"
#include "io/registry.hpp"

namespace {

using sigchain::io::FormatHandler;

// Parses `text` as `handler`'s format and returns its canonical form.
std::string canonical(const FormatHandler& handler, std::string text, const std::string& name) {
    sigchain::TextInput input = sigchain::TextInput::from_string(std::move(text), name);
    handler.check(input);
    std::ostringstream out;
    handler.rewrite(input, out);
    return out.str();
}

[[noreturn]] void round_trip_failure(const FormatHandler& handler, const std::string& what,
                                     const std::string& first, const std::string& second) {
    std::fprintf(stderr,
                 "fuzz_parsers: .%s: %s\n--- canonical text ---\n%s\n--- second pass ---\n%s\n",
                 handler.extension.c_str(), what.c_str(), first.c_str(), second.c_str());
    std::abort();
}

// The writer's contract: canonical text reads back and is a fixed point of rewrite.
void check_round_trip(const FormatHandler& handler, const std::string& first) {
    std::string second;
    try {
        second = canonical(handler, first, "canonical." + handler.extension);
    } catch (const sigchain::Error& e) {
        round_trip_failure(handler, std::string("canonical form does not parse: ") + e.what(),
                           first, "");
    }
    if (second != first)
        round_trip_failure(handler, "rewriting the canonical form changes it", first, second);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    for (int i = 1; i < *argc; ++i) {
        if (std::strcmp((*argv)[i], "--list-formats") == 0) {
            for (const auto& f : sigchain::io::formats()) std::printf("%s\n", f.extension.c_str());
            std::exit(0);
        }
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto& all = sigchain::io::formats();
    if (all.empty() || size == 0) return 0;
    const FormatHandler& handler = all[data[0] % all.size()];
    std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
    std::string first;
    try {
        first = canonical(handler, std::move(text), "fuzz." + handler.extension);
    } catch (const sigchain::Error&) {
        return 0;  // bad input, rejected as it should be
    }
    check_round_trip(handler, first);
    return 0;
}
