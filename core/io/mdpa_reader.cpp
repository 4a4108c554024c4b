// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/mdpa_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <set>
#include <unordered_map>

#include "core/geometries/reference_element.h"
#include "core/io/mdpa_values.h"
#include "core/model/model_part.h"
#include "core/model/registry.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/variable_registry.h"

namespace mc {

namespace {

using mdpa::IsBlank;
using mdpa::Line;
using mdpa::LineCursor;
using mdpa::NextToken;
using mdpa::ToDouble;
using mdpa::ToInteger;
using mdpa::TrimView;

/// Registered names live as long as the program, so entities can point at them.
const std::string* InternName(const std::string& name) {
  static std::mutex mutex;
  static std::set<std::string> names;
  const std::lock_guard<std::mutex> lock(mutex);
  return &*names.insert(name).first;
}

/// Id -> entity lookup for the duration of one read: a dense table when ids are compact,
/// a hash map otherwise. Cheaper than the containers' binary search, and unaffected by the
/// re-sorting that adding to sub-model-parts triggers in the ancestors.
template <class T>
class IdIndex {
 public:
  void Invalidate() noexcept { built_ = false; }
  T* Find(IndexType id, const EntityContainer<T>& items) {
    if (!built_) Build(items);
    if (!dense_.empty() || sparse_.empty()) return id < dense_.size() ? dense_[id] : nullptr;
    const auto it = sparse_.find(id);
    return it == sparse_.end() ? nullptr : it->second;
  }

 private:
  void Build(const EntityContainer<T>& items) {
    dense_.clear();
    sparse_.clear();
    built_ = true;
    if (items.empty()) return;
    const IndexType max_id = items[items.size() - 1]->Id();
    if (max_id <= 4 * items.size() + 1024) {
      dense_.assign(max_id + 1, nullptr);
      for (T* item : items) dense_[item->Id()] = item;
    } else {
      sparse_.reserve(items.size());
      for (T* item : items) sparse_.emplace(item->Id(), item);
    }
  }

  bool built_ = false;
  std::vector<T*> dense_;
  std::unordered_map<IndexType, T*> sparse_;
};

/// The ids a filtered read met, kept or not (MdpaReaderOptions::piece): what a line referring to
/// an entity of another rank's piece is checked against, and where a duplicate id shows.
class IdsRead {
 public:
  /// False when `id` was read before.
  bool Add(IndexType id) {
    if (ids_.empty() || id > ids_.back()) {
      ids_.push_back(id);
      return true;
    }
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
    if (it != ids_.end() && *it == id) return false;
    ids_.insert(it, id);
    return true;
  }
  bool Has(IndexType id) const { return std::binary_search(ids_.begin(), ids_.end(), id); }

 private:
  std::vector<IndexType> ids_;
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& origin, ModelPart& target, const MdpaReaderOptions& options,
         std::vector<FixityRequest>& fixities)
      : cursor_(text),
        origin_(origin),
        target_(target),
        root_(target.GetRootModelPart()),
        options_(options),
        piece_(options.piece),
        fixities_(fixities) {}

  void Run() {
    Line line;
    while (cursor_.Next(line)) {
      std::string_view rest = line.text;
      if (NextToken(rest) != "Begin") Fail(line.number, "expected 'Begin <block>'", line.text);
      const std::string_view keyword = NextToken(rest);
      if (keyword == "ModelPartData") {
        ExpectEnd(line, rest);
        ReadValueLines(line, keyword, &root_.GetProcessInfo());
      } else if (keyword == "Properties") {
        ReadProperties(line, rest);
      } else if (keyword == "Table") {
        ReadModelPartTable(line, rest);
      } else if (keyword == "Nodes") {
        ExpectEnd(line, rest);
        ReadNodes(line);
      } else if (keyword == "Elements") {
        ReadEntities<Element>(line, rest, "element", "Elements");
      } else if (keyword == "Conditions") {
        ReadEntities<Condition>(line, rest, "condition", "Conditions");
      } else if (keyword == "NodalData") {
        ReadNodalData(line, rest);
      } else if (keyword == "ElementalData") {
        ReadEntityData<Element>(line, rest, "element", "ElementalData");
      } else if (keyword == "ConditionalData") {
        ReadEntityData<Condition>(line, rest, "condition", "ConditionalData");
      } else if (keyword == "SubModelPart") {
        ReadSubModelPart(line, rest, target_);
      } else {
        static const std::vector<std::string> blocks = {"ModelPartData",   "Properties",  "Table",     "Nodes",
                                                        "Elements",        "Conditions",  "NodalData", "ElementalData",
                                                        "ConditionalData", "SubModelPart"};
        Fail(line.number,
             Concat("expected a block name (ModelPartData, Properties, Table, Nodes, Elements, Conditions, "
                    "NodalData, ElementalData, ConditionalData or SubModelPart)",
                    DidYouMean(keyword, blocks)),
             line.text);
      }
    }
  }

