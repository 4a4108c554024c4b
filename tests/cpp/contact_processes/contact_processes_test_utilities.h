// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the contact search tests: a registered stand-in pair condition and model set-up.
#pragma once

#include <string>
#include <vector>

#include "core/model/model.h"
#include "custom_conditions/paired_condition.h"

namespace mc::test {

/// Minimal PairedCondition registered under the ALM frictionless names the search creates.
class TestPairCondition : public PairedCondition {
 public:
  using PairedCondition::PairedCondition;
  std::string Info() const override { return "TestPairCondition"; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo&) const override { dofs.clear(); }
};

/// Registers TestPairCondition as "ALMFrictionlessMortarContactCondition" + 2D2N, 3D3N, 3D4N,
/// 3D3N4N, 3D4N3N (and the Penalty names), and the structural classes.
void RegisterTestPairs();

std::string CasesDir();

/// A root "Structure" with NORMAL, NODAL_H and DISPLACEMENT, read from a shared case mdpa.
ModelPart& ReadCase(Model& model, const std::string& relative_mdpa);

/// The contact interface of `parts` under `root`, `slave_parts` their slave side (automatic
/// roles when empty), the other settings at their defaults.
ModelPart& BuildInterface(ModelPart& root, std::vector<std::string> parts, std::vector<std::string> slave_parts = {});

/// The shared 2D patch case (hyper_simple_patch_test.mdpa: two unit squares, the upper one
/// 0.001 above the lower one).
ModelPart& ReadPatch2D(Model& model);
/// Its interface: Contact_Part, the lower body's face (Parts_Parts_Auto2) the slave side.
ModelPart& PatchInterface(ModelPart& root);

/// Captures Logger warnings while alive.
class WarningCapture {
 public:
  WarningCapture();
  ~WarningCapture();
  const std::vector<std::string>& Messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

}  // namespace mc::test
