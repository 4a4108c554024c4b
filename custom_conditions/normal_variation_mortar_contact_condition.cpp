// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/normal_variation_mortar_contact_condition.h"

#include <algorithm>
#include <array>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

// Names of the NV variants (spec 6.2), chosen by overload on the formulation.
template <int D, int S, int M>
const char* NormalVariationStem(const ALMFrictionlessMortarContactCondition<D, S, M>*) {
  return "ALMNVFrictionlessMortarContactCondition";
}
template <int D, int S, int M>
const char* NormalVariationStem(const ALMFrictionlessComponentsMortarContactCondition<D, S, M>*) {
  return "ALMNVFrictionlessComponentsMortarContactCondition";
}
template <int D, int S, int M>
const char* NormalVariationStem(const PenaltyFrictionlessMortarContactCondition<D, S, M>*) {
  return "PenaltyNVFrictionlessMortarContactCondition";
}

template <int D, int S, int M>
const char* NormalVariationStem(const ALMFrictionalMortarContactCondition<D, S, M>*) {
  return "ALMNVFrictionalMortarContactCondition";
}
template <int D, int S, int M>
const char* NormalVariationStem(const PenaltyFrictionalMortarContactCondition<D, S, M>*) {
  return "PenaltyNVFrictionalMortarContactCondition";
}

const char* NormalVariationStem(const ALMFrictionlessAxisymMortarContactCondition<2, 2, 2>*) {
  return "ALMNVFrictionlessAxisymMortarContactCondition";
}
const char* NormalVariationStem(const PenaltyFrictionlessAxisymMortarContactCondition<2, 2, 2>*) {
  return "PenaltyNVFrictionlessAxisymMortarContactCondition";
}
const char* NormalVariationStem(const ALMFrictionalAxisymMortarContactCondition<2, 2, 2>*) {
  return "ALMNVFrictionalAxisymMortarContactCondition";
}
const char* NormalVariationStem(const PenaltyFrictionalAxisymMortarContactCondition<2, 2, 2>*) {
  return "PenaltyNVFrictionalAxisymMortarContactCondition";
}

bool Holds(const Geometry& geometry, const Node* node) {
  return std::find(geometry.Nodes().begin(), geometry.Nodes().end(), node) != geometry.Nodes().end();
}

}  // namespace

template <class TFormulation>
const char* NormalVariationMortarContactCondition<TFormulation>::Stem() const {
  return NormalVariationStem(static_cast<const TFormulation*>(nullptr));
}

template <class TFormulation>
std::unique_ptr<Condition> NormalVariationMortarContactCondition<TFormulation>::Create(IndexType id,
                                                                                       Geometry::NodesArray nodes,
                                                                                       Properties* properties) const {
  return this->CreateOfType(*this, id, std::move(nodes), properties);
}

template <class TFormulation>
std::unique_ptr<PairedCondition> NormalVariationMortarContactCondition<TFormulation>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  return this->template CreatePairedOfType<NormalVariationMortarContactCondition>(id, slave, master, properties);
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::SetNodalNormalSupport(
    std::shared_ptr<const NodalNormalSupport> support) {
  support_ = std::move(support);
  neighbours_.clear();
  if (!support_) return;
  const Geometry& slave = this->GetGeometry();
  const Geometry& master = this->GetPairedGeometry();
  for (const Node* node : slave.Nodes())
    for (const Geometry* face : support_->Faces(*node))
      for (Node* k : face->Nodes())
        if (!Holds(slave, k) && !Holds(master, k) &&
            std::find(neighbours_.begin(), neighbours_.end(), k) == neighbours_.end())
          neighbours_.push_back(k);
}

template <class TFormulation>
const NodalNormalSupport& NormalVariationMortarContactCondition<TFormulation>::Support() const {
  if (!support_)
    throw Error(Concat("condition ", this->Id(), " (", this->Info(),
                       "): no nodal normal support; the contact search gives it to the NV pair conditions it "
                       "creates (SetNodalNormalSupport)"));
  return *support_;
}

