// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/node.h"

#include <algorithm>

namespace mc {

Node::Node(IndexType id, const Array3& coordinates, const VariablesList& variables, int buffer_size)
    : id_(id),
      x0_(coordinates),
      x_(coordinates),
      variables_(&variables),
      stride_(variables.Stride()),
      buffer_size_(std::max(1, buffer_size)),
      data_(stride_ * buffer_size_, 0.0) {}

void Node::SetBufferSize(int buffer_size) {
  buffer_size = std::max(1, buffer_size);
  if (buffer_size == buffer_size_) return;
  data_.resize(stride_ * buffer_size, 0.0);
  buffer_size_ = buffer_size;
}

void Node::CloneSolutionStep() {
  if (buffer_size_ < 2) return;
  std::copy_backward(data_.begin(), data_.begin() + (buffer_size_ - 1) * stride_, data_.end());
}

Dof& Node::AddDof(const Variable<double>& var, const Variable<double>* reaction) {
  if (Dof* existing = FindDof(var)) {
    if (reaction && !existing->reaction) existing->reaction = reaction;
    return *existing;
  }
  if (!variables_->Has(var))
    throw Error(Concat("node ", id_, ": cannot add a DoF for ", var.Name(),
                       ", which is not a historical variable of the model part"));
  if (reaction && !variables_->Has(*reaction))
    throw Error(Concat("node ", id_, ": reaction ", reaction->Name(), " of DoF ", var.Name(),
                       " is not a historical variable of the model part"));
  auto dof = std::make_unique<Dof>();
  dof->node = this;
  dof->variable = &var;
  dof->reaction = reaction;
  dofs_.push_back(std::move(dof));
  return *dofs_.back();
}

Dof& Node::GetDof(const Variable<double>& var) const {
  if (Dof* d = FindDof(var)) return *d;
  throw Error(Concat("node ", id_, " has no degree of freedom ", var.Name()));
}

void Node::CheckHistorical(const VariableData& var, int step) const {
  if (!variables_->Has(var))
    throw Error(Concat("node ", id_, ": ", var.Name(), " is not a historical variable of the model part"));
  if (step < 0 || step >= buffer_size_)
    throw Error(Concat("node ", id_, ": step ", step, " outside the buffer of size ", buffer_size_));
}

}  // namespace mc
