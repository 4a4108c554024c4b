// SPDX-License-Identifier: BSD-3-Clause
// Issue 2 (kernel, geometries): quadrature rules of orders 1..5 integrate monomials exactly up to their degree on
// every reference family (and not beyond where the degree is the rule's limit).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/geometries/quadrature.h"
#include "core/geometries/reference_element.h"
#include "geometry_test_utilities.h"

namespace mc {
namespace {

double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }

// Exact integral of x^a y^b z^c over the reference element of the family.
double ExactMonomialIntegral(GeometryFamily family, int a, int b, int c) {
  const auto line = [](int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); };
  switch (family) {
    case GeometryFamily::Line: return line(a);
    case GeometryFamily::Quadrilateral: return line(a) * line(b);
    case GeometryFamily::Hexahedron: return line(a) * line(b) * line(c);
    case GeometryFamily::Triangle: return Factorial(a) * Factorial(b) / Factorial(a + b + 2);
    case GeometryFamily::Tetrahedron: return Factorial(a) * Factorial(b) * Factorial(c) / Factorial(a + b + c + 3);
    case GeometryFamily::Prism: return Factorial(a) * Factorial(b) / Factorial(a + b + 2) / (c + 1);
    default: return 1.0;
  }
}

double RuleMonomialIntegral(const std::vector<IntegrationPoint>& rule, int a, int b, int c) {
  double sum = 0.0;
  for (const IntegrationPoint& p : rule)
    sum += p.weight * std::pow(p.local[0], a) * std::pow(p.local[1], b) * std::pow(p.local[2], c);
  return sum;
}

struct FamilyCase {
  GeometryFamily family;
  GeometryType type;  // a type of the family, for IsInside
  int dim;
};

const std::vector<FamilyCase> kFamilies = {
    {GeometryFamily::Line, GeometryType::Line2D2, 1},
    {GeometryFamily::Quadrilateral, GeometryType::Quadrilateral2D4, 2},
    {GeometryFamily::Hexahedron, GeometryType::Hexahedra3D8, 3},
    {GeometryFamily::Triangle, GeometryType::Triangle2D3, 2},
    {GeometryFamily::Tetrahedron, GeometryType::Tetrahedra3D4, 3},
    {GeometryFamily::Prism, GeometryType::Prism3D6, 3},
};

bool IsSimplex(GeometryFamily f) { return f == GeometryFamily::Triangle || f == GeometryFamily::Tetrahedron; }

// Whether the rule of `order` must be exact for x^a y^b z^c.
bool ExpectedExact(GeometryFamily family, int order, int a, int b, int c) {
  const int degree = Quadrature::ExactDegree(family, order);
  if (IsSimplex(family)) return a + b + c <= degree;
  if (family == GeometryFamily::Prism) return a + b <= degree && c <= 2 * order - 1;
  return a <= degree && b <= degree && c <= degree;
}

}  // namespace

