// SPDX-License-Identifier: BSD-3-Clause
// Requirement: imposed values written as expressions of x, y, z, X, Y, Z, t in Kratos settings
// ("-0.15*t", Python's ** included) are compiled once and evaluated exactly; their dependence on
// space and time is known; a malformed expression is an InputError quoting it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/utilities/error.h"
#include "core/utilities/function_expression.h"

namespace mc {
namespace {

TEST(FunctionExpression, LinearInTime) {
  const FunctionExpression f("-0.15*t");
  EXPECT_DOUBLE_EQ(f.Evaluate(0, 0, 0, 2.0), -0.3);
  EXPECT_TRUE(f.DependsOnTime());
  EXPECT_FALSE(f.DependsOnSpace());
  EXPECT_EQ(f.Text(), "-0.15*t");
}

TEST(FunctionExpression, PythonPowerAndCurrentCoordinates) {
  const FunctionExpression f("x**2+y*t");
  EXPECT_DOUBLE_EQ(f.Evaluate(3.0, 2.0, 0.0, 0.5), 10.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(-1.5, 4.0, 7.0, 2.0), 10.25);
  EXPECT_TRUE(f.DependsOnTime());
  EXPECT_TRUE(f.DependsOnSpace());
  EXPECT_DOUBLE_EQ(FunctionExpression("-2**2").Evaluate(0, 0, 0, 0), -4.0);  // as in Python
  EXPECT_DOUBLE_EQ(FunctionExpression("2**3**2").Evaluate(0, 0, 0, 0), 512.0);
}

TEST(FunctionExpression, InitialCoordinates) {
  const FunctionExpression f("sqrt(X^2+Y^2)");
  EXPECT_DOUBLE_EQ(f.Evaluate(100, 100, 100, 100, 3.0, 4.0, 9.0), 5.0);
  EXPECT_TRUE(f.DependsOnSpace());
  EXPECT_FALSE(f.DependsOnTime());
  EXPECT_TRUE(FunctionExpression("Z").DependsOnSpace());
}

TEST(FunctionExpression, FunctionsAndConstants) {
  const FunctionExpression f(
      "sin(pi/2) + cos(0) + tan(0) + exp(1) - e + log(e) + abs(-2) + min(1, 2) + max(3, 4) + pow(2, 3)");
  EXPECT_NEAR(f.Evaluate(0, 0, 0, 0), 1 + 1 + 0 + 0 + 1 + 2 + 1 + 4 + 8, 1e-14);
  EXPECT_FALSE(f.DependsOnSpace());
  EXPECT_FALSE(f.DependsOnTime());
  EXPECT_DOUBLE_EQ(FunctionExpression("1.0e-3*t + 2e1").Evaluate(0, 0, 0, 1000.0), 21.0);
  EXPECT_DOUBLE_EQ(FunctionExpression("1.0 - 1.0*(t-10.0)/8.0").Evaluate(0, 0, 0, 14.0), 0.5);
}

TEST(FunctionExpression, MovedExpressionStillEvaluates) {
  FunctionExpression a("x*t");
  FunctionExpression b(std::move(a));
  EXPECT_DOUBLE_EQ(b.Evaluate(2.0, 0, 0, 3.0), 6.0);
  FunctionExpression c("0");
  c = std::move(b);
  EXPECT_DOUBLE_EQ(c.Evaluate(4.0, 0, 0, 0.25), 1.0);
}

TEST(FunctionExpression, MalformedExpressionIsInputErrorQuotingIt) {
  for (const std::string text : {"sin(t", "2*w", "t**", "x +* y", ""}) {
    try {
      FunctionExpression f(text);
      ADD_FAILURE() << "no error for \"" << text << "\"";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("\"" + text + "\""), std::string::npos) << e.what();
    }
  }
  try {
    FunctionExpression f("x**2 + (y");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    // The position refers to the text as written, before "**" became "^".
    EXPECT_NE(std::string(e.what()).find("position 9"), std::string::npos) << e.what();
  }
  try {
    FunctionExpression f("T*2");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown variable 'T' (did you mean 't'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mc
