// SPDX-License-Identifier: BSD-3-Clause
#include "contact_processes_test_utilities.h"

#include "core/io/mdpa_reader.h"
#include "core/model/registry.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_processes/contact_interface_builder.h"
#include "structural/application/register_structural_mechanics.h"

namespace mc::test {

std::unique_ptr<Condition> TestPairCondition::Create(IndexType id, Geometry::NodesArray nodes,
                                                     Properties* properties) const {
  return std::make_unique<TestPairCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties,
                                             GetPairedGeometry());
}

std::unique_ptr<PairedCondition> TestPairCondition::CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                                 Properties* properties) const {
  auto pair = std::make_unique<TestPairCondition>(id, slave.GetGeometry(), properties, master.GetGeometry());
  pair->SetPair(&slave, &master);
  return pair;
}

void RegisterTestPairs() {
  RegisterStructuralMechanics();
  using GT = GeometryType;
  const struct {
    const char* token;
    GT slave, master;
  } kinds[] = {{"2D2N", GT::Line2D2, GT::Line2D2},
               {"3D3N", GT::Triangle3D3, GT::Triangle3D3},
               {"3D4N", GT::Quadrilateral3D4, GT::Quadrilateral3D4},
               {"3D3N4N", GT::Triangle3D3, GT::Quadrilateral3D4},
               {"3D4N3N", GT::Quadrilateral3D4, GT::Triangle3D3}};
  for (const char* stem : {"ALMFrictionlessMortarContactCondition", "PenaltyFrictionlessMortarContactCondition"})
    for (const auto& kind : kinds)
      Registry<Condition>::Instance().Add(
          std::string(stem) + kind.token,
          std::make_shared<const TestPairCondition>(0, Geometry(kind.slave, {}), nullptr, Geometry(kind.master, {})));
}

std::string CasesDir() { return std::string(MC_TEST_CASES_DIR) + "/kratos_csma"; }

ModelPart& ReadCase(Model& model, const std::string& relative_mdpa) {
  RegisterTestPairs();
  ModelPart& root = model.CreateModelPart("Structure", 2);
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  root.AddNodalSolutionStepVariable(NORMAL);
  root.AddNodalSolutionStepVariable(NODAL_H);
  MdpaReader(CasesDir() + "/" + relative_mdpa).ReadModelPart(root);
  return root;
}

ModelPart& BuildInterface(ModelPart& root, std::vector<std::string> parts, std::vector<std::string> slave_parts) {
  ContactInterfaceSettings settings;
  settings.parts = std::move(parts);
  settings.slave_parts = std::move(slave_parts);
  return ContactInterfaceBuilder(root).Build(settings);
}

ModelPart& ReadPatch2D(Model& model) {
  return ReadCase(model, "ALM_frictionless_contact_test_2D/hyper_simple_patch_test.mdpa");
}

ModelPart& PatchInterface(ModelPart& root) { return BuildInterface(root, {"Contact_Part"}, {"Parts_Parts_Auto2"}); }

WarningCapture::WarningCapture() {
  Logger::SetSink([this](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) messages_.push_back(message);
  });
}

WarningCapture::~WarningCapture() { Logger::ResetSink(); }

}  // namespace mc::test
