// SPDX-License-Identifier: BSD-3-Clause
// Issue 16: every input a fuzz harness failed on (a crash, an escaped exception, a sanitizer
// report, a hang) is kept, minimized, in tests/fuzz/regressions/<target>/ and replayed here through
// the harness' own entry point: each must now end normally or with an InputError.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "tests/fuzz/fuzz_targets.h"

namespace mc {
namespace {

/// Runs every file of regressions/<target>/ (a target without findings has no folder); returns
/// how many.
std::size_t ReplayAll(const std::string& target, const std::function<void(std::string_view)>& run) {
  const std::filesystem::path folder = std::filesystem::path(MC_FUZZ_REGRESSIONS_DIR) / target;
  if (!std::filesystem::is_directory(folder)) return 0;
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::ifstream file(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NO_THROW(run(text.str())) << entry.path();
    // The harness' timeout is 10 s under the sanitizers; a hang found there stays fast here.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0) << entry.path();
    ++count;
  }
  return count;
}

TEST(FuzzRegressions, EveryKeptInputEndsCleanly) {
  const std::size_t count = ReplayAll("mdpa", fuzz::ReadMdpa) + ReplayAll("parameters", fuzz::ReadParameters) +
                            ReplayAll("expression", fuzz::ParseExpression);
  EXPECT_GT(count, 0u) << "no regression inputs under " << MC_FUZZ_REGRESSIONS_DIR;
}

}  // namespace
}  // namespace mc
