// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "core/geometries/geometry.h"

namespace mc {

/// The current coordinates of a slave and a master face as the mortar segmentation takes them:
/// row i of x1 (x2) is node i of the slave (master), its first TDim coordinates.
template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarPairCoordinates(const Geometry& slave, const Geometry& master, Eigen::Matrix<double, TNumNodes, TDim>& x1,
                           Eigen::Matrix<double, TNumNodesMaster, TDim>& x2) {
  for (int i = 0; i < TNumNodes; ++i) x1.row(i) = slave[i].Coordinates().template head<TDim>().transpose();
  for (int l = 0; l < TNumNodesMaster; ++l) x2.row(l) = master[l].Coordinates().template head<TDim>().transpose();
}

}  // namespace mc
