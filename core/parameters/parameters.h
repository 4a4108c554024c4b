// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

/// JSON settings with Kratos' semantics. A Parameters object is a view into a shared JSON
/// document: `settings["solver_settings"]["max_iteration"]` refers to the same storage, so
/// writes through a sub-view are seen by the whole document.
///
/// Every error is an InputError that names where the value lives: the file the document came
/// from (if any) and the dotted key path, e.g.
///   "ProjectParameters.json: solver_settings: unknown key 'max_iteraton' (did you mean 'max_iteration'?)".
/// Views hold a pointer into the document: a view of an array item must not be used after the
/// array grows (Append), nor a view of a removed key.
class Parameters {
 public:
  /// An empty object.
  Parameters();
  /// Parses JSON text; `origin` (usually a file name) is quoted in errors. Parse errors give
  /// the line and column.
  explicit Parameters(const std::string& json_text, std::string origin = "");
  static Parameters FromFile(const std::string& path);

  // Structure ---------------------------------------------------------------------------------
  bool Has(const std::string& key) const;
  /// Sub-view; throws InputError if the key is absent (with the nearest existing keys).
  Parameters operator[](const std::string& key) const;
  /// Array element; throws InputError if out of range.
  Parameters operator[](std::size_t index) const;
  std::size_t size() const;
  std::vector<std::string> Keys() const;
  /// Dotted path of this view inside its document ("" for the root).
  const std::string& Path() const noexcept { return path_; }
  /// "file: path" prefix used in error messages.
  std::string Where() const;
  /// The file (or label) the document was read from; "" if built in code.
  const std::string& Origin() const noexcept { return document_->origin; }

  // Types -------------------------------------------------------------------------------------
  bool IsNull() const;
  bool IsNumber() const;
  bool IsDouble() const;
  bool IsInt() const;
  bool IsBool() const;
  bool IsString() const;
  bool IsArray() const;
  bool IsVector() const;        ///< array of numbers
  bool IsMatrix() const;        ///< array of equally long arrays of numbers
  bool IsSubParameter() const;  ///< JSON object
  bool IsStringArray() const;

  // Getters (throw InputError naming the path, the expected and the found type) --------------
  double GetDouble() const;
  int GetInt() const;
  bool GetBool() const;
  std::string GetString() const;
  Vector GetVector() const;
  Matrix GetMatrix() const;
  std::vector<std::string> GetStringArray() const;

  // Setters (replace the value at this view) ------------------------------------------------
  void SetDouble(double v);
  void SetInt(int v);
  void SetBool(bool v);
  void SetString(const std::string& v);
  void SetVector(const Vector& v);
  void SetMatrix(const Matrix& v);
  void SetStringArray(const std::vector<std::string>& v);
  void SetValue(const Parameters& other);  ///< deep copy of other's value
  /// Replaces the value of an existing key (InputError if absent).
  void SetValue(const std::string& key, const Parameters& other);

  // Object / array editing --------------------------------------------------------------------
  void AddValue(const std::string& key, const Parameters& value);  ///< deep copy; overwrites
  void AddEmptyValue(const std::string& key);                      ///< null value, to be set; keeps an existing one
  void AddEmptyArray(const std::string& key);
  // Add a key, or overwrite it if present.
  void AddDouble(const std::string& key, double v);
  void AddInt(const std::string& key, int v);
  void AddBool(const std::string& key, bool v);
  void AddString(const std::string& key, const std::string& v);
  void AddVector(const std::string& key, const Vector& v);
  void AddMatrix(const std::string& key, const Matrix& v);
  void AddStringArray(const std::string& key, const std::vector<std::string>& v);
  /// To an array. Views of the array's existing items must not be used afterwards (the items
  /// may move in memory); views of objects stay valid when keys are added or removed elsewhere.
  void Append(const Parameters& value);
  bool RemoveValue(const std::string& key);
  /// Independent deep copy; keeps the origin and the path, so errors found while validating
  /// the copy still say where the value came from.
  Parameters Clone() const;

  // Validation ----------------------------------------------------------------------------------
  /// Every key here must exist in `defaults` (else InputError naming the key and the nearest
  /// valid keys); every value must have the type of its default (numbers: int and double are
  /// interchangeable; a null default accepts anything); missing keys are copied from defaults.
  /// Does not descend into sub-objects.
  void ValidateAndAssignDefaults(const Parameters& defaults);
  /// As above, and recursively for sub-objects whose default is a non-empty object (an empty
  /// default object means "free-form, validated by whoever reads it").
  void RecursivelyValidateAndAssignDefaults(const Parameters& defaults);
  /// Copies missing keys from defaults without rejecting unknown ones.
  void AddMissingParameters(const Parameters& defaults);
  void RecursivelyAddMissingParameters(const Parameters& defaults);
  /// Throws InputError for each key not in `valid_keys`, with the nearest valid key.
  void CheckKeys(const std::vector<std::string>& valid_keys) const;

  // Text ----------------------------------------------------------------------------------------
  std::string WriteJsonString() const;
  std::string PrettyPrintJsonString() const;

  nlohmann::json& Json() noexcept { return *node_; }
  const nlohmann::json& Json() const noexcept { return *node_; }

 private:
  struct Document {
    nlohmann::json root;
    std::string origin;
  };
  Parameters(std::shared_ptr<Document> document, nlohmann::json* node, std::string path);
  std::string ChildPath(const std::string& key) const;
  std::string WhereChild(const std::string& child_path) const;
  [[noreturn]] void ThrowType(const char* expected) const;
  void RequireObject() const;
  void RequireArray() const;
  void ValidateImpl(const Parameters& defaults, bool recursive);
  void AddMissingImpl(const Parameters& defaults, bool recursive);

  std::shared_ptr<Document> document_;
  nlohmann::json* node_;
  std::string path_;
};

}  // namespace mc
