// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "core/variables/value_types.h"

namespace mc {

class Properties;
class ProcessInfo;
class Geometry;

/// Everything a law needs at one integration point, and what it returns. Strains and stresses
/// are in Voigt notation of the law's strain size: 3 (xx, yy, xy) in plane strain/stress,
/// 4 (rr, zz, rz, theta-theta) in axisymmetry, 6 (xx, yy, zz, xy, yz, xz) in 3D; engineering
/// shear strains.
struct ConstitutiveLawParameters {
  const Properties* properties = nullptr;
  const ProcessInfo* process_info = nullptr;
  /// Deformation gradient, always 3x3 (2D: F(2,2) = 1 in plane strain, r/R in axisymmetry).
  /// Small-strain elements pass the symmetric I + eps instead (Kratos' "equivalent" F).
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  double detF = 1.0;
  /// Set by small-strain elements: `strain` is infinitesimal and F = I + eps.
  bool small_strain = false;
  /// Input strain: infinitesimal for small-strain elements, Green-Lagrange for finite strain.
  Vector strain;
  /// Output: stress in the measure asked for, and its tangent d stress / d strain.
  Vector stress;
  Matrix tangent;
  bool compute_stress = true;
  bool compute_tangent = true;
};

/// A material model. Properties hold one prototype; elements clone it per integration point
/// so that laws with internal variables keep them there.
class ConstitutiveLaw {
 public:
  /// The stress measure returned by CalculateMaterialResponse, with its energetic conjugate
  /// strain: PK2 with Green-Lagrange (also the small-strain case, where they coincide with
  /// Cauchy and infinitesimal strain), Kirchhoff with Almansi in the current configuration.
  enum class StressMeasure { PK2, Kirchhoff, Cauchy };

  virtual ~ConstitutiveLaw() = default;
  virtual std::string Name() const = 0;
  virtual std::unique_ptr<ConstitutiveLaw> Clone() const = 0;

  /// 2 or 3.
  virtual int WorkingSpaceDimension() const = 0;
  /// 3 (plane), 4 (axisymmetric) or 6 (3D).
  virtual int StrainSize() const = 0;
  /// True when the law needs the deformation gradient (hyperelastic laws).
  virtual bool IsFiniteStrain() const { return false; }
  /// True when the tangent does not depend on the strain (a linear law): an element with
  /// linear kinematics then has a stiffness that stays the same through a solution step.
  virtual bool HasConstantTangent() const { return false; }

  /// Validates the properties: throws InputError naming the property id, the variable and
  /// the offending value (missing, negative, zero, NaN, out of range).
  virtual void Check(const Properties& properties) const = 0;

  virtual void InitializeMaterial(const Properties& properties, const Geometry& geometry, const Vector& N) {}
  virtual void CalculateMaterialResponse(ConstitutiveLawParameters& values, StressMeasure measure) = 0;
  /// Commits internal variables at the end of a converged step.
  virtual void FinalizeMaterialResponse(ConstitutiveLawParameters& values, StressMeasure measure) {}
  /// Stored energy density (for outputs and energy checks).
  virtual double StrainEnergy(ConstitutiveLawParameters& values) { return 0.0; }
};

}  // namespace mc
