// SPDX-License-Identifier: BSD-3-Clause
// Test doubles for the IO tests: element, condition and constitutive-law prototypes that do
// nothing but carry a registered name, and helpers to find and scan the shared Kratos cases.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/model/condition.h"
#include "core/model/constitutive_law.h"
#include "core/model/element.h"
#include "core/model/model_part.h"

namespace mc::test {

template <class Base>
class NamedEntity : public Base {
 public:
  NamedEntity(std::string name, IndexType id, Geometry geometry, Properties* properties)
      : Base(id, std::move(geometry), properties), name_(std::move(name)) {}
  std::string Info() const override { return name_; }
  std::unique_ptr<Base> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<NamedEntity>(name_, id, Geometry(this->GetGeometry().Type(), std::move(nodes)), properties);
  }
  void GetDofList(DofsVectorType& dofs, const ProcessInfo&) const override { dofs.clear(); }

 private:
  std::string name_;
};

class NamedLaw : public ConstitutiveLaw {
 public:
  explicit NamedLaw(std::string name) : name_(std::move(name)) {}
  std::string Name() const override { return name_; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<NamedLaw>(name_); }
  int WorkingSpaceDimension() const override { return 3; }
  int StrainSize() const override { return 6; }
  void Check(const Properties&) const override {}
  void CalculateMaterialResponse(ConstitutiveLawParameters&, StressMeasure) override {}

 private:
  std::string name_;
};

/// Geometry implied by a Kratos entity name ("...2D4N", "...3D8N"; 3D4N is a quadrilateral for
/// conditions and membranes, a tetrahedron for solids).
GeometryType GeometryTypeOfName(const std::string& name, bool is_condition);
void RegisterElement(const std::string& name);
void RegisterCondition(const std::string& name);
void RegisterLaw(const std::string& name);
/// Registers every name found after "Begin Elements" / "Begin Conditions" in mdpa text.
void RegisterEntitiesNamedIn(const std::string& mdpa_text);

std::string ReadFile(const std::string& path);
std::string CasesDir();
/// Every file under the Kratos cases folder whose name ends with `suffix`, sorted.
std::vector<std::string> CaseFiles(const std::string& suffix);

/// Asserts (gtest) that two model parts hold the same entities, values and sub-model-parts.
void ExpectSameModelPart(const ModelPart& a, const ModelPart& b);

}  // namespace mc::test
