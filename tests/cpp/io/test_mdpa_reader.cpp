// Issue: mdpa input (MdpaReader). Every Kratos CSMA case mesh is read with the counts found by
// an independent scan and by INDEX.md; every block type, CRLF, tabs and comments are accepted;
// each kind of malformed input gives an InputError with file, line and offending text.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/io/mdpa_reader.h"
#include "core/model/model.h"
#include "core/model/model_part_partitioner.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "io_test_utilities.h"

namespace mc {
namespace {

using test::CaseFiles;
using test::CasesDir;
using test::ReadFile;

/// Counts found with plain string handling, independently of the reader.
struct Scan {
  std::size_t nodes = 0, elements = 0, conditions = 0, sub_model_parts = 0;
  std::map<std::string, std::set<std::size_t>> sub_nodes, sub_elements;
  std::map<std::size_t, Array3> coordinates;
};

Scan ScanMdpa(const std::string& text) {
  Scan scan;
  std::istringstream in(text);
  std::string raw, block, sub;
  while (std::getline(in, raw)) {
    raw = raw.substr(0, raw.find("//"));
    std::istringstream words(raw);
    std::string first, second, third;
    if (!(words >> first)) continue;
    if (first == "Begin") {
      words >> block >> third;
      if (block == "SubModelPart") {
        ++scan.sub_model_parts;
        sub = third;
      }
      continue;
    }
    if (first == "End") {
      block.clear();
      continue;
    }
    std::istringstream values(raw);
    if (block == "Nodes") {
      ++scan.nodes;
      std::size_t id;
      Array3 x;
      values >> id >> x[0] >> x[1] >> x[2];
      scan.coordinates[id] = x;
    } else if (block == "Elements") {
      ++scan.elements;
    } else if (block == "Conditions") {
      ++scan.conditions;
    } else if (block == "SubModelPartNodes" || block == "SubModelPartElements") {
      auto& target = block == "SubModelPartNodes" ? scan.sub_nodes[sub] : scan.sub_elements[sub];
      for (std::size_t id; values >> id;) target.insert(id);
    }
  }
  return scan;
}

/// Nodes / elements / conditions of the cases listed in INDEX.md.
const std::map<std::string, std::array<std::size_t, 3>>& KnownCounts() {
  static const std::map<std::string, std::array<std::size_t, 3>> known = {
      {"ALM_frictionless_contact_test_2D/hyper_simple_patch_test.mdpa", {8, 2, 0}},
      {"ALM_frictionless_contact_test_2D/hyper_simple_slope_patch_test.mdpa", {8, 2, 1}},
      {"ALM_frictionless_contact_test_2D/hyper_simple_triangle_patch_test.mdpa", {6, 2, 0}},
      {"ALM_frictionless_contact_test_2D/taylor_patch_dynamic_test.mdpa", {37, 21, 7}},
      {"ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test.mdpa", {16, 2, 0}},
      {"ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_triquad_test.mdpa", {18, 19, 0}},
      {"ALM_frictional_contact_test_2D/hyper_simple_patch_test.mdpa", {8, 2, 0}},
      {"ALM_frictional_contact_test_2D/mesh_moving_matching_test.mdpa", {36, 20, 2}},
      {"ALM_frictional_contact_test_3D/friction_block_test.mdpa", {363, 172, 52}},
      {"penalty_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test.mdpa", {16, 2, 0}},
      {"penalty_frictional_contact_test_2D/hyper_simple_patch_test.mdpa", {8, 2, 0}},
      {"mesh_tying_test/simple_patch_test_2D.mdpa", {24, 12, 0}},
      {"mesh_tying_test/hyper_simple_slope_patch_test_2D.mdpa", {8, 2, 1}},
      {"mesh_tying_test/3D_contact_simplest_patch_matching_test.mdpa", {16, 2, 0}},
      {"mpc_contact_tests/2D_contact_simplest_patch_matching_test.mdpa", {8, 2, 2}},
  };
  return known;
}

std::size_t CountSubModelParts(const ModelPart& part) {
  std::size_t n = 0;
  for (const ModelPart* sub : part.SubModelParts()) n += 1 + CountSubModelParts(*sub);
  return n;
}

TEST(MdpaReader, ReadsEverySharedCase) {
  const std::vector<std::string> files = CaseFiles(".mdpa");
  ASSERT_GE(files.size(), 19u);
  std::size_t known_checked = 0;
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const std::string text = ReadFile(path);
    test::RegisterEntitiesNamedIn(text);
    const Scan scan = ScanMdpa(text);
    Model model;
    ModelPart& root = model.CreateModelPart("Structure");
    root.AddNodalSolutionStepVariable(DISPLACEMENT);
    MdpaReader(path).ReadModelPart(root);
    EXPECT_EQ(root.NumberOfNodes(), scan.nodes);
    EXPECT_EQ(root.NumberOfElements(), scan.elements);
    EXPECT_EQ(root.NumberOfConditions(), scan.conditions);
    EXPECT_EQ(CountSubModelParts(root), scan.sub_model_parts);
    for (const auto& [id, x] : scan.coordinates) EXPECT_EQ(root.GetNode(id).X0(), x) << "node " << id;
    for (const auto& [name, ids] : scan.sub_nodes)
      EXPECT_EQ(root.GetSubModelPart(name).NumberOfNodes(), ids.size()) << name;
    for (const auto& [name, ids] : scan.sub_elements)
      EXPECT_EQ(root.GetSubModelPart(name).NumberOfElements(), ids.size()) << name;
    const std::string relative = path.substr(CasesDir().size() + 1);
    const auto known = KnownCounts().find(relative);
    if (known != KnownCounts().end()) {
      ++known_checked;
      EXPECT_EQ(root.NumberOfNodes(), known->second[0]);
      EXPECT_EQ(root.NumberOfElements(), known->second[1]);
      EXPECT_EQ(root.NumberOfConditions(), known->second[2]);
    }
  }
  EXPECT_EQ(known_checked, KnownCounts().size());
}

TEST(MdpaReader, FrictionBlockDetails) {
  const std::string path = CasesDir() + "/ALM_frictional_contact_test_3D/friction_block_test.mdpa";
  test::RegisterEntitiesNamedIn(ReadFile(path));
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  MdpaReader(path).ReadModelPart(root);
  // 36 master and 16 slave surface conditions (INDEX.md, case 10).
  std::vector<std::size_t> counts;
  for (const ModelPart* sub : root.SubModelParts())
    if (sub->NumberOfConditions() > 0) counts.push_back(sub->NumberOfConditions());
  std::sort(counts.begin(), counts.end());
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts[0], 16u);
  EXPECT_EQ(counts[1], 36u);
  EXPECT_EQ(root.Elements()[0]->RegisteredName(), "TotalLagrangianElement3D8N");
  EXPECT_EQ(root.Conditions()[0]->RegisteredName(), "SurfaceCondition3D4N");
}