TEST(Quadrature, GaussLegendreMatchesClosedForms) {
  std::vector<double> x, w;
  Quadrature::GaussLegendre(2, x, w);
  EXPECT_NEAR(x[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(w[0], 1.0, 1e-15);
  Quadrature::GaussLegendre(3, x, w);
  EXPECT_NEAR(x[2], std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(x[1], 0.0, 1e-15);
  EXPECT_NEAR(w[1], 8.0 / 9.0, 1e-15);
  EXPECT_NEAR(w[0], 5.0 / 9.0, 1e-15);
}

TEST(Quadrature, RulesArePositiveInsideAndSumToTheReferenceMeasure) {
  for (const FamilyCase& f : kFamilies) {
    const ReferenceElement& ref = ReferenceElement::Get(f.type);
    for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
      const auto rule = Quadrature::Rule(f.family, order);
      double sum = 0.0;
      for (const IntegrationPoint& p : rule) {
        EXPECT_GT(p.weight, 0.0) << ref.Name() << " order " << order;
        EXPECT_TRUE(ref.IsInside(p.local, 0.0)) << ref.Name() << " order " << order << " point " << p.local.transpose();
        sum += p.weight;
      }
      EXPECT_NEAR(sum, test::ReferenceMeasure(f.family), 2e-15 * test::ReferenceMeasure(f.family))
          << ref.Name() << " order " << order;
    }
  }
}

TEST(Quadrature, TensorRulesUseKratosPointCounts) {
  for (int order = 1; order <= 5; ++order) {
    EXPECT_EQ(Quadrature::Rule(GeometryFamily::Line, order).size(), std::size_t(order));
    EXPECT_EQ(Quadrature::Rule(GeometryFamily::Quadrilateral, order).size(), std::size_t(order * order));
    EXPECT_EQ(Quadrature::Rule(GeometryFamily::Hexahedron, order).size(), std::size_t(order * order * order));
  }
  EXPECT_EQ(Quadrature::Rule(GeometryFamily::Triangle, 1).size(), 1u);
  EXPECT_EQ(Quadrature::Rule(GeometryFamily::Triangle, 2).size(), 3u);
  EXPECT_EQ(Quadrature::Rule(GeometryFamily::Tetrahedron, 2).size(), 4u);
  EXPECT_EQ(Quadrature::Rule(GeometryFamily::Prism, 2).size(), 6u);
}

TEST(Quadrature, ExactForMonomialsUpToTheRuleDegree) {
  for (const FamilyCase& f : kFamilies) {
    for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
      const auto rule = Quadrature::Rule(f.family, order);
      int checked = 0;
      for (int a = 0; a <= 10; ++a)
        for (int b = 0; b <= (f.dim > 1 ? 10 : 0); ++b)
          for (int c = 0; c <= (f.dim > 2 ? 10 : 0); ++c) {
            if (!ExpectedExact(f.family, order, a, b, c)) continue;
            const double exact = ExactMonomialIntegral(f.family, a, b, c);
            EXPECT_NEAR(RuleMonomialIntegral(rule, a, b, c), exact, 2e-15 * test::ReferenceMeasure(f.family))
                << ReferenceElement::Get(f.type).Name() << " order " << order << " monomial " << a << b << c;
            ++checked;
          }
      EXPECT_GT(checked, 0);
    }
  }
}

TEST(Quadrature, RuleOfOrderIsExactAtLeastToThatOrder) {
  for (const FamilyCase& f : kFamilies)
    for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
      EXPECT_GE(Quadrature::ExactDegree(f.family, order), order);
      EXPECT_TRUE(ExpectedExact(f.family, order, order, 0, 0));
    }
}

TEST(Quadrature, NotExactOneDegreeBeyondTheLimit) {
  // Lines: n Gauss points fail on x^(2n).
  for (int order = 1; order <= 5; ++order) {
    const auto rule = Quadrature::Rule(GeometryFamily::Line, order);
    const int p = 2 * order;
    EXPECT_GT(std::abs(RuleMonomialIntegral(rule, p, 0, 0) - 2.0 / (p + 1)), 1e-6) << "order " << order;
  }
  // Simplices: some monomial of total degree ExactDegree + 1 is not integrated exactly.
  for (GeometryFamily family : {GeometryFamily::Triangle, GeometryFamily::Tetrahedron}) {
    const int dim = family == GeometryFamily::Triangle ? 2 : 3;
    for (int order = 1; order <= 5; ++order) {
      const auto rule = Quadrature::Rule(family, order);
      const int p = Quadrature::ExactDegree(family, order) + 1;
      double worst = 0.0;
      for (int a = 0; a <= p; ++a)
        for (int b = 0; a + b <= p; ++b) {
          const int c = p - a - b;
          if (dim == 2 && c != 0) continue;
          worst =
              std::max(worst, std::abs(RuleMonomialIntegral(rule, a, b, c) - ExactMonomialIntegral(family, a, b, c)));
        }
      EXPECT_GT(worst, 1e-8) << "family " << dim << "D simplex order " << order;
    }
  }
}

TEST(Quadrature, UnsupportedOrderIsAnInputError) {
  const ReferenceElement& ref = ReferenceElement::Get(GeometryType::Triangle2D3);
  EXPECT_THROW(ref.IntegrationPoints(0), InputError);
  EXPECT_THROW(ref.IntegrationPoints(6), InputError);
}

}  // namespace mc
