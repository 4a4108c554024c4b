// SPDX-License-Identifier: BSD-3-Clause
#include "core/parameters/parameters.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {
namespace {

using json = nlohmann::json;

/// Appends the compact JSON text of `value` (as json::dump) to `out`, stopping soon after `out`
/// passes `max_chars`: a message quoting a large document does not serialize all of it.
void DumpPrefix(const json& value, std::string& out, std::size_t max_chars) {
  if (value.is_array() || value.is_object()) {
    out += value.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (out.size() > max_chars) return;
      if (!first) out += ',';
      first = false;
      if (value.is_object()) out += json(it.key()).dump() + ':';
      DumpPrefix(*it, out, max_chars);
    }
    out += value.is_array() ? ']' : '}';
  } else {
    out += value.dump();
  }
}

/// "string \"ten\"", "integer 3", "object {...}": what the user wrote, short enough for one line.
std::string Describe(const json& value) {
  constexpr std::size_t max_chars = 60;
  std::string text;
  DumpPrefix(value, text, max_chars);
  if (text.size() > max_chars) text = text.substr(0, max_chars) + "...";
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "boolean " + text;
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "integer " + text;
    case json::value_t::number_float: return "number " + text;
    case json::value_t::string: return "string " + text;
    case json::value_t::array: return "array " + text;
    case json::value_t::object: return "object " + text;
    default: return text;
  }
}

/// What a value of the default's type is called in "expected ..." messages.
const char* ExpectedLike(const json& default_value) {
  switch (default_value.type()) {
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    default: return "any value";
  }
}

bool SameKind(const json& value, const json& default_value) {
  if (default_value.is_null()) return true;
  if (default_value.is_number()) return value.is_number();
  return value.type() == default_value.type();
}

std::vector<std::string> KeysOf(const json& object) {
  std::vector<std::string> keys;
  for (auto it = object.begin(); it != object.end(); ++it) keys.push_back(it.key());
  return keys;
}

std::string JoinQuoted(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += ", ";
    text += "'" + names[i] + "'";
  }
  return text;
}

/// " (did you mean 'x'?)", else the list of valid names so the user can pick one.
std::string Suggestion(const std::string& name, const std::vector<std::string>& valid) {
  std::string hint = DidYouMean(name, valid);
  if (!hint.empty()) return hint;
  if (valid.empty()) return " (no keys are accepted here)";
  return " (valid keys: " + JoinQuoted(valid) + ")";
}

bool IsNumberArray(const json& value) {
  return value.is_array() && std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); });
}

json FromVector(const Vector& v) {
  json array = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(v[i]);
  return array;
}

json FromMatrix(const Matrix& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

/// Turns nlohmann's parse error into "origin: line L, column C: <reason>" plus the line itself.
/// `offset`: 0-based offset of the character the parser stopped at.
[[noreturn]] void ThrowParseError(std::size_t offset, const std::string& reason, const std::string& text,
                                  const std::string& origin) {
  offset = std::min(offset, text.size());
  const std::size_t line_start = offset == 0 ? 0 : text.rfind('\n', offset - 1) + 1;  // npos + 1 == 0
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + line_start, '\n'));
  const std::size_t column = offset - line_start + 1;
  std::size_t line_end = text.find('\n', line_start);
  if (line_end == std::string::npos) line_end = text.size();
  std::string line_text = text.substr(line_start, line_end - line_start);
  if (!line_text.empty() && line_text.back() == '\r') line_text.pop_back();

  const std::string where = origin.empty() ? std::string("JSON text") : origin;
  throw InputError(Concat(where, ": line ", line, ", column ", column, ": invalid JSON: ", reason, "\n  ", line_text,
                          "\n  ", std::string(column > 0 ? column - 1 : 0, ' '), "^"));
}

}  // namespace

// Construction --------------------------------------------------------------------------------

Parameters::Parameters() : Parameters(std::make_shared<Document>(), nullptr, "") {}