// A file using every block type, with CRLF endings, tabs, comments and several ids per line.
std::string FullExample() {
  std::string text =
      "// header comment\n"
      "Begin ModelPartData // comment after a keyword\n"
      "  DOMAIN_SIZE 2\n"
      "  TIME\t0.5\n"
      "End ModelPartData\n"
      "\n"
      "Begin Properties 1\n"
      "\tYOUNG_MODULUS\t2.1e11\n"
      "  THICKNESS 0.5 // trailing comment\n"
      "  VOLUME_ACCELERATION [3]( 0, -9.81 ,0 )\n"
      "  PK2_STRESS_TENSOR [2,2]((1,2),(3,4))\n"
      "  CAUCHY_STRESS_VECTOR [3](1.5,2.5,3.5)\n"
      "  INTEGRATION_ORDER 3\n"
      "  Begin Table TEMPERATURE YOUNG_MODULUS\n"
      "    0 1.0\n"
      "    100 2.0  200 3.0\n"
      "  End Table\n"
      "End Properties\n"
      "Begin Table 3 TIME PRESSURE\n"
      "  0.0 0.0\n"
      "  1.0 10.0\n"
      "End Table\n"
      "Begin Nodes\n"
      "  2  1.0 0.0 0.0\n"
      "  1\t0.0\t0.0\t0.0   \n"
      "  3  1.0 1.0 0.0\n"
      "  4  0.0 1.0 0.0\n"
      "  5  2.5e-1 -1.0E+00 +0.0\n"
      "End Nodes\n"
      "Begin Elements SmallDisplacementElement2D4N// GUI group identifier: Parts Auto1\n"
      "  1 1 1 2 3 4\n"
      "End Elements\n"
      "Begin Conditions LineLoadCondition2D2N\n"
      "  7 0 3 4\n"
      "End Conditions\n"
      "Begin NodalData DISPLACEMENT_X\n"
      "  1 1 0.0\n"
      "  2 1 0.25\n"
      "End NodalData\n"
      "Begin NodalData DISPLACEMENT\n"
      "  3 0 [3](1,2,3)\n"
      "End NodalData\n"
      "Begin NodalData NODAL_H\n"
      "  4 0 0.3\n"
      "End NodalData\n"
      "Begin ElementalData THICKNESS\n"
      "  1 0.7\n"
      "End ElementalData\n"
      "Begin ConditionalData LINE_LOAD\n"
      "  7 [3](0,-1,0)\n"
      "End ConditionalData\n"
      "Begin SubModelPart Parts // Group Parts\n"
      "  Begin SubModelPartData\n"
      "  End SubModelPartData\n"
      "  Begin SubModelPartNodes\n"
      "    1 2\n"
      "    3\t4\n"
      "  End SubModelPartNodes\n"
      "  Begin SubModelPartElements\n"
      "    1\n"
      "  End SubModelPartElements\n"
      "  Begin SubModelPartConditions\n"
      "  End SubModelPartConditions\n"
      "  Begin SubModelPart Inner\n"
      "    Begin SubModelPartNodes\n"
      "      3 4\n"
      "    End SubModelPartNodes\n"
      "    Begin SubModelPartConditions\n"
      "      7\n"
      "    End SubModelPartConditions\n"
      "    Begin SubModelPartTables\n"
      "      3\n"
      "    End SubModelPartTables\n"
      "    Begin SubModelPartProperties\n"
      "      1\n"
      "    End SubModelPartProperties\n"
      "  End SubModelPart\n"
      "End SubModelPart\n";
  return text;
}

