// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mc {

/// A piecewise-linear function y(x) given by sorted points; constant beyond its ends.
class Table {
 public:
  Table() = default;
  Table(std::string input_variable, std::string output_variable)
      : input_(std::move(input_variable)), output_(std::move(output_variable)) {}

  /// Points must be added with increasing x.
  void PushBack(double x, double y);
  double GetValue(double x) const;
  /// Derivative dy/dx of the segment holding x (0 outside the range).
  double GetDerivative(double x) const;
  const std::vector<std::pair<double, double>>& Data() const noexcept { return data_; }
  const std::string& InputVariable() const noexcept { return input_; }
  const std::string& OutputVariable() const noexcept { return output_; }
  void SetVariables(std::string input, std::string output) {
    input_ = std::move(input);
    output_ = std::move(output);
  }

 private:
  std::string input_;
  std::string output_;
  std::vector<std::pair<double, double>> data_;
};

}  // namespace mc
