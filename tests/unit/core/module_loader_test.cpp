// Tests for the loader of sigchain's shared modules: a module that is not there, and
// one built for another interface, are refused with a message naming its path.
#include "core/module_loader.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using namespace sigchain;

namespace {

struct TestApi {
    std::uint32_t size;
    std::uint32_t version;
};

}  // namespace

TEST(ModuleLoader, MissingModuleNamesItsPath) {
    const auto loaded =
        load_module<TestApi>("sigchain_no_such_module.so", "no_such_entry", "Test", 1);
    EXPECT_EQ(loaded.api, nullptr);
    EXPECT_EQ(loaded.error.rfind("cannot load the Test module /", 0), 0u) << loaded.error;
    EXPECT_NE(loaded.error.find("/sigchain_no_such_module.so: "), std::string::npos)
        << loaded.error;
}

TEST(ModuleLoader, AnotherInterfaceIsRefused) {
    // The OpenImageIO module of this build tree, asked for an interface it does not have.
    const auto loaded =
        load_module<TestApi>("sigchain_oiio.so", "sigchain_oiio_api", "Test", 1000);
    if (!loaded.api && loaded.error.find("built for another interface") == std::string::npos)
        GTEST_SKIP() << "no module to load: " << loaded.error;
    EXPECT_EQ(loaded.api, nullptr);
    EXPECT_NE(loaded.error.find("/sigchain_oiio.so: built for another interface (version "),
              std::string::npos)
        << loaded.error;
    EXPECT_NE(loaded.error.find(", expected 1000)"), std::string::npos) << loaded.error;
}