std::string WithCrlf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

void RegisterExampleEntities() {
  test::RegisterElement("SmallDisplacementElement2D4N");
  test::RegisterCondition("LineLoadCondition2D2N");
}

void CheckFullExample(ModelPart& root, const MdpaReader& reader) {
  EXPECT_EQ(root.GetProcessInfo().GetValue(DOMAIN_SIZE), 2);
  EXPECT_EQ(root.GetProcessInfo().GetValue(TIME), 0.5);
  const Properties& p = root.GetProperties(1);
  EXPECT_EQ(p.GetValue(YOUNG_MODULUS), 2.1e11);
  EXPECT_EQ(p.GetValue(THICKNESS), 0.5);
  EXPECT_EQ(p.GetValue(VOLUME_ACCELERATION), Array3(0, -9.81, 0));
  EXPECT_EQ(p.GetValue(INTEGRATION_ORDER), 3);
  const Matrix m = p.GetValue(PK2_STRESS_TENSOR);
  ASSERT_EQ(m.rows(), 2);
  EXPECT_EQ(m(0, 1), 2.0);
  EXPECT_EQ(m(1, 0), 3.0);
  EXPECT_EQ(p.GetValue(CAUCHY_STRESS_VECTOR).size(), 3);
  EXPECT_EQ(p.GetValue(CAUCHY_STRESS_VECTOR)[2], 3.5);
  EXPECT_EQ(p.GetTable("TEMPERATURE", "YOUNG_MODULUS").GetValue(150.0), 2.5);
  EXPECT_EQ(root.GetTable(3).GetValue(0.5), 5.0);
  ASSERT_EQ(root.NumberOfNodes(), 5u);
  EXPECT_EQ(root.GetNode(5).X0(), Array3(0.25, -1.0, 0.0));
  EXPECT_EQ(root.Nodes()[0]->Id(), 1u);
  const Element& e = root.GetElement(1);
  EXPECT_EQ(e.RegisteredName(), "SmallDisplacementElement2D4N");
  EXPECT_EQ(e.pGetProperties(), &p);
  EXPECT_EQ(e.GetGeometry()[2].Id(), 3u);
  EXPECT_EQ(e.GetValue(THICKNESS), 0.7);
  EXPECT_EQ(root.GetCondition(7).GetValue(LINE_LOAD), Array3(0, -1, 0));
  EXPECT_EQ(root.GetCondition(7).pGetProperties()->Id(), 0u);
  EXPECT_EQ(root.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 0.25);
  EXPECT_EQ(root.GetNode(3).FastGetSolutionStepValue(DISPLACEMENT), Array3(1, 2, 3));
  EXPECT_EQ(root.GetNode(4).GetValue(NODAL_H), 0.3);  // not historical -> non-historical
  ModelPart& parts = root.GetSubModelPart("Parts");
  EXPECT_EQ(parts.NumberOfNodes(), 4u);
  EXPECT_EQ(parts.NumberOfElements(), 1u);
  ModelPart& inner = root.GetSubModelPart("Parts.Inner");
  EXPECT_EQ(inner.NumberOfNodes(), 2u);
  EXPECT_EQ(inner.NumberOfConditions(), 1u);
  EXPECT_TRUE(inner.HasTable(3));
  EXPECT_TRUE(inner.HasProperties(1));
  ASSERT_EQ(reader.FixityRequests().size(), 2u);
  EXPECT_EQ(reader.FixityRequests()[1].node->Id(), 2u);
  EXPECT_EQ(reader.FixityRequests()[1].variable, &DISPLACEMENT_X);
}

