// SPDX-License-Identifier: BSD-3-Clause
// Text <-> value conversions of the mdpa format, shared by MdpaReader and MdpaWriter:
// numbers ("1.5", "2e-3"), booleans, strings, arrays "[3](1,2,3)", vectors "[n](...)" and
// matrices "[2,2]((1,2),(3,4))".
#pragma once

#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>

#include "core/variables/data_value_container.h"

namespace mc::mdpa {

constexpr bool IsBlank(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline std::string_view TrimView(std::string_view s) noexcept {
  std::size_t b = 0, e = s.size();
  while (b < e && IsBlank(s[b])) ++b;
  while (e > b && IsBlank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

/// Splits off the next whitespace-separated token of `rest` (empty at the end).
inline std::string_view NextToken(std::string_view& rest) noexcept {
  std::size_t b = 0;
  while (b < rest.size() && IsBlank(rest[b])) ++b;
  std::size_t e = b;
  while (e < rest.size() && !IsBlank(rest[e])) ++e;
  const std::string_view token = rest.substr(b, e - b);
  rest.remove_prefix(e);
  return token;
}

/// The whole token must be a finite number; a leading '+' is accepted.
inline bool ToDouble(std::string_view token, double& value) noexcept {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last && first != last && std::isfinite(value);
}

template <class Int>
bool ToInteger(std::string_view token, Int& value) noexcept {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last && first != last;
}

/// One non-blank line with its comment and surrounding whitespace removed.
struct Line {
  std::string_view text;
  std::size_t number = 0;
};

/// Walks the text line by line without copying; accepts LF and CRLF endings.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  bool Next(Line& line) {
    while (pos_ < text_.size()) {
      const char* begin = text_.data() + pos_;
      const void* newline = std::memchr(begin, '\n', text_.size() - pos_);
      const std::size_t length =
          newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - begin) : text_.size() - pos_;
      std::string_view raw(begin, length);
      pos_ += length + 1;
      ++number_;
      const std::size_t comment = raw.find("//");
      if (comment != std::string_view::npos) raw = raw.substr(0, comment);
      raw = TrimView(raw);
      if (!raw.empty()) {
        line = {raw, number_};
        return true;
      }
    }
    return false;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

/// The whole file (InputError naming it when it cannot be read).
std::string ReadText(const std::string& filename);
/// Parses `text` as a value of the type of `var` (a component takes a double).
bool ParseValue(const VariableData& var, std::string_view text, DataValueContainer::Value& value);
/// "a number", "an array '[3](x,y,z)'"... for error messages.
const char* ExpectedValue(const VariableData& var);
/// Shortest text that reads back to exactly the same value.
void AppendValue(std::string& out, const DataValueContainer::Value& value);
void AppendDouble(std::string& out, double value);

}  // namespace mc::mdpa
