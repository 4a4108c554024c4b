// Issue: materials input (ReadMaterials, spec 1.8). The materials file of every Kratos case
// assigns its properties, law and values to all elements and conditions of the named parts;
// unknown keys, variables, laws and parts are InputErrors naming the key and the nearest name.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/io/materials_reader.h"
#include "core/io/mdpa_reader.h"
#include "core/model/model.h"
#include "core/model/registry.h"
#include "core/parameters/parameters.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "io_test_utilities.h"

namespace mc {
namespace {

void RegisterLaws() {
  for (const char* name : {"LinearElasticPlaneStrain2DLaw", "LinearElastic3DLaw", "HyperElastic3DLaw"})
    test::RegisterLaw(name);
}

TEST(MaterialsReader, AppliesEverySharedCaseMaterialsFile) {
  RegisterLaws();
  std::size_t cases = 0;
  for (const std::string& parameters_file : test::CaseFiles("_parameters.json")) {
    SCOPED_TRACE(parameters_file);
    const nlohmann::json settings = nlohmann::json::parse(test::ReadFile(parameters_file));
    const auto& solver = settings["solver_settings"];
    const std::string root_name =
        solver.value("model_part_name", settings["problem_data"].value("model_part_name", ""));
    const std::string mdpa =
        test::CasesDir() + "/" + solver["model_import_settings"]["input_filename"].get<std::string>() + ".mdpa";
    const std::string materials_file =
        test::CasesDir() + "/" + solver["material_import_settings"]["materials_filename"].get<std::string>();
    test::RegisterEntitiesNamedIn(test::ReadFile(mdpa));
    Model model;
    ModelPart& root = model.CreateModelPart(root_name);
    MdpaReader(mdpa).ReadModelPart(root);

    // Legacy bare names are resolved by the caller (spec 1.6); here they are direct children.
    Parameters materials(test::ReadFile(materials_file), materials_file);
    const nlohmann::json expected = nlohmann::json::parse(test::ReadFile(materials_file));
    for (std::size_t i = 0; i < materials["properties"].size(); ++i) {
      Parameters name = materials["properties"][i]["model_part_name"];
      if (name.GetString().find('.') == std::string::npos) name.SetString(root_name + "." + name.GetString());
    }
    ReadMaterials(model, materials, materials_file);

    for (std::size_t i = 0; i < materials["properties"].size(); ++i) {
      const auto& entry = expected["properties"][i];
      const ModelPart& part = model.GetModelPart(materials["properties"][i]["model_part_name"].GetString());
      const auto id = entry["properties_id"].get<IndexType>();
      const auto& variables = entry["Material"]["Variables"];
      ASSERT_TRUE(root.HasProperties(id));
      const Properties& properties = root.GetProperties(id);
      EXPECT_EQ(properties.GetConstitutiveLaw()->Name(),
                entry["Material"]["constitutive_law"]["name"].get<std::string>());
      EXPECT_EQ(properties.GetValue(YOUNG_MODULUS), variables["YOUNG_MODULUS"].get<double>());
      EXPECT_EQ(properties.GetValue(POISSON_RATIO), variables["POISSON_RATIO"].get<double>());
      if (variables.contains("FRICTION_COEFFICIENT")) {
        EXPECT_EQ(properties.GetValue(FRICTION_COEFFICIENT), variables["FRICTION_COEFFICIENT"].get<double>());
      }
      EXPECT_GT(part.NumberOfElements() + part.NumberOfConditions(), 0u);
      for (const Element* e : part.Elements()) EXPECT_EQ(e->pGetProperties(), &properties) << "element " << e->Id();
      for (const Condition* c : part.Conditions())
        EXPECT_EQ(c->pGetProperties(), &properties) << "condition " << c->Id();
    }
    ++cases;
  }
  EXPECT_EQ(cases, 22u);  // with hyper_simple_patch_test_with_elimination_with_constraints (issue 18)
}

/// A root with one quad element and one line condition in the sub part "Parts".
class MaterialsFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    RegisterLaws();
    test::RegisterElement("SmallDisplacementElement2D4N");
    test::RegisterCondition("LineLoadCondition2D2N");
    ModelPart& root = model_.CreateModelPart("Structure");
    MdpaReader("m.mdpa").ReadModelPartFromText(
        "Begin Nodes\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\nEnd Nodes\n"
        "Begin Elements SmallDisplacementElement2D4N\n1 0 1 2 3 4\nEnd Elements\n"
        "Begin Conditions LineLoadCondition2D2N\n1 0 3 4\nEnd Conditions\n"
        "Begin SubModelPart Parts\nBegin SubModelPartElements\n1\nEnd SubModelPartElements\n"
        "Begin SubModelPartConditions\n1\nEnd SubModelPartConditions\nEnd SubModelPart\n",
        root);
  }
  std::string Error(const std::string& entry) {
    try {
      ReadMaterials(model_, Parameters("{\"properties\": [" + entry + "]}"), "mat.json");
    } catch (const InputError& error) {
      return error.what();
    }
    return "no error";
  }
  Model model_;
};

