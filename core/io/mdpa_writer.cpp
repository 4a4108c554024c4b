// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/mdpa_writer.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include "core/io/mdpa_values.h"
#include "core/model/model_part.h"
#include "core/model/registry.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/variables/variable_registry.h"

namespace mc {

namespace {

using mdpa::AppendDouble;
using mdpa::AppendValue;

/// Text buffer flushed to the file in large chunks.
class Output {
 public:
  explicit Output(std::FILE* file) : file_(file) { text_.reserve(kChunk + 4096); }
  std::string& Text() { return text_; }
  void MaybeFlush() {
    if (text_.size() >= kChunk) Flush();
  }
  void Flush() {
    if (!text_.empty() && std::fwrite(text_.data(), 1, text_.size(), file_) != text_.size())
      throw Error("writing the mdpa file failed (disk full?)");
    text_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 20;
  std::FILE* file_;
  std::string text_;
};

using FixityKey = std::pair<const Node*, const VariableData*>;

class Writer {
 public:
  Writer(Output& out, const ModelPart& part, const std::vector<FixityRequest>& pending) : out_(out), part_(part) {
    for (const FixityRequest& request : pending) pending_.insert({request.node, request.variable});
  }

  void Run() {
    WriteModelPartData();
    for (const Properties* properties : part_.PropertiesList()) WriteProperties(*properties);
    for (const auto& [id, table] : part_.Tables()) {
      Text() += Concat("Begin Table ", id, ' ', table.InputVariable(), ' ', table.OutputVariable(), '\n');
      WriteTablePoints(table, "");
      Text() += "End Table\n\n";
    }
    WriteNodes();
    WriteEntities(part_.Elements(), "Elements");
    WriteEntities(part_.Conditions(), "Conditions");
    WriteNodalData();
    WriteEntityData(part_.Elements(), "ElementalData");
    WriteEntityData(part_.Conditions(), "ConditionalData");
    for (const ModelPart* sub : part_.SubModelParts()) WriteSubModelPart(*sub, "");
  }

 private:
  std::string& Text() { return out_.Text(); }

  void WriteValueLine(const VariableData& var, const DataValueContainer::Value& value, const char* indent) {
    Text() += indent;
    Text() += var.Name();
    Text() += ' ';
    AppendValue(Text(), value);
    Text() += '\n';
  }

  void WriteModelPartData() {
    Text() += "Begin ModelPartData\n";
    for (const auto& [var, value] : part_.GetProcessInfo().Items()) WriteValueLine(*var, value, "  ");
    Text() += "End ModelPartData\n\n";
  }

  void WriteTablePoints(const Table& table, const char* indent) {
    for (const auto& [x, y] : table.Data()) {
      Text() += indent;
      AppendDouble(Text(), x);
      Text() += ' ';
      AppendDouble(Text(), y);
      Text() += '\n';
    }
  }

  void WriteProperties(const Properties& properties) {
    Text() += Concat("Begin Properties ", properties.Id(), '\n');
    for (const auto& [var, value] : properties.Items()) WriteValueLine(*var, value, "  ");
    for (const auto& [names, table] : properties.Tables()) {
      Text() += Concat("  Begin Table ", names.first, ' ', names.second, '\n');
      WriteTablePoints(table, "    ");
      Text() += "  End Table\n";
    }
    Text() += "End Properties\n\n";
  }

  void WriteNodes() {
    Text() += "Begin Nodes\n";
    for (const Node* node : part_.Nodes()) {
      Text() += std::to_string(node->Id());
      for (int k = 0; k < 3; ++k) {
        Text() += ' ';
        AppendDouble(Text(), node->X0()[k]);
      }
      Text() += '\n';
      out_.MaybeFlush();
    }
    Text() += "End Nodes\n\n";
  }

  template <class T>
  static const std::string& NameOf(const T& entity, std::string& scratch) {
    const std::string& registered = entity.RegisteredName();
    if (!registered.empty()) return registered;
    scratch = entity.Info();
    if (!Registry<T>::Instance().Has(scratch))
      throw InputError(Concat("cannot write ", std::is_same_v<T, Element> ? "element " : "condition ", entity.Id(),
                              ": its class name '", scratch, "' is not a registered name"));
    return scratch;
  }

  template <class T>
  void WriteEntities(const EntityContainer<T>& entities, const char* keyword) {
    std::string current;
    std::string scratch;
    for (const T* entity : entities) {
      const std::string& name = NameOf(*entity, scratch);
      if (name != current) {
        if (!current.empty()) Text() += Concat("End ", keyword, "\n\n");
        current = name;
        Text() += Concat("Begin ", keyword, ' ', name, '\n');
      }
      Text() += std::to_string(entity->Id());
      Text() += ' ';
      Text() += std::to_string(entity->HasProperties() ? entity->pGetProperties()->Id() : 0);
      for (const Node* node : entity->GetGeometry().Nodes()) {
        Text() += ' ';
        Text() += std::to_string(node->Id());
      }
      Text() += '\n';
      out_.MaybeFlush();
    }
    if (!current.empty()) Text() += Concat("End ", keyword, "\n\n");
  }

  bool IsFixed(const Node& node, const Variable<double>& var) const {
    return node.IsFixed(var) || pending_.count({&node, &var}) > 0;
  }

