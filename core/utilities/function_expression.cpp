// SPDX-License-Identifier: BSD-3-Clause
#include "core/utilities/function_expression.h"

#include <algorithm>
#include <cmath>
#include <muParser.h>
#include <numbers>
#include <vector>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {
namespace {

const std::vector<std::string> kVariables = {"x", "y", "z", "X", "Y", "Z", "t"};

double Power(double base, double exponent) { return std::pow(base, exponent); }

}  // namespace

struct FunctionExpression::Impl {
  std::string text;
  mu::Parser parser;
  // muparser reads the variables through these addresses, so they live here, next to it.
  double x = 0.0, y = 0.0, z = 0.0, X = 0.0, Y = 0.0, Z = 0.0, t = 0.0;
  bool depends_on_space = false;
  bool depends_on_time = false;
};

FunctionExpression::FunctionExpression(const std::string& expression) : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.text = expression;

  // Python's power operator becomes muparser's; origin[i] is where character i came from.
  std::string translated;
  std::vector<int> origin;
  for (std::size_t i = 0; i < expression.size(); ++i) {
    origin.push_back(static_cast<int>(i));
    if (expression.compare(i, 2, "**") == 0) {
      translated += '^';
      ++i;
    } else {
      translated += expression[i];
    }
  }
  origin.push_back(static_cast<int>(expression.size()));

  try {
    d.parser.DefineVar("x", &d.x);
    d.parser.DefineVar("y", &d.y);
    d.parser.DefineVar("z", &d.z);
    d.parser.DefineVar("X", &d.X);
    d.parser.DefineVar("Y", &d.Y);
    d.parser.DefineVar("Z", &d.Z);
    d.parser.DefineVar("t", &d.t);
    d.parser.DefineConst("pi", std::numbers::pi);
    d.parser.DefineConst("e", std::numbers::e);
    d.parser.DefineFun("pow", Power);
    d.parser.SetExpr(translated);
    // GetUsedVar finds syntax errors and lists every name used, defined or not.
    const mu::varmap_type used = d.parser.GetUsedVar();
    for (const auto& [name, address] : used) {
      if (std::find(kVariables.begin(), kVariables.end(), name) == kVariables.end())
        throw InputError(Concat("invalid expression \"", expression, "\": unknown variable '", name, "'",
                                DidYouMean(name, kVariables),
                                "; the variables are x, y, z (current coordinates), "
                                "X, Y, Z (initial coordinates) and t"));
      if (name == "t")
        d.depends_on_time = true;
      else
        d.depends_on_space = true;
    }
    // Compiles to bytecode now, so any remaining mistake surfaces here and not in Evaluate.
    d.parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    // muparser counts from 0 in its own text and may point one past the end.
    const int raw = error.GetPos();
    const int position = raw < 0 ? -1 : origin[std::min(static_cast<std::size_t>(raw), origin.size() - 1)];
    std::string message = error.GetMsg();
    if (position >= 0) {
      const std::string raw_text = "position " + std::to_string(raw);
      if (const auto at = message.find(raw_text); at != std::string::npos)
        message.replace(at, raw_text.size(), "position " + std::to_string(position));
      else
        message += Concat(" at position ", position);
    }
    std::string text = Concat("invalid expression \"", expression, "\": ", message);
    if (position >= 0)
      text += Concat("\n  ", expression, "\n  ", std::string(static_cast<std::size_t>(position), ' '), "^");
    throw InputError(text);
  }
}

FunctionExpression::~FunctionExpression() = default;
FunctionExpression::FunctionExpression(FunctionExpression&&) noexcept = default;
FunctionExpression& FunctionExpression::operator=(FunctionExpression&&) noexcept = default;

double FunctionExpression::Evaluate(double x, double y, double z, double t, double X, double Y, double Z) const {
  Impl& d = *impl_;
  d.x = x;
  d.y = y;
  d.z = z;
  d.t = t;
  d.X = X;
  d.Y = Y;
  d.Z = Z;
  return d.parser.Eval();
}

bool FunctionExpression::DependsOnSpace() const noexcept { return impl_->depends_on_space; }
bool FunctionExpression::DependsOnTime() const noexcept { return impl_->depends_on_time; }
const std::string& FunctionExpression::Text() const noexcept { return impl_->text; }

}  // namespace mc
