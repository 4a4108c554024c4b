// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (part 1): contact interface set-up — Contact/ContactSub<k> parts, INTERFACE/SLAVE/
// MASTER flags, interface conditions generated from element faces with outward normals, the
// interface property, NODAL_H, averaged nodal normals and the normal checks.
#include <gtest/gtest.h>

#include <set>

#include "contact_processes_test_utilities.h"
#include "core/model/model.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_utilities/normal_calculation_utilities.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

std::set<IndexType> FlaggedNodes(const ModelPart& part, const Flag& flag) {
  std::set<IndexType> ids;
  for (const Node* node : part.Nodes())
    if (node->Is(flag)) ids.insert(node->Id());
  return ids;
}

double NodalH(const ModelPart& part, IndexType id) { return part.GetNode(id).FastGetSolutionStepValue(NODAL_H); }

TEST(ContactInterface, Patch2DGeneratesOutwardFacesAndFlags) {
  Model model;
  ModelPart& root = test::ReadPatch2D(model);
  ModelPart& sub = test::PatchInterface(root);

  EXPECT_EQ(sub.FullName(), "Structure.Contact.ContactSub0");
  EXPECT_TRUE(root.HasSubModelPart("ComputingContact.ComputingContactSub0"));
  EXPECT_EQ(sub.NumberOfNodes(), 4u);
  ASSERT_EQ(sub.NumberOfConditions(), 2u);
  EXPECT_EQ(FlaggedNodes(sub, SLAVE), (std::set<IndexType>{3, 4}));
  EXPECT_EQ(FlaggedNodes(sub, MASTER), (std::set<IndexType>{5, 6}));
  EXPECT_EQ(FlaggedNodes(sub, INTERFACE), (std::set<IndexType>{3, 4, 5, 6}));
  for (const Condition* condition : sub.Conditions()) {
    EXPECT_EQ(condition->Info(), "LineCondition2D2N");
    EXPECT_TRUE(condition->Is(INTERFACE));
    const Array3 n = condition->GetValue(NORMAL);
    // Lower body (slave) top face points up, upper body (master) bottom face points down.
    if (condition->Is(SLAVE)) {
      EXPECT_NEAR((n - Array3(0, 1, 0)).norm(), 0.0, 1e-14);
      EXPECT_EQ(condition->GetGeometry()[0].Id(), 3u);  // element 1 order 1-2-3-4: edge 3-4
    } else {
      EXPECT_TRUE(condition->Is(MASTER));
      EXPECT_NEAR((n - Array3(0, -1, 0)).norm(), 0.0, 1e-14);
    }
    EXPECT_EQ(condition->pGetProperties()->Id(), 100u);
  }
  for (IndexType id : {3, 4})
    EXPECT_NEAR((NormalCalculationUtilities::GetNodalNormal(root.GetNode(id)) - Array3(0, 1, 0)).norm(), 0.0, 1e-14);
  for (IndexType id : {5, 6})
    EXPECT_NEAR((NormalCalculationUtilities::GetNodalNormal(root.GetNode(id)) - Array3(0, -1, 0)).norm(), 0.0, 1e-14);
  // Lower square of side 1; upper element 1 x 0.999 (from y = 1.001 to 2).
  EXPECT_DOUBLE_EQ(NodalH(root, 3), 1.0);
  EXPECT_DOUBLE_EQ(NodalH(root, 4), 1.0);
  EXPECT_NEAR(NodalH(root, 5), 0.999, 1e-12);
  EXPECT_NEAR(NodalH(root, 6), 0.999, 1e-12);
  EXPECT_TRUE(root.GetProperties(100).Has(FRICTION_COEFFICIENT));
  EXPECT_EQ(root.GetProperties(100).GetValue(FRICTION_COEFFICIENT), 0.0);
  // Rebuilding reuses the existing interface.
  EXPECT_EQ(&test::PatchInterface(root), &sub);
  EXPECT_EQ(sub.NumberOfConditions(), 2u);
}