 private:
  // Errors ------------------------------------------------------------------------------------
  [[noreturn]] void Fail(std::size_t number, std::string_view expected, std::string_view got) const {
    throw InputError(Concat(origin_, ":", number, ": ", expected, ", got '", got, "'"));
  }
  [[noreturn]] void FailIn(std::size_t number, std::string_view what, std::string_view text) const {
    throw InputError(Concat(origin_, ":", number, ": ", what, " (line '", text, "')"));
  }

  void ExpectEnd(const Line& line, std::string_view rest) const {
    const std::string_view extra = TrimView(rest);
    if (!extra.empty()) Fail(line.number, "expected the end of the line", extra);
  }

  /// The next line of the block opened by `begin`; false at its `End <keyword>` line. A `Begin`
  /// line is returned only in blocks that nest others (`nests`); elsewhere it means the block
  /// was left open.
  bool NextInBlock(Line& line, const Line& begin, std::string_view keyword, bool nests = false) {
    if (!cursor_.Next(line))
      Fail(begin.number, Concat("expected 'End ", keyword, "' to close this block before the end of the file"),
           begin.text);
    std::string_view rest = line.text;
    const std::string_view first = NextToken(rest);
    if (first == "Begin" && !nests)
      Fail(line.number,
           Concat("expected 'End ", keyword, "' to close the block opened at line ", begin.number, " ('", begin.text,
                  "') before the next block"),
           line.text);
    if (first != "End") return true;
    const std::string_view closed = NextToken(rest);
    if (closed != keyword || !TrimView(rest).empty())
      Fail(line.number, Concat("expected 'End ", keyword, "' (block opened at line ", begin.number, ")"), line.text);
    return false;
  }

  void SkipBlock(const Line& begin, std::string_view keyword) {
    Line line;
    while (NextInBlock(line, begin, keyword)) {
    }
  }

  /// `what` describes the expected id: a string, or a callable building it only on failure.
  template <class What>
  IndexType ParseId(const Line& line, std::string_view token, const What& what) const {
    IndexType id = 0;
    if (!ToInteger(token, id)) {
      std::string expected;
      if constexpr (std::is_invocable_v<What>)
        expected = what();
      else
        expected = std::string(what);
      Fail(line.number, Concat("expected ", expected, " (a non-negative integer)"), token.empty() ? line.text : token);
    }
    return id;
  }

  // Variables and values ----------------------------------------------------------------------
  /// The registered variable `name`; with `tolerant` and the ignore option, null (plus a
  /// warning) for unknown names.
  const VariableData* LookupVariable(const Line& line, std::string_view name, bool tolerant) const {
    const VariableRegistry& registry = VariableRegistry::Instance();
    const std::string key(name);
    if (registry.Has(key)) return &registry.Get(key);
    if (tolerant && options_.ignore_variables_not_in_solution_step_data) {
      Logger::Warning(Concat(origin_, ":", line.number, ": unknown variable '", key,
                             "', block skipped (ignore_variables_not_in_solution_step_data)"));
      return nullptr;
    }
    Fail(line.number, Concat("expected a registered variable name", DidYouMean(key, registry.Names())),
         name.empty() ? line.text : name);
  }

  DataValueContainer::Value ParseValue(const Line& line, const VariableData& var, std::string_view text) const {
    DataValueContainer::Value value;
    if (!mdpa::ParseValue(var, text, value))
      Fail(line.number, Concat("expected ", mdpa::ExpectedValue(var), " for ", var.Name()),
           text.empty() ? line.text : text);
    return value;
  }

