// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometries/geometry.h"
#include "core/model/process_info.h"
#include "core/model/properties.h"
#include "core/variables/data_value_container.h"
#include "core/variables/flags.h"

namespace mc {

using EquationIdVectorType = std::vector<std::int64_t>;
using DofsVectorType = std::vector<Dof*>;

/// What elements and conditions have in common: a geometry, properties, flags, values and the
/// finite-element interface the builders, schemes and strategies call. Element and Condition
/// derive from it so that assembly code is written once for both.
///
/// Local systems use dynamic Eigen types; builders keep one per thread and reuse it, so no
/// allocation happens once the first entity of each size has been seen.
class Entity {
 public:
  Entity(IndexType id, Geometry geometry, Properties* properties)
      : id_(id), geometry_(std::move(geometry)), properties_(properties) {}
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;
  virtual ~Entity() = default;

  /// The registered name of the class (e.g. "SmallDisplacementElement2D4N" is built by the
  /// class named "SmallDisplacementElement").
  virtual std::string Info() const = 0;

  /// The name this entity was created with through the registry ("SmallDisplacementElement2D4N"),
  /// empty for entities built directly. Writers use it to name the entity in output files.
  const std::string& RegisteredName() const noexcept;
  /// `name` must outlive the entity (registry names are interned for the program's lifetime).
  void SetRegisteredName(const std::string* name) noexcept { registered_name_ = name; }

  IndexType Id() const noexcept { return id_; }
  void SetId(IndexType id) noexcept { id_ = id; }
  Geometry& GetGeometry() noexcept { return geometry_; }
  const Geometry& GetGeometry() const noexcept { return geometry_; }
  Properties& GetProperties() const { return *properties_; }
  Properties* pGetProperties() const noexcept { return properties_; }
  void SetProperties(Properties* properties) noexcept { properties_ = properties; }
  bool HasProperties() const noexcept { return properties_ != nullptr; }

  Flags& GetFlags() noexcept { return flags_; }
  const Flags& GetFlags() const noexcept { return flags_; }
  bool Is(const Flag& f) const noexcept { return flags_.Is(f); }
  void Set(const Flag& f, bool value = true) noexcept { flags_.Set(f, value); }
  /// Inactive when ACTIVE is explicitly false; builders skip inactive entities.
  bool IsActive() const noexcept { return !flags_.IsDefined(ACTIVE) || flags_.Is(ACTIVE); }

  DataValueContainer& Data() noexcept { return values_; }
  const DataValueContainer& Data() const noexcept { return values_; }
  template <class T>
  T GetValue(const Variable<T>& var) const {
    return values_.GetValue(var);
  }
  template <class T, class U>
  void SetValue(const Variable<T>& var, U&& value) {
    values_.SetValue(var, std::forward<U>(value));
  }
  template <class T>
  bool Has(const Variable<T>& var) const noexcept {
    return values_.Has(var);
  }

  // Degrees of freedom --------------------------------------------------------------------
  virtual void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const = 0;
  /// Default: the equation ids of GetDofList.
  virtual void EquationIdVector(EquationIdVectorType& ids, const ProcessInfo& info) const;

  // Local systems ---------------------------------------------------------------------------
  /// LHS = d(residual)/d(unknowns), RHS = external - internal forces (the residual).
  virtual void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info);
  virtual void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info);
  virtual void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info);
  /// Default: empty (size 0) matrices, meaning no contribution.
  virtual void CalculateMassMatrix(Matrix& mass, const ProcessInfo& info);
  virtual void CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info);
  /// Nodal unknowns, their first and second time derivatives, in the GetDofList order. The
  /// defaults read the DoF values and, for DISPLACEMENT and ROTATION components, VELOCITY /
  /// ACCELERATION and ANGULAR_VELOCITY / ANGULAR_ACCELERATION (zero for other DoFs).
  virtual void GetValuesVector(Vector& values, int step = 0) const;
  virtual void GetFirstDerivativesVector(Vector& values, int step = 0) const;
  virtual void GetSecondDerivativesVector(Vector& values, int step = 0) const;

  // Life cycle ------------------------------------------------------------------------------
  virtual void Initialize(const ProcessInfo& info) {}
  virtual void InitializeSolutionStep(const ProcessInfo& info) {}
  virtual void InitializeNonLinearIteration(const ProcessInfo& info) {}
  virtual void FinalizeNonLinearIteration(const ProcessInfo& info) {}
  virtual void FinalizeSolutionStep(const ProcessInfo& info) {}
  /// Validates data (properties, variables, DoFs); throws InputError naming the entity.
  virtual void Check(const ProcessInfo& info) const {}

  // Results at integration points -----------------------------------------------------------
  virtual void CalculateOnIntegrationPoints(const Variable<double>& var, std::vector<double>& out,
                                            const ProcessInfo& info);
  virtual void CalculateOnIntegrationPoints(const Variable<Array3>& var, std::vector<Array3>& out,
                                            const ProcessInfo& info);
  virtual void CalculateOnIntegrationPoints(const Variable<Vector>& var, std::vector<Vector>& out,
                                            const ProcessInfo& info);
  virtual void CalculateOnIntegrationPoints(const Variable<Matrix>& var, std::vector<Matrix>& out,
                                            const ProcessInfo& info);
  /// Number of integration points the results above refer to.
  virtual int NumberOfIntegrationPoints() const;

 private:
  IndexType id_;
  const std::string* registered_name_ = nullptr;
  Geometry geometry_;
  Properties* properties_;
  Flags flags_;
  DataValueContainer values_;
};

}  // namespace mc
