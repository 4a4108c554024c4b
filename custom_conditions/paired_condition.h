// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <utility>

#include "core/model/condition.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/exact_mortar_integration_utility.h"

namespace mc {

class NodalNormalSupport;

/// Base of every mortar pair condition (contact, mesh tying): a condition on the nodes of one
/// slave interface condition that also knows the master interface condition it is paired with.
/// Its own geometry is the slave geometry; the master geometry is a copy of the master
/// condition's geometry (same nodes), kept so that integration never chases pointers.
///
/// The contact search creates pairs through Registry<Condition>: it looks up the prototype by
/// name (stem + geometry token, spec 6.2), checks that it is a PairedCondition and calls
/// CreatePaired. Prototypes are registered with node-less geometries of the right types.
class PairedCondition : public Condition {
 public:
  PairedCondition(IndexType id, Geometry slave_geometry, Properties* properties, Geometry paired_geometry)
      : Condition(id, std::move(slave_geometry), properties), paired_geometry_(std::move(paired_geometry)) {}

  /// A new pair of the same class on `slave`'s nodes, paired with `master`. Both conditions are
  /// interface conditions owned by the model part and outlive the pair.
  virtual std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                        Properties* properties) const = 0;

  /// The master geometry (current nodes of the master interface condition).
  const Geometry& GetPairedGeometry() const noexcept { return paired_geometry_; }
  Geometry& GetPairedGeometry() noexcept { return paired_geometry_; }

  /// The interface conditions this pair was built from (null for prototypes).
  Condition* GetParentSlaveCondition() const noexcept { return slave_; }
  Condition* GetPairedCondition() const noexcept { return master_; }
  void SetPair(Condition* slave, Condition* master) noexcept {
    slave_ = slave;
    master_ = master;
  }

  /// The mortar integration settings every pair takes: INTEGRATION_ORDER_CONTACT of its
  /// properties and ZERO_TOLERANCE_FACTOR of the ProcessInfo (the defaults where absent).
  MortarIntegrationSettings PairIntegrationSettings(const ProcessInfo& info) const {
    MortarIntegrationSettings settings;
    if (HasProperties() && GetProperties().Has(INTEGRATION_ORDER_CONTACT))
      settings.integration_order = GetProperties().GetValue(INTEGRATION_ORDER_CONTACT);
    if (info.Has(ZERO_TOLERANCE_FACTOR)) settings.zero_tolerance_factor = info.GetValue(ZERO_TOLERANCE_FACTOR);
    return settings;
  }

  /// Explicit (RHS-only) update of nodal mortar quantities, e.g. the contact conditions add
  /// their weighted gap to WEIGHTED_GAP. Thread-safe across pairs; default: nothing.
  virtual void AddExplicitContribution(const ProcessInfo& info) {}

  /// Pairs whose tangent includes the variation of the slave nodal normals (the NV names) need
  /// the interface faces around their slave nodes: the contact search builds one
  /// NodalNormalSupport per search and hands it to every pair that asks. Default: not needed.
  virtual bool NeedsNodalNormalSupport() const { return false; }
  virtual void SetNodalNormalSupport(std::shared_ptr<const NodalNormalSupport> support) {}

 protected:
  /// Create and CreatePaired of a concrete pair class T (constructed like PairedCondition): a
  /// condition on `nodes` with the prototype's geometry types, and a pair on `slave`'s nodes.
  template <class T>
  static std::unique_ptr<Condition> CreateOfType(const T& prototype, IndexType id, Geometry::NodesArray nodes,
                                                 Properties* properties) {
    return std::make_unique<T>(id, Geometry(prototype.GetGeometry().Type(), std::move(nodes)), properties,
                               prototype.GetPairedGeometry());
  }
  template <class T>
  static std::unique_ptr<PairedCondition> CreatePairedOfType(IndexType id, Condition& slave, Condition& master,
                                                             Properties* properties) {
    auto pair = std::make_unique<T>(id, slave.GetGeometry(), properties, master.GetGeometry());
    pair->SetPair(&slave, &master);
    return pair;
  }

 private:
  Geometry paired_geometry_;
  Condition* slave_ = nullptr;
  Condition* master_ = nullptr;
};

}  // namespace mc
