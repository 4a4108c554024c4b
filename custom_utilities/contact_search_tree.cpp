// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_search_tree.h"

#include <cassert>
#include <cmath>
#include <nanoflann.hpp>

namespace mc {

namespace {

struct PointsAdaptor {
  const std::vector<Array3>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>, PointsAdaptor, 3,
                                                 std::size_t>;

}  // namespace

struct ContactSearchTree::Index {
  PointsAdaptor adaptor;
  Tree tree;
  Index(const std::vector<Array3>* points, int bucket_size)
      : adaptor{points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(bucket_size)) {}
};

ContactSearchTree::ContactSearchTree(std::vector<Array3> points, int bucket_size) : points_(std::move(points)) {
  index_ = std::make_unique<Index>(&points_, bucket_size > 0 ? bucket_size : 4);
}

ContactSearchTree::~ContactSearchTree() = default;

void ContactSearchTree::RadiusSearch(const Array3& center, double radius, std::vector<std::size_t>& out) const {
  out.clear();
  if (points_.empty()) return;
  thread_local std::vector<std::pair<std::size_t, double>> matches;
  matches.clear();
  nanoflann::SearchParams params;
  params.sorted = false;
  index_->tree.radiusSearch(center.data(), radius * radius, matches, params);
  for (const auto& match : matches) out.push_back(match.first);
}

std::size_t ContactSearchTree::Nearest(const Array3& point, double& distance) const {
  assert(!points_.empty());
  std::size_t index = 0;
  double distance_sq = 0.0;
  index_->tree.knnSearch(point.data(), 1, &index, &distance_sq);
  distance = std::sqrt(distance_sq);
  return index;
}

}  // namespace mc
