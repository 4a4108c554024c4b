// SPDX-License-Identifier: BSD-3-Clause
// Requirement: every Kratos reference case's *_parameters.json and *_materials.json is read, and
// every string "value" in their process lists (e.g. "-1.0e3*t") compiles as an expression.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "core/parameters/parameters.h"
#include "core/utilities/function_expression.h"

namespace mc {
namespace {

std::vector<std::filesystem::path> CaseFiles() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path root = std::filesystem::path(MC_TEST_CASES_DIR) / "kratos_csma";
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with("_parameters.json") || name.ends_with("_materials.json")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Calls f on every string found under a key named "value".
void ForEachValueString(const Parameters& p, const std::function<void(const std::string&)>& f) {
  if (p.IsSubParameter()) {
    for (const auto& key : p.Keys()) {
      const Parameters child = p[key];
      if (key == "value" && child.IsString()) f(child.GetString());
      if (key == "value" && child.IsArray())
        for (std::size_t i = 0; i < child.size(); ++i)
          if (child[i].IsString()) f(child[i].GetString());
      ForEachValueString(child, f);
    }
  } else if (p.IsArray()) {
    for (std::size_t i = 0; i < p.size(); ++i) ForEachValueString(p[i], f);
  }
}

TEST(ParametersCases, EveryReferenceSettingsFileParses) {
  const auto files = CaseFiles();
  ASSERT_GE(files.size(), 30u) << "reference cases not found under " << MC_TEST_CASES_DIR;
  std::size_t expressions = 0;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const Parameters p = Parameters::FromFile(file.string());
    ASSERT_TRUE(p.IsSubParameter());
    if (file.filename().string().ends_with("_materials.json")) {
      ASSERT_TRUE(p["properties"].IsArray());
      EXPECT_GE(p["properties"].size(), 1u);
      EXPECT_TRUE(p["properties"][0]["Material"]["Variables"].IsSubParameter());
    } else {
      EXPECT_TRUE(p.Has("problem_data"));
      EXPECT_TRUE(p["solver_settings"].IsSubParameter());
      ForEachValueString(p, [&](const std::string& text) {
        EXPECT_NO_THROW(FunctionExpression{text}) << text;
        ++expressions;
      });
    }
    // Writing and re-reading gives the same document.
    EXPECT_EQ(Parameters(p.PrettyPrintJsonString()).WriteJsonString(), p.WriteJsonString());
  }
  EXPECT_GE(expressions, 10u);
}

}  // namespace
}  // namespace mc