  /// Lines "VARIABLE value" up to `End <keyword>`; stored in `target` unless it is null.
  std::size_t ReadValueLines(const Line& begin, std::string_view keyword, DataValueContainer* target) {
    Line line;
    std::size_t count = 0;
    while (NextInBlock(line, begin, keyword)) {
      SetValueLine(line, target);
      ++count;
    }
    return count;
  }

  void SetValueLine(const Line& line, DataValueContainer* target) const {
    std::string_view rest = line.text;
    const std::string_view name = NextToken(rest);
    const VariableData& var = *LookupVariable(line, name, false);
    const DataValueContainer::Value value = ParseValue(line, var, TrimView(rest));
    if (target) target->SetGeneric(var, value);
  }

  // Properties and tables ---------------------------------------------------------------------
  void ReadProperties(const Line& begin, std::string_view rest) {
    const IndexType id = ParseId(begin, NextToken(rest), "a properties id after 'Begin Properties'");
    ExpectEnd(begin, rest);
    Properties& properties = target_.GetOrCreateProperties(id);
    Line line;
    while (NextInBlock(line, begin, "Properties", true)) {
      std::string_view tail = line.text;
      if (NextToken(tail) == "Begin") {
        if (NextToken(tail) != "Table")
          Fail(line.number, "expected 'Begin Table <input> <output>', 'VARIABLE value' or 'End Properties'", line.text);
        // "Begin Table [id] INPUT OUTPUT": the id is optional inside properties.
        std::string_view first = NextToken(tail);
        IndexType ignored_id = 0;
        if (ToInteger(first, ignored_id)) first = NextToken(tail);
        const std::string_view output = NextToken(tail);
        ExpectEnd(line, tail);
        Table table = ReadTablePoints(line, first, output);
        const std::string input_name = table.InputVariable();
        const std::string output_name = table.OutputVariable();
        properties.SetTable(input_name, output_name, std::move(table));
      } else {
        SetValueLine(line, &properties);
      }
    }
  }

  void ReadModelPartTable(const Line& begin, std::string_view rest) {
    const IndexType id = ParseId(begin, NextToken(rest), "a table id in 'Begin Table <id> <input> <output>'");
    const std::string_view input = NextToken(rest);
    const std::string_view output = NextToken(rest);
    ExpectEnd(begin, rest);
    target_.AddTable(id, ReadTablePoints(begin, input, output));
  }

  /// Pairs "x y" (any number per line) with increasing x, up to `End Table`.
  Table ReadTablePoints(const Line& begin, std::string_view input, std::string_view output) {
    for (const std::string_view name : {input, output}) {
      if (name.empty())
        Fail(begin.number, "expected 'Begin Table <id> <input variable> <output variable>'", begin.text);
      LookupVariable(begin, name, false);
    }
    Table table{std::string(input), std::string(output)};
    Line line;
    bool have_x = false;
    double x = 0.0;
    std::size_t last_line = begin.number;
    while (NextInBlock(line, begin, "Table")) {
      std::string_view rest = line.text;
      for (std::string_view token = NextToken(rest); !token.empty(); token = NextToken(rest)) {
        double v = 0.0;
        if (!ToDouble(token, v)) Fail(line.number, "expected a table value (a finite number)", token);
        if (!have_x) {
          if (!table.Data().empty() && v <= table.Data().back().first)
            Fail(line.number,
                 Concat("expected table x values in increasing order (previous x ", table.Data().back().first, ")"),
                 token);
          x = v;
        } else {
          table.PushBack(x, v);
        }
        have_x = !have_x;
      }
      last_line = line.number;
    }
    if (have_x) Fail(last_line, "expected pairs 'x y' in the table, the last x has no y", begin.text);
    return table;
  }

