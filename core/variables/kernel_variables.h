// SPDX-License-Identifier: BSD-3-Clause
// The variables every mortarcontact program knows, named as in Kratos so that mdpa files,
// materials and settings carry over unchanged. Applications define more the same way.
#pragma once

#include "core/variables/variable.h"

#define MC_DECLARE_VARIABLE(type, NAME) extern const ::mc::Variable<type> NAME
#define MC_DECLARE_ARRAY3_VARIABLE(NAME)          \
  extern const ::mc::Variable<::mc::Array3> NAME; \
  extern const ::mc::Variable<double> NAME##_X;   \
  extern const ::mc::Variable<double> NAME##_Y;   \
  extern const ::mc::Variable<double> NAME##_Z

#define MC_DEFINE_VARIABLE(type, NAME) const ::mc::Variable<type> NAME(#NAME)
#define MC_DEFINE_ARRAY3_VARIABLE(NAME)                                 \
  const ::mc::Variable<::mc::Array3> NAME(#NAME, ::mc::Array3::Zero()); \
  const ::mc::Variable<double> NAME##_X(#NAME "_X", NAME, 0);           \
  const ::mc::Variable<double> NAME##_Y(#NAME "_Y", NAME, 1);           \
  const ::mc::Variable<double> NAME##_Z(#NAME "_Z", NAME, 2)

namespace mc {

// Time and control (ProcessInfo).
MC_DECLARE_VARIABLE(double, TIME);
MC_DECLARE_VARIABLE(double, DELTA_TIME);
/// ProcessInfo: the DELTA_TIME of the step before the current one (set by CloneTimeStep).
MC_DECLARE_VARIABLE(double, PREVIOUS_DELTA_TIME);
MC_DECLARE_VARIABLE(int, STEP);
MC_DECLARE_VARIABLE(int, NL_ITERATION_NUMBER);
MC_DECLARE_VARIABLE(int, DOMAIN_SIZE);
MC_DECLARE_VARIABLE(bool, IS_RESTARTED);
MC_DECLARE_VARIABLE(bool, COMPUTE_LUMPED_MASS_MATRIX);
/// ProcessInfo: the step is solved as a linear problem (analysis_type linear, LinearStrategy), so
/// entities leave out the stiffness of their dependence on the current configuration.
MC_DECLARE_VARIABLE(bool, LINEAR_ANALYSIS);
MC_DECLARE_VARIABLE(double, RAYLEIGH_ALPHA);
MC_DECLARE_VARIABLE(double, RAYLEIGH_BETA);
MC_DECLARE_VARIABLE(double, BOSSAK_ALPHA);
MC_DECLARE_VARIABLE(double, NEWMARK_BETA);
MC_DECLARE_VARIABLE(double, NEWMARK_GAMMA);

// Kinematics and reactions.
MC_DECLARE_ARRAY3_VARIABLE(DISPLACEMENT);
MC_DECLARE_ARRAY3_VARIABLE(REACTION);
MC_DECLARE_ARRAY3_VARIABLE(VELOCITY);
MC_DECLARE_ARRAY3_VARIABLE(ACCELERATION);
MC_DECLARE_ARRAY3_VARIABLE(ROTATION);
MC_DECLARE_ARRAY3_VARIABLE(REACTION_MOMENT);
MC_DECLARE_ARRAY3_VARIABLE(ANGULAR_VELOCITY);
MC_DECLARE_ARRAY3_VARIABLE(ANGULAR_ACCELERATION);
MC_DECLARE_ARRAY3_VARIABLE(NORMAL);
MC_DECLARE_VARIABLE(double, TEMPERATURE);
MC_DECLARE_VARIABLE(double, NODAL_H);
MC_DECLARE_VARIABLE(double, NODAL_AREA);
MC_DECLARE_VARIABLE(double, NODAL_MASS);

// Loads.
MC_DECLARE_ARRAY3_VARIABLE(VOLUME_ACCELERATION);
MC_DECLARE_ARRAY3_VARIABLE(POINT_LOAD);
MC_DECLARE_ARRAY3_VARIABLE(POINT_MOMENT);
MC_DECLARE_ARRAY3_VARIABLE(LINE_LOAD);
MC_DECLARE_ARRAY3_VARIABLE(SURFACE_LOAD);
MC_DECLARE_ARRAY3_VARIABLE(FORCE);
MC_DECLARE_VARIABLE(double, POSITIVE_FACE_PRESSURE);
MC_DECLARE_VARIABLE(double, NEGATIVE_FACE_PRESSURE);
MC_DECLARE_VARIABLE(double, PRESSURE);

// Material properties.
MC_DECLARE_VARIABLE(double, YOUNG_MODULUS);
MC_DECLARE_VARIABLE(double, POISSON_RATIO);
MC_DECLARE_VARIABLE(double, DENSITY);
MC_DECLARE_VARIABLE(double, THICKNESS);
MC_DECLARE_VARIABLE(double, FRICTION_COEFFICIENT);
MC_DECLARE_VARIABLE(int, INTEGRATION_ORDER);

// Integration-point results.
MC_DECLARE_VARIABLE(double, VON_MISES_STRESS);
MC_DECLARE_VARIABLE(Vector, CAUCHY_STRESS_VECTOR);
MC_DECLARE_VARIABLE(Vector, PK2_STRESS_VECTOR);
MC_DECLARE_VARIABLE(Vector, GREEN_LAGRANGE_STRAIN_VECTOR);
MC_DECLARE_VARIABLE(Vector, STRAIN);
MC_DECLARE_VARIABLE(Matrix, CAUCHY_STRESS_TENSOR);
MC_DECLARE_VARIABLE(Matrix, PK2_STRESS_TENSOR);
MC_DECLARE_VARIABLE(Matrix, GREEN_LAGRANGE_STRAIN_TENSOR);
MC_DECLARE_VARIABLE(double, STRAIN_ENERGY);

}  // namespace mc
