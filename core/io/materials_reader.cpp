// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/materials_reader.h"

#include <memory>

#include "core/model/constitutive_law.h"
#include "core/model/model.h"
#include "core/model/registry.h"
#include "core/parameters/parameters.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/variable_registry.h"

namespace mc {

namespace {

class MaterialsReader {
 public:
  MaterialsReader(Model& model, const std::string& origin) : model_(model), origin_(origin) {}

  void Read(const Parameters& materials) {
    materials.CheckKeys({"properties"});
    if (!materials.Has("properties")) return;
    const Parameters list = materials["properties"];
    if (!list.IsArray()) Fail("properties", "expected a list of properties entries", list.WriteJsonString());
    for (std::size_t i = 0; i < list.size(); ++i) ReadEntry(list[i], Concat("properties[", i, "]"));
  }

 private:
  [[noreturn]] void Fail(const std::string& path, const std::string& expected, const std::string& got) const {
    throw InputError(Concat(origin_, ": ", path, ": ", expected, ", got ", got));
  }

  void ReadEntry(const Parameters& entry, const std::string& path) {
    entry.CheckKeys({"model_part_name", "properties_id", "Material", "sub_properties"});
    for (const char* key : {"model_part_name", "properties_id"})
      if (!entry.Has(key)) Fail(path, Concat("expected the key '", key, "'"), entry.WriteJsonString());

    const Parameters name_value = entry["model_part_name"];
    if (!name_value.IsString()) Fail(path + ".model_part_name", "expected a string", name_value.WriteJsonString());
    const std::string name = name_value.GetString();
    ModelPart* part = nullptr;
    try {
      part = &model_.GetModelPart(name);
    } catch (const InputError& error) {
      Fail(path + ".model_part_name", Concat("expected an existing model part (", error.what(), ")"), "'" + name + "'");
    }

    const Parameters id_value = entry["properties_id"];
    if (!id_value.IsInt() || id_value.GetInt() < 0)
      Fail(path + ".properties_id", "expected a non-negative integer", id_value.WriteJsonString());
    Properties& properties = part->GetOrCreateProperties(static_cast<IndexType>(id_value.GetInt()));

    if (entry.Has("Material")) ReadMaterial(entry["Material"], path + ".Material", properties);
    if (entry.Has("sub_properties"))
      Logger::Warning(Concat(origin_, ": ", path, ".sub_properties: sub-properties are not supported and are ignored"));

    for (Element* element : part->Elements()) element->SetProperties(&properties);
    for (Condition* condition : part->Conditions()) condition->SetProperties(&properties);
  }

  void ReadMaterial(const Parameters& material, const std::string& path, Properties& properties) {
    material.CheckKeys({"name", "constitutive_law", "Variables", "Tables"});
    if (material.Has("constitutive_law")) {
      const Parameters law = material["constitutive_law"];
      law.CheckKeys({"name"});
      if (!law.Has("name") || !law["name"].IsString())
        Fail(path + ".constitutive_law", "expected {\"name\": \"<law name>\"}", law.WriteJsonString());
      const std::string law_name = law["name"].GetString();
      std::shared_ptr<const ConstitutiveLaw> prototype;
      try {
        prototype = Registry<ConstitutiveLaw>::Instance().GetShared(law_name);
      } catch (const InputError& error) {
        Fail(path + ".constitutive_law.name", Concat("expected a registered constitutive law (", error.what(), ")"),
             "'" + law_name + "'");
      }
      properties.SetConstitutiveLaw(std::shared_ptr<const ConstitutiveLaw>(prototype->Clone()));
    }
    if (material.Has("Variables")) {
      const Parameters variables = material["Variables"];
      if (!variables.IsSubParameter()) Fail(path + ".Variables", "expected an object", variables.WriteJsonString());
      for (const std::string& key : variables.Keys())
        SetVariable(properties, key, variables[key], path + ".Variables." + key);
    }
    if (material.Has("Tables")) {
      const Parameters tables = material["Tables"];
      if (!tables.IsSubParameter()) Fail(path + ".Tables", "expected an object", tables.WriteJsonString());
      for (const std::string& key : tables.Keys()) ReadTable(properties, tables[key], path + ".Tables." + key);
    }
  }

