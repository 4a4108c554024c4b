// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/io/mdpa_mesh.h"
#include "core/variables/variable.h"

namespace mc {

class ModelPart;
class Node;

struct MdpaReaderOptions {
  /// Kratos' `ignore_variables_not_in_solution_step_data`: when true, data blocks naming a
  /// variable that is not registered are skipped with a warning instead of being an error.
  bool ignore_variables_not_in_solution_step_data = false;
  /// A distributed run's filtered read (issue 17): only these nodes, elements and conditions are
  /// built; every line is read and checked as without it, so every rank stops at the same bad
  /// line with the same message. Data of entities not kept is read and dropped.
  const MdpaMesh::Piece* piece = nullptr;
};

/// A `Begin NodalData VAR` line with fixity flag 1. Nodes get their DoFs only when the solver
/// calls AddDofs, after reading, so the reader records the request and the solver applies it
/// afterwards with MdpaReader::ApplyFixityRequests. The node is owned by the model part read.
struct FixityRequest {
  Node* node;
  const Variable<double>* variable;
};

/// Reads a Kratos .mdpa file into a model part (usually an empty root):
///   ModelPartData (into the ProcessInfo), Properties (values and tables), Table, Nodes,
///   Elements <Name>, Conditions <Name> (created through the registries), NodalData,
///   ElementalData, ConditionalData and nested SubModelPart blocks.
/// NodalData values go to the historical data when the variable (or, for a component, its
/// source) is in the solution-step variables, else to the node's non-historical data.
/// SubModelPartData is checked but not stored (model parts have no data container of their own;
/// a warning says so).
/// Every error is an InputError "<file>:<line>: <what was expected>, got '<text>'".
class MdpaReader {
 public:
  explicit MdpaReader(std::string filename, MdpaReaderOptions options = {});

  /// Reads the whole file (one read, parsed in place) into `model_part`.
  void ReadModelPart(ModelPart& model_part);
  /// Reads mdpa text; errors quote the file name given to the constructor.
  void ReadModelPartFromText(std::string_view text, ModelPart& model_part);

  /// Fixity requests of the NodalData blocks read so far, in file order.
  const std::vector<FixityRequest>& FixityRequests() const noexcept { return fixities_; }
  /// Fixes the requested DoFs that exist; returns how many requests found no DoF.
  static std::size_t ApplyFixityRequests(const std::vector<FixityRequest>& requests);

 private:
  std::string filename_;
  MdpaReaderOptions options_;
  std::vector<FixityRequest> fixities_;
};

}  // namespace mc
