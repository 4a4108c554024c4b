// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (part 1): automatic ALM penalty and scale factor (thesis eq. 4.11, spec 4.4/4.5).
#include <gtest/gtest.h>

#include "contact_processes_test_utilities.h"
#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "custom_processes/alm_variables_calculation_process.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

ModelPart& Patch(Model& model) {
  ModelPart& root = test::ReadPatch2D(model);
  root.GetProperties(1).SetValue(YOUNG_MODULUS, 2.0e5);  // lower body, slave
  root.GetProperties(2).SetValue(YOUNG_MODULUS, 1.0e5);  // upper body, master
  return test::PatchInterface(root);
}

TEST(ALMVariables, SmallerSideOfEOverH) {
  Model model;
  ModelPart& sub = Patch(model);
  ModelPart& root = sub.GetRootModelPart();
  ALMVariablesCalculationProcess process(root, sub,
                                         Parameters(R"({"stiffness_factor": 2.0, "penalty_scale_factor": 3.0})"));
  process.Execute();
  // slave 2e5 / 1, master 1e5 / 0.999: the master is the less stiff side.
  const double value = 1.0e5 / 0.999;
  EXPECT_NEAR(process.Penalty(), 2.0 * value, 1e-6);
  EXPECT_NEAR(process.ScaleFactor(), 3.0 * 2.0 * value, 1e-6);
  EXPECT_DOUBLE_EQ(root.GetProcessInfo().GetValue(INITIAL_PENALTY), process.Penalty());
  EXPECT_DOUBLE_EQ(root.GetProcessInfo().GetValue(SCALE_FACTOR), process.ScaleFactor());
  EXPECT_DOUBLE_EQ(root.GetNode(3).GetValue(INITIAL_PENALTY), process.Penalty());
}

TEST(ALMVariables, PenaltyVariantAndFloors) {
  Model model;
  ModelPart& sub = Patch(model);
  ModelPart& root = sub.GetRootModelPart();
  ALMVariablesCalculationProcess penalty(root, sub, Parameters(R"({"use_scale_factor": false})"), 1e4, 1e16);
  penalty.Execute();
  EXPECT_NEAR(penalty.Penalty(), 1e4 * 1.0e5 / 0.999, 1e-2);
  EXPECT_EQ(penalty.ScaleFactor(), 1.0);
  // Without YOUNG_MODULUS the estimate is zero: the floors apply.
  root.GetProperties(1).SetValue(YOUNG_MODULUS, 0.0);
  root.GetProperties(2).SetValue(YOUNG_MODULUS, 0.0);
  ALMVariablesCalculationProcess floors(root, sub, Parameters("{}"), 1e4, 1e16);
  floors.Execute();
  EXPECT_EQ(floors.Penalty(), 1e16);
  EXPECT_EQ(floors.ScaleFactor(), 1.0);
  ALMVariablesCalculationProcess alm(root, sub, Parameters("{}"));
  alm.Execute();
  EXPECT_EQ(alm.Penalty(), 1.0);
}

}  // namespace
}  // namespace mc
