// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/table.h"

#include <algorithm>

#include "core/utilities/error.h"

namespace mc {

void Table::PushBack(double x, double y) {
  if (!data_.empty() && x <= data_.back().first)
    throw InputError(Concat("table points must have increasing x: ", x, " after ", data_.back().first));
  data_.emplace_back(x, y);
}

namespace {
// Index of the segment [i, i+1] holding x, for a table of at least two points.
std::size_t Segment(const std::vector<std::pair<double, double>>& d, double x) {
  auto it = std::upper_bound(d.begin(), d.end(), x, [](double v, const auto& p) { return v < p.first; });
  std::size_t i = static_cast<std::size_t>(it - d.begin());
  return std::clamp<std::size_t>(i, 1, d.size() - 1) - 1;
}
}  // namespace

double Table::GetValue(double x) const {
  if (data_.empty()) throw Error("evaluating an empty table");
  if (data_.size() == 1 || x <= data_.front().first) return data_.front().second;
  if (x >= data_.back().first) return data_.back().second;
  const std::size_t i = Segment(data_, x);
  const auto& [x0, y0] = data_[i];
  const auto& [x1, y1] = data_[i + 1];
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

double Table::GetDerivative(double x) const {
  if (data_.size() < 2 || x < data_.front().first || x > data_.back().first) return 0.0;
  const std::size_t i = Segment(data_, x);
  return (data_[i + 1].second - data_[i].second) / (data_[i + 1].first - data_[i].first);
}

}  // namespace mc
