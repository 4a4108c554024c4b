// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mc {

/// Levenshtein edit distance, case-insensitive.
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The candidates closest to `name` (at most `max_count`, only reasonably close ones), best
/// first. Used by every "unknown name" error to suggest a valid spelling.
std::vector<std::string> NearestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t max_count = 3);

/// " (did you mean 'A', 'B'?)" or an empty string when nothing is close.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates);

std::string ToLower(std::string_view s);
std::string Trim(std::string_view s);

}  // namespace mc
