// ../shared, the read-only reference data beside the checkout (the public USD corpus, peers' VDB
// files): the tests that read it fail when it is missing, naming what is missing, so a checkout
// without it does not pass by skipping them quietly. FLUENCE_NO_SHARED=1 in the environment opts
// out: those tests are then skipped, each with a message naming the data it needs
// (tests/README.md).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fluence::test {

// FLUENCE_SOURCE_DIR/../shared, normalised.
inline std::filesystem::path sharedRoot() {
    return (std::filesystem::path(FLUENCE_SOURCE_DIR) / "../shared").lexically_normal();
}

// ../shared/<relative>.
inline std::filesystem::path sharedPath(const std::string& relative) {
    return (sharedRoot() / relative).lexically_normal();
}

// Whether FLUENCE_NO_SHARED=1 says to run without ../shared.
inline bool sharedOptedOut() {
    const char* value = std::getenv("FLUENCE_NO_SHARED");
    return value && std::string(value) == "1";
}

// Why a test that reads `path` (under ../shared) cannot run: "" when it can.
inline std::string sharedUnavailable(const std::filesystem::path& path) {
    const std::string shown = "../shared/" + path.lexically_relative(sharedRoot()).generic_string();
    if (sharedOptedOut()) return "skipped: FLUENCE_NO_SHARED=1, and this test reads " + shown;
    if (std::filesystem::exists(path)) return "";
    return shown + " is missing (looked for " + path.string() +
           "): this test reads the shared reference data beside the checkout; set FLUENCE_NO_SHARED=1 to skip it";
}

}  // namespace fluence::test

// In a test body (or SetUp): fails the test, or skips it under FLUENCE_NO_SHARED=1, when `path`
// under ../shared cannot be read.
#define FLUENCE_REQUIRE_SHARED(path)                                                                                   \
    if (const std::string fluenceUnavailable = ::fluence::test::sharedUnavailable(path); fluenceUnavailable.empty()) { \
    } else if (::fluence::test::sharedOptedOut())                                                                      \
        GTEST_SKIP() << fluenceUnavailable;                                                                            \
    else                                                                                                               \
        FAIL() << fluenceUnavailable