TEST(ContactInterface, Patch3DAutomaticRolesAndNormals) {
  Model model;
  ModelPart& root =
      test::ReadCase(model, "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test.mdpa");
  ContactInterfaceSettings settings;
  settings.parts = {"Structure.Contact_Part"};
  settings.property_id = 7;
  settings.friction_coefficient = 0.3;
  ModelPart& sub = ContactInterfaceBuilder(root).Build(settings);
  EXPECT_EQ(sub.NumberOfNodes(), 8u);
  ASSERT_EQ(sub.NumberOfConditions(), 2u);
  for (const Condition* condition : sub.Conditions()) {
    EXPECT_EQ(condition->Info(), "SurfaceCondition3D4N");
    EXPECT_TRUE(condition->Is(SLAVE) && condition->Is(MASTER));  // the search decides
    const Array3 n = condition->GetValue(NORMAL);
    const double z = condition->GetGeometry().Center().z();
    // Lower block top (z = 1) points up, upper block bottom (z = 0.99999) points down.
    EXPECT_NEAR((n - Array3(0, 0, z > 0.999995 ? 1.0 : -1.0)).norm(), 0.0, 1e-14);
    EXPECT_EQ(condition->pGetProperties()->Id(), 7u);
  }
  EXPECT_EQ(root.GetProperties(7).GetValue(FRICTION_COEFFICIENT), 0.3);
  for (const Node* node : sub.Nodes()) {
    EXPECT_EQ(node->GetValue(FRICTION_COEFFICIENT), 0.3);  // what the frictional conditions read
    const double expected = node->Z() > 0.999995 ? 1.0 : -1.0;
    EXPECT_NEAR((NormalCalculationUtilities::GetNodalNormal(*node) - Array3(0, 0, expected)).norm(), 0.0, 1e-14);
    EXPECT_DOUBLE_EQ(node->FastGetSolutionStepValue(NODAL_H), 1.0);
  }
}

TEST(ContactInterface, FrictionCoefficientOfTheMaterialsWinsOverTheProcessOne) {
  // As materials.json does: the bodies' property carries FRICTION_COEFFICIENT; the new interface
  // property copies it and friction_coefficients[k] is only the fallback (spec 4.1).
  Model model;
  ModelPart& root = test::ReadPatch2D(model);
  for (Element* element : root.Elements()) element->GetProperties().SetValue(FRICTION_COEFFICIENT, 0.01);
  ContactInterfaceSettings settings;
  settings.parts = {"Contact_Part"};
  settings.slave_parts = {"Parts_Parts_Auto2"};
  settings.friction_coefficient = 0.5;
  ModelPart& sub = ContactInterfaceBuilder(root).Build(settings);
  EXPECT_EQ(root.GetProperties(100).GetValue(FRICTION_COEFFICIENT), 0.01);
  ASSERT_EQ(sub.NumberOfNodes(), 4u);
  for (const Node* node : sub.Nodes()) EXPECT_EQ(node->GetValue(FRICTION_COEFFICIENT), 0.01);
}

TEST(ContactInterface, TriQuadFacesOfTetrahedraAndHexahedron) {
  Model model;
  ModelPart& root =
      test::ReadCase(model, "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_triquad_test.mdpa");
  ModelPart& sub = test::BuildInterface(root, {"DISPLACEMENT_Displacement_Auto3"}, {"Parts_Parts_Auto2"});
  std::size_t triangles = 0, quads = 0;
  double slave_area = 0.0, master_area = 0.0;
  for (const Condition* condition : sub.Conditions()) {
    const Array3 n = condition->GetValue(NORMAL);
    if (condition->Is(SLAVE)) {
      ++triangles;
      EXPECT_EQ(condition->Info(), "SurfaceCondition3D3N");
      slave_area += condition->GetGeometry().DomainSize();
    } else {
      ++quads;
      EXPECT_EQ(condition->Info(), "SurfaceCondition3D4N");
      master_area += condition->GetGeometry().DomainSize();
    }
    // Every slave normal is opposite to every master normal on this flat interface.
    EXPECT_NEAR(std::abs(n.z()), 1.0, 1e-12);
  }
  EXPECT_EQ(quads, 1u);
  EXPECT_GT(triangles, 1u);
  EXPECT_NEAR(slave_area, master_area, 1e-9);
  for (const Condition* condition : sub.Conditions())
    for (const Condition* other : sub.Conditions())
      if (condition->Is(SLAVE) && other->Is(MASTER)) {
        EXPECT_NEAR(condition->GetValue(NORMAL).dot(other->GetValue(NORMAL)), -1.0, 1e-12);
      }
}

