// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/model/model_part.h"

namespace mc {

/// Owner of the root model parts of a simulation, addressed by dotted names.
class Model {
 public:
  Model() = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  ModelPart& CreateModelPart(const std::string& name, int buffer_size = 1);
  /// "Structure" or "Structure.Contact.ContactSub0". Throws InputError with suggestions.
  ModelPart& GetModelPart(const std::string& name) const;
  bool HasModelPart(const std::string& name) const;
  void DeleteModelPart(const std::string& name);
  std::vector<std::string> ModelPartNames() const;

 private:
  std::map<std::string, std::unique_ptr<ModelPart>> parts_;
};

}  // namespace mc
