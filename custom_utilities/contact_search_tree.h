// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

/// A KD-tree (nanoflann) over a fixed set of 3D points, e.g. the centres of the master
/// conditions. Queries are const and thread-safe; callers pass their own result buffers so that
/// repeated queries do not allocate.
class ContactSearchTree {
 public:
  ContactSearchTree(std::vector<Array3> points, int bucket_size);
  ~ContactSearchTree();
  ContactSearchTree(const ContactSearchTree&) = delete;
  ContactSearchTree& operator=(const ContactSearchTree&) = delete;

  std::size_t size() const noexcept { return points_.size(); }
  const Array3& Point(std::size_t i) const noexcept { return points_[i]; }

  /// Indices of the points within `radius` of `center` (unordered), into `out` (cleared).
  void RadiusSearch(const Array3& center, double radius, std::vector<std::size_t>& out) const;
  /// Index of the nearest point and its distance; size() must be > 0.
  std::size_t Nearest(const Array3& point, double& distance) const;

 private:
  struct Index;
  std::vector<Array3> points_;
  std::unique_ptr<Index> index_;
};

}  // namespace mc
