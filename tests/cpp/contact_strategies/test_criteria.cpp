// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (contact criteria): block norms split by DoF variable (displacement / rotation /
// multiplier) against hand-computed ratios, each criterion's convergence decision, the
// ensure_contact rule, settings validation, the mortar-and table columns and the condition
// number estimate.
#include <gtest/gtest.h>

#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"
#include "custom_strategies/custom_convergencecriterias/condition_number_utility.h"
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"
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

}  // namespace
}  // namespace mc