TEST(ContactInterface, UnknownPartSuggestsNearestName) {
  Model model;
  ModelPart& root = test::ReadPatch2D(model);
  const std::string message = test::ErrorMessageOf([&] { test::BuildInterface(root, {"Contact_Prt"}); });
  EXPECT_NE(message.find("Contact_Part"), std::string::npos) << message;
}

TEST(ContactInterface, InvertedMdpaConditionIsFlippedWithAWarning) {
  Model model;
  ModelPart& root = test::ReadPatch2D(model);
  ModelPart& part = root.CreateSubModelPart("Given");
  Condition& inverted =
      part.CreateNewCondition("LineCondition2D2N", 1, {4, 3}, &root.GetOrCreateProperties(0));  // into element 1
  part.CreateNewCondition("LineCondition2D2N", 2, {5, 6}, &root.GetOrCreateProperties(0));
  std::vector<std::string> warnings;
  ModelPart* sub = nullptr;
  {
    test::WarningCapture capture;
    sub = &test::BuildInterface(root, {"Given"}, {"Parts_Parts_Auto2"});
    warnings = capture.Messages();
  }
  EXPECT_EQ(inverted.GetGeometry()[0].Id(), 3u);
  EXPECT_EQ(inverted.GetGeometry()[1].Id(), 4u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("condition 1 (nodes 4 3) points into element 1; now nodes 3 4"), std::string::npos)
      << warnings[0];
  // The flipped face's normal leaves its element, as the generated face 3-4 of the same side would.
  const Array3 n = inverted.GetValue(NORMAL);
  const Array3 nodal = sub->GetNode(3).FastGetSolutionStepValue(NORMAL);
  EXPECT_GT(n.dot(nodal), 0.99) << n.transpose() << " / " << nodal.transpose();
}

TEST(ContactInterface, NormalCheckProportionZeroKeepsTheFacesAsGiven) {
  Model model;
  ModelPart& root = test::ReadPatch2D(model);
  ModelPart& part = root.CreateSubModelPart("Given");
  Condition& inverted = part.CreateNewCondition("LineCondition2D2N", 1, {4, 3}, &root.GetOrCreateProperties(0));
  part.CreateNewCondition("LineCondition2D2N", 2, {5, 6}, &root.GetOrCreateProperties(0));
  ContactInterfaceSettings settings;
  settings.parts = {"Given"};
  settings.slave_parts = {"Parts_Parts_Auto2"};
  settings.normal_check_proportion = 0.0;
  // Not flipped, the face then meets the check that the two sides face each other.
  const std::string message = test::ErrorMessageOf([&] { ContactInterfaceBuilder(root).Build(settings); });
  EXPECT_NE(message.find("slave condition 1 (nodes 4 3)"), std::string::npos) << message;
  EXPECT_EQ(inverted.GetGeometry()[0].Id(), 4u);
}

TEST(ContactInterface, SidesNormalsPointingTheSameWayIsAnError) {
  // Two surfaces without elements, both oriented downwards.
  test::RegisterTestPairs();
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  root.CreateNewNode(1, 0, 0, 0);
  root.CreateNewNode(2, 1, 0, 0);
  root.CreateNewNode(3, 0, 0.001, 0);
  root.CreateNewNode(4, 1, 0.001, 0);
  ModelPart& lower = root.CreateSubModelPart("Lower");
  ModelPart& upper = root.CreateSubModelPart("Upper");
  lower.CreateNewCondition("LineCondition2D2N", 1, {1, 2}, &root.GetOrCreateProperties(0));
  upper.CreateNewCondition("LineCondition2D2N", 2, {3, 4}, &root.GetOrCreateProperties(0));
  const std::string message = test::ErrorMessageOf([&] { test::BuildInterface(root, {"Lower", "Upper"}, {"Lower"}); });
  EXPECT_NE(message.find("pointing the same way"), std::string::npos) << message;
  EXPECT_NE(message.find("slave condition 1 (nodes 1 2)"), std::string::npos) << message;
  EXPECT_NE(message.find("Lower"), std::string::npos) << message;
}

}  // namespace
}  // namespace mc
