// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/model/model_part.h"
#include "core/parameters/parameters.h"

namespace mc {

class PairedCondition;

/// What one search found (also used for timings).
struct ContactSearchStatistics {
  std::size_t slave_conditions = 0;
  std::size_t master_conditions = 0;
  std::size_t pairs = 0;
  std::size_t active_nodes = 0;
  std::size_t isolated_nodes = 0;
  double min_search_radius = 0.0;
  double max_search_radius = 0.0;
  double seconds = 0.0;
};

/// What the contact process tells the search of one interface slot, besides the user's
/// search_parameters.
struct ContactSearchSlot {
  std::string id = "0";  ///< the slot: pairs go to ComputingContact.ComputingContactSub<id>
  /// Pair-condition name stem; the name is stem + geometry token + final_string.
  std::string condition_name = "ALMFrictionlessMortarContactCondition";
  std::string final_string;
  bool predefined_master_slave = true;  ///< roles from assume_master_slave, else assigned
  int property_id = 0;                  ///< properties of the pairs (0: the slave condition's)
};

/// Contact search of one interface slot (spec 4.3): pairs every slave condition of
/// `Contact.ContactSub<k>` with the master conditions facing it and creates one pair condition
/// per (slave, master) in `ComputingContact.ComputingContactSub<k>`.
///
/// Per slave condition s (size L_s, centre c_s, unit normal n_s), in parallel:
///  1. candidates from a KD-tree over the master centres: masters whose bounding ball (centre,
///     farthest node) meets the ball of radius r = search_factor * L_s around c_s
///     (`in_radius*`), or whose bounding box meets s's box grown by r (`in_box*`);
///  2. drop masters sharing a node with s and those not facing it: n_s . n_m >= -threshold
///     (normal_orientation_threshold), or lying behind s by more than a face's size (the larger
///     of the two; the smaller for a face of s's own body; a tenth of it for a face of s's own
///     body that a path along element edges of twice that length reaches: the far side of a thin
///     body);
///  3. `*_with_obb`: drop masters whose oriented box (grown by bounding_box_factor * L) does not
///     meet s's (separating-axis test) — removes far-but-in-radius faces;
///  4. check_gap: `mapping_check` (default, also "check_mapping") keeps m when its projection
///     on s's plane overlaps s, or comes within 0.1 L_s of it when some master overlaps s (it may
///     slide onto m within the step); `direct_check` projects s on m's plane; `no_check` keeps
///     all; with consider_gap_threshold, masters farther than DISTANCE_THRESHOLD are dropped.
/// Then slave nodes without any pair are flagged ISOLATED (and inactive), and at every search
/// (every step) a slave node is predicted ACTIVE when its normal gap (along its nodal normal to
/// a paired master, stored in NORMAL_GAP; when the normal misses every paired master, to the
/// plane of the nearest one) is below active_check_factor * h_M, or when it is active and its
/// last weighted gap over its nodal area is below that too, and inactive otherwise, with h_M the
/// mean NODAL_H of the master interface nodes (Kratos' length scale).
///
/// Dynamic aids (issue 18):
///  - dynamic_search: the search and the prediction run on the positions the last step's
///    motion reaches within this step, x + dt v + dt^2/2 a (PredictedConfiguration); a body
///    about to hit is paired and predicted active before the step that closes the gap, not
///    after. The coordinates and normals are put back afterwards. Static problems: no effect.
///  - static_check_movement: a slave node whose normal gap has not closed since the previous
///    search (it is at rest or moving away) is predicted active up to Kratos' fixed gap of
///    kStaticCheckGap (a length) instead of the active-check threshold, when that is smaller.
///    (Kratos widens the threshold only together with consider_gap_threshold, so the key alone
///    does nothing there, and it compares the weighted gap with its own history, which the step
///    has just copied: the check never sees a movement. Here the gap is compared with the one of
///    the previous search.)
///
/// Pair names: condition_name + geometry token (+ final_string), e.g.
/// "ALMFrictionlessMortarContactCondition" + "3D3N4N"; the prototype must be a
/// PairedCondition registered in Registry<Condition>.
///
/// Without predefined roles (no assume_master_slave) every search treats every face as slave and
/// as master, then assigns the roles: the connected groups of interface conditions are visited
/// in id order; the first that finds a partner in another group becomes slave and the partners'
/// groups master, for the rest of the run. Within a group (self contact) the pairs are oriented
/// at every search, one slave side per pair of facing sheets of the surface, kept from search to
/// search.
class ContactSearchProcess {
 public:
  /// The gap below which static_check_movement predicts a node at rest active (Kratos'
  /// GapThreshold).
  static constexpr double kStaticCheckGap = 2.0e-4;

