// SPDX-License-Identifier: BSD-3-Clause
// Issue 10 (output parity): the contact results of the slave nodes at the end of a step, on
// hand-made nodes: tractions only where active, force = traction x area x normal, the converged
// gap, and the augmented pressure of open nodes cleared only when asked.
#include <gtest/gtest.h>

#include "core/model/model.h"
#include "custom_utilities/contact_output_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

struct Interface {
  Model model;
  ModelPart& contact = model.CreateModelPart("Structure", 2).CreateSubModelPart("Contact");
  Interface() {
    ModelPart& root = contact.GetRootModelPart();
    root.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    root.AddNodalSolutionStepVariable(NORMAL);
    // An ALM interface: the traction is the augmented pressure (penalty: the applied force, from
    // the pairs; tests/python/test_contact_pressure_output.py).
    root.AddNodalSolutionStepVariable(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
    // 1: active, pressed; 2: open (eps g > 0); 3: master; 4: slave outside every overlap.
    const double augmented[] = {-30.0, 4.0, 0.0, 0.0};
    const double gaps[] = {-1e-9, 0.02, 0.0, 0.0};
    const double areas[] = {0.5, 0.25, 0.0, 0.0};
    for (IndexType id = 1; id <= 4; ++id) {
      Node& node = contact.CreateNewNode(id, double(id), 0.0, 0.0);
      node.Set(SLAVE, id != 3);
      node.Set(MASTER, id == 3);
      node.Set(ACTIVE, id == 1);
      node.Set(ISOLATED, id == 4);
      node.FastGetSolutionStepValue(NORMAL) = Array3(0.0, -1.0, 0.0);
      node.FastGetSolutionStepValue(WEIGHTED_GAP) = gaps[id - 1];
      node.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented[id - 1]);
      if (id != 3) node.SetValue(NODAL_AREA, areas[id - 1]);
      node.SetValue(NORMAL_GAP, 7.0);  // what the search measured before the step
    }
  }
  Node& N(IndexType id) { return contact.GetNode(id); }
};

TEST(ContactOutputs, TractionsForcesAndGapsOfTheSlaveNodes) {
  Interface s;
  EXPECT_EQ(ComputeContactOutputs(s.contact, true), 3u);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(NORMAL_CONTACT_STRESS), -30.0);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(CONTACT_PRESSURE), 30.0);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(TANGENTIAL_CONTACT_STRESS), 0.0);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(CONTACT_FORCE)[1], 15.0);  // -30 x 0.5 x (-1)
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(NORMAL_GAP), -2e-9);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -30.0);
  // Open: no traction, eps g cleared, the converged gap 0.02 / 0.25.
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(NORMAL_CONTACT_STRESS), 0.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(CONTACT_PRESSURE), 0.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(CONTACT_FORCE).norm(), 0.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 0.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(NORMAL_GAP), 0.08);
  // Master: untouched. Isolated slave: no mortar area, the search's gap stays.
  EXPECT_FALSE(s.N(3).Has(NORMAL_CONTACT_STRESS));
  EXPECT_DOUBLE_EQ(s.N(3).GetValue(NORMAL_GAP), 7.0);
  EXPECT_DOUBLE_EQ(s.N(4).GetValue(NORMAL_GAP), 7.0);
  EXPECT_DOUBLE_EQ(s.N(4).GetValue(CONTACT_PRESSURE), 0.0);
}

TEST(ContactOutputs, OpenNodesKeepTheirAugmentedPressureWhenNotCleared) {
  Interface s;
  ComputeContactOutputs(s.contact, false);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 4.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(CONTACT_PRESSURE), 0.0);
}

TEST(ContactOutputs, TangentialStressIsTheAugmentedTangentPressureOfActiveNodes) {
  // Issue 12: frictional runs store the augmented tangent pressure (stress units) per node.
  Interface s;
  s.N(1).SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(3.0, 0.0, -4.0));
  s.N(2).SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(1.0, 0.0, 0.0));
  ComputeContactOutputs(s.contact, true);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(TANGENTIAL_CONTACT_STRESS), 5.0);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE).norm(), 5.0);
  // Open: no traction, and the tangent indicator cleared like the normal one.
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(TANGENTIAL_CONTACT_STRESS), 0.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE).norm(), 0.0);
  s.N(2).SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(1.0, 0.0, 0.0));
  ComputeContactOutputs(s.contact, false);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE)[0], 1.0);
}

}  // namespace
}  // namespace mc