Parameters::Parameters(const std::string& json_text, std::string origin)
    : Parameters(std::make_shared<Document>(), nullptr, "") {
  document_->origin = std::move(origin);
  std::string_view text = json_text;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  try {
    // Comments are accepted: Kratos' own reader accepts them.
    document_->root = json::parse(text, nullptr, true, true);
  } catch (const json::parse_error& error) {
    // error.byte is the 1-based offset of the last character read (0 if unknown). Keep nlohmann's
    // explanation, without its exception id and its own position.
    std::string reason = error.what();
    const std::size_t colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    ThrowParseError(error.byte > 0 ? error.byte - 1 : 0, reason, std::string(text), document_->origin);
  } catch (const json::out_of_range& error) {
    // A number beyond the range of a double ("1e400"): nlohmann gives no position, so point at
    // the first place the number is written.
    std::string reason = error.what();
    const std::size_t quote = reason.find('\'');
    const std::string number =
        quote == std::string::npos ? std::string() : reason.substr(quote + 1, reason.rfind('\'') - quote - 1);
    const std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
    ThrowParseError(at == std::string_view::npos ? 0 : at,
                    Concat("the number ", number, " is outside the range of a double"), std::string(text),
                    document_->origin);
  }
}

Parameters::Parameters(std::shared_ptr<Document> document, nlohmann::json* node, std::string path)
    : document_(std::move(document)), node_(node ? node : &document_->root), path_(std::move(path)) {
  if (!node) document_->root = json::object();
}

Parameters Parameters::FromFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(Concat("cannot open settings file '", path, "'"));
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) throw InputError(Concat("cannot read settings file '", path, "'"));
  return Parameters(content.str(), path);
}

// Paths and messages --------------------------------------------------------------------------

std::string Parameters::ChildPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string Parameters::WhereChild(const std::string& child_path) const {
  const std::string& origin = document_->origin;
  if (origin.empty()) return child_path.empty() ? std::string("settings") : child_path;
  return child_path.empty() ? origin : origin + ": " + child_path;
}

std::string Parameters::Where() const { return WhereChild(path_); }

void Parameters::ThrowType(const char* expected) const {
  throw InputError(Concat(Where(), ": expected ", expected, ", found ", Describe(*node_)));
}

void Parameters::RequireObject() const {
  if (!node_->is_object()) ThrowType("an object");
}

void Parameters::RequireArray() const {
  if (!node_->is_array()) ThrowType("an array");
}

// Structure -----------------------------------------------------------------------------------

bool Parameters::Has(const std::string& key) const { return node_->is_object() && node_->contains(key); }

Parameters Parameters::operator[](const std::string& key) const {
  RequireObject();
  const auto it = node_->find(key);
  if (it == node_->end())
    throw InputError(Concat(WhereChild(ChildPath(key)), ": missing key", DidYouMean(key, KeysOf(*node_))));
  return Parameters(document_, &*it, ChildPath(key));
}

Parameters Parameters::operator[](std::size_t index) const {
  RequireArray();
  const std::string child = Concat(path_, "[", index, "]");
  if (index >= node_->size())
    throw InputError(Concat(WhereChild(child), ": index out of range (the array has ", node_->size(), " items)"));
  return Parameters(document_, &(*node_)[index], child);
}

std::size_t Parameters::size() const {
  if (!node_->is_array() && !node_->is_object()) ThrowType("an array or an object");
  return node_->size();
}

std::vector<std::string> Parameters::Keys() const {
  RequireObject();
  return KeysOf(*node_);
}

// Types ---------------------------------------------------------------------------------------

bool Parameters::IsNull() const { return node_->is_null(); }
bool Parameters::IsNumber() const { return node_->is_number(); }
bool Parameters::IsDouble() const { return node_->is_number_float(); }
bool Parameters::IsInt() const { return node_->is_number_integer(); }
bool Parameters::IsBool() const { return node_->is_boolean(); }
bool Parameters::IsString() const { return node_->is_string(); }
bool Parameters::IsArray() const { return node_->is_array(); }
bool Parameters::IsVector() const { return IsNumberArray(*node_); }
bool Parameters::IsSubParameter() const { return node_->is_object(); }

bool Parameters::IsMatrix() const {
  if (!node_->is_array()) return false;
  if (node_->empty()) return true;
  const std::size_t cols = node_->front().is_array() ? node_->front().size() : 0;
  return std::all_of(node_->begin(), node_->end(),
                     [cols](const json& row) { return IsNumberArray(row) && row.size() == cols; });
}

bool Parameters::IsStringArray() const {
  return node_->is_array() && std::all_of(node_->begin(), node_->end(), [](const json& v) { return v.is_string(); });
}

// Getters -------------------------------------------------------------------------------------

double Parameters::GetDouble() const {
  if (!node_->is_number()) ThrowType("a number");
  return node_->get<double>();
}