  /// `search_parameters` is the contact process' block of that name, validated here (unknown keys
  /// are errors naming their JSON path) and read where it lives, so later errors name it too.
  ContactSearchProcess(ModelPart& root, ModelPart& interface, Parameters search_parameters,
                       ContactSearchSlot slot = {});

  /// Kratos' search_parameters (spec 4.3), every key with its default. Not all act here:
  /// debug_mode, predict_correct_lagrange_multiplier and octree_search_parameters other than
  /// bounding_box_factor are accepted with a warning when given (NoEffectWarnings), as is
  /// type_search "octree_with_obb"; database_step_update and adapt_search are the contact
  /// process'.
  static Parameters GetDefaultParameters();

  /// Clears this slot's pairs, searches, creates the pairs and predicts the active set.
  ContactSearchStatistics UpdateMortarConditions();
  /// Removes this slot's pair conditions.
  void ClearMortarConditions();
  /// Sets ACTIVE on the interface nodes and conditions and on the pairs (outside the
  /// process interval they are all inactive).
  void SetInterfaceActive(bool active);

  /// Finds the bodies (connected sets of elements of the root model part) now and keeps those of
  /// the interface's faces: called on the whole model before it is cut across the ranks
  /// (MORTARCONTACT_PARTITIONED_MODEL), where a body cut into pieces would fall apart. Without a
  /// cut, the first search finds them.
  void FindBodies();
  /// The bodies as FindBodies finds them, found instead on the whole mesh file before a rank built
  /// its piece (MdpaMesh::Bodies): `body_of` by node id, every label below `labels`.
  void SetBodies(const std::unordered_map<IndexType, std::size_t>& body_of, std::size_t labels);

  ModelPart& InterfacePart() const noexcept { return interface_; }
  ModelPart& ComputingPart() const noexcept { return computing_; }
  const Parameters& Settings() const noexcept { return settings_; }
  const ContactSearchSlot& Slot() const noexcept { return slot_; }

  /// Canonical search type and gap check names ("in_radius_with_obb", "mapping_check", ...).
  const std::string& SearchType() const noexcept { return type_search_; }
  const std::string& CheckGap() const noexcept { return check_gap_; }

  /// Wall-clock seconds of every UpdateMortarConditions so far, and how many ran (benchmarks).
  double TotalSeconds() const noexcept { return total_seconds_; }
  std::size_t NumberOfSearches() const noexcept { return searches_; }

 private:
  struct Candidate;
  void AssignAutomaticRoles(const std::vector<Condition*>& conditions,
                            std::vector<std::vector<std::size_t>>& candidates);
  void PredictActiveSet(const std::vector<std::pair<Condition*, Condition*>>& pairs, ContactSearchStatistics& stats);
  /// The keys above accepted without effect: a warning for each one given a non-default value.
  void WarnAboutKeysWithoutEffect() const;
  /// The registered prototype of the pair name for these geometries, and its interned name.
  const PairedCondition& Prototype(const Geometry& slave, const Geometry& master, const std::string** interned);
  /// The body (connected set of elements of the root model part) a face of the interface lies on;
  /// the bodies are found once, at the first call.
  std::size_t BodyOf(const Condition& condition);
  /// Finds, once, the nodes that share an element with each node (mesh_neighbours_).
  void FindMeshNeighbours();
  /// Whether a path along element edges no longer than `reach` joins a node of `from` to one of
  /// `to` (current coordinates). After FindMeshNeighbours.
  bool NearInMesh(const Geometry& from, const Geometry& to, double reach) const;

  ModelPart& root_;
  ModelPart& interface_;
  ModelPart& computing_;
  Parameters settings_;
  ContactSearchSlot slot_;
  std::string type_search_;
  std::string check_gap_;
  /// Automatic roles: per interface condition, the role its group was given by the first search
  /// that found the group a partner in another group.
  enum DecidedRole : char { kUndecided, kDecidedSlave, kDecidedMaster };
  std::vector<char> decided_role_;
  /// Self contact: per interface condition, its side in the last pair of its group it was in.
  enum SelfSide : char { kSideUnknown, kSideSlave, kSideMaster };
  std::vector<char> self_side_;
  /// NORMAL_GAP of each slave node at the previous search (static_check_movement).
  std::unordered_map<const Node*, double> previous_gap_;
  std::unordered_map<const Node*, std::size_t> body_of_node_;
  /// The body of a face on no element is this plus its id: above every body's number.
  std::size_t bodiless_offset_ = 0;
  bool bodies_found_ = false;
  /// Per node of an element, the other nodes of the elements that hold it (sorted); built only
  /// when a slave face may meet a face of its own body, never on a piece of a cut model.
  std::unordered_map<const Node*, std::vector<const Node*>> mesh_neighbours_;
  double total_seconds_ = 0.0;
  std::size_t searches_ = 0;
};

}  // namespace mc
