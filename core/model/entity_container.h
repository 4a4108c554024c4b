// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

/// Non-owning set of nodes, elements or conditions of one model part, ordered by id. Adding in
/// increasing id order (the usual case when reading a mesh) stays sorted for free; otherwise
/// the set is sorted and de-duplicated lazily on the next lookup or iteration.
template <class T>
class EntityContainer {
 public:
  using iterator = typename std::vector<T*>::const_iterator;

  void Add(T* item) {
    if (!items_.empty() && item->Id() <= items_.back()->Id()) sorted_ = false;
    items_.push_back(item);
  }
  T* Find(IndexType id) const {
    Sort();
    auto it =
        std::lower_bound(items_.begin(), items_.end(), id, [](const T* a, IndexType value) { return a->Id() < value; });
    return (it != items_.end() && (*it)->Id() == id) ? *it : nullptr;
  }
  bool Contains(IndexType id) const { return Find(id) != nullptr; }
  std::size_t size() const {
    Sort();
    return items_.size();
  }
  bool empty() const noexcept { return items_.empty(); }
  iterator begin() const {
    Sort();
    return items_.begin();
  }
  iterator end() const {
    Sort();
    return items_.end();
  }
  T* operator[](std::size_t i) const {
    Sort();
    return items_[i];
  }
  /// Removes every item for which `predicate` is true.
  template <class Predicate>
  void RemoveIf(Predicate predicate) {
    items_.erase(std::remove_if(items_.begin(), items_.end(), predicate), items_.end());
  }
  void Clear() noexcept {
    items_.clear();
    sorted_ = true;
  }
  void Reserve(std::size_t n) { items_.reserve(n); }

 private:
  void Sort() const {
    if (sorted_) return;
    std::sort(items_.begin(), items_.end(), [](const T* a, const T* b) { return a->Id() < b->Id(); });
    items_.erase(std::unique(items_.begin(), items_.end()), items_.end());
    sorted_ = true;
  }

  mutable std::vector<T*> items_;
  mutable bool sorted_ = true;
};

}  // namespace mc
