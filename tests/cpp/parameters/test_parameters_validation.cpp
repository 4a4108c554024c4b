// SPDX-License-Identifier: BSD-3-Clause
// Requirement: each class validates its settings against its defaults (Kratos semantics): unknown
// keys are rejected with the nearest valid key, values must have the default's type (int/double
// interchangeable, null accepts anything), missing keys are filled, recursively on request.
#include <gtest/gtest.h>

#include "core/parameters/parameters.h"
#include "core/utilities/error.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

const char* kDefaults = R"({
  "max_iteration": 10,
  "tolerance": 1e-6,
  "solver_type": "newton",
  "echo": false,
  "list": [],
  "anything": null,
  "free_form": {},
  "search": {"factor": 3.5, "type": "obb", "inner": {"depth": 2, "name": "x"}}
})";

TEST(ParametersValidation, UnknownKeyNamesTheNearestKey) {
  Parameters p(R"({"solver_settings": {"max_iteraton": 3}})", "ProjectParameters.json");
  const std::string message =
      test::ErrorMessageOf([&] { p["solver_settings"].ValidateAndAssignDefaults(Parameters(kDefaults)); });
  EXPECT_EQ(message,
            "ProjectParameters.json: solver_settings: unknown key 'max_iteraton' (did you mean 'max_iteration'?)");
}

TEST(ParametersValidation, UnknownKeyWithNothingCloseListsValidKeys) {
  Parameters p(R"({"zzzzzzzzzz": 3})", "a.json");
  const std::string message =
      test::ErrorMessageOf([&] { p.ValidateAndAssignDefaults(Parameters(R"({"alpha": 1, "beta": 2})")); });
  EXPECT_EQ(message, "a.json: unknown key 'zzzzzzzzzz' (valid keys: 'alpha', 'beta')");
}

TEST(ParametersValidation, TypeMismatchNamesPathExpectedAndFound) {
  Parameters p(R"({"s": {"solver_type": 3}})", "c.json");
  EXPECT_EQ(test::ErrorMessageOf([&] { p["s"].ValidateAndAssignDefaults(Parameters(kDefaults)); }),
            "c.json: s.solver_type: expected a string (like the default \"newton\"), found integer 3");
  Parameters q(R"({"echo": "yes"})");
  EXPECT_NE(test::ErrorMessageOf([&] {
              q.ValidateAndAssignDefaults(Parameters(kDefaults));
            }).find("echo: expected a boolean"),
            std::string::npos);
  Parameters r(R"({"list": {}})");
  EXPECT_NE(
      test::ErrorMessageOf([&] { r.ValidateAndAssignDefaults(Parameters(kDefaults)); }).find("list: expected an array"),
      std::string::npos);
  Parameters o(R"({"search": 1})");
  EXPECT_NE(test::ErrorMessageOf([&] {
              o.ValidateAndAssignDefaults(Parameters(kDefaults));
            }).find("search: expected an object"),
            std::string::npos);
}

TEST(ParametersValidation, NumbersInterchangeableAndNullAcceptsAnything) {
  Parameters p(R"({"max_iteration": 5.0, "tolerance": 1, "anything": [1, "two"]})");
  EXPECT_EQ(test::ErrorMessageOf([&] { p.ValidateAndAssignDefaults(Parameters(kDefaults)); }), "");
  EXPECT_EQ(p["max_iteration"].GetInt(), 5);
  EXPECT_DOUBLE_EQ(p["tolerance"].GetDouble(), 1.0);
  EXPECT_EQ(p["anything"].size(), 2u);
  EXPECT_EQ(p["solver_type"].GetString(), "newton");  // filled
  EXPECT_EQ(p["search"]["inner"]["depth"].GetInt(), 2);
}

TEST(ParametersValidation, MissingDefaultsAreDeepCopies) {
  Parameters defaults(kDefaults);
  Parameters p;
  p.ValidateAndAssignDefaults(defaults);
  p["search"]["factor"].SetDouble(9.0);
  EXPECT_DOUBLE_EQ(defaults["search"]["factor"].GetDouble(), 3.5);
}

TEST(ParametersValidation, NonRecursiveLeavesSubObjectsAlone) {
  Parameters p(R"({"search": {"factor": 1.0, "typo": 1}})");
  p.ValidateAndAssignDefaults(Parameters(kDefaults));
  EXPECT_FALSE(p["search"].Has("type"));
  EXPECT_TRUE(p["search"].Has("typo"));
}

TEST(ParametersValidation, RecursiveFillsNestedObjects) {
  Parameters p(R"({"search": {"factor": 1.0, "inner": {"name": "y"}}, "free_form": {"whatever": 1}})");
  p.RecursivelyValidateAndAssignDefaults(Parameters(kDefaults));
  EXPECT_DOUBLE_EQ(p["search"]["factor"].GetDouble(), 1.0);
  EXPECT_EQ(p["search"]["type"].GetString(), "obb");
  EXPECT_EQ(p["search"]["inner"]["depth"].GetInt(), 2);
  EXPECT_EQ(p["search"]["inner"]["name"].GetString(), "y");
  EXPECT_EQ(p["free_form"]["whatever"].GetInt(), 1);  // an empty default object is free-form
}

TEST(ParametersValidation, RecursiveRejectsNestedUnknownKeyWithItsPath) {
  Parameters p(R"({"search": {"inner": {"dept": 3}}})", "p.json");
  EXPECT_EQ(test::ErrorMessageOf([&] { p.RecursivelyValidateAndAssignDefaults(Parameters(kDefaults)); }),
            "p.json: search.inner: unknown key 'dept' (did you mean 'depth'?)");
}

TEST(ParametersValidation, AddMissingDoesNotReject) {
  Parameters p(R"({"extra": 1, "search": {"extra2": 2}})");
  p.AddMissingParameters(Parameters(kDefaults));
  EXPECT_TRUE(p.Has("extra"));
  EXPECT_TRUE(p.Has("tolerance"));
  EXPECT_FALSE(p["search"].Has("factor"));
  p.RecursivelyAddMissingParameters(Parameters(kDefaults));
  EXPECT_TRUE(p["search"].Has("factor"));
  EXPECT_EQ(p["search"]["inner"]["name"].GetString(), "x");
  EXPECT_EQ(p["search"]["extra2"].GetInt(), 2);
}

TEST(ParametersValidation, CheckKeys) {
  Parameters p(R"({"model_part_name": "a", "intervl": [0, 1]})", "k.json");
  EXPECT_EQ(test::ErrorMessageOf([&] {
              p.CheckKeys({"model_part_name", "interval"});
            }),
            "k.json: unknown key 'intervl' (did you mean 'interval'?)");
  EXPECT_EQ(test::ErrorMessageOf([&] { p.CheckKeys({"model_part_name", "intervl"}); }), "");
}

}  // namespace
}  // namespace mc
