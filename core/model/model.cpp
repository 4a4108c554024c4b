// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/model.h"

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

ModelPart& Model::CreateModelPart(const std::string& name, int buffer_size) {
  const auto dot = name.find('.');
  if (dot != std::string::npos) {
    const std::string root = name.substr(0, dot);
    ModelPart& parent = HasModelPart(root) ? GetModelPart(root) : CreateModelPart(root, buffer_size);
    return parent.CreateSubModelPart(name.substr(dot + 1));
  }
  if (parts_.count(name)) throw InputError(Concat("model part '", name, "' already exists"));
  auto part = std::make_unique<ModelPart>(name, buffer_size, this);
  ModelPart& ref = *part;
  parts_.emplace(name, std::move(part));
  return ref;
}

ModelPart& Model::GetModelPart(const std::string& name) const {
  const auto dot = name.find('.');
  const std::string root = name.substr(0, dot);
  const auto it = parts_.find(root);
  if (it == parts_.end())
    throw InputError(Concat("no model part named '", root, "'", DidYouMean(root, ModelPartNames())));
  return dot == std::string::npos ? *it->second : it->second->GetSubModelPart(name.substr(dot + 1));
}

bool Model::HasModelPart(const std::string& name) const {
  const auto dot = name.find('.');
  const auto it = parts_.find(name.substr(0, dot));
  if (it == parts_.end()) return false;
  return dot == std::string::npos || it->second->HasSubModelPart(name.substr(dot + 1));
}

void Model::DeleteModelPart(const std::string& name) { parts_.erase(name); }

std::vector<std::string> Model::ModelPartNames() const {
  std::vector<std::string> names;
  for (const auto& [name, part] : parts_) names.push_back(name);
  return names;
}

}  // namespace mc
