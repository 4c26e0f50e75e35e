// Where the project's shared test data lives (CMake cache variable SCENFUZZ_SHARED_DIR, by
// default ../shared beside the repository), and a guard for the tests that need it: without the
// folder they are skipped with a message saying so, and every other test still runs.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

#ifndef SCENFUZZ_SHARED_DIR
#error "tests are compiled with SCENFUZZ_SHARED_DIR (see tests/CMakeLists.txt)"
#endif

namespace scenfuzz::test {

inline std::filesystem::path shared_dir() { return SCENFUZZ_SHARED_DIR; }

inline bool have_shared_dir() {
  return SCENFUZZ_HAVE_SHARED_DIR != 0 && std::filesystem::is_directory(shared_dir());
}

}  // namespace scenfuzz::test

// First statement of a test that reads shared data.
#define SCENFUZZ_REQUIRE_SHARED_DIR()                                             \
  do {                                                                            \
    if (!::scenfuzz::test::have_shared_dir())                                     \
      GTEST_SKIP() << "shared test data not found at " << SCENFUZZ_SHARED_DIR     \
                   << " (configure with -DSCENFUZZ_SHARED_DIR=<path to shared>)"; \
  } while (false)
