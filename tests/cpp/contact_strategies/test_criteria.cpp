// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (contact criteria): block norms split by DoF variable (displacement / rotation /
// multiplier) against hand-computed ratios, each criterion's convergence decision, the
// ensure_contact rule, settings validation, the mortar-and table columns and the condition
// number estimate. Issue 12 (friction): the normal / stick / slip multiplier blocks, the
// ratio_normal_tangent_threshold acceptance, the frictional mortar criteria and their column.
#include <gtest/gtest.h>

#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"
#include "custom_strategies/custom_convergencecriterias/condition_number_utility.h"
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictionless_mortar_criteria.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

// Node 1: u = (3, 4), lambda = -2 (eqs 0, 1, 2); node 2: u_x fixed (eq 3), u_y = 0 (eq 4),
// lambda = 0 (eq 5). Free displacement DoFs: 3, |u| = 5; multipliers: 2, |lambda| = 2.
struct Synthetic {
  Model model;
  ModelPart& mp = model.CreateModelPart("Structure", 2);
  std::vector<Dof*> dofs;
  Vector dx = Vector::Zero(6);
  Vector b = Vector::Zero(6);
  SparseMatrix A{6, 6};
  Synthetic() {
    for (const VariableData* v : std::initializer_list<const VariableData*>{
             &DISPLACEMENT, &ROTATION, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, &WEIGHTED_GAP, &NORMAL})
      mp.AddNodalSolutionStepVariable(*v);
    ModelPart& contact = mp.CreateSubModelPart("Contact");
    for (IndexType id : {1, 2}) {
      Node& n = contact.CreateNewNode(id, double(id), 0.0, 0.0);
      for (const Variable<double>* v : {&DISPLACEMENT_X, &DISPLACEMENT_Y, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE}) {
        Dof& d = n.AddDof(*v);
        d.equation_id = static_cast<std::int64_t>(dofs.size());
        dofs.push_back(&d);
      }
    }
    mp.GetNode(2).Fix(DISPLACEMENT_X);
    Set(0, 3.0);
    Set(1, 4.0);
    Set(2, -2.0);
    Set(3, 7.0);
    dx << 0.003, 0.004, 1e-3, 100.0, 0.0, 0.0;
    b << 6.0, 8.0, 0.5, 999.0, 0.0, 0.0;
    mp.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 2);
  }
  void Set(int eq, double value) { dofs[eq]->Value() = value; }
  template <class C>
  bool Check(C& c) {
    c.InitializeSolutionStep(mp, dofs, A, dx, b);
    return c.PostCriteria(mp, dofs, A, dx, b);
  }
};

void ExpectValues(const std::vector<CriterionValue>& values,
                  const std::vector<std::pair<std::string, double>>& expected) {
  ASSERT_EQ(values.size(), expected.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(values[i].name, expected[i].first);
    EXPECT_NEAR(values[i].value, expected[i].second, 1e-15 + 1e-12 * std::abs(expected[i].second)) << values[i].name;
  }
}

TEST(ContactCriteria, TableRowsHaveKratosNamesKeysAndDefaults) {
  const auto expect = [](const Parameters& defaults, const std::string& name, std::vector<std::string> prefixes) {
    EXPECT_EQ(defaults["name"].GetString(), name);
    EXPECT_FALSE(defaults["ensure_contact"].GetBool());
    EXPECT_FALSE(defaults["print_convergence_criterion"].GetBool());
    EXPECT_EQ(defaults.size(), 3 + 2 * prefixes.size()) << name;
    for (const std::string& prefix : prefixes) {
      EXPECT_EQ(defaults[prefix + "_relative_tolerance"].GetDouble(), 1e-4) << name;
      EXPECT_EQ(defaults[prefix + "_absolute_tolerance"].GetDouble(), 1e-9) << name;
    }
  };
  expect(DisplacementContactCriteria::GetDefaultParameters(), "displacement_contact_criteria",
         {"displacement", "rotation"});
  expect(DisplacementResidualContactCriteria::GetDefaultParameters(), "displacement_residual_contact_criteria",
         {"residual", "rotation_residual"});
  expect(DisplacementLagrangeMultiplierContactCriteria::GetDefaultParameters(),
         "displacement_lagrangemultiplier_contact_criteria", {"displacement", "rotation", "contact_displacement"});
  expect(DisplacementLagrangeMultiplierResidualContactCriteria::GetDefaultParameters(),
         "displacement_lagrangemultiplier_residual_contact_criteria",
         {"residual", "rotation_residual", "contact_residual"});
  expect(DisplacementLagrangeMultiplierMixedContactCriteria::GetDefaultParameters(),
         "displacement_lagrange_multiplier_mixed_contact_criteria",
         {"residual", "rotation_residual", "contact_displacement"});
  EXPECT_EQ(DisplacementContactCriteria().Name(), "displacement_contact_criteria");
  EXPECT_FALSE(DisplacementContactCriteria().GetActualizeRHSFlag());
  EXPECT_TRUE(DisplacementLagrangeMultiplierMixedContactCriteria().GetActualizeRHSFlag());
}

