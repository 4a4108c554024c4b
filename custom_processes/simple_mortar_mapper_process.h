// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "core/model/model_part.h"
#include "core/parameters/parameters.h"

namespace mc {

/// Mortar mapping of a nodal variable (a scalar, or each component of an array variable) between two
/// non-matching surfaces (lines in 2D), Kratos' SimpleMortarMapperProcess with its settings
/// (GetDefaultParameters). The surfaces are the conditions of the two model parts, or their elements
/// (membranes) when a part has no conditions or `*_are_conditions` is false; linear faces only
/// (Line2D2, Triangle3D3, Quadrilateral3D4, mixed triangle / quadrilateral pairs).
///
/// With the destination as the mortar (slave) side, the mortar operators of every overlapping
/// (destination face, origin face) pair (MortarPairKinematics: exact segmentation / clipping, the
/// pair's dual basis) are summed into D (diagonal) and M, and the destination values are
///   consistent, inverse_of_d true (default):  u_d = c D^-1 M u_o   (a field: linear fields are
///                                             mapped exactly on a flat interface)
///   consistent, inverse_of_d false:          g_d = c M u_o        (the field weighted by the dual
///                                             basis, int Phi_j u_o: e.g. a traction as nodal forces)
/// with c = mapping_coefficient. The conservative mapping (our key `conservative`) transfers
/// integrated quantities (nodal forces) with the transpose of the consistent mapping the other way,
/// the origin being the mortar side:
///   conservative, inverse_of_d true:   f_d = c M_od^T D_o^-1 f_o   (sum f_d = sum f_o when the
///                                       destination covers the origin, and f_d . u_d = f_o . u_o
///                                       for every field u_d that the consistent map takes exactly)
///   conservative, inverse_of_d false:  f_d = c M_od^T f_o          (f_o a multiplier-like nodal
///                                       traction, as the master forces of the contact conditions)
/// Nodes of the destination that no overlap reaches keep their values.
///
/// Differences from Kratos, by design: the dual basis makes D diagonal, so the mapping is exact in
/// one pass instead of Kratos' fixed-point iterations on the standard-basis D (its convergence
/// tolerances and max_number_iterations have no effect here and warn when given); the pairs come
/// from a brute-force bounding-ball test (search_factor times the larger face size between the face
/// centres, exact clipping deciding), quadratic in the number of faces: meant for interfaces of a
/// few thousand faces, not for contact searches.
class SimpleMortarMapperProcess {
 public:
  SimpleMortarMapperProcess(ModelPart& origin, ModelPart& destination, Parameters settings);
  /// Kratos' keys and defaults, plus ours: "conservative" (false) and "inverse_of_d" (true).
  static Parameters GetDefaultParameters();

  /// Maps the current values (pairs searched again when update_interface, else once).
  void Execute();

  /// Pairs with an overlap in the last Execute, and destination nodes they reached.
  std::size_t NumberOfPairs() const noexcept { return pairs_; }
  std::size_t NumberOfMappedNodes() const noexcept { return mapped_nodes_; }

 private:
  struct Operators;
  void CheckSettings() const;
  void BuildOperators();

  ModelPart& origin_;
  ModelPart& destination_;
  Parameters settings_;
  std::string origin_variable_;
  std::string destination_variable_;
  bool built_ = false;
  std::size_t pairs_ = 0;
  std::size_t mapped_nodes_ = 0;
  std::shared_ptr<Operators> operators_;  // an incomplete type here (Eigen's sparse matrices stay in the .cpp)
};

}  // namespace mc
