// Issue 2: model parts nest, share nodes with their ancestors and resolve dotted names.
#include <gtest/gtest.h>

#include <vector>

#include "core/model/model.h"
#include "core/variables/kernel_variables.h"

namespace mc {

TEST(ModelPart, SubModelPartsShareEntitiesWithAncestors) {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure", 2);
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  ModelPart& contact = root.CreateSubModelPart("Contact");
  ModelPart& sub = contact.CreateSubModelPart("ContactSub0");
  sub.CreateNewNode(3, 0.0, 1.0, 0.0);
  root.CreateNewNode(1, 0.0, 0.0, 0.0);
  contact.AddNodes({1});
  EXPECT_EQ(root.NumberOfNodes(), 2u);
  EXPECT_EQ(contact.NumberOfNodes(), 2u);
  EXPECT_EQ(sub.NumberOfNodes(), 1u);
  EXPECT_EQ(sub.FullName(), "Structure.Contact.ContactSub0");
  EXPECT_EQ(&model.GetModelPart("Structure.Contact.ContactSub0"), &sub);
  EXPECT_EQ(root.Nodes()[0]->Id(), 1u);
  EXPECT_EQ(sub.GetNode(3).GetSolutionStepValue(DISPLACEMENT).size(), 3);
  EXPECT_THROW(contact.AddNodes({99}), InputError);
}

// Adding to a sub model part also adds to the root, which then needs sorting before its next
// lookup: one lookup per addition made AddNodes quadratic (minutes for 100k ids, seconds here).
TEST(ModelPart, AddingManyIdsToASubModelPartIsLinear) {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  constexpr IndexType kCount = 100000;
  std::vector<IndexType> ids;
  for (IndexType id = 1; id <= kCount; ++id) {
    root.CreateNewNode(id, static_cast<double>(id), 0.0, 0.0);
    ids.push_back(id);
  }
  ModelPart& part = root.CreateSubModelPart("All");
  part.AddNodes(ids);
  EXPECT_EQ(part.NumberOfNodes(), kCount);
  EXPECT_EQ(root.NumberOfNodes(), kCount);
  EXPECT_EQ(part.GetNode(kCount / 2).Id(), kCount / 2);
}

TEST(ModelPart, UnknownSubModelPartSuggestsNearest) {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  root.CreateSubModelPart("Contact_Part");
  try {
    model.GetModelPart("Structure.Contact_Prt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Contact_Part"), std::string::npos) << e.what();
  }
}

TEST(ModelPart, VariablesAreLockedOnceNodesExist) {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  root.CreateNewNode(1, 0.0, 0.0, 0.0);
  EXPECT_THROW(root.AddNodalSolutionStepVariable(TEMPERATURE), Error);
  EXPECT_NO_THROW(root.AddNodalSolutionStepVariable(DISPLACEMENT_X));
}

TEST(ModelPart, CloneTimeStepAdvancesTime) {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure", 2);
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  Node& n = root.CreateNewNode(1, 0.0, 0.0, 0.0);
  n.FastGetSolutionStepValue(DISPLACEMENT_X) = 1.0;
  root.CloneTimeStep(0.5);
  EXPECT_DOUBLE_EQ(root.GetProcessInfo().GetValue(TIME), 0.5);
  EXPECT_DOUBLE_EQ(root.GetProcessInfo().GetValue(DELTA_TIME), 0.5);
  EXPECT_EQ(root.GetProcessInfo().GetValue(STEP), 1);
  EXPECT_DOUBLE_EQ(n.FastGetSolutionStepValue(DISPLACEMENT_X, 1), 1.0);
}

}  // namespace mc