TEST(ContactCriteria, IncrementBlocksAgainstHandValues) {
  Synthetic s;
  DisplacementLagrangeMultiplierContactCriteria c(Parameters(R"({"displacement_relative_tolerance": 1e-2,
      "contact_displacement_relative_tolerance": 1e-4, "contact_displacement_absolute_tolerance": 1e-9})"));
  EXPECT_EQ(c.Name(), "displacement_lagrangemultiplier_contact_criteria");
  // |du| = 0.005 (the fixed DoF is ignored): ratio 1e-3, absolute 0.005 / 3; |dlm| = 1e-3.
  EXPECT_FALSE(s.Check(c));
  ExpectValues(c.LastValues(), {{"|du|/|u|", 1e-3}, {"|du|/n", 0.005 / 3}, {"|dlm|/|lm|", 5e-4}, {"|dlm|/n", 5e-4}});
  EXPECT_TRUE(c.Result(DofFamily::kDisplacement).converged);
  EXPECT_FALSE(c.Result(DofFamily::kMultiplier).converged);
  EXPECT_FALSE(c.Result(DofFamily::kRotation).present);
  // The multiplier block converges through its absolute value.
  DisplacementLagrangeMultiplierContactCriteria loose(Parameters(R"({"displacement_relative_tolerance": 1e-2,
      "contact_displacement_absolute_tolerance": 6e-4})"));
  EXPECT_TRUE(s.Check(loose));
}

TEST(ContactCriteria, DisplacementOnlyCriteriaIgnoreMultipliers) {
  Synthetic s;
  DisplacementContactCriteria c(Parameters(R"({"displacement_relative_tolerance": 1e-3})"));
  EXPECT_TRUE(s.Check(c));  // 1e-3 <= 1e-3; the unconverged multipliers are not measured
  ExpectValues(c.LastValues(), {{"|du|/|u|", 1e-3}, {"|du|/n", 0.005 / 3}});
  DisplacementResidualContactCriteria r;
  EXPECT_EQ(r.Name(), "displacement_residual_contact_criteria");
  EXPECT_FALSE(s.Check(r));
  ExpectValues(r.LastValues(), {{"|r_u|^2/|r_u0|^2", 1.0}, {"|r_u|^2/n", 100.0 / 3}});
}

TEST(ContactCriteria, ResidualBlocksUseTheFirstResidualOfTheStep) {
  Synthetic s;
  DisplacementLagrangeMultiplierResidualContactCriteria c(Parameters(R"({"residual_relative_tolerance": 1e-3,
      "contact_residual_relative_tolerance": 1e-4})"));
  EXPECT_TRUE(c.GetActualizeRHSFlag());
  EXPECT_FALSE(s.Check(c));
  ExpectValues(
      c.LastValues(),
      {{"|r_u|^2/|r_u0|^2", 1.0}, {"|r_u|^2/n", 100.0 / 3}, {"|r_lm|^2/|r_lm0|^2", 1.0}, {"|r_lm|^2/n", 0.125}});
  s.b << 0.006, 0.008, 5e-5, 999.0, 0.0, 0.0;
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  // Squared norms, as in Kratos: |r_u| fell by 1e-3, |r_lm| by 1e-4.
  ExpectValues(
      c.LastValues(),
      {{"|r_u|^2/|r_u0|^2", 1e-6}, {"|r_u|^2/n", 1e-4 / 3}, {"|r_lm|^2/|r_lm0|^2", 1e-8}, {"|r_lm|^2/n", 1.25e-9}});
  // A new step takes a new reference.
  EXPECT_FALSE(s.Check(c));
  EXPECT_DOUBLE_EQ(c.LastValues()[0].value, 1.0);
}

