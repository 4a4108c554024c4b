// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/parameters/parameters.h"
#include "core/solving/convergence_criteria.h"

namespace mc {

/// One mortar contact formulation, registered under its Kratos `mortar_type`: everything the
/// solver, the contact processes and the criteria factory need to know about it. Adding a
/// formulation is one Register call (custom_formulations/register_contact_formulations.cpp) plus
/// its conditions and kernels.
///
/// Names follow Kratos: the solver's `contact_settings.mortar_type` (ALMContactFrictionless), the
/// process (alm_contact_process) and its `contact_type` (Frictionless), and the pair conditions
/// `<enforcement>[NV]<contact kind>[Axisym]MortarContactCondition<geometry token>`
/// (ALMNVFrictionlessMortarContactCondition3D3N4N).
class ContactFormulation {
 public:
  /// The mortar (active-set) criterion of the formulation, from the validated contact_settings.
  using CriterionFactory = std::function<std::shared_ptr<ConvergenceCriteria>(Parameters contact_settings)>;

  struct Description {
    std::string mortar_type;     ///< "ALMContactFrictionless"
    std::string process;         ///< python_module of its process: "alm_contact_process"
    std::string contact_type;    ///< that process' contact_type: "Frictionless"
    std::string enforcement;     ///< condition name stem: "ALM", "Penalty"
    std::string contact_kind{};  ///< condition name stem: "Frictionless", "FrictionlessComponents"
    /// End of the condition name stem: the contact pairs' ("MortarContactCondition") or the tying
    /// pairs' ("MortarCondition", spec 6.2: MeshTyingMortarCondition3D4N).
    std::string condition_suffix = "MortarContactCondition";
    /// Nodal solution-step variables the solver adds, and the (DoF, reaction) pairs.
    std::vector<std::string> variables;
    std::vector<std::pair<std::string, std::string>> dofs;
    /// The nodal multiplier variable ("" without multipliers).
    std::string multiplier;
    /// Multiplier blocks of the contact convergence criteria: 0 (penalty), 1 (normal), 3 (normal,
    /// stick and slip tangents).
    int multiplier_blocks = 0;
    /// The MixedULM solver can condense its multipliers (vector multipliers with a diagonal D).
    bool condensable = false;
    /// Axisymmetric conditions exist (alternative_formulations.axisymmetric).
    bool axisymmetric = false;
    /// Every active node slips (the "PureSlip" formulations): no stick state.
    bool pure_slip = false;
    /// Smallest nodal history the formulation needs (spec 2.10: 3 for friction, whose weighted
    /// slip is measured from the last converged step).
    int buffer_size = 2;
    CriterionFactory active_set_criterion;
    /// Non-empty for a formulation that is known but not implemented yet: what is missing.
    std::string not_implemented{};
  };

  explicit ContactFormulation(Description description) : d_(std::move(description)) {}

  /// Adds a formulation (replacing one of the same mortar_type: plugins may override).
  static void Register(Description description);
  /// The formulation of a `contact_settings.mortar_type`: the registered name, or the longest
  /// registered name it starts with (Kratos dispatches on substrings, so names with a suffix
  /// such as "...WithNormalUpdate" keep working). `where` prefixes the errors: InputError with
  /// the nearest names for an unknown one, NotImplementedError for one not implemented yet.
  static const ContactFormulation& Get(const std::string& mortar_type, const std::string& where = "mortar_type");
  /// The formulation of a contact process and its contact_type, e.g. ("penalty_contact_process",
  /// "Frictionless") -> PenaltyContactFrictionless.
  static const ContactFormulation& OfProcess(const std::string& process, const std::string& contact_type,
                                             const std::string& where = "contact_type");
  /// Every registered mortar_type, implemented or not, sorted.
  static std::vector<std::string> Names();
  /// The contact_type values a process accepts.
  static std::vector<std::string> ContactTypes(const std::string& process);

  const Description& Describe() const noexcept { return d_; }
  const std::string& MortarType() const noexcept { return d_.mortar_type; }
  bool IsImplemented() const noexcept { return d_.not_implemented.empty(); }
  /// Coulomb friction: the conditions read SLIP and FRICTION_COEFFICIENT, the model part carries SLIP.
  bool IsFrictional() const noexcept { return d_.contact_kind == "Frictional"; }
  /// The pair-condition name stem searched for by the contact search.
  std::string ConditionStem(bool normal_variation, bool axisymmetric) const;
  std::shared_ptr<ConvergenceCriteria> CreateActiveSetCriterion(Parameters contact_settings) const;

 private:
  Description d_;
};

}  // namespace mc
