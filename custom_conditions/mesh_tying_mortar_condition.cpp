// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mesh_tying_mortar_condition.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "core/variables/variable_registry.h"
#include "custom_conditions/mortar_geometry_token.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

const char* const kAxes[3] = {"_X", "_Y", "_Z"};

}  // namespace

template <int TDim, int TNumNodes, int TNumNodesMaster>
MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::MeshTyingMortarCondition(IndexType id,
                                                                                     Geometry slave_geometry,
                                                                                     Properties* properties,
                                                                                     Geometry paired_geometry)
    : MeshTyingMortarConditionBase(id, std::move(slave_geometry), properties, std::move(paired_geometry)) {
  const std::string name = properties && properties->Has(TYING_VARIABLE) ? properties->GetValue(TYING_VARIABLE)
                                                                         : std::string("DISPLACEMENT");
  const VariableRegistry& registry = VariableRegistry::Instance();
  const VariableData& variable = registry.Get(name);  // InputError with the nearest names
  if (variable.Type() == ValueType::Array3) {
    components_ = TDim;
    for (int c = 0; c < TDim; ++c) {
      tied_[c] = &registry.GetTyped<double>(name + kAxes[c]);
      multiplier_[c] = &registry.GetTyped<double>(std::string("VECTOR_LAGRANGE_MULTIPLIER") + kAxes[c]);
    }
  } else if (variable.Type() == ValueType::Double) {
    components_ = 1;
    tied_[0] = &registry.GetTyped<double>(name);
    multiplier_[0] = &SCALAR_LAGRANGE_MULTIPLIER;
  } else {
    throw InputError(Concat("TYING_VARIABLE '", name, "' of properties ", properties->Id(), " is a ",
                            ValueTypeName(variable.Type()),
                            " variable: mesh tying ties a scalar (double) or an array (components) variable"));
  }
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::string MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::Info() const {
  return "MeshTyingMortarCondition" + MortarGeometryToken(TDim, TNumNodes, TNumNodesMaster);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<Condition> MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::Create(
    IndexType id, Geometry::NodesArray nodes, Properties* properties) const {
  return CreateOfType(*this, id, std::move(nodes), properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<PairedCondition> MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  return CreatePairedOfType<MeshTyingMortarCondition>(id, slave, master, properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::GetDofList(DofsVectorType& dofs,
                                                                            const ProcessInfo& info) const {
  const Geometry& slave = GetGeometry();
  const Geometry& master = GetPairedGeometry();
  dofs.resize(LocalSize(info));
  std::size_t i = 0;
  for (int l = 0; l < TNumNodesMaster; ++l)
    for (int c = 0; c < components_; ++c) dofs[i++] = &master[l].GetDof(*tied_[c]);
  for (int j = 0; j < TNumNodes; ++j)
    for (int c = 0; c < components_; ++c) dofs[i++] = &slave[j].GetDof(*tied_[c]);
  if (!overlap_) return;
  for (int j = 0; j < TNumNodes; ++j)
    for (int c = 0; c < components_; ++c) dofs[i++] = &slave[j].GetDof(*multiplier_[c]);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
int MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::LocalSize(const ProcessInfo& info) const {
  EnsureOperators(info);
  return (TNumNodesMaster + (overlap_ ? 2 : 1) * TNumNodes) * components_;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::EnsureOperators(const ProcessInfo& info) const {
  if (operators_ready_) return;
  // One per thread: the kinematics object is large (derivative arrays) and only its values are used.
  thread_local Kinematics kinematics;
  typename Kinematics::SlaveMatrix x1, n1;
  typename Kinematics::MasterMatrix x2;
  const Geometry& slave = GetGeometry();
  const Geometry& master = GetPairedGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    x1.row(j) = slave[j].X0().template head<TDim>().transpose();
    n1.row(j) = NormalCalculationUtilities::GetNodalNormal(slave[j]).template head<TDim>().transpose();
  }
  for (int l = 0; l < TNumNodesMaster; ++l) x2.row(l) = master[l].X0().template head<TDim>().transpose();
  overlap_ = kinematics.ComputeValues(x1, x2, n1, PairIntegrationSettings(info));
  d_ = kinematics.D;
  m_ = kinematics.M;
  // A sliver's area does not count (as for contact): a node covered by slivers alone stays ISOLATED.
  nodal_area_ = kinematics.sliver ? SlaveVector::Zero() : kinematics.nodal_area;
  operators_ready_ = true;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
const typename MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::DMatrix&
MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::D(const ProcessInfo& info) const {
  EnsureOperators(info);
  return d_;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
const typename MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::MMatrix&
MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::M(const ProcessInfo& info) const {
  EnsureOperators(info);
  return m_;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
bool MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::HasOverlap(const ProcessInfo& info) const {
  EnsureOperators(info);
  return overlap_;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::vector<std::array<bool, 3>> MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::SlaveRowsWithFreeDofs(
    const ProcessInfo& info) const {
  EnsureOperators(info);
  std::vector<std::array<bool, 3>> free(TNumNodes, std::array<bool, 3>{});
  if (!overlap_) return free;
  const Geometry& slave = GetGeometry();
  const Geometry& master = GetPairedGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    // An M entry that vanishes analytically (the dual basis is biorthogonal to the linear functions
    // of the pair) comes out at round-off level.
    const double scale = std::max(d_.row(j).cwiseAbs().maxCoeff(), m_.row(j).cwiseAbs().maxCoeff());
    const double tolerance = 1e-10 * scale;
    for (int c = 0; c < components_; ++c) {
      bool any = false;
      for (int i = 0; i < TNumNodes && !any; ++i)  // D is diagonal but for a sliver (standard basis)
        any = std::abs(d_(j, i)) > tolerance && !slave[i].GetDof(*tied_[c]).fixed;
      for (int l = 0; l < TNumNodesMaster && !any; ++l)
        any = std::abs(m_(j, l)) > tolerance && !master[l].GetDof(*tied_[c]).fixed;
      free[j][c] = any;
    }
  }
  return free;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::InitializeSolutionStep(const ProcessInfo& info) {
  EnsureOperators(info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateLocalSystem(Matrix& lhs, Vector& rhs,
                                                                                      const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateLeftHandSide(Matrix& lhs,
                                                                                       const ProcessInfo& info) {
  CalculateAll(&lhs, nullptr, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateRightHandSide(Vector& rhs,
                                                                                        const ProcessInfo& info) {
  CalculateAll(nullptr, &rhs, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateAll(Matrix* lhs, Vector* rhs,
                                                                              const ProcessInfo& info) {
  EnsureOperators(info);
  const double k = info.Has(SCALE_FACTOR) ? info.GetValue(SCALE_FACTOR) : 1.0;
  if (!(k > 0.0))
    throw InputError(Concat("condition ", Id(), " (", Info(), "): SCALE_FACTOR = ", k, " must be positive"));
  const int n = components_;
  const int slave_offset = TNumNodesMaster * n;
  const int multiplier_offset = slave_offset + TNumNodes * n;
  const int size = LocalSize(info);
  if (lhs) lhs->setZero(size, size);
  if (rhs) rhs->setZero(size);
  if (!overlap_) return;
  if (lhs) {
    for (int j = 0; j < TNumNodes; ++j)
      for (int c = 0; c < n; ++c) {
        const int row = multiplier_offset + j * n + c;
        for (int i = 0; i < TNumNodes; ++i) {
          (*lhs)(row, slave_offset + i * n + c) = -k * d_(j, i);
          (*lhs)(slave_offset + i * n + c, row) = -k * d_(j, i);
        }
        for (int l = 0; l < TNumNodesMaster; ++l) {
          (*lhs)(row, l * n + c) = k * m_(j, l);
          (*lhs)(l * n + c, row) = k * m_(j, l);
        }
      }
  }
  if (rhs) {
    const Geometry& slave = GetGeometry();
    const Geometry& master = GetPairedGeometry();
    for (int c = 0; c < n; ++c) {
      SlaveVector us, lambda;
      Eigen::Matrix<double, TNumNodesMaster, 1> um;
      for (int j = 0; j < TNumNodes; ++j) {
        us(j) = slave[j].FastGetSolutionStepValue(*tied_[c]);
        lambda(j) = slave[j].FastGetSolutionStepValue(*multiplier_[c]);
      }
      for (int l = 0; l < TNumNodesMaster; ++l) um(l) = master[l].FastGetSolutionStepValue(*tied_[c]);
      const SlaveVector gap = k * (d_ * us - m_ * um);
      const SlaveVector slave_force = k * d_.transpose() * lambda;
      const Eigen::Matrix<double, TNumNodesMaster, 1> master_force = -k * m_.transpose() * lambda;
      for (int l = 0; l < TNumNodesMaster; ++l) (*rhs)(l * n + c) = master_force(l);
      for (int j = 0; j < TNumNodes; ++j) {
        (*rhs)(slave_offset + j * n + c) = slave_force(j);
        (*rhs)(multiplier_offset + j * n + c) = gap(j);
      }
    }
  }
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::AddExplicitContribution(const ProcessInfo& info) {
  EnsureOperators(info);
  Geometry& slave = GetGeometry();
  for (int j = 0; j < TNumNodes; ++j)
    std::atomic_ref<double>(slave[j].GetValueRef(NODAL_AREA)).fetch_add(nodal_area_(j));
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MeshTyingMortarCondition<TDim, TNumNodes, TNumNodesMaster>::Check(const ProcessInfo& info) const {
  auto check = [&](const Node& node, const Variable<double>& variable) {
    if (!node.HasDofFor(variable))
      throw InputError(Concat("condition ", Id(), " (", Info(), "): node ", node.Id(), " has no DoF ", variable.Name(),
                              " (the tied variable and its multiplier need one)"));
  };
  for (int c = 0; c < components_; ++c) {
    for (int l = 0; l < TNumNodesMaster; ++l) check(GetPairedGeometry()[l], *tied_[c]);
    for (int j = 0; j < TNumNodes; ++j) {
      check(GetGeometry()[j], *tied_[c]);
      check(GetGeometry()[j], *multiplier_[c]);
    }
  }
  if (info.Has(SCALE_FACTOR) && !(info.GetValue(SCALE_FACTOR) > 0.0))
    throw InputError(Concat("condition ", Id(), " (", Info(), "): SCALE_FACTOR = ", info.GetValue(SCALE_FACTOR),
                            " must be positive"));
}

#define MC_INSTANTIATE(D, S, M) template class MeshTyingMortarCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
