// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

namespace mc {

/// A scalar expression of x, y, z (current coordinates), X, Y, Z (initial coordinates) and t,
/// as written in Kratos settings ("-0.15*t", "sqrt(x**2+y**2)*sin(t)"), compiled once by a
/// real expression parser (muparser) and evaluated many times. Never Python's eval.
/// Not thread-safe: use one instance per thread.
class FunctionExpression {
 public:
  /// Throws InputError quoting the expression and the position of the mistake.
  explicit FunctionExpression(const std::string& expression);
  ~FunctionExpression();
  FunctionExpression(FunctionExpression&&) noexcept;
  FunctionExpression& operator=(FunctionExpression&&) noexcept;

  double Evaluate(double x, double y, double z, double t, double X = 0.0, double Y = 0.0, double Z = 0.0) const;
  bool DependsOnSpace() const noexcept;
  bool DependsOnTime() const noexcept;
  const std::string& Text() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc
