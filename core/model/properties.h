// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "core/model/table.h"
#include "core/variables/data_value_container.h"

namespace mc {

class ConstitutiveLaw;

/// Material and numerical properties shared by elements and conditions: values
/// (YOUNG_MODULUS, ...), the constitutive law prototype that elements clone per integration
/// point, and tables y(x) keyed by (input, output) variable names.
class Properties : public DataValueContainer {
 public:
  explicit Properties(IndexType id) : id_(id) {}
  Properties(const Properties&) = delete;
  Properties& operator=(const Properties&) = delete;

  IndexType Id() const noexcept { return id_; }

  const ConstitutiveLaw* GetConstitutiveLaw() const noexcept { return law_.get(); }
  bool HasConstitutiveLaw() const noexcept { return law_ != nullptr; }
  void SetConstitutiveLaw(std::shared_ptr<const ConstitutiveLaw> law) { law_ = std::move(law); }

  void SetTable(const std::string& input, const std::string& output, Table table) {
    tables_[{input, output}] = std::move(table);
  }
  bool HasTable(const std::string& input, const std::string& output) const {
    return tables_.count({input, output}) > 0;
  }
  const Table& GetTable(const std::string& input, const std::string& output) const;
  const std::map<std::pair<std::string, std::string>, Table>& Tables() const noexcept { return tables_; }

  /// A required positive finite value: throws InputError naming the property id and the value.
  double GetPositive(const Variable<double>& var) const;

 private:
  IndexType id_;
  std::shared_ptr<const ConstitutiveLaw> law_;
  std::map<std::pair<std::string, std::string>, Table> tables_;
};

}  // namespace mc