  void WriteHistoricalScalar(const Variable<double>& var) {
    bool open = false;
    for (const Node* node : part_.Nodes()) {
      const double value = node->FastGetSolutionStepValue(var);
      const bool fixed = IsFixed(*node, var);
      if (value == 0.0 && !fixed) continue;
      if (!open) Text() += Concat("Begin NodalData ", var.Name(), '\n');
      open = true;
      Text() += Concat(node->Id(), fixed ? " 1 " : " 0 ");
      AppendDouble(Text(), value);
      Text() += '\n';
      out_.MaybeFlush();
    }
    if (open) Text() += "End NodalData\n\n";
  }

  void WriteNodalData() {
    const VariablesList& list = part_.GetNodalSolutionStepVariablesList();
    const VariableRegistry& registry = VariableRegistry::Instance();
    for (const VariableData* var : list.Variables()) {
      if (var->Type() == ValueType::Double) {
        WriteHistoricalScalar(static_cast<const Variable<double>&>(*var));
        continue;
      }
      // Array3: per component, so that each component keeps its own fixity.
      for (const char* suffix : {"_X", "_Y", "_Z"}) {
        const std::string name = var->Name() + suffix;
        if (!registry.Has(name) || registry.Get(name).Source() != var)
          throw Error(Concat("cannot write nodal data of ", var->Name(), ": component ", name, " is not registered"));
        WriteHistoricalScalar(registry.GetTyped<double>(name));
      }
    }

    // Non-historical values, grouped per variable in registration order.
    std::map<std::size_t, std::vector<std::pair<const Node*, const DataValueContainer::Value*>>> groups;
    std::set<std::string> skipped;
    for (const Node* node : part_.Nodes())
      for (const auto& [var, value] : node->Data().Items()) {
        if (list.Has(*var)) {
          skipped.insert(var->Name());
          continue;
        }
        groups[var->Key()].push_back({node, &value});
      }
    for (const std::string& name : skipped)
      Logger::Warning(Concat("mdpa writer: non-historical nodal values of ", name,
                             " are not written (the variable is also historical)"));
    for (const auto& [key, items] : groups) {
      const VariableData& var = registry.GetByKey(key);
      Text() += Concat("Begin NodalData ", var.Name(), '\n');
      for (const auto& [node, value] : items) {
        const bool fixed = var.Type() == ValueType::Double && pending_.count({node, &var}) > 0;
        Text() += Concat(node->Id(), fixed ? " 1 " : " 0 ");
        AppendValue(Text(), *value);
        Text() += '\n';
        out_.MaybeFlush();
      }
      Text() += "End NodalData\n\n";
    }
  }

  template <class T>
  void WriteEntityData(const EntityContainer<T>& entities, const char* keyword) {
    std::map<std::size_t, std::vector<std::pair<const T*, const DataValueContainer::Value*>>> groups;
    for (const T* entity : entities)
      for (const auto& [var, value] : entity->Data().Items()) groups[var->Key()].push_back({entity, &value});
    for (const auto& [key, items] : groups) {
      Text() += Concat("Begin ", keyword, ' ', VariableRegistry::Instance().GetByKey(key).Name(), '\n');
      for (const auto& [entity, value] : items) {
        Text() += Concat(entity->Id(), ' ');
        AppendValue(Text(), *value);
        Text() += '\n';
        out_.MaybeFlush();
      }
      Text() += Concat("End ", keyword, "\n\n");
    }
  }

  template <class Range>
  void WriteIds(const Range& items, const std::string& indent, const char* keyword) {
    Text() += Concat(indent, "  Begin ", keyword, '\n');
    for (const auto* item : items) {
      Text() += indent;
      Text() += "    ";
      Text() += std::to_string(item->Id());
      Text() += '\n';
      out_.MaybeFlush();
    }
    Text() += Concat(indent, "  End ", keyword, '\n');
  }

  void WriteSubModelPart(const ModelPart& sub, const std::string& indent) {
    Text() += Concat(indent, "Begin SubModelPart ", sub.Name(), '\n');
    if (!sub.Tables().empty()) {
      Text() += Concat(indent, "  Begin SubModelPartTables\n");
      for (const auto& [id, table] : sub.Tables()) Text() += Concat(indent, "    ", id, '\n');
      Text() += Concat(indent, "  End SubModelPartTables\n");
    }
    const std::vector<Properties*> properties = sub.PropertiesList();
    if (!properties.empty()) WriteIds(properties, indent, "SubModelPartProperties");
    WriteIds(sub.Nodes(), indent, "SubModelPartNodes");
    WriteIds(sub.Elements(), indent, "SubModelPartElements");
    WriteIds(sub.Conditions(), indent, "SubModelPartConditions");
    for (const ModelPart* child : sub.SubModelParts()) WriteSubModelPart(*child, indent + "  ");
    Text() += Concat(indent, "End SubModelPart\n");
    if (indent.empty()) Text() += '\n';
  }

  Output& out_;
  const ModelPart& part_;
  std::set<FixityKey> pending_;
};

}  // namespace

void MdpaWriter::Write(const ModelPart& model_part, const std::vector<FixityRequest>& pending_fixities) const {
  const std::filesystem::path target(filename_);
  const std::filesystem::path temporary(filename_ + ".part");
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) throw InputError(Concat("cannot create the mdpa file '", temporary.string(), "'"));
  try {
    Output out(file);
    Writer(out, model_part, pending_fixities).Run();
    out.Flush();
    if (std::fclose(file) != 0) {
      file = nullptr;
      throw Error(Concat("closing '", temporary.string(), "' failed (disk full?)"));
    }
    file = nullptr;
    std::filesystem::rename(temporary, target);
  } catch (...) {
    if (file) std::fclose(file);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

}  // namespace mc
