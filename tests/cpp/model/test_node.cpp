// Issue 2: nodes carry historical data with a buffer, non-historical data, flags and DoFs.
#include <gtest/gtest.h>

#include "core/model/node.h"
#include "core/variables/kernel_variables.h"

namespace mc {

TEST(Node, HistoricalBufferShiftsOnClone) {
  VariablesList list;
  list.Add(DISPLACEMENT);
  list.Add(TEMPERATURE);
  Node node(7, Array3(1.0, 2.0, 3.0), list, 3);
  node.FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 2.0, 3.0);
  node.FastGetSolutionStepValue(TEMPERATURE) = 5.0;
  node.CloneSolutionStep();
  node.FastGetSolutionStepValue(DISPLACEMENT_Y) = 20.0;
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_Y, 1), 2.0);
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_Y, 0), 20.0);
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_X, 0), 1.0);
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(TEMPERATURE, 1), 5.0);
  node.CloneSolutionStep();
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_Y, 2), 2.0);
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_Y, 1), 20.0);
}

TEST(Node, CheckedAccessNamesNodeAndVariable) {
  VariablesList list;
  list.Add(DISPLACEMENT);
  Node node(42, Array3::Zero(), list, 1);
  try {
    node.GetSolutionStepValue(TEMPERATURE);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("node 42"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("TEMPERATURE"), std::string::npos);
  }
}

TEST(Node, DofsAndNonHistoricalValues) {
  VariablesList list;
  list.Add(DISPLACEMENT);
  list.Add(REACTION);
  Node node(1, Array3::Zero(), list, 2);
  Dof& dx = node.AddDof(DISPLACEMENT_X, &REACTION_X);
  EXPECT_EQ(&dx, &node.AddDof(DISPLACEMENT_X, &REACTION_X));
  node.Fix(DISPLACEMENT_X);
  EXPECT_TRUE(node.IsFixed(DISPLACEMENT_X));
  dx.Value() = 0.5;
  EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_X), 0.5);
  EXPECT_THROW(node.GetDof(DISPLACEMENT_Y), Error);
  EXPECT_THROW(node.AddDof(TEMPERATURE), Error);
  node.SetValue(NORMAL_Z, 1.0);
  EXPECT_DOUBLE_EQ(node.GetValue(NORMAL)[2], 1.0);
  EXPECT_DOUBLE_EQ(node.GetValue(NODAL_H), 0.0);
  node.Set(SLAVE);
  EXPECT_TRUE(node.Is(SLAVE));
  EXPECT_FALSE(node.Is(MASTER));
}

}  // namespace mc