TEST(ContactCriteria, MixedMeasuresResidualForDisplacementsAndIncrementForMultipliers) {
  Synthetic s;
  DisplacementLagrangeMultiplierMixedContactCriteria c(
      Parameters(R"({"contact_displacement_relative_tolerance": 1e-3})"));
  EXPECT_EQ(c.Name(), "displacement_lagrange_multiplier_mixed_contact_criteria");
  EXPECT_FALSE(s.Check(c));
  ExpectValues(c.LastValues(),
               {{"|r_u|^2/|r_u0|^2", 1.0}, {"|r_u|^2/n", 100.0 / 3}, {"|dlm|/|lm|", 5e-4}, {"|dlm|/n", 5e-4}});
  EXPECT_FALSE(c.Result(DofFamily::kDisplacement).converged);
  EXPECT_TRUE(c.Result(DofFamily::kMultiplier).converged);
}

TEST(ContactCriteria, RotationBlockAppearsWithRotationDofs) {
  Synthetic s;
  Node& n = s.mp.GetNode(1);
  Dof& w = n.AddDof(ROTATION_Z);
  w.equation_id = 6;
  s.dofs.push_back(&w);
  w.Value() = 0.5;
  s.dx.conservativeResize(7);
  s.b.conservativeResize(7);
  s.dx[6] = 0.25;
  s.b[6] = 0.0;
  DisplacementContactCriteria c(Parameters(R"({"rotation_relative_tolerance": 0.4})"));
  EXPECT_FALSE(s.Check(c));  // displacements: 1e-3 > 1e-4
  ExpectValues(c.LastValues(), {{"|du|/|u|", 1e-3}, {"|du|/n", 0.005 / 3}, {"|dw|/|w|", 0.5}, {"|dw|/n", 0.25}});
  EXPECT_FALSE(c.Result(DofFamily::kRotation).converged);
}