TEST(MdpaReader, ReadsEveryBlockTypeWithLfAndCrlf) {
  RegisterExampleEntities();
  for (const std::string& text : {FullExample(), WithCrlf(FullExample())}) {
    Model model;
    ModelPart& root = model.CreateModelPart("Structure");
    root.AddNodalSolutionStepVariable(DISPLACEMENT);
    MdpaReader reader("example.mdpa");
    reader.ReadModelPartFromText(text, root);
    CheckFullExample(root, reader);
  }
}

TEST(MdpaReader, FixityRequestsApplyAfterAddDofs) {
  RegisterExampleEntities();
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  root.AddNodalSolutionStepVariable(DISPLACEMENT);
  MdpaReader reader("example.mdpa");
  reader.ReadModelPartFromText(FullExample(), root);
  root.GetNode(1).AddDof(DISPLACEMENT_X);
  EXPECT_EQ(MdpaReader::ApplyFixityRequests(reader.FixityRequests()), 1u);  // node 2 has no DoF
  EXPECT_TRUE(root.GetNode(1).IsFixed(DISPLACEMENT_X));
  root.GetNode(2).AddDof(DISPLACEMENT_X);
  EXPECT_EQ(MdpaReader::ApplyFixityRequests(reader.FixityRequests()), 0u);
  EXPECT_TRUE(root.GetNode(2).IsFixed(DISPLACEMENT_X));
  EXPECT_FALSE(root.GetNode(3).HasDofFor(DISPLACEMENT_X));
}

TEST(MdpaReader, ReadsTheCrlfSharedCaseLikeItsLfCopy) {
  const std::string path = CasesDir() + "/ALM_frictional_contact_test_2D/mesh_moving_matching_test.mdpa";
  const std::string crlf = ReadFile(path);
  ASSERT_NE(crlf.find("\r\n"), std::string::npos);
  std::string lf;
  for (char c : crlf)
    if (c != '\r') lf += c;
  test::RegisterEntitiesNamedIn(lf);
  Model model_a, model_b;
  ModelPart& a = model_a.CreateModelPart("Structure");
  ModelPart& b = model_b.CreateModelPart("Structure");
  MdpaReader(path).ReadModelPartFromText(crlf, a);
  MdpaReader(path).ReadModelPartFromText(lf, b);
  EXPECT_EQ(a.NumberOfNodes(), 36u);
  EXPECT_EQ(a.GetSubModelPart("CUSTOM").NumberOfNodes(), b.GetSubModelPart("CUSTOM").NumberOfNodes());
  test::ExpectSameModelPart(a, b);
}