int Parameters::GetInt() const {
  constexpr double lowest = std::numeric_limits<int>::lowest();
  constexpr double highest = std::numeric_limits<int>::max();
  bool integral = true;
  if (node_->is_number_unsigned()) {
    const auto v = node_->get<std::uint64_t>();
    if (v <= static_cast<std::uint64_t>(highest)) return static_cast<int>(v);
  } else if (node_->is_number_integer()) {
    const auto v = node_->get<std::int64_t>();
    if (v >= lowest && v <= highest) return static_cast<int>(v);
  } else if (node_->is_number_float()) {
    // 10.0 is accepted as 10: some writers emit every number as a float.
    const double v = node_->get<double>();
    integral = std::floor(v) == v;
    if (integral && v >= lowest && v <= highest) return static_cast<int>(v);
  } else {
    integral = false;
  }
  // An integer too large for an int would otherwise read "expected an integer, found integer".
  ThrowType(integral ? "an integer from -2147483648 to 2147483647" : "an integer");
}

bool Parameters::GetBool() const {
  if (!node_->is_boolean()) ThrowType("a boolean");
  return node_->get<bool>();
}

std::string Parameters::GetString() const {
  if (!node_->is_string()) ThrowType("a string");
  return node_->get<std::string>();
}

Vector Parameters::GetVector() const {
  if (!node_->is_array()) ThrowType("an array of numbers");
  Vector v(static_cast<Eigen::Index>(node_->size()));
  for (std::size_t i = 0; i < node_->size(); ++i) v[static_cast<Eigen::Index>(i)] = (*this)[i].GetDouble();
  return v;
}

Matrix Parameters::GetMatrix() const {
  if (!node_->is_array()) ThrowType("an array of equally long arrays of numbers");
  const std::size_t rows = node_->size();
  if (rows == 0) return Matrix(0, 0);
  for (std::size_t i = 0; i < rows; ++i)
    if (!(*node_)[i].is_array()) (*this)[i].ThrowType("an array of numbers (a matrix row)");
  const std::size_t cols = node_->front().size();
  Matrix m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  for (std::size_t i = 0; i < rows; ++i) {
    const Parameters row = (*this)[i];
    if (row.node_->size() != cols)
      throw InputError(
          Concat(row.Where(), ": matrix row has ", row.node_->size(), " entries, the first row has ", cols));
    for (std::size_t j = 0; j < cols; ++j)
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j].GetDouble();
  }
  return m;
}

std::vector<std::string> Parameters::GetStringArray() const {
  if (!node_->is_array()) ThrowType("an array of strings");
  std::vector<std::string> strings;
  strings.reserve(node_->size());
  for (std::size_t i = 0; i < node_->size(); ++i) strings.push_back((*this)[i].GetString());
  return strings;
}

// Setters -------------------------------------------------------------------------------------

void Parameters::SetDouble(double v) { *node_ = v; }
void Parameters::SetInt(int v) { *node_ = v; }
void Parameters::SetBool(bool v) { *node_ = v; }
void Parameters::SetString(const std::string& v) { *node_ = v; }
void Parameters::SetVector(const Vector& v) { *node_ = FromVector(v); }
void Parameters::SetMatrix(const Matrix& v) { *node_ = FromMatrix(v); }
void Parameters::SetStringArray(const std::vector<std::string>& v) { *node_ = json(v); }

void Parameters::SetValue(const Parameters& other) {
  json copy = *other.node_;  // other may live inside this node
  *node_ = std::move(copy);
}

void Parameters::SetValue(const std::string& key, const Parameters& other) { (*this)[key].SetValue(other); }

// Object / array editing ----------------------------------------------------------------------

void Parameters::AddValue(const std::string& key, const Parameters& value) {
  RequireObject();
  json copy = *value.node_;
  (*node_)[key] = std::move(copy);
}

void Parameters::AddEmptyValue(const std::string& key) {
  RequireObject();
  if (!node_->contains(key)) (*node_)[key] = nullptr;
}

void Parameters::AddEmptyArray(const std::string& key) {
  RequireObject();
  (*node_)[key] = json::array();
}

