// SPDX-License-Identifier: BSD-3-Clause
#include "core/utilities/string_utilities.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace mc {

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> NearestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t max_count) {
  // "Close" means fewer edits than a third of the longer name, or one name contains the other.
  std::vector<std::pair<std::size_t, std::string>> scored;
  const std::string lower_name = ToLower(name);
  for (const auto& candidate : candidates) {
    const std::size_t d = EditDistance(name, candidate);
    const std::size_t limit = std::max<std::size_t>(2, std::max(name.size(), candidate.size()) / 3);
    const std::string lower_candidate = ToLower(candidate);
    const bool contains = !lower_name.empty() && (lower_candidate.find(lower_name) != std::string::npos ||
                                                  lower_name.find(lower_candidate) != std::string::npos);
    if (d <= limit || contains) scored.emplace_back(d, candidate);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> result;
  for (std::size_t i = 0; i < scored.size() && i < max_count; ++i) result.push_back(scored[i].second);
  return result;
}

std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto nearest = NearestNames(name, candidates);
  if (nearest.empty()) return {};
  std::string text = " (did you mean ";
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    if (i > 0) text += ", ";
    text += "'" + nearest[i] + "'";
  }
  return text + "?)";
}

std::string ToLower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string Trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

}  // namespace mc
