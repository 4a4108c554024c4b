// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/model/model_part.h"

namespace mc {

/// One interface slot of a contact process (spec 4.1): the parts of interface k, the parts
/// that are its slave side, its property id and friction coefficient.
struct ContactInterfaceSettings {
  std::string slot = "0";
  std::vector<std::string> parts;        ///< contact_model_part[k]
  std::vector<std::string> slave_parts;  ///< assume_master_slave[k]; empty = automatic roles
  int property_id = 0;                   ///< contact_property_ids[k]; 0 -> 100 + k
  double friction_coefficient = 0.0;     ///< friction_coefficients[k]
  /// Fraction of the face size by which the inverted-normal check probes inside the parent
  /// element (normal_check_proportion); 0 turns the check and the flipping off.
  double normal_check_proportion = 0.1;
};

/// Builds the interface of one slot under `root` (spec 4.2, ExecuteInitialize):
///  - sub-model-parts `Contact` / `Contact.ContactSub<k>` (interface nodes and conditions) and
///    `ComputingContact` / `ComputingContact.ComputingContactSub<k>` (the pairs, filled by the
///    search);
///  - interface conditions: those of the listed parts, or, when a part holds only nodes,
///    LineCondition2D2N/2D3N and SurfaceCondition3D3N/3D4N generated from the boundary faces
///    of the root's elements whose nodes all belong to the part (outward orientation kept);
///  - flags INTERFACE on nodes and conditions, SLAVE on those of the slave parts and MASTER on
///    the others (both when no slave part is given: the search decides);
///  - the interface property (id, or new id 100 + k copying the values of the first interface
///    condition's or parent element's property; FRICTION_COEFFICIENT unless already set), and
///    its FRICTION_COEFFICIENT on every interface node (non-historical);
///  - NODAL_H on the interface nodes, condition and nodal NORMAL;
///  - the normal checks: an interface condition given in the mdpa whose normal points into its
///    parent element is flipped (node order reversed, as Kratos' normal check does) with a
///    warning naming it, unless normal_check_proportion is 0; slave and master sides whose
///    normals point the same way are an InputError naming the conditions and the part.
class ContactInterfaceBuilder {
 public:
  explicit ContactInterfaceBuilder(ModelPart& root) : root_(root) {}

  /// Returns `Contact.ContactSub<k>`. An existing sub-part is reused unless the root is
  /// flagged MODIFIED (remeshed), in which case it is rebuilt.
  ModelPart& Build(const ContactInterfaceSettings& settings);

  /// The property of slot k's interface (valid after Build).
  static Properties& InterfaceProperties(ModelPart& root, const std::string& slot);

  /// NODAL_H of every node of `part`: the smallest distance to another node of an element of
  /// `root` holding it (Kratos' nodal length); for nodes in no element, the shortest edge of
  /// the part's faces holding them. Historical when the model has NODAL_H.
  static void ComputeNodalH(ModelPart& root, ModelPart& part);
  static double GetNodalH(const Node& node);

  /// The element of `root` that holds all nodes of each condition of `part`, in the order of
  /// part.Conditions() (null when there is none).
  static std::vector<Element*> FindParentElements(ModelPart& root, ModelPart& part);

  /// Resolves a part name as written in the settings: "Contact_Part", "Structure.Contact_Part"
  /// (path from the root) or a bare name found once anywhere below the root.
  static ModelPart& ResolvePart(ModelPart& root, const std::string& name);

 private:
  void AddPart(ModelPart& sub, ModelPart& part, Properties& properties);
  void CheckNormals(ModelPart& sub, const ContactInterfaceSettings& settings);

  ModelPart& root_;
};

}  // namespace mc
