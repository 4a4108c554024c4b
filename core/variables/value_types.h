// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>

namespace mc {

using IndexType = std::size_t;
using Array3 = Eigen::Vector3d;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

/// The value types a variable may carry.
enum class ValueType { Double, Int, Bool, String, Array3, Vector, Matrix };

const char* ValueTypeName(ValueType type);

template <class T>
struct ValueTypeOf;
template <>
struct ValueTypeOf<double> {
  static constexpr ValueType value = ValueType::Double;
};
template <>
struct ValueTypeOf<int> {
  static constexpr ValueType value = ValueType::Int;
};
template <>
struct ValueTypeOf<bool> {
  static constexpr ValueType value = ValueType::Bool;
};
template <>
struct ValueTypeOf<std::string> {
  static constexpr ValueType value = ValueType::String;
};
template <>
struct ValueTypeOf<Array3> {
  static constexpr ValueType value = ValueType::Array3;
};
template <>
struct ValueTypeOf<Vector> {
  static constexpr ValueType value = ValueType::Vector;
};
template <>
struct ValueTypeOf<Matrix> {
  static constexpr ValueType value = ValueType::Matrix;
};

}  // namespace mc