  // Nodes -------------------------------------------------------------------------------------
  void ReadNodes(const Line& begin) {
    struct Entry {
      IndexType id;
      double x[3];
      std::size_t line;
    };
    std::vector<Entry> entries;
    bool sorted = true;
    Line line;
    while (NextInBlock(line, begin, "Nodes")) {
      std::string_view rest = line.text;
      Entry e{};
      e.line = line.number;
      const std::string_view id_token = NextToken(rest);
      if (!ToInteger(id_token, e.id)) Fail(line.number, "expected a node line 'id x y z' or 'End Nodes'", line.text);
      for (int k = 0; k < 3; ++k) {
        const std::string_view token = NextToken(rest);
        if (!ToDouble(token, e.x[k]))
          Fail(line.number, Concat("expected the ", "xyz"[k], " coordinate of node ", e.id, " (a finite number)"),
               token.empty() ? line.text : token);
      }
      ExpectEnd(line, rest);
      if (!entries.empty() && e.id <= entries.back().id) sorted = false;
      entries.push_back(e);
    }
    if (!sorted)
      std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.id < b.id; });
    for (std::size_t i = 1; i < entries.size(); ++i)
      if (entries[i].id == entries[i - 1].id)
        Fail(std::max(entries[i].line, entries[i - 1].line),
             Concat("expected a unique node id, node ", entries[i].id, " is defined at lines ",
                    std::min(entries[i].line, entries[i - 1].line), " and ",
                    std::max(entries[i].line, entries[i - 1].line)),
             std::to_string(entries[i].id));
    for (const Entry& e : entries) {
      if (piece_) {
        nodes_read_.Add(e.id);
        if (!piece_->KeepsNode(e.id)) continue;
      }
      try {
        target_.CreateNewNode(e.id, e.x[0], e.x[1], e.x[2]);
      } catch (const InputError& error) {
        FailIn(e.line, error.what(), std::to_string(e.id));
      }
    }
    nodes_.Invalidate();
  }

  Node* FindNode(IndexType id) { return nodes_.Find(id, root_.Nodes()); }
  /// Whether a filtered read met node `id` (FindNode finds the kept ones only).
  bool NodeRead(IndexType id) const { return piece_ && nodes_read_.Has(id); }

  // Elements and conditions -------------------------------------------------------------------
  template <class T>
  IdIndex<T>& IndexOf() {
    if constexpr (std::is_same_v<T, Element>)
      return elements_;
    else
      return conditions_;
  }
  template <class T>
  const EntityContainer<T>& EntitiesOf() const {
    if constexpr (std::is_same_v<T, Element>)
      return root_.Elements();
    else
      return root_.Conditions();
  }
  template <class T>
  IdsRead& ReadOf() {
    if constexpr (std::is_same_v<T, Element>)
      return elements_read_;
    else
      return conditions_read_;
  }
  template <class T>
  bool EntityRead(IndexType id) {
    return piece_ && ReadOf<T>().Has(id);
  }
  template <class T>
  bool Keeps(IndexType id) const {
    if constexpr (std::is_same_v<T, Element>)
      return !piece_ || piece_->KeepsElement(id);
    else
      return !piece_ || piece_->KeepsCondition(id);
  }
  template <class T>
  T* FindEntity(IndexType id) {
    if constexpr (std::is_same_v<T, Element>)
      return elements_.Find(id, root_.Elements());
    else
      return conditions_.Find(id, root_.Conditions());
  }

  template <class T>
  void ReadEntities(const Line& begin, std::string_view rest, const char* kind, const char* keyword) {
    const std::string_view name_view = NextToken(rest);
    if (name_view.empty())
      Fail(begin.number, Concat("expected the ", kind, " name after 'Begin ", keyword, "'"), begin.text);
    ExpectEnd(begin, rest);
    const std::string name(name_view);
    const T* prototype = nullptr;
    try {
      prototype = &Registry<T>::Instance().Get(name);
    } catch (const InputError& error) {
      Fail(begin.number, Concat("expected a registered ", kind, " name: ", error.what()), name);
    }
    const auto expected = static_cast<std::size_t>(prototype->GetGeometry().Reference().NodesNumber());
    const std::string* registered_name = InternName(name);
    std::vector<IndexType> node_ids;
    node_ids.reserve(27);
    const EntityContainer<T>& existing = EntitiesOf<T>();
    bool any_id = !existing.empty();
    IndexType max_id = any_id ? existing[existing.size() - 1]->Id() : 0;
    Properties* properties = nullptr;
    IndexType properties_id = std::numeric_limits<IndexType>::max();
    Line line;
    while (NextInBlock(line, begin, keyword)) {
      std::string_view tail = line.text;
      const IndexType id =
          ParseId(line, NextToken(tail), [&] { return Concat("an ", kind, " line 'id property_id node_ids...'"); });
      const IndexType pid =
          ParseId(line, NextToken(tail), [&] { return Concat("the property id of ", kind, " ", id); });
      node_ids.clear();
      for (std::string_view token = NextToken(tail); !token.empty(); token = NextToken(tail))
        node_ids.push_back(ParseId(line, token, [&] { return Concat("a node id of ", kind, " ", id); }));
      if (node_ids.size() != expected)
        Fail(line.number,
             Concat("expected ", expected, " node ids for ", name, " ", id, " (found ", node_ids.size(), ")"),
             line.text);
      const bool kept = Keeps<T>(id);
      Geometry::NodesArray nodes;
      nodes.reserve(node_ids.size());
      for (IndexType nid : node_ids) {
        Node* node = kept ? FindNode(nid) : nullptr;
        if (!node && (kept || !NodeRead(nid)))
          FailIn(line.number, Concat(kind, " ", id, " refers to node ", nid, ", which does not exist"), line.text);
        nodes.push_back(node);
      }
      if (pid != properties_id) {
        // Kratos 10.4 stops here ("Properties #5 is not found"); we go on with empty properties
        // (materials.json usually assigns the element's properties afterwards) but say so once
        // per id, since a typo in the id otherwise surfaces later as "no constitutive law".
        if (!root_.HasProperties(pid) && undefined_properties_.insert(pid).second)
          Logger::Warning(Concat(origin_, ":", line.number, ": ", kind, " ", id, " refers to properties ", pid,
                                 ", which no 'Begin Properties ", pid,
                                 "' block defines; empty properties are created (Kratos 10.4 rejects this file)"));
        properties = &target_.GetOrCreateProperties(pid);
        properties_id = pid;
      }
      // Ids above every id seen so far cannot be duplicates; only the others need a lookup. A
      // filtered read holds some entities only: it looks among the ids read.
      const bool twice = piece_ ? !ReadOf<T>().Add(id) : any_id && id <= max_id && existing.Find(id);
      if (twice) FailIn(line.number, Concat("expected a unique id: ", kind, " ", id, " is defined twice"), line.text);
      if (!any_id || id > max_id) max_id = id;
      any_id = true;
      if (!kept) continue;
      std::unique_ptr<T> entity;
      try {
        entity = prototype->Create(id, std::move(nodes), properties);
      } catch (const InputError& error) {
        FailIn(line.number, error.what(), line.text);
      }
      entity->SetRegisteredName(registered_name);
      if constexpr (std::is_same_v<T, Element>)
        target_.AddElement(std::move(entity));
      else
        target_.AddCondition(std::move(entity));
    }
    IndexOf<T>().Invalidate();
  }

  // Data blocks -------------------------------------------------------------------------------
  void ReadNodalData(const Line& begin, std::string_view rest) {
    const std::string_view name = NextToken(rest);
    ExpectEnd(begin, rest);
    const VariableData* var = LookupVariable(begin, name, true);
    if (!var) return SkipBlock(begin, "NodalData");
    const bool scalar = var->IsComponent() || var->Type() == ValueType::Double;
    const bool historical =
        (scalar || var->Type() == ValueType::Array3) && root_.GetNodalSolutionStepVariablesList().Has(*var);
    // A fixity flag on an Array3 variable fixes its three components.
    std::vector<const Variable<double>*> fixable;
    if (scalar) {
      fixable.push_back(static_cast<const Variable<double>*>(var));
    } else if (var->Type() == ValueType::Array3) {
      const VariableRegistry& registry = VariableRegistry::Instance();
      for (const char* suffix : {"_X", "_Y", "_Z"}) {
        const std::string component = var->Name() + suffix;
        if (registry.Has(component) && registry.Get(component).Source() == var)
          fixable.push_back(&registry.GetTyped<double>(component));
      }
    }
    Line line;
    while (NextInBlock(line, begin, "NodalData")) {
      std::string_view tail = line.text;
      const IndexType id = ParseId(line, NextToken(tail), "a nodal data line 'node_id fixity value'");
      Node* node = FindNode(id);
      if (!node && !NodeRead(id))
        FailIn(line.number, Concat("NodalData ", var->Name(), ": node ", id, " does not exist"), line.text);
      const std::string_view fix_token = NextToken(tail);
      int fixed = 0;
      if (!ToInteger(fix_token, fixed) || (fixed != 0 && fixed != 1))
        Fail(line.number, Concat("expected the fixity flag (0 or 1) of node ", id),
             fix_token.empty() ? line.text : fix_token);
      const std::string_view text = TrimView(tail);
      if (historical && scalar) {
        double v = 0.0;
        if (!ToDouble(text, v))
          Fail(line.number, Concat("expected a finite number for ", var->Name()), text.empty() ? line.text : text);
        if (node) node->FastGetSolutionStepValue(*static_cast<const Variable<double>*>(var)) = v;
      } else {
        // Another rank's node (a filtered read): parsed for its errors only.
        const DataValueContainer::Value value = ParseValue(line, *var, text);
        if (node && historical)
          node->FastGetSolutionStepValue(*static_cast<const Variable<Array3>*>(var)) = std::get<Array3>(value);
        else if (node)
          node->Data().SetGeneric(*var, value);
      }
      if (fixed == 1) {
        if (fixable.empty())
          Fail(line.number,
               Concat("expected fixity 0: ", var->Name(), " is a ", ValueTypeName(var->Type()), " and has no DoF"),
               fix_token);
        if (node)
          for (const Variable<double>* component : fixable) fixities_.push_back({node, component});
      }
    }
  }

  template <class T>
  void ReadEntityData(const Line& begin, std::string_view rest, const char* kind, const char* keyword) {
    const std::string_view name = NextToken(rest);
    ExpectEnd(begin, rest);
    const VariableData* var = LookupVariable(begin, name, true);
    if (!var) return SkipBlock(begin, keyword);
    Line line;
    while (NextInBlock(line, begin, keyword)) {
      std::string_view tail = line.text;
      const IndexType id = ParseId(line, NextToken(tail), [&] { return Concat("a data line '", kind, "_id value'"); });
      T* entity = FindEntity<T>(id);
      if (!entity && !EntityRead<T>(id))
        FailIn(line.number, Concat(keyword, " ", var->Name(), ": ", kind, " ", id, " does not exist"), line.text);
      const DataValueContainer::Value value = ParseValue(line, *var, TrimView(tail));
      if (entity) entity->Data().SetGeneric(*var, value);
    }
  }

  // Sub-model-parts ---------------------------------------------------------------------------
  template <class Callback>
  void ReadIds(const Line& begin, std::string_view keyword, Callback&& callback) {
    Line line;
    while (NextInBlock(line, begin, keyword)) {
      std::string_view rest = line.text;
      for (std::string_view token = NextToken(rest); !token.empty(); token = NextToken(rest))
        callback(ParseId(line, token, [&] { return Concat("an id in ", keyword); }), line);
    }
  }

  void ReadSubModelPart(const Line& begin, std::string_view rest, ModelPart& parent) {
    const std::string_view name = NextToken(rest);
    if (name.empty() || name.find('.') != std::string_view::npos)
      Fail(begin.number, "expected a sub model part name without '.' after 'Begin SubModelPart'", begin.text);
    ExpectEnd(begin, rest);
    ModelPart& sub = parent.CreateSubModelPart(std::string(name));
    Line line;
    while (NextInBlock(line, begin, "SubModelPart", true)) {
      std::string_view tail = line.text;
      const std::string_view word = NextToken(tail);
      const std::string_view keyword = NextToken(tail);
      if (word == "Begin" && keyword == "SubModelPart") {
        ReadSubModelPart(line, tail, sub);
        continue;
      }
      static const std::vector<std::string> blocks = {"SubModelPartNodes",
                                                      "SubModelPartElements",
                                                      "SubModelPartConditions",
                                                      "SubModelPartProperties",
                                                      "SubModelPartTables",
                                                      "SubModelPartData",
                                                      "SubModelPart"};
      if (word != "Begin" || std::find(blocks.begin(), blocks.end(), keyword) == blocks.end())
        Fail(line.number,
             Concat("expected 'Begin <block>' with one of SubModelPartNodes, SubModelPartElements, "
                    "SubModelPartConditions, SubModelPartProperties, SubModelPartTables, SubModelPartData, "
                    "SubModelPart, or 'End SubModelPart'",
                    word == "Begin" ? DidYouMean(keyword, blocks) : std::string()),
             line.text);
      ExpectEnd(line, tail);
      const std::string where = sub.FullName();
      if (keyword == "SubModelPartNodes") {
        ReadIds(line, keyword, [&](IndexType id, const Line& at) {
          Node* node = FindNode(id);
          if (!node && !NodeRead(id))
            FailIn(at.number, Concat("sub model part ", where, ": node ", id, " does not exist"), at.text);
          if (node) sub.AddNode(node);
        });
      } else if (keyword == "SubModelPartElements") {
        ReadIds(line, keyword, [&](IndexType id, const Line& at) {
          Element* element = FindEntity<Element>(id);
          if (!element && !EntityRead<Element>(id))
            FailIn(at.number, Concat("sub model part ", where, ": element ", id, " does not exist"), at.text);
          if (element) sub.AddElement(element);
        });
      } else if (keyword == "SubModelPartConditions") {
        ReadIds(line, keyword, [&](IndexType id, const Line& at) {
          Condition* condition = FindEntity<Condition>(id);
          if (!condition && !EntityRead<Condition>(id))
            FailIn(at.number, Concat("sub model part ", where, ": condition ", id, " does not exist"), at.text);
          if (condition) sub.AddCondition(condition);
        });
      } else if (keyword == "SubModelPartProperties") {
        ReadIds(line, keyword, [&](IndexType id, const Line& at) {
          if (!root_.HasProperties(id))
            FailIn(at.number, Concat("sub model part ", where, ": properties ", id, " do not exist"), at.text);
          sub.GetOrCreateProperties(id);
        });
      } else if (keyword == "SubModelPartTables") {
        ReadIds(line, keyword, [&](IndexType id, const Line& at) {
          if (!target_.HasTable(id))
            FailIn(at.number, Concat("sub model part ", where, ": table ", id, " does not exist"), at.text);
          sub.AddTable(id, target_.GetTable(id));
        });
      } else {
        const std::size_t count = ReadValueLines(line, keyword, nullptr);
        if (count > 0)
          Logger::Warning(Concat(origin_, ":", line.number, ": SubModelPartData of ", where, " (", count,
                                 " value(s)) is checked but not stored: model parts keep no data of their own"));
      }
    }
  }

  LineCursor cursor_;
  const std::string& origin_;
  ModelPart& target_;
  ModelPart& root_;
  const MdpaReaderOptions& options_;
  std::vector<FixityRequest>& fixities_;
  IdIndex<Node> nodes_;
  IdIndex<Element> elements_;
  IdIndex<Condition> conditions_;
  std::set<IndexType> undefined_properties_;
  const MdpaMesh::Piece* piece_;
  IdsRead nodes_read_, elements_read_, conditions_read_;
};

}  // namespace

MdpaReader::MdpaReader(std::string filename, MdpaReaderOptions options)
    : filename_(std::move(filename)), options_(options) {}

void MdpaReader::ReadModelPart(ModelPart& model_part) { ReadModelPartFromText(mdpa::ReadText(filename_), model_part); }

void MdpaReader::ReadModelPartFromText(std::string_view text, ModelPart& model_part) {
  Reader(text, filename_, model_part, options_, fixities_).Run();
}

std::size_t MdpaReader::ApplyFixityRequests(const std::vector<FixityRequest>& requests) {
  std::size_t missing = 0;
  for (const FixityRequest& request : requests) {
    if (Dof* dof = request.node->FindDof(*request.variable)) {
      dof->fixed = true;
    } else {
      ++missing;
    }
  }
  return missing;
}

}  // namespace mc
