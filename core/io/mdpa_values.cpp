// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/mdpa_values.h"

#include <fstream>
#include <variant>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc::mdpa {

std::string ReadText(const std::string& filename) {
  std::ifstream file(filename, std::ios::binary | std::ios::ate);
  if (!file) throw InputError(Concat("cannot open the mdpa file '", filename, "'"));
  const std::streamsize size = file.tellg();
  std::string text(static_cast<std::size_t>(size), '\0');
  file.seekg(0);
  if (!file.read(text.data(), size)) throw InputError(Concat("cannot read the mdpa file '", filename, "'"));
  return text;
}

namespace {

/// Character-level scanner for the bracketed forms; blanks are allowed between any two items.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : s_(text) {}

  bool Eat(char c) {
    Skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool Number(double& v) { return ToDouble(Item(), v); }
  bool Size(std::size_t& n) { return ToInteger(Item(), n); }
  bool AtEnd() {
    Skip();
    return i_ == s_.size();
  }

 private:
  void Skip() {
    while (i_ < s_.size() && IsBlank(s_[i_])) ++i_;
  }
  std::string_view Item() {
    Skip();
    const std::size_t b = i_;
    while (i_ < s_.size() && !IsBlank(s_[i_]) && s_[i_] != ',' && s_[i_] != ')' && s_[i_] != ']') ++i_;
    return s_.substr(b, i_ - b);
  }

  std::string_view s_;
  std::size_t i_ = 0;
};

/// "(a, b, ...)" with exactly `n` numbers written into `out`.
template <class Out>
bool ParseTuple(Scanner& scan, std::size_t n, Out&& out) {
  if (!scan.Eat('(')) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && !scan.Eat(',')) return false;
    double v = 0.0;
    if (!scan.Number(v)) return false;
    out(i, v);
  }
  return scan.Eat(')');
}

bool ParseVector(std::string_view text, Vector& vector) {
  Scanner scan(text);
  std::size_t n = 0;
  if (!scan.Eat('[') || !scan.Size(n) || !scan.Eat(']')) return false;
  vector.resize(static_cast<Eigen::Index>(n));
  return ParseTuple(scan, n, [&](std::size_t i, double v) { vector[static_cast<Eigen::Index>(i)] = v; }) &&
         scan.AtEnd();
}

bool ParseMatrix(std::string_view text, Matrix& matrix) {
  Scanner scan(text);
  std::size_t rows = 0, cols = 0;
  if (!scan.Eat('[') || !scan.Size(rows) || !scan.Eat(',') || !scan.Size(cols) || !scan.Eat(']')) return false;
  matrix.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  if (!scan.Eat('(')) return false;
  for (std::size_t r = 0; r < rows; ++r) {
    if (r > 0 && !scan.Eat(',')) return false;
    const auto row = static_cast<Eigen::Index>(r);
    if (!ParseTuple(scan, cols, [&](std::size_t c, double v) { matrix(row, static_cast<Eigen::Index>(c)) = v; }))
      return false;
  }
  return scan.Eat(')') && scan.AtEnd();
}

}  // namespace

bool ParseValue(const VariableData& var, std::string_view text, DataValueContainer::Value& value) {
  text = TrimView(text);
  const ValueType type = var.IsComponent() ? ValueType::Double : var.Type();
  switch (type) {
    case ValueType::Double: {
      double v = 0.0;
      if (!ToDouble(text, v)) return false;
      value = v;
      return true;
    }
    case ValueType::Int: {
      int v = 0;
      if (!ToInteger(text, v)) return false;
      value = v;
      return true;
    }
    case ValueType::Bool:
      if (text == "1" || text == "true" || text == "True") {
        value = true;
      } else if (text == "0" || text == "false" || text == "False") {
        value = false;
      } else {
        return false;
      }
      return true;
    case ValueType::String:
      if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
      value = std::string(text);
      return true;
    case ValueType::Array3: {
      Vector v;
      if (!ParseVector(text, v) || v.size() != 3) return false;
      value = Array3(v);
      return true;
    }
    case ValueType::Vector: {
      Vector v;
      if (!ParseVector(text, v)) return false;
      value = std::move(v);
      return true;
    }
    case ValueType::Matrix: {
      Matrix m;
      if (!ParseMatrix(text, m)) return false;
      value = std::move(m);
      return true;
    }
  }
  return false;
}

const char* ExpectedValue(const VariableData& var) {
  switch (var.IsComponent() ? ValueType::Double : var.Type()) {
    case ValueType::Double: return "a finite number";
    case ValueType::Int: return "an integer";
    case ValueType::Bool: return "a boolean (0, 1, true or false)";
    case ValueType::String: return "a string";
    case ValueType::Array3: return "an array '[3](x,y,z)'";
    case ValueType::Vector: return "a vector '[n](v1,...,vn)'";
    case ValueType::Matrix: return "a matrix '[rows,cols]((a,b),(c,d))'";
  }
  return "a value";
}

void AppendDouble(std::string& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, end);
}

namespace {
void AppendTuple(std::string& out, const double* data, Eigen::Index n, Eigen::Index stride) {
  out += '(';
  for (Eigen::Index i = 0; i < n; ++i) {
    if (i > 0) out += ',';
    AppendDouble(out, data[i * stride]);
  }
  out += ')';
}
}  // namespace

void AppendValue(std::string& out, const DataValueContainer::Value& value) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) {
          AppendDouble(out, v);
        } else if constexpr (std::is_same_v<T, int>) {
          out += std::to_string(v);
        } else if constexpr (std::is_same_v<T, bool>) {
          out += v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          out += '"';
          out += v;
          out += '"';
        } else if constexpr (std::is_same_v<T, Matrix>) {
          out += Concat('[', v.rows(), ',', v.cols(), "](");
          for (Eigen::Index r = 0; r < v.rows(); ++r) {
            if (r > 0) out += ',';
            AppendTuple(out, v.data() + r, v.cols(), v.rows());
          }
          out += ')';
        } else {
          out += '[' + std::to_string(v.size()) + ']';
          AppendTuple(out, v.data(), v.size(), 1);
        }
      },
      value);
}

}  // namespace mc::mdpa