TEST(MdpaReader, IgnoreOptionSkipsUnknownVariables) {
  const std::string text = "Begin Nodes\n1 0 0 0\nEnd Nodes\nBegin NodalData NOT_A_VARIABLE\n1 0 2.0\nEnd NodalData\n";
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  MdpaReaderOptions options;
  options.ignore_variables_not_in_solution_step_data = true;
  EXPECT_NO_THROW(MdpaReader("x.mdpa", options).ReadModelPartFromText(text, root));
  EXPECT_EQ(root.NumberOfNodes(), 1u);
  Model strict;
  EXPECT_THROW(MdpaReader("x.mdpa").ReadModelPartFromText(text, strict.CreateModelPart("Structure")), InputError);
}

// Each malformed input: the message names the file, the line and the offending text.
struct BadCase {
  const char* what;
  std::string text;
  std::vector<std::string> expected;  // substrings of the message
};

std::string Mesh(const std::string& tail) {
  return "Begin Nodes\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\nEnd Nodes\n" + tail;
}

// Kratos 10.4 rejects an element whose properties id no block defines; we warn once per id, naming
// the file, the line and the entity, and go on (materials.json usually assigns the properties).
TEST(MdpaReader, UndefinedPropertiesIdIsWarnedOncePerId) {
  RegisterExampleEntities();
  std::vector<std::string> warnings;
  Logger::SetSink([&](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) warnings.push_back(message);
  });
  Model model;
  ModelPart& root = model.CreateModelPart("Structure");
  MdpaReader("props.mdpa")
      .ReadModelPartFromText("Begin Properties 1\nEnd Properties\n" +
                                 Mesh("Begin Elements SmallDisplacementElement2D4N\n1 1 1 2 3 4\n2 5 1 2 3 4\n"
                                      "3 5 1 2 3 4\n4 1 1 2 3 4\nEnd Elements\n"),
                             root);
  Logger::ResetSink();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "props.mdpa:11: element 2 refers to properties 5, which no 'Begin Properties 5' block defines; empty "
            "properties are created (Kratos 10.4 rejects this file)");
  EXPECT_EQ(root.GetElement(3).pGetProperties()->Id(), 5u);
}

