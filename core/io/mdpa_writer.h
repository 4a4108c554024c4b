// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/io/mdpa_reader.h"

namespace mc {

class ModelPart;

/// Writes a model part as a Kratos .mdpa file that MdpaReader reads back into the same model:
/// ModelPartData (the ProcessInfo values), properties with values and tables, tables, nodes at
/// their initial coordinates, elements and conditions under their registered names, nodal,
/// elemental and conditional data, and the nested sub-model-parts.
///
/// Nodal data: historical doubles and Array3 components are written where non-zero or fixed
/// (fixity flag 1 for a fixed DoF or a pending FixityRequest); non-historical values of
/// variables that are not also historical are written in full. A non-historical value of a
/// variable that is also historical cannot be told apart in the format and is skipped with a
/// warning.
///
/// The file is written under a temporary name and renamed at the end, so a failure never
/// leaves a half-written file behind.
class MdpaWriter {
 public:
  explicit MdpaWriter(std::string filename) : filename_(std::move(filename)) {}

  void Write(const ModelPart& model_part, const std::vector<FixityRequest>& pending_fixities = {}) const;

 private:
  std::string filename_;
};

}  // namespace mc