TEST(ContactCriteria, ZeroMultipliersMeanNoContact) {
  Synthetic s;
  s.Set(2, 0.0);
  s.dx[2] = 0.0;
  DisplacementLagrangeMultiplierContactCriteria lenient(Parameters(R"({"displacement_relative_tolerance": 1e-2})"));
  EXPECT_TRUE(s.Check(lenient));
  DisplacementLagrangeMultiplierContactCriteria strict(
      Parameters(R"({"displacement_relative_tolerance": 1e-2, "ensure_contact": true})"));
  try {
    s.Check(strict);
    FAIL() << "expected a SolutionError";
  } catch (const SolutionError& e) {
    EXPECT_NE(std::string(e.what()).find("ensure_contact is true but every Lagrange multiplier is zero at iteration 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(ContactCriteria, SettingsAreValidatedWithSuggestions) {
  try {
    DisplacementLagrangeMultiplierContactCriteria c(Parameters(R"({"contact_displacement_relative_tolerence": 1e-3})"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact_displacement_relative_tolerance"), std::string::npos) << e.what();
  }
  EXPECT_THROW(DisplacementContactCriteria(Parameters(R"({"displacement_relative_tolerance": -1.0})")), InputError);
  // The active-set criteria read their keys from the solver's contact_settings, whose other keys
  // they leave to the solver's validation; a value of the wrong type names its key.
  EXPECT_TRUE(ALMFrictionlessMortarConvergenceCriteria(Parameters(R"({"mortar_type": "ALMContactFrictionless",
                                                                      "print_convergence_criterion": true})"))
                  .PrintConvergenceCriterion());
  try {
    ALMFrictionlessMortarConvergenceCriteria c(Parameters(R"({"compute_dynamic_factor": 1})"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compute_dynamic_factor"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ALMFrictionlessMortarConvergenceCriteria().Name(), "alm_frictionless_mortar_criteria");
  EXPECT_EQ(PenaltyFrictionlessMortarConvergenceCriteria().Name(), "penalty_frictionless_mortar_criteria");
}

TEST(ContactCriteria, MortarAndTableColumnsAndDecision) {
  Synthetic s;
  s.mp.Set(INTERACTION, true);
  s.mp.GetProcessInfo().SetValue(SCALE_FACTOR, 1.0);
  s.mp.GetProcessInfo().SetValue(INITIAL_PENALTY, 10.0);
  Node& slave = s.mp.GetNode(1);
  slave.Set(SLAVE, true);
  slave.FastGetSolutionStepValue(WEIGHTED_GAP) = 0.5;  // 1 * -2 + 10 * 0.5 = 3 > 0: releases
  slave.Set(ACTIVE, true);
  auto mechanical = std::make_shared<DisplacementLagrangeMultiplierContactCriteria>(
      Parameters(R"({"displacement_relative_tolerance": 1e-2, "contact_displacement_relative_tolerance": 1e-3})"));
  auto mortar = std::make_shared<ALMFrictionlessMortarConvergenceCriteria>();
  MortarAndConvergenceCriteria c(mechanical, mortar, false, ConditionNumberUtility{});
  EXPECT_EQ(c.Name(), "mortar_and_criteria");
  EXPECT_TRUE(c.GetActualizeRHSFlag());
  s.A.setIdentity();
  s.A.coeffRef(0, 0) = 4.0;
  s.A.coeffRef(5, 5) = 0.5;
  c.InitializeSolutionStep(s.mp, s.dofs, s.A, s.dx, s.b);
  EXPECT_EQ(c.TableHeader(), (std::vector<std::string>{"ITER", "COND.NUM.", "|du|/|u|", "|du|/n", "|dlm|/|lm|",
                                                       "|dlm|/n", "CONVERGENCE", "ACTIVE SET CONV"}));
  EXPECT_FALSE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  EXPECT_TRUE(c.MechanicalConverged());
  EXPECT_FALSE(c.ActiveSetConverged());
  EXPECT_FALSE(slave.Is(ACTIVE));
  EXPECT_FALSE(s.mp.GetProcessInfo().GetValue(ACTIVE_SET_CONVERGED));
  EXPECT_EQ(c.LastTableRow(), (std::vector<std::string>{"2", "8.000e+00", "1.000e-03", "1.667e-03", "5.000e-04",
                                                        "5.000e-04", "yes", "no (1)"}));
  // Same state again: the set holds, both converge.
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  EXPECT_EQ(c.LastTableRow().back(), "yes");
  // Simplified semi-smooth Newton: without INTERACTION the set is only evaluated at iteration 1.
  s.mp.Set(INTERACTION, false);
  slave.FastGetSolutionStepValue(WEIGHTED_GAP) = -0.5;
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  EXPECT_FALSE(slave.Is(ACTIVE));
  s.mp.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
  EXPECT_FALSE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  EXPECT_TRUE(slave.Is(ACTIVE));
}

TEST(ContactCriteria, ConditionNumberEstimate) {
  SparseMatrix d(3, 3);
  d.insert(0, 0) = 1.0;
  d.insert(1, 1) = -2.0;
  d.insert(2, 2) = 10.0;
  d.makeCompressed();
  EXPECT_NEAR(ConditionNumberUtility{}.Estimate(d), 10.0, 1e-6);
  SparseMatrix s(2, 2);  // eigenvalues 1 and 3
  s.insert(0, 0) = 2.0;
  s.insert(0, 1) = 1.0;
  s.insert(1, 0) = 1.0;
  s.insert(1, 1) = 2.0;
  s.makeCompressed();
  EXPECT_NEAR(ConditionNumberUtility{}.Estimate(s), 3.0, 1e-6);
  SparseMatrix singular(2, 2);
  singular.insert(0, 0) = 1.0;
  singular.makeCompressed();
  EXPECT_TRUE(std::isinf(ConditionNumberUtility{}.Estimate(singular)));
}

// Node 1: u = (3, 4) (eqs 0, 1), normal (0, 1, 0), sticking, lambda = (1, -2, 0) (eqs 2-4): normal
// part 2, tangential (1, 0, 0). Node 2: normal (1, 0, 0), slipping, lambda = (-4, 0, 3) (eqs 5-7):
// normal part 4, tangential (0, 0, 3). |lm_n| = sqrt(20), |lm_st| = 1, |lm_sl| = 3.
struct SyntheticFrictional {
  Model model;
  ModelPart& mp = model.CreateModelPart("Structure", 3);
  std::vector<Dof*> dofs;
  Vector dx = Vector::Zero(8);
  Vector b = Vector::Zero(8);
  SparseMatrix A{8, 8};
  SyntheticFrictional() {
    for (const VariableData* v :
         std::initializer_list<const VariableData*>{&DISPLACEMENT, &VECTOR_LAGRANGE_MULTIPLIER, &NORMAL})
      mp.AddNodalSolutionStepVariable(*v);
    Node& n1 = mp.CreateNewNode(1, 0.0, 0.0, 0.0);
    Node& n2 = mp.CreateNewNode(2, 1.0, 0.0, 0.0);
    for (auto [node, variable] :
         std::initializer_list<std::pair<Node*, const Variable<double>*>>{{&n1, &DISPLACEMENT_X},
                                                                          {&n1, &DISPLACEMENT_Y},
                                                                          {&n1, &VECTOR_LAGRANGE_MULTIPLIER_X},
                                                                          {&n1, &VECTOR_LAGRANGE_MULTIPLIER_Y},
                                                                          {&n1, &VECTOR_LAGRANGE_MULTIPLIER_Z},
                                                                          {&n2, &VECTOR_LAGRANGE_MULTIPLIER_X},
                                                                          {&n2, &VECTOR_LAGRANGE_MULTIPLIER_Y},
                                                                          {&n2, &VECTOR_LAGRANGE_MULTIPLIER_Z}}) {
      Dof& d = node->AddDof(*variable);
      d.equation_id = static_cast<std::int64_t>(dofs.size());
      dofs.push_back(&d);
    }
    n1.FastGetSolutionStepValue(NORMAL) = Array3(0.0, 1.0, 0.0);
    n2.FastGetSolutionStepValue(NORMAL) = Array3(1.0, 0.0, 0.0);
    n2.Set(SLIP, true);
    const double values[] = {3.0, 4.0, 1.0, -2.0, 0.0, -4.0, 0.0, 3.0};
    for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i]->Value() = values[i];
    // Increments: normal 0.002 (node 1) and 0.004 (node 2), stick tangential 0.001, slip none.
    dx << 0.003, 0.004, 0.001, 0.002, 0.0, 0.004, 0.0, 0.0;
    // Residuals: normal 1 (node 1), stick tangential 0.5, slip tangential 2.
    b << 6.0, 8.0, 0.5, 1.0, 0.0, 0.0, 0.0, 2.0;
    mp.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 2);
  }
  template <class C>
  bool Check(C& c) {
    c.InitializeSolutionStep(mp, dofs, A, dx, b);
    return c.PostCriteria(mp, dofs, A, dx, b);
  }
};

TEST(ContactCriteria, FrictionalIncrementBlocksSplitNormalStickSlip) {
  SyntheticFrictional s;
  const double n_abs = std::sqrt(20e-6) / 6;  // six multiplier DoFs
  DisplacementLagrangeMultiplierFrictionalContactCriteria c(Parameters(R"({"displacement_relative_tolerance": 1e-2,
      "contact_displacement_relative_tolerance": 1e-2})"));
  EXPECT_EQ(c.Name(), "displacement_lagrangemultiplier_frictional_contact_criteria");
  EXPECT_FALSE(s.Check(c));
  ExpectValues(c.LastValues(), {{"|du|/|u|", 1e-3},
                                {"|du|/n", 0.005 / 2},
                                {"|dlm_n|/|lm_n|", 1e-3},
                                {"|dlm_n|/n", n_abs},
                                {"|dlm_st|/|lm_st|", 1e-3},
                                {"|dlm_st|/n", 1e-3 / 6},
                                {"|dlm_sl|/|lm_sl|", 0.0},
                                {"|dlm_sl|/n", 0.0}});
  EXPECT_TRUE(c.Result(DofFamily::kMultiplier).converged);
  EXPECT_FALSE(c.Result(DofFamily::kStickMultiplier).converged);
  EXPECT_TRUE(c.Result(DofFamily::kSlipMultiplier).converged);
  // The stick block is 0.2236 of the normal one: accepted with a threshold above that.
  DisplacementLagrangeMultiplierFrictionalContactCriteria ratio(Parameters(R"({
      "displacement_relative_tolerance": 1e-2, "contact_displacement_relative_tolerance": 1e-2,
      "ratio_normal_tangent_threshold": 0.25})"));
  EXPECT_TRUE(s.Check(ratio));
  EXPECT_NEAR(ratio.Result(DofFamily::kStickMultiplier).absolute / ratio.Result(DofFamily::kMultiplier).absolute,
              std::sqrt(0.05), 1e-12);
  // The normal block itself is never accepted by the ratio.
  DisplacementLagrangeMultiplierFrictionalContactCriteria normal(Parameters(R"({
      "displacement_relative_tolerance": 1e-2, "ratio_normal_tangent_threshold": 1e6})"));
  EXPECT_FALSE(s.Check(normal));
  EXPECT_FALSE(normal.Result(DofFamily::kMultiplier).converged);
  // Pure slip: every tangential part is slip (|lm_sl| = sqrt(10)) and there is no stick column.
  DisplacementLagrangeMultiplierFrictionalContactCriteria pure(Parameters(R"({"pure_slip": true})"));
  EXPECT_TRUE(pure.PureSlip());
  s.Check(pure);
  EXPECT_FALSE(pure.Result(DofFamily::kStickMultiplier).present);
  EXPECT_NEAR(pure.Result(DofFamily::kSlipMultiplier).ratio, 1e-3 / std::sqrt(10.0), 1e-15);
  EXPECT_EQ(pure.LastValues().size(), 6u);
  // Without SLIP on node 2 its tangential part is stick: |lm_st| = sqrt(10).
  s.mp.GetNode(2).Set(SLIP, false);
  s.Check(c);
  EXPECT_NEAR(c.Result(DofFamily::kStickMultiplier).ratio, 1e-3 / std::sqrt(10.0), 1e-15);
  EXPECT_DOUBLE_EQ(c.Result(DofFamily::kSlipMultiplier).ratio, 0.0);
}

TEST(ContactCriteria, FrictionalResidualBlocksTakeTheirFirstResidual) {
  SyntheticFrictional s;
  DisplacementLagrangeMultiplierResidualFrictionalContactCriteria c;
  EXPECT_EQ(c.Name(), "displacement_lagrangemultiplier_ressidual_frictional_contact_criteria");
  EXPECT_TRUE(c.GetActualizeRHSFlag());
  EXPECT_FALSE(s.Check(c));
  ExpectValues(c.LastValues(), {{"|r_u|^2/|r_u0|^2", 1.0},
                                {"|r_u|^2/n", 50.0},
                                {"|r_lm_n|^2/|r_lm_n0|^2", 1.0},
                                {"|r_lm_n|^2/n", 1.0 / 6},
                                {"|r_lm_st|^2/|r_lm_st0|^2", 1.0},
                                {"|r_lm_st|^2/n", 0.25 / 6},
                                {"|r_lm_sl|^2/|r_lm_sl0|^2", 1.0},
                                {"|r_lm_sl|^2/n", 4.0 / 6}});
  s.b *= 1e-3;
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, s.dx, s.b));
  EXPECT_NEAR(c.Result(DofFamily::kSlipMultiplier).ratio, 1e-6, 1e-18);
}

TEST(ContactCriteria, MixedFrictionalKeepsKratosToleranceKeys) {
  const Parameters defaults = DisplacementLagrangeMultiplierMixedFrictionalContactCriteria::GetDefaultParameters();
  EXPECT_EQ(defaults["name"].GetString(), "displacement_lagrangemultiplier_mixed_frictional_contact_criteria");
  EXPECT_EQ(defaults["frictional_stick_contact_residual_relative_tolerance"].GetDouble(), 1e-9);
  EXPECT_EQ(defaults["ratio_normal_tangent_threshold"].GetDouble(), 1e-4);
  EXPECT_FALSE(defaults["pure_slip"].GetBool());
  EXPECT_FALSE(defaults.Has("frictional_stick_contact_displacement_absolute_tolerance"));
  DisplacementLagrangeMultiplierMixedFrictionalContactCriteria own(
      Parameters(R"({"frictional_stick_contact_residual_relative_tolerance": 5e-3})"));
  EXPECT_EQ(own.Configuration(DofFamily::kStickMultiplier)->absolute_tolerance, 5e-3);
  EXPECT_EQ(own.Configuration(DofFamily::kStickMultiplier)->measure, BlockContactCriteria::Measure::kIncrement);
  EXPECT_EQ(own.Configuration(DofFamily::kDisplacement)->measure, BlockContactCriteria::Measure::kResidual);
  // From a contact solver's settings the absolute tolerance is the ..._residual_absolute_tolerance key.
  Parameters contact = BlockContactCriteria::GetContactSettingsDefaults();
  contact.AddBool("print_convergence_criterion", false);
  contact["frictional_slip_contact_residual_absolute_tolerance"].SetDouble(7e-3);
  contact["ratio_normal_tangent_threshold"].SetDouble(0.5);
  const Parameters solver(R"({"residual_relative_tolerance": 1e-4, "residual_absolute_tolerance": 1e-9})");
  DisplacementLagrangeMultiplierMixedFrictionalContactCriteria solver_criterion(solver, contact, true);
  EXPECT_EQ(solver_criterion.Configuration(DofFamily::kSlipMultiplier)->absolute_tolerance, 7e-3);
  EXPECT_EQ(solver_criterion.RatioNormalTangentThreshold(), 0.5);
  EXPECT_TRUE(solver_criterion.PureSlip());
  // The contact_settings block declares each frictional key once, with the spec's defaults.
  for (const char* key : {"frictional_stick_contact_displacement_relative_tolerance",
                          "frictional_stick_contact_residual_relative_tolerance",
                          "frictional_slip_contact_displacement_relative_tolerance",
                          "frictional_slip_contact_residual_relative_tolerance"})
    EXPECT_EQ(BlockContactCriteria::GetContactSettingsDefaults()[key].GetDouble(), 1e-4) << key;
  EXPECT_EQ(
      BlockContactCriteria::GetContactSettingsDefaults()["frictional_stick_contact_displacement_absolute_tolerance"]
          .GetDouble(),
      1e-9);
  EXPECT_THROW(DisplacementLagrangeMultiplierFrictionalContactCriteria(
                   Parameters(R"({"ratio_normal_tangent_threshold": -1.0})")),
               InputError);
}

TEST(ContactCriteria, CreateByKratosNameAcceptsBothSpellings) {
  const auto sic = BlockContactCriteria::Create(
      Parameters(R"({"name": "displacement_lagrangemultiplier_ressidual_frictional_contact_criteria"})"));
  const auto right = BlockContactCriteria::Create(Parameters(
      R"({"name": "displacement_lagrangemultiplier_residual_frictional_contact_criteria", "pure_slip": true})"));
  EXPECT_EQ(sic->Name(), "displacement_lagrangemultiplier_ressidual_frictional_contact_criteria");
  EXPECT_EQ(right->Name(), sic->Name());
  EXPECT_TRUE(right->PureSlip());
  EXPECT_EQ(BlockContactCriteria::Create(Parameters(R"({"name": "displacement_contact_criteria"})"))->Name(),
            "displacement_contact_criteria");
  try {
    BlockContactCriteria::Create(Parameters(R"({"name": "displacement_lagrangemultiplier_frictional_criteria"})"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("displacement_lagrangemultiplier_frictional_contact_criteria"),
              std::string::npos)
        << e.what();
  }
}

// One slave node, n = (0, 1, 0), k = 2, eps = 8, c_tau = 0.5, mu = 0.25, active and sticking with
// lambda = (0.125, -1, 0): lbar_n = -2, limit 0.5; its weighted slip decides stick or slip.
struct FrictionalContact {
  Model model;
  ModelPart& mp = model.CreateModelPart("Structure", 3);
  Node* node = nullptr;
  std::vector<Dof*> dofs;
  Vector v = Vector::Zero(0);
  SparseMatrix A{0, 0};
  FrictionalContact() {
    for (const VariableData* var : std::initializer_list<const VariableData*>{&VECTOR_LAGRANGE_MULTIPLIER,
                                                                              &WEIGHTED_GAP, &WEIGHTED_SLIP, &NORMAL})
      mp.AddNodalSolutionStepVariable(*var);
    mp.Set(INTERACTION, true);
    ProcessInfo& info = mp.GetProcessInfo();
    info.SetValue(SCALE_FACTOR, 2.0);
    info.SetValue(INITIAL_PENALTY, 8.0);
    info.SetValue(TANGENT_FACTOR, 0.5);
    info.SetValue(NL_ITERATION_NUMBER, 2);
    node = &mp.CreateSubModelPart("Contact").CreateNewNode(1, 0.0, 0.0, 0.0);
    node->Set(SLAVE, true);
    node->Set(ACTIVE, true);
    node->FastGetSolutionStepValue(NORMAL) = Array3(0.0, 1.0, 0.0);
    node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.125, -1.0, 0.0);
    node->SetValue(FRICTION_COEFFICIENT, 0.25);
  }
  void Slide() { node->FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.25, 0.0, 0.0); }
};

TEST(ContactCriteria, FrictionalMortarCriteriaReportBothSets) {
  FrictionalContact s;
  ALMFrictionalMortarConvergenceCriteria alm;
  EXPECT_EQ(alm.Name(), "alm_frictional_mortar_criteria");
  EXPECT_TRUE(alm.HasSlipSet());
  EXPECT_FALSE(alm.PureSlip());
  EXPECT_TRUE(alm.PostCriteria(s.mp, s.dofs, s.A, s.v, s.v));
  s.Slide();  // the node slips: the active set holds, the stick/slip set does not
  EXPECT_FALSE(alm.PostCriteria(s.mp, s.dofs, s.A, s.v, s.v));
  EXPECT_TRUE(s.node->Is(SLIP));
  EXPECT_TRUE(s.mp.GetProcessInfo().GetValue(ACTIVE_SET_CONVERGED));
  EXPECT_FALSE(s.mp.GetProcessInfo().GetValue(SLIP_SET_CONVERGED));
  EXPECT_EQ(alm.LastChangeCount(), 0u);
  EXPECT_EQ(alm.LastSlipChangeCount(), 1u);
  EXPECT_EQ(alm.LastChangedNodes(), (ActiveSetUtilities::ChangedNodes{1}));
  ExpectValues(alm.LastValues(), {{"active set changes", 0.0}, {"slip set changes", 1.0}});

  FrictionalContact p;
  PenaltyFrictionalMortarConvergenceCriteria penalty(Parameters(), true);
  EXPECT_EQ(penalty.Name(), "penalty_frictional_mortar_criteria");
  EXPECT_TRUE(penalty.PureSlip());
  p.node->FastGetSolutionStepValue(WEIGHTED_GAP) = -0.25;
  // Pure slip: the active node is set SLIP without counting a change.
  EXPECT_TRUE(penalty.PostCriteria(p.mp, p.dofs, p.A, p.v, p.v));
  EXPECT_TRUE(p.node->Is(SLIP));
  PenaltyFrictionalMortarConvergenceCriteria coulomb;
  p.node->Set(SLIP, false);
  p.Slide();  // 4 * 0.25 = 1 > 0.5: slips; the penalty criterion sums both sets
  EXPECT_FALSE(coulomb.PostCriteria(p.mp, p.dofs, p.A, p.v, p.v));
  EXPECT_FALSE(p.mp.GetProcessInfo().GetValue(ACTIVE_SET_CONVERGED));
  EXPECT_FALSE(p.mp.GetProcessInfo().GetValue(SLIP_SET_CONVERGED));
}

TEST(ContactCriteria, MortarAndTableHasTheSlipStickColumn) {
  FrictionalContact s;
  auto mechanical = std::make_shared<DisplacementContactCriteria>();
  MortarAndConvergenceCriteria c(mechanical, std::make_shared<ALMFrictionalMortarConvergenceCriteria>());
  // Slip nodes keep the full c_tau: the node stays slipping once it slips.
  s.mp.GetProcessInfo().SetValue(SLIP_AUGMENTATION_COEFFICIENT, 1.0);
  c.InitializeSolutionStep(s.mp, s.dofs, s.A, s.v, s.v);
  EXPECT_EQ(c.TableHeader(), (std::vector<std::string>{"ITER", "|du|/|u|", "|du|/n", "CONVERGENCE", "ACTIVE SET CONV",
                                                       "SLIP/STICK CONV"}));
  s.Slide();
  EXPECT_FALSE(c.PostCriteria(s.mp, s.dofs, s.A, s.v, s.v));
  EXPECT_EQ(c.LastTableRow(), (std::vector<std::string>{"2", "0.000e+00", "0.000e+00", "yes", "yes", "no (1)"}));
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, s.v, s.v));
  EXPECT_EQ(c.LastTableRow().back(), "yes");
  // Frictionless criteria keep the old columns.
  MortarAndConvergenceCriteria frictionless(mechanical, std::make_shared<ALMFrictionlessMortarConvergenceCriteria>());
  EXPECT_EQ(frictionless.TableHeader().back(), "ACTIVE SET CONV");
}

}  // namespace
}  // namespace mc
