// SPDX-License-Identifier: BSD-3-Clause
// Small builders shared by the mortar tests.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <initializer_list>

#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc::mortar_test {

/// Rows from a flat list of coordinates.
template <class TMatrix>
TMatrix Rows(std::initializer_list<double> values) {
  TMatrix m;
  auto it = values.begin();
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) m(i, j) = *it++;
  return m;
}

/// Every slave node gets the geometric unit normal of the slave condition (flat interfaces).
template <class K>
typename K::SlaveMatrix ConditionNormals(const typename K::SlaveMatrix& x1) {
  using Exact = ExactMortarIntegrationUtility<K::kDim, K::kNumSlaveNodes, K::kNumMasterNodes>;
  const Eigen::Matrix<double, K::kDim, 1> n = Exact::template SlaveConditionNormal<double>(x1);
  typename K::SlaveMatrix normals;
  for (int i = 0; i < K::kNumSlaveNodes; ++i) normals.row(i) = n.transpose();
  return normals;
}

inline MortarIntegrationSettings Order(int order) {
  MortarIntegrationSettings s;
  s.integration_order = order;
  return s;
}

}  // namespace mc::mortar_test