TEST(MdpaReader, MalformedInputNamesFileLineAndText) {
  RegisterExampleEntities();
  const std::vector<BadCase> cases = {
      {"malformed number", "Begin Nodes\n1 0.0 1.5x 0.0\nEnd Nodes\n", {"bad.mdpa:2:", "'1.5x'", "y coordinate"}},
      {"missing coordinate", "Begin Nodes\n1 0.0 1.5\nEnd Nodes\n", {"bad.mdpa:2:", "z coordinate", "'1 0.0 1.5'"}},
      {"unknown block", "Begin Nodez\nEnd Nodez\n", {"bad.mdpa:1:", "'Begin Nodez'", "did you mean 'Nodes'"}},
      {"text outside blocks", "Nodes\n", {"bad.mdpa:1:", "expected 'Begin <block>'", "'Nodes'"}},
      {"missing End", "\nBegin Nodes\n1 0 0 0\n", {"bad.mdpa:2:", "End Nodes", "'Begin Nodes'"}},
      {"wrong End", "Begin Nodes\n1 0 0 0\nEnd Elements\n", {"bad.mdpa:3:", "'End Elements'", "End Nodes"}},
      {"End missing before the next block",
       Mesh("Begin Elements SmallDisplacementElement2D4N\n1 0 1 2 3 4\nBegin SubModelPart P\nEnd SubModelPart\n"),
       {"bad.mdpa:9:", "expected 'End Elements' to close the block opened at line 7",
        "('Begin Elements SmallDisplacementElement2D4N')", "got 'Begin SubModelPart P'"}},
      {"missing node",
       Mesh("Begin Elements SmallDisplacementElement2D4N\n12 0 1 2 3 99\nEnd Elements\n"),
       {"bad.mdpa:8:", "element 12 refers to node 99, which does not exist", "'12 0 1 2 3 99'"}},
      {"unknown element",
       Mesh("Begin Elements SmallDisplacementElement2D4\n1 0 1 2 3 4\nEnd Elements\n"),
       {"bad.mdpa:7:", "SmallDisplacementElement2D4N", "'SmallDisplacementElement2D4'"}},
      {"unknown condition",
       Mesh("Begin Conditions LineLoadCondition2D\n1 0 1 2\nEnd Conditions\n"),
       {"bad.mdpa:7:", "LineLoadCondition2D2N", "'LineLoadCondition2D'"}},
      {"wrong node count",
       Mesh("Begin Elements SmallDisplacementElement2D4N\n1 0 1 2 3\nEnd Elements\n"),
       {"bad.mdpa:8:", "expected 4 node ids", "'1 0 1 2 3'"}},
      {"bad node id",
       Mesh("Begin Conditions LineLoadCondition2D2N\n1 0 1 x2\nEnd Conditions\n"),
       {"bad.mdpa:8:", "node id of condition 1", "'x2'"}},
      {"duplicate node",
       "Begin Nodes\n1 0 0 0\n2 0 0 0\n1 0 0 0\nEnd Nodes\n",
       {"bad.mdpa:4:", "node 1 is defined at lines 2 and 4", "'1'"}},
      {"duplicate element",
       Mesh("Begin Elements SmallDisplacementElement2D4N\n1 0 1 2 3 4\n1 0 1 2 3 4\nEnd Elements\n"),
       {"bad.mdpa:9:", "element 1", "defined twice", "'1 0 1 2 3 4'"}},
      {"nodal data unknown node",
       Mesh("Begin NodalData DISPLACEMENT_X\n77 1 0.5\nEnd NodalData\n"),
       {"bad.mdpa:8:", "node 77 does not exist", "'77 1 0.5'"}},
      {"nodal data unknown variable",
       Mesh("Begin NodalData DISPLACEMENT_XX\n1 1 0.5\nEnd NodalData\n"),
       {"bad.mdpa:7:", "DISPLACEMENT_X", "'DISPLACEMENT_XX'"}},
      {"nodal data bad fixity",
       Mesh("Begin NodalData DISPLACEMENT_X\n1 2 0.5\nEnd NodalData\n"),
       {"bad.mdpa:8:", "fixity flag", "'2'"}},
      {"nodal data bad value",
       Mesh("Begin NodalData DISPLACEMENT\n1 0 [3](1,2)\nEnd NodalData\n"),
       {"bad.mdpa:8:", "[3](x,y,z)", "'[3](1,2)'"}},
      {"property bad number",
       "Begin Properties 1\n  YOUNG_MODULUS 2.1e11x\nEnd Properties\n",
       {"bad.mdpa:2:", "'2.1e11x'", "YOUNG_MODULUS"}},
      {"property unknown variable",
       "Begin Properties 1\n  YOUNG_MODULOS 1.0\nEnd Properties\n",
       {"bad.mdpa:2:", "YOUNG_MODULUS", "'YOUNG_MODULOS'"}},
      {"properties id", "Begin Properties one\nEnd Properties\n", {"bad.mdpa:1:", "properties id", "'one'"}},
      {"table not increasing",
       "Begin Table 1 TIME PRESSURE\n0 1\n2 3\n1 4\nEnd Table\n",
       {"bad.mdpa:4:", "increasing", "'1'"}},
      {"table odd count", "Begin Table 1 TIME PRESSURE\n0 1 2\nEnd Table\n", {"bad.mdpa:2:", "pairs"}},
      {"elemental data missing element",
       Mesh("Begin ElementalData THICKNESS\n5 1.0\nEnd ElementalData\n"),
       {"bad.mdpa:8:", "element 5 does not exist", "'5 1.0'"}},
      {"sub model part missing node",
       Mesh("Begin SubModelPart Part\nBegin SubModelPartNodes\n1 2 42\nEnd SubModelPartNodes\nEnd SubModelPart\n"),
       {"bad.mdpa:9:", "Structure.Part: node 42 does not exist", "'1 2 42'"}},
      {"sub model part unknown block",
       Mesh("Begin SubModelPart Part\nBegin SubModelPartNode\nEnd SubModelPartNode\nEnd SubModelPart\n"),
       {"bad.mdpa:8:", "did you mean 'SubModelPartNodes'", "'Begin SubModelPartNode'"}},
      {"sub model part not closed",
       Mesh("Begin SubModelPart Part\nBegin SubModelPartNodes\n1\nEnd SubModelPartNodes\n"),
       {"bad.mdpa:7:", "End SubModelPart", "'Begin SubModelPart Part'"}},
  };
  // Read whole, and as each piece of a distributed run (issue 17: every rank reads every line):
  // the same message, so every rank stops at the same line.
  const auto message_of = [](const std::string& text, const MdpaMesh::Piece* piece) {
    Model model;
    ModelPart& root = model.CreateModelPart("Structure");
    root.AddNodalSolutionStepVariable(DISPLACEMENT);
    MdpaReaderOptions options;
    options.piece = piece;
    try {
      MdpaReader("bad.mdpa", options).ReadModelPartFromText(text, root);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  for (const BadCase& bad : cases) {
    SCOPED_TRACE(bad.what);
    const std::string message = message_of(bad.text, nullptr);
    for (const std::string& part : bad.expected) EXPECT_NE(message.find(part), std::string::npos) << message;
    const MdpaMesh mesh = MdpaMesh::FromText(bad.text);
    for (int rank = 0; rank < 2; ++rank) {
      const MdpaMesh::Piece piece =
          mesh.PieceOf([](IndexType id) { return static_cast<int>(id % 2); }, rank, "Structure", {});
      EXPECT_EQ(message_of(bad.text, &piece), message) << "piece of rank " << rank;
    }
    const MdpaMesh::Piece nothing;
    EXPECT_EQ(message_of(bad.text, &nothing), message) << "a piece holding nothing";
  }
}

// Issue 17: a rank reading its piece of Kratos' Hertz case (3 ranks, owners by blocks of node ids)
// holds part of the model only, the elements around every interface node as the whole model does,
// and, cut as a model read whole is cut (ModelPartPartitioner), exactly that model's piece.
TEST(MdpaReader, APieceReadThenCutIsTheModelReadWholeThenCut) {
  const std::string path = CasesDir() + "/ALM_frictionless_contact_test_2D/simple_hertz_sphere_plate_test.mdpa";
  test::RegisterEntitiesNamedIn(ReadFile(path));
  const auto owner = [](IndexType id) { return static_cast<int>((id / 37) % 3); };
  const auto node_owner = [&](const Node& node) { return owner(node.Id()); };
  const MdpaMesh mesh = MdpaMesh::Read(path);
  const auto read = [&](Model& model, const MdpaMesh::Piece* piece) -> ModelPart& {
    ModelPart& root = model.CreateModelPart("Structure");
    root.AddNodalSolutionStepVariable(DISPLACEMENT);
    MdpaReaderOptions options;
    options.piece = piece;
    MdpaReader(path, options).ReadModelPart(root);
    return root;
  };
  Model whole_model;
  const ModelPart& whole = read(whole_model, nullptr);
  const auto elements_around = [](const ModelPart& part, IndexType node) {
    std::set<IndexType> ids;
    for (const Element* element : part.Elements())
      for (const Node* n : element->GetGeometry().Nodes())
        if (n->Id() == node) ids.insert(element->Id());
    return ids;
  };
  for (int rank = 0; rank < 3; ++rank) {
    SCOPED_TRACE(rank);
    const MdpaMesh::Piece piece = mesh.PieceOf(owner, rank, "Structure", {"Structure.Contact_Part"});
    Model piece_model, cut_model;
    ModelPart& read_piece = read(piece_model, &piece);
    EXPECT_LT(read_piece.NumberOfNodes(), whole.NumberOfNodes());
    EXPECT_LT(read_piece.NumberOfElements(), whole.NumberOfElements());
    for (const Node* node : whole.GetSubModelPart("Contact_Part").Nodes())
      EXPECT_EQ(elements_around(read_piece, node->Id()), elements_around(whole, node->Id())) << "node " << node->Id();
    EXPECT_EQ(read_piece.Conditions()[read_piece.NumberOfConditions() - 1]->Id(),
              whole.Conditions()[whole.NumberOfConditions() - 1]->Id());
    ModelPart& cut = read(cut_model, nullptr);
    const ModelPartPartitioner partitioner(node_owner, rank);
    partitioner.Cut(cut, {&cut.GetSubModelPart("Contact_Part")});
    partitioner.Cut(read_piece, {&read_piece.GetSubModelPart("Contact_Part")});
    test::ExpectSameModelPart(cut, read_piece);
  }
  // The two bodies, as ContactSearchProcess::FindBodies labels them on the whole model.
  std::vector<IndexType> contact_nodes;
  for (const Node* node : whole.GetSubModelPart("Contact_Part").Nodes()) contact_nodes.push_back(node->Id());
  const auto [body_of, labels] = mesh.Bodies(contact_nodes);
  std::set<std::size_t> hemisphere, plate;
  for (const auto& [node, body] : body_of) {
    EXPECT_LT(body, labels);
    (whole.GetSubModelPart("Parts_parts_hemisphere").HasNode(node) ? hemisphere : plate).insert(body);
  }
  EXPECT_EQ(hemisphere.size(), 1U);
  EXPECT_EQ(plate.size(), 1U);
  EXPECT_NE(*hemisphere.begin(), *plate.begin());
  EXPECT_EQ(body_of.size(), whole.GetSubModelPart("Contact_Part").NumberOfNodes());
}

TEST(MdpaReader, MissingFileIsAnInputError) {
  Model model;
  EXPECT_THROW(MdpaReader("/nonexistent/file.mdpa").ReadModelPart(model.CreateModelPart("S")), InputError);
}

// Speed: a structured quadrilateral mesh; the figures are printed, not asserted.
TEST(MdpaReader, ThroughputOnSyntheticMesh) {
  test::RegisterElement("SmallDisplacementElement2D4N");
  const std::size_t nx = 800, ny = 800;
  std::string nodes = "Begin Nodes\n";
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      nodes +=
          std::to_string(j * nx + i + 1) + " " + std::to_string(0.125 * i) + " " + std::to_string(0.25 * j) + " 0.0\n";
  nodes += "End Nodes\n";
  std::string elements = "Begin Elements SmallDisplacementElement2D4N\n";
  std::size_t id = 0;
  for (std::size_t j = 0; j + 1 < ny; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const std::size_t n = j * nx + i + 1;
      elements += std::to_string(++id) + " 0 " + std::to_string(n) + " " + std::to_string(n + 1) + " " +
                  std::to_string(n + nx + 1) + " " + std::to_string(n + nx) + "\n";
    }
  elements += "End Elements\n";
  using Clock = std::chrono::steady_clock;
  double node_seconds = 0.0, element_seconds = 0.0;
  {
    Model model;
    ModelPart& root = model.CreateModelPart("Structure");
    root.AddNodalSolutionStepVariable(DISPLACEMENT);
    const auto t0 = Clock::now();
    MdpaReader("nodes.mdpa").ReadModelPartFromText(nodes, root);
    const auto t1 = Clock::now();
    MdpaReader("elements.mdpa").ReadModelPartFromText(elements, root);
    const auto t2 = Clock::now();
    node_seconds = std::chrono::duration<double>(t1 - t0).count();
    element_seconds = std::chrono::duration<double>(t2 - t1).count();
    ASSERT_EQ(root.NumberOfNodes(), nx * ny);
    ASSERT_EQ(root.NumberOfElements(), id);
  }
  const double node_rate = static_cast<double>(nx * ny) / node_seconds;
  const double element_rate = static_cast<double>(id) / element_seconds;
  std::cout << "[ figures  ] mdpa nodes: " << nx * ny << " in " << node_seconds << " s = " << node_rate / 1e6
            << " M nodes/s; quad elements: " << id << " in " << element_seconds << " s = " << element_rate / 1e6
            << " M elements/s\n";
  RecordProperty("nodes_per_second", std::to_string(node_rate));
  RecordProperty("elements_per_second", std::to_string(element_rate));
}

}  // namespace
}  // namespace mc
