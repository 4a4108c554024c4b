// SPDX-License-Identifier: BSD-3-Clause
// Issue 18: a key accepted without effect warns once per run, naming the key, its value, the file
// and the JSON path, and only when the user gave a value other than the default.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/parameters/no_effect_warnings.h"
#include "core/parameters/parameters.h"
#include "core/utilities/logger.h"

namespace mc {
namespace {

std::vector<std::string> CaptureWarnings(const std::function<void()>& run) {
  std::vector<std::string> warnings;
  Logger::SetSink([&warnings](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) warnings.push_back(message);
  });
  run();
  Logger::ResetSink();
  return warnings;
}

TEST(NoEffectWarnings, NonDefaultValueWarnsOncePerRunWithFileAndPath) {
  NoEffectWarnings::Reset();
  const Parameters defaults(R"({"dynamic_search": false, "debug_mode": false})");
  Parameters settings(R"({"search": {"dynamic_search": true, "debug_mode": false}})", "case.json");
  const Parameters search = settings["search"];
  const auto warnings = CaptureWarnings([&] {
    EXPECT_TRUE(NoEffectWarnings::IfGiven(search, defaults, "dynamic_search", "no prediction"));
    EXPECT_TRUE(NoEffectWarnings::IfGiven(search, defaults, "dynamic_search", "no prediction"));
    EXPECT_FALSE(NoEffectWarnings::IfGiven(search, defaults, "debug_mode", "no dumps"));
    EXPECT_FALSE(NoEffectWarnings::IfGiven(search, defaults, "absent", "not given"));
  });
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "key 'dynamic_search' = true at case.json: search.dynamic_search has no effect in mortarcontact: "
            "no prediction");
  NoEffectWarnings::Reset();
  EXPECT_EQ(CaptureWarnings([&] { NoEffectWarnings::IfGiven(search, defaults, "dynamic_search", "again"); }).size(),
            1u);
}

TEST(NoEffectWarnings, NumbersCompareByValueAndWarnNamesTheValue) {
  NoEffectWarnings::Reset();
  const Parameters defaults(R"({"factor": 1.0, "type": "a"})");
  const Parameters settings(R"({"factor": 1, "type": "b"})");
  const auto warnings = CaptureWarnings([&] {
    EXPECT_FALSE(NoEffectWarnings::IfGiven(settings, defaults, "factor", "integer 1 is the default 1.0"));
    NoEffectWarnings::Warn(settings, "type", "runs as 'a'");
  });
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "key 'type' = \"b\" at type has no effect in mortarcontact: runs as 'a'");
}

}  // namespace
}  // namespace mc