void Parameters::AddDouble(const std::string& key, double v) {
  RequireObject();
  (*node_)[key] = v;
}
void Parameters::AddInt(const std::string& key, int v) {
  RequireObject();
  (*node_)[key] = v;
}
void Parameters::AddBool(const std::string& key, bool v) {
  RequireObject();
  (*node_)[key] = v;
}
void Parameters::AddString(const std::string& key, const std::string& v) {
  RequireObject();
  (*node_)[key] = v;
}
void Parameters::AddVector(const std::string& key, const Vector& v) {
  RequireObject();
  (*node_)[key] = FromVector(v);
}
void Parameters::AddMatrix(const std::string& key, const Matrix& v) {
  RequireObject();
  (*node_)[key] = FromMatrix(v);
}

void Parameters::AddStringArray(const std::string& key, const std::vector<std::string>& v) {
  RequireObject();
  (*node_)[key] = json(v);
}

void Parameters::Append(const Parameters& value) {
  RequireArray();
  json copy = *value.node_;
  node_->push_back(std::move(copy));
}

bool Parameters::RemoveValue(const std::string& key) {
  RequireObject();
  return node_->erase(key) > 0;
}

Parameters Parameters::Clone() const {
  auto document = std::make_shared<Document>();
  document->root = *node_;
  document->origin = document_->origin;
  return Parameters(document, &document->root, path_);
}

// Validation ----------------------------------------------------------------------------------

void Parameters::ValidateImpl(const Parameters& defaults, bool recursive) {
  RequireObject();
  if (!defaults.node_->is_object())
    throw Error(Concat(Where(), ": the defaults to validate against are not an object"));
  const json& default_object = *defaults.node_;
  const std::vector<std::string> valid = KeysOf(default_object);

  // Every unknown key at once: the user fixes them in one go.
  std::string unknown;
  for (auto it = node_->begin(); it != node_->end(); ++it) {
    if (default_object.contains(it.key())) continue;
    if (!unknown.empty()) unknown += "\n";
    unknown += Concat(Where(), ": unknown key '", it.key(), "'", Suggestion(it.key(), valid));
  }
  if (!unknown.empty()) throw InputError(unknown);

  for (auto it = node_->begin(); it != node_->end(); ++it) {
    const json& default_value = default_object.at(it.key());
    if (!SameKind(it.value(), default_value))
      throw InputError(Concat(WhereChild(ChildPath(it.key())), ": expected ", ExpectedLike(default_value),
                              " (like the default ", default_value.dump(), "), found ", Describe(it.value())));
  }

  AddMissingImpl(defaults, false);

  if (!recursive) return;
  for (auto it = default_object.begin(); it != default_object.end(); ++it) {
    if (!it.value().is_object() || it.value().empty()) continue;
    (*this)[it.key()].ValidateImpl(defaults[it.key()], true);
  }
}

void Parameters::AddMissingImpl(const Parameters& defaults, bool recursive) {
  RequireObject();
  if (!defaults.node_->is_object()) throw Error(Concat(Where(), ": the defaults to add are not an object"));
  for (auto it = defaults.node_->begin(); it != defaults.node_->end(); ++it) {
    const auto mine = node_->find(it.key());
    if (mine == node_->end()) {
      (*node_)[it.key()] = it.value();
    } else if (recursive && mine->is_object() && it.value().is_object()) {
      (*this)[it.key()].AddMissingImpl(defaults[it.key()], true);
    }
  }
}

void Parameters::ValidateAndAssignDefaults(const Parameters& defaults) { ValidateImpl(defaults, false); }
void Parameters::RecursivelyValidateAndAssignDefaults(const Parameters& defaults) { ValidateImpl(defaults, true); }
void Parameters::AddMissingParameters(const Parameters& defaults) { AddMissingImpl(defaults, false); }
void Parameters::RecursivelyAddMissingParameters(const Parameters& defaults) { AddMissingImpl(defaults, true); }

void Parameters::CheckKeys(const std::vector<std::string>& valid_keys) const {
  RequireObject();
  std::string unknown;
  for (auto it = node_->begin(); it != node_->end(); ++it) {
    if (std::find(valid_keys.begin(), valid_keys.end(), it.key()) != valid_keys.end()) continue;
    if (!unknown.empty()) unknown += "\n";
    unknown += Concat(Where(), ": unknown key '", it.key(), "'", Suggestion(it.key(), valid_keys));
  }
  if (!unknown.empty()) throw InputError(unknown);
}

// Text ----------------------------------------------------------------------------------------

std::string Parameters::WriteJsonString() const { return node_->dump(); }
std::string Parameters::PrettyPrintJsonString() const { return node_->dump(4); }

}  // namespace mc