template <class TFormulation>
int NormalVariationMortarContactCondition<TFormulation>::Column(const Node* node) const {
  const Geometry& master = this->GetPairedGeometry();
  const Geometry& slave = this->GetGeometry();
  for (int l = 0; l < kNumMasterNodes; ++l)
    if (master.pGetNode(l) == node) return l * kDim;
  for (int i = 0; i < kNumSlaveNodes; ++i)
    if (slave.pGetNode(i) == node) return (kNumMasterNodes + i) * kDim;
  for (std::size_t e = 0; e < neighbours_.size(); ++e)
    if (neighbours_[e] == node) return this->LocalSize() + static_cast<int>(e) * kDim;
  throw Error(Concat("condition ", this->Id(), " (", this->Info(), "): node ", node->Id(),
                     " moves a slave normal but is not in the DoF list (support changed after SetNodalNormalSupport)"));
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::GetDofList(DofsVectorType& dofs,
                                                                     const ProcessInfo& info) const {
  Base::GetDofList(dofs, info);
  for (Node* node : neighbours_)
    for (int c = 0; c < kDim; ++c) dofs.push_back(&node->GetDof(*kDisplacement[c]));
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::CalculateLocalSystem(Matrix& lhs, Vector& rhs,
                                                                               const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) {
  CalculateAll(&lhs, nullptr, info);
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) {
  CalculateAll(nullptr, &rhs, info);
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::CalculateAll(Matrix* lhs, Vector* rhs,
                                                                       const ProcessInfo& info) {
  const NodalNormalSupport& support = Support();
  const Geometry& slave = this->GetGeometry();
  // Per-thread buffers, reused by every pair of this geometry case (no allocation once warm).
  thread_local std::array<NodalNormalSupport::Derivatives, kNumSlaveNodes> normals;
  thread_local Matrix pair_lhs, sensitivity;
  thread_local Vector pair_rhs;

  // The residual uses the normals of the support (equal to the refreshed nodal NORMAL), so that it
  // is exactly the function whose derivative the tangent holds.
  typename Kinematics::SlaveMatrix n1;
  for (int j = 0; j < kNumSlaveNodes; ++j) {
    Array3 n;
    if (lhs) {
      support.Compute(slave[j], normals[j]);
      n = normals[j].normal;
    } else {
      n = support.Normal(slave[j]);
    }
    n1.row(j) = n.template head<kDim>().transpose();
  }
  this->CalculatePairSystem(lhs ? &pair_lhs : nullptr, rhs ? &pair_rhs : nullptr, info, n1,
                            lhs ? &sensitivity : nullptr);

  const int pair_size = this->LocalSize();
  const int size = ExtendedSize();
  if (rhs) {
    rhs->setZero(size);
    rhs->head(pair_size) = pair_rhs;
  }
  if (!lhs) return;
  lhs->setZero(size, size);
  lhs->topLeftCorner(pair_size, pair_size) = pair_lhs;
  // -d rhs/du through the normals: S (= -d rhs/dn) times dn_j/dx_k, for every node k around j.
  for (int j = 0; j < kNumSlaveNodes; ++j) {
    const auto s = sensitivity.middleCols(j * kDim, kDim);
    if (s.isZero(0.0)) continue;  // inactive node: its normal does not enter the residual
    const NodalNormalSupport::Derivatives& d = normals[j];
    for (std::size_t i = 0; i < d.nodes.size(); ++i)
      lhs->block(0, Column(d.nodes[i]), pair_size, kDim).noalias() +=
          s * d.dn_dx[i].template topLeftCorner<kDim, kDim>();
  }
}

template <class TFormulation>
void NormalVariationMortarContactCondition<TFormulation>::Check(const ProcessInfo& info) const {
  Base::Check(info);
  Support();
  for (const Node* node : neighbours_)
    for (int c = 0; c < kDim; ++c)
      if (!node->HasDofFor(*kDisplacement[c]))
        throw InputError(Concat("condition ", this->Id(), " (", this->Info(), "): neighbour node ", node->Id(),
                                " (its displacement moves a slave normal) has no DoF ", kDisplacement[c]->Name()));
}

template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<2, 2, 2>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 3, 3>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 4, 4>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 3, 4>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 4, 3>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<2, 2, 2>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 3, 3>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 4, 4>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 3, 4>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 4, 3>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<2, 2, 2>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 3, 3>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 4, 4>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 4, 3>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 3, 4>>;
template class NormalVariationMortarContactCondition<ALMFrictionlessAxisymMortarContactCondition<2, 2, 2>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionlessAxisymMortarContactCondition<2, 2, 2>>;
#define MC_INSTANTIATE(D, S, M)                                                                       \
  template class NormalVariationMortarContactCondition<ALMFrictionalMortarContactCondition<D, S, M>>; \
  template class NormalVariationMortarContactCondition<PenaltyFrictionalMortarContactCondition<D, S, M>>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE
template class NormalVariationMortarContactCondition<ALMFrictionalAxisymMortarContactCondition<2, 2, 2>>;
template class NormalVariationMortarContactCondition<PenaltyFrictionalAxisymMortarContactCondition<2, 2, 2>>;

}  // namespace mc