TEST_F(MaterialsFixture, TypedVariablesTablesAndLawClones) {
  ReadMaterials(model_, Parameters(R"({"properties": [{
      "model_part_name": "Structure.Parts", "properties_id": 7,
      "Material": {"name": "steel", "constitutive_law": {"name": "LinearElastic3DLaw"},
                   "Variables": {"YOUNG_MODULUS": 200, "INTEGRATION_ORDER": 2, "VOLUME_ACCELERATION": [0, -9.81, 0],
                                 "CAUCHY_STRESS_VECTOR": [1, 2], "PK2_STRESS_TENSOR": [[1, 2], [3, 4]],
                                 "DISPLACEMENT_X": 0.5},
                   "Tables": {"t": {"input_variable": "TEMPERATURE", "output_variable": "YOUNG_MODULUS",
                                    "data": [[0, 1], [10, 3]]}}}}]})"),
                "mat.json");
  ModelPart& root = model_.GetModelPart("Structure");
  const Properties& p = root.GetProperties(7);
  EXPECT_TRUE(model_.GetModelPart("Structure.Parts").HasProperties(7));
  EXPECT_EQ(p.GetValue(YOUNG_MODULUS), 200.0);
  EXPECT_EQ(p.GetValue(INTEGRATION_ORDER), 2);
  EXPECT_EQ(p.GetValue(VOLUME_ACCELERATION), Array3(0, -9.81, 0));
  EXPECT_EQ(p.GetValue(CAUCHY_STRESS_VECTOR).size(), 2);
  EXPECT_EQ(p.GetValue(PK2_STRESS_TENSOR)(1, 0), 3.0);
  EXPECT_EQ(p.GetValue(DISPLACEMENT_X), 0.5);
  EXPECT_EQ(p.GetTable("TEMPERATURE", "YOUNG_MODULUS").GetValue(5.0), 2.0);
  EXPECT_EQ(p.GetConstitutiveLaw()->Name(), "LinearElastic3DLaw");
  EXPECT_NE(p.GetConstitutiveLaw(), &Registry<ConstitutiveLaw>::Instance().Get("LinearElastic3DLaw"));
  EXPECT_EQ(root.GetElement(1).pGetProperties(), &p);
  EXPECT_EQ(root.GetCondition(1).pGetProperties(), &p);
}

TEST_F(MaterialsFixture, ErrorsNameTheKeyAndTheNearestName) {
  const std::string part = R"("model_part_name": "Structure.Parts", "properties_id": 1)";
  struct Case {
    std::string entry;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {R"({"model_part_name": "Structure.Prts", "properties_id": 1})", {"mat.json", "model_part_name", "Parts"}},
      {R"({"model_part_name": "Structure.Parts", "properties_idd": 1})",
       {"mat.json", "properties_idd", "properties_id"}},
      {"{" + part + R"(, "Material": {"Variables": {"YOUNG_MODULOS": 1.0}}})",
       {"mat.json", "Variables.YOUNG_MODULOS", "YOUNG_MODULUS"}},
      {"{" + part + R"(, "Material": {"Variable": {}}})", {"mat.json", "Variable", "Variables"}},
      {"{" + part + R"(, "Material": {"constitutive_law": {"name": "LinearElastic3DLow"}}})",
       {"mat.json", "constitutive_law.name", "LinearElastic3DLaw"}},
      {"{" + part + R"(, "Material": {"Variables": {"YOUNG_MODULUS": "steel"}}})",
       {"mat.json", "YOUNG_MODULUS", "expected a number", "steel"}},
      {"{" + part + R"(, "Material": {"Variables": {"VOLUME_ACCELERATION": [1, 2]}}})",
       {"mat.json", "VOLUME_ACCELERATION", "3 numbers"}},
      {"{" + part +
           R"(, "Material": {"Tables": {"t": {"input_variable": "TIME", "output_variable": "PRESURE", "data": []}}}})",
       {"mat.json", "output_variable", "PRESSURE"}},
      {R"({"model_part_name": "Structure.Parts", "properties_id": -1})", {"mat.json", "properties_id", "-1"}},
  };
  for (const Case& c : cases) {
    const std::string message = Error(c.entry);
    for (const std::string& part_of_message : c.expected)
      EXPECT_NE(message.find(part_of_message), std::string::npos) << c.entry << "\n -> " << message;
  }
}

TEST_F(MaterialsFixture, SubPropertiesAreSkippedWithAWarning) {
  std::vector<std::string> warnings;
  Logger::SetSink([&](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) warnings.push_back(message);
  });
  ReadMaterials(model_, Parameters(R"({"properties": [{"model_part_name": "Structure.Parts", "properties_id": 3,
      "Material": {"Variables": {"DENSITY": 5.0}}, "sub_properties": [{"properties_id": 4}]}]})"),
                "mat.json");
  Logger::ResetSink();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("sub_properties"), std::string::npos);
  EXPECT_EQ(model_.GetModelPart("Structure").GetProperties(3).GetValue(DENSITY), 5.0);
  EXPECT_FALSE(model_.GetModelPart("Structure").HasProperties(4));
}

}  // namespace
}  // namespace mc
