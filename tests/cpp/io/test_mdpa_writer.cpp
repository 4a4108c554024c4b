// Issue: mdpa output (MdpaWriter). read -> write -> read gives the same model for a file with
// every block type and for every Kratos case mesh; fixities survive; a failed write leaves
// the previous file untouched and no temporary behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/io/mdpa_reader.h"
#include "core/io/mdpa_writer.h"
#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "io_test_utilities.h"

namespace mc {
namespace {

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("mc_test_io_" + name)).string();
}

const std::string kExample =
    "Begin ModelPartData\n  DOMAIN_SIZE 3\n  TIME 0.125\nEnd ModelPartData\n"
    "Begin Properties 2\n  YOUNG_MODULUS 0.1\n  VOLUME_ACCELERATION [3](0,0,-9.81)\n"
    "  PK2_STRESS_TENSOR [2,3]((1,2,3),(4,5,6))\n  Begin Table TEMPERATURE YOUNG_MODULUS\n 0 1\n 10 2\n  End Table\n"
    "End Properties\n"
    "Begin Table 4 TIME PRESSURE\n 0 0\n 1 1e-300\nEnd Table\n"
    "Begin Nodes\n 10 0 0 0\n 11 0.1 0 0\n 12 0.1 0.30000000000000004 0\n 13 0 1 0\n 14 3 3 3\nEnd Nodes\n"
    "Begin Elements SmallDisplacementElement2D4N\n 5 2 10 11 12 13\nEnd Elements\n"
    "Begin Elements SmallDisplacementElement2D3N\n 6 2 11 14 12\nEnd Elements\n"
    "Begin Conditions LineLoadCondition2D2N\n 1 0 12 13\n 2 2 13 10\nEnd Conditions\n"
    "Begin NodalData DISPLACEMENT_Y\n 10 1 0\n 11 1 -0.5\nEnd NodalData\n"
    "Begin NodalData TEMPERATURE\n 12 1 300\nEnd NodalData\n"
    "Begin NodalData NODAL_H\n 13 0 0.75\nEnd NodalData\n"
    "Begin NodalData CAUCHY_STRESS_VECTOR\n 13 0 [2](1,2)\nEnd NodalData\n"
    "Begin ElementalData THICKNESS\n 5 0.3\nEnd ElementalData\n"
    "Begin ConditionalData LINE_LOAD\n 2 [3](1,0,0)\nEnd ConditionalData\n"
    "Begin SubModelPart A\n Begin SubModelPartNodes\n 10 11\n End SubModelPartNodes\n"
    " Begin SubModelPartElements\n 5\n End SubModelPartElements\n"
    " Begin SubModelPart B\n  Begin SubModelPartTables\n 4\n  End SubModelPartTables\n"
    "  Begin SubModelPartProperties\n 2\n  End SubModelPartProperties\n"
    "  Begin SubModelPartConditions\n 2\n  End SubModelPartConditions\n"
    "  Begin SubModelPart C\n  End SubModelPart\n"
    " End SubModelPart\nEnd SubModelPart\n"
    "Begin SubModelPart Empty\nEnd SubModelPart\n";

void Register() {
  test::RegisterElement("SmallDisplacementElement2D4N");
  test::RegisterElement("SmallDisplacementElement2D3N");
  test::RegisterCondition("LineLoadCondition2D2N");
}

ModelPart& NewRoot(Model& model) {
  ModelPart& root = model.CreateModelPart("Structure");
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  root.AddNodalSolutionStepVariable(TEMPERATURE);
  return root;
}

std::vector<std::pair<IndexType, std::string>> Fixities(const MdpaReader& reader) {
  std::vector<std::pair<IndexType, std::string>> out;
  for (const FixityRequest& r : reader.FixityRequests()) out.push_back({r.node->Id(), r.variable->Name()});
  std::sort(out.begin(), out.end());
  return out;
}

