// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/alm_variables_calculation_process.h"

#include <algorithm>
#include <limits>
#include <unordered_set>

#include "core/variables/kernel_variables.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

namespace {

// E / h of one side (0 when the side has no stiffness or no size).
double SideStiffness(const std::vector<const Condition*>& faces, const std::vector<const Element*>& parents) {
  double area = 0.0, h_area = 0.0;
  for (const Condition* face : faces) {
    const Geometry& geometry = face->GetGeometry();
    double h = 0.0;
    for (const Node* node : geometry.Nodes()) h += ContactInterfaceBuilder::GetNodalH(*node);
    h /= static_cast<double>(geometry.PointsNumber());
    const double a = geometry.DomainSize();
    area += a;
    h_area += a * h;
  }
  double volume = 0.0, e_volume = 0.0;
  std::unordered_set<const Element*> seen;
  for (const Element* element : parents) {
    if (!element || !seen.insert(element).second || !element->pGetProperties()) continue;
    const double v = element->GetGeometry().DomainSize();
    volume += v;
    e_volume += v * element->GetProperties().GetValue(YOUNG_MODULUS);
  }
  if (!(area > 0.0) || !(volume > 0.0) || !(h_area > 0.0)) return 0.0;
  return (e_volume / volume) / (h_area / area);
}

}  // namespace

Parameters ALMVariablesCalculationProcess::GetDefaultParameters() {
  return Parameters(R"({
    "stiffness_factor": 1.0,
    "penalty_scale_factor": 1.0,
    "use_scale_factor": true
  })");
}

ALMVariablesCalculationProcess::ALMVariablesCalculationProcess(ModelPart& root, ModelPart& interface,
                                                               Parameters settings, double penalty_multiplier,
                                                               double penalty_floor)
    : root_(root),
      interface_(interface),
      settings_(std::move(settings)),
      penalty_multiplier_(penalty_multiplier),
      penalty_floor_(penalty_floor) {
  settings_.AddMissingParameters(GetDefaultParameters());
}

void ALMVariablesCalculationProcess::Execute() {
  const std::vector<Element*> parents = ContactInterfaceBuilder::FindParentElements(root_, interface_);
  std::vector<const Condition*> slave_faces, master_faces;
  std::vector<const Element*> slave_parents, master_parents;
  std::size_t i = 0;
  for (const Condition* face : interface_.Conditions()) {
    const Element* parent = parents[i++];
    if (face->Is(SLAVE)) {
      slave_faces.push_back(face);
      slave_parents.push_back(parent);
    }
    if (face->Is(MASTER)) {
      master_faces.push_back(face);
      master_parents.push_back(parent);
    }
  }
  const double slave = SideStiffness(slave_faces, slave_parents);
  const double master = SideStiffness(master_faces, master_parents);
  const double value = (slave > 0.0 && master > 0.0) ? std::min(slave, master) : std::max(slave, master);

  const double stiffness_factor = settings_["stiffness_factor"].GetDouble();
  const double eps = std::numeric_limits<double>::epsilon();
  penalty_ = penalty_multiplier_ * stiffness_factor * value;
  if (penalty_ < eps) penalty_ = penalty_floor_;
  scale_factor_ = settings_["penalty_scale_factor"].GetDouble() * stiffness_factor * value;
  if (!settings_["use_scale_factor"].GetBool() || scale_factor_ < eps) scale_factor_ = 1.0;

  ProcessInfo& info = root_.GetProcessInfo();
  info.SetValue(INITIAL_PENALTY, penalty_);
  info.SetValue(SCALE_FACTOR, scale_factor_);
  for (Node* node : interface_.Nodes()) node->SetValue(INITIAL_PENALTY, penalty_);
}

}  // namespace mc