  const VariableData& LookupVariable(const std::string& name, const std::string& path) const {
    const VariableRegistry& registry = VariableRegistry::Instance();
    if (!registry.Has(name))
      Fail(path, Concat("expected a registered variable", DidYouMean(name, registry.Names())), "'" + name + "'");
    return registry.Get(name);
  }

  void SetVariable(Properties& properties, const std::string& name, const Parameters& value, const std::string& path) {
    const VariableData& var = LookupVariable(name, path);
    const ValueType type = var.IsComponent() ? ValueType::Double : var.Type();
    const std::string got = value.WriteJsonString();
    switch (type) {
      case ValueType::Double:
        if (!value.IsNumber()) Fail(path, "expected a number", got);
        properties.SetGeneric(var, value.GetDouble());
        return;
      case ValueType::Int:
        if (!value.IsInt()) Fail(path, "expected an integer", got);
        properties.SetGeneric(var, value.GetInt());
        return;
      case ValueType::Bool:
        if (!value.IsBool()) Fail(path, "expected true or false", got);
        properties.SetGeneric(var, value.GetBool());
        return;
      case ValueType::String:
        if (!value.IsString()) Fail(path, "expected a string", got);
        properties.SetGeneric(var, value.GetString());
        return;
      case ValueType::Array3:
        if (!value.IsVector() || value.size() != 3) Fail(path, "expected a list of 3 numbers", got);
        properties.SetGeneric(var, Array3(value.GetVector()));
        return;
      case ValueType::Vector:
        if (!value.IsVector()) Fail(path, "expected a list of numbers", got);
        properties.SetGeneric(var, value.GetVector());
        return;
      case ValueType::Matrix:
        if (!value.IsMatrix()) Fail(path, "expected a list of equally long lists of numbers", got);
        properties.SetGeneric(var, value.GetMatrix());
        return;
    }
  }

  void ReadTable(Properties& properties, const Parameters& table, const std::string& path) {
    table.CheckKeys({"input_variable", "output_variable", "data"});
    for (const char* key : {"input_variable", "output_variable", "data"})
      if (!table.Has(key)) Fail(path, Concat("expected the key '", key, "'"), table.WriteJsonString());
    const std::string input = table["input_variable"].GetString();
    const std::string output = table["output_variable"].GetString();
    LookupVariable(input, path + ".input_variable");
    LookupVariable(output, path + ".output_variable");
    const Parameters data = table["data"];
    if (!data.IsMatrix() || (data.size() > 0 && data[std::size_t{0}].size() != 2))
      Fail(path + ".data", "expected a list of [x, y] pairs", data.WriteJsonString());
    const Matrix points = data.size() > 0 ? data.GetMatrix() : Matrix();
    Table result(input, output);
    for (Eigen::Index r = 0; r < points.rows(); ++r) {
      if (r > 0 && points(r, 0) <= points(r - 1, 0))
        Fail(path + ".data", "expected x values in increasing order",
             Concat(points(r, 0), " after ", points(r - 1, 0)));
      result.PushBack(points(r, 0), points(r, 1));
    }
    properties.SetTable(input, output, std::move(result));
  }

  Model& model_;
  const std::string& origin_;
};

}  // namespace

void ReadMaterials(Model& model, const Parameters& materials, const std::string& origin) {
  try {
    MaterialsReader(model, origin).Read(materials);
  } catch (const InputError& error) {
    // Errors raised by Parameters itself name the document's origin, which may be empty.
    const std::string message = error.what();
    if (message.rfind(origin, 0) == 0) throw;
    throw InputError(Concat(origin, ": ", message));
  }
}

}  // namespace mc