TEST(MdpaWriter, RoundTripOfEveryBlockType) {
  Register();
  Model model;
  ModelPart& first = NewRoot(model);
  MdpaReader reader("example.mdpa");
  reader.ReadModelPartFromText(kExample, first);
  const std::string path = TempPath("roundtrip.mdpa");
  MdpaWriter(path).Write(first, reader.FixityRequests());

  Model again;
  ModelPart& second = NewRoot(again);
  MdpaReader reader2(path);
  reader2.ReadModelPart(second);
  test::ExpectSameModelPart(first, second);
  const std::vector<std::pair<IndexType, std::string>> expected = {
      {10, "DISPLACEMENT_Y"}, {11, "DISPLACEMENT_Y"}, {12, "TEMPERATURE"}};
  EXPECT_EQ(Fixities(reader), expected);
  EXPECT_EQ(Fixities(reader2), expected);
  EXPECT_EQ(second.GetNode(12).X0()[1], 0.30000000000000004);
  EXPECT_EQ(second.GetTable(4).Data()[1].second, 1e-300);
  EXPECT_EQ(second.GetSubModelPart("A.B").NumberOfConditions(), 1u);
  EXPECT_TRUE(second.HasSubModelPart("A.B.C"));

  // A third generation is byte-identical to the second.
  const std::string path2 = TempPath("roundtrip2.mdpa");
  MdpaWriter(path2).Write(second, reader2.FixityRequests());
  EXPECT_EQ(test::ReadFile(path), test::ReadFile(path2));
  std::filesystem::remove(path);
  std::filesystem::remove(path2);
}

TEST(MdpaWriter, FixedDofsAreWrittenAsFixityFlags) {
  Register();
  Model model;
  ModelPart& root = NewRoot(model);
  Node& node = root.CreateNewNode(1, 0.0, 0.0, 0.0);
  node.AddDof(DISPLACEMENT_Z).fixed = true;
  const std::string path = TempPath("fixed.mdpa");
  MdpaWriter(path).Write(root);
  Model again;
  MdpaReader reader(path);
  reader.ReadModelPart(NewRoot(again));
  const std::vector<std::pair<IndexType, std::string>> expected = {{1, "DISPLACEMENT_Z"}};
  EXPECT_EQ(Fixities(reader), expected);
  std::filesystem::remove(path);
}

TEST(MdpaWriter, RoundTripOfEverySharedCase) {
  for (const std::string& file : test::CaseFiles(".mdpa")) {
    SCOPED_TRACE(file);
    test::RegisterEntitiesNamedIn(test::ReadFile(file));
    Model model;
    ModelPart& first = NewRoot(model);
    MdpaReader(file).ReadModelPart(first);
    const std::string path = TempPath("case.mdpa");
    MdpaWriter(path).Write(first);
    Model again;
    ModelPart& second = NewRoot(again);
    MdpaReader(path).ReadModelPart(second);
    test::ExpectSameModelPart(first, second);
    std::filesystem::remove(path);
  }
}

class UnregisteredElement : public test::NamedEntity<Element> {
 public:
  using NamedEntity::NamedEntity;
};

TEST(MdpaWriter, FailedWriteLeavesPreviousFileAndNoTemporary) {
  const std::string path = TempPath("atomic.mdpa");
  {
    std::ofstream old(path);
    old << "previous content\n";
  }
  Model model;
  ModelPart& root = NewRoot(model);
  Node& a = root.CreateNewNode(1, 0, 0, 0);
  Node& b = root.CreateNewNode(2, 1, 0, 0);
  Node& c = root.CreateNewNode(3, 0, 1, 0);
  root.AddElement(std::make_unique<UnregisteredElement>(
      "NotARegisteredName2D3N", 1, Geometry(GeometryType::Triangle2D3, {&a, &b, &c}), &root.GetOrCreateProperties(0)));
  try {
    MdpaWriter(path).Write(root);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("NotARegisteredName2D3N"), std::string::npos) << error.what();
  }
  EXPECT_EQ(test::ReadFile(path), "previous content\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mc
