// A folder of the running test's own, empty: <build>/artifacts/<area>/<test name>. For tests
// that write files (scenes, summaries, reports) and leave them to look at after a failure.
// Needs JELLY_BINARY_DIR (every test target defines it).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jelly::testing {

inline std::filesystem::path fresh_test_folder(const std::string& area) {
  const std::filesystem::path dir = std::filesystem::path(JELLY_BINARY_DIR) / "artifacts" / area /
                                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace jelly::testing
