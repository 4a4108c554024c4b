// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (exact normal variation, the NV pair conditions of normal_variation
// "nodal_elemental_derivatives"):
//  - NodalNormalSupport: dn_j/dx_k of the averaged nodal normals equals central finite differences
//    for 2D lines and 3D triangle / quadrilateral patches (curved, warped), is zero for the nodes
//    outside the faces around j, and its normals equal NormalCalculationUtilities' (same corner
//    normals, normals out of the slave body); a face contributes its normal at the node;
//  - the assembled tangent of all NV pairs of a small interface (2D: slave segments on an arc vs
//    2 master segments; 3D: a 2x2 quad or triangle slave patch vs a quad or triangle master patch),
//    with mixed active / inactive nodes, equals central finite differences of the assembled
//    residual whose normals follow the perturbed coordinates (ALM scalar, ALM components,
//    penalty; issue 12: ALM and penalty frictional with slip, stick and inactive nodes and a
//    non-zero weighted slip); the fixed-normal tangent of the plain conditions fails the same
//    comparison;
//  - NV names resolve to real conditions whose DoF list ends with the neighbour displacements.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>

#include "contact_condition_test_utilities.h"
#include "core/geometries/reference_element.h"
#include "core/model/registry.h"
#include "custom_conditions/normal_variation_mortar_contact_condition.h"
#include "custom_conditions/register_contact_conditions.h"
#include "custom_processes/contact_search_process.h"
#include "custom_utilities/nodal_normal_support.h"

namespace mc::test {
namespace {

using Connectivity = std::vector<std::vector<IndexType>>;

/// An interface face: geometry only (what the nodal normals are averaged from).
class FaceCondition final : public Condition {
 public:
  using Condition::Condition;
  std::string Info() const override { return "FaceCondition"; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<FaceCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }
  void GetDofList(DofsVectorType& dofs, const ProcessInfo&) const override { dofs.clear(); }
};

struct Interface {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  ModelPart& contact = root.CreateSubModelPart("Contact");
  int dim = 2;
  Connectivity slave, master;
  Array3 slave_direction;  ///< roughly where the slave normals point
  std::shared_ptr<const NodalNormalSupport> support;

  static GeometryType Type(int dim, std::size_t nodes) {
    if (dim == 2) return GeometryType::Line2D2;
    return nodes == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4;
  }
  Geometry Face(const std::vector<IndexType>& ids) {
    Geometry::NodesArray nodes;
    for (IndexType id : ids) nodes.push_back(&root.GetNode(id));
    return Geometry(Type(dim, ids.size()), nodes);
  }

  /// Slave data (multipliers, penalties, mixed ACTIVE flags), the face conditions of "Contact",
  /// the support and the stored nodal normals.
  void Finish() {
    IndexType id = 1;
    for (const Connectivity* faces : {&slave, &master})
      for (const auto& f : *faces) contact.AddCondition(std::make_unique<FaceCondition>(id++, Face(f), nullptr));
    support = std::make_shared<const NodalNormalSupport>(contact);
    NormalCalculationUtilities::ComputeNodalNormals(contact);
    int j = 0;
    for (Node* node : SlaveNodes()) {
      node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -0.7 - 0.1 * j;
      node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
          Array3(0.15 - 0.05 * j, -0.8 - 0.1 * j, dim == 3 ? -0.9 + 0.07 * j : 0.0);
      node->SetValue(INITIAL_PENALTY, 12.0 + 3.0 * (j % 3));
      node->SetValue(DYNAMIC_FACTOR, 1.0 + 0.05 * j);
      node->Set(ACTIVE, j % 3 != 1);
      node->Set(SLIP, j % 3 == 0);  // frictional: slip, inactive, stick, slip, ...
      ++j;
    }
    SetFrictionParameters(root, SlaveNodes());
    Properties& properties = root.GetOrCreateProperties(1);
    properties.SetValue(INTEGRATION_ORDER_CONTACT, 3);
    root.GetProcessInfo().SetValue(INITIAL_PENALTY, 1.0);
    root.GetProcessInfo().SetValue(SCALE_FACTOR, 2.5);
  }

  std::vector<Node*> SlaveNodes() {
    std::vector<Node*> nodes;
    for (const auto& f : slave)
      for (IndexType id : f)
        if (std::find(nodes.begin(), nodes.end(), &root.GetNode(id)) == nodes.end()) nodes.push_back(&root.GetNode(id));
    return nodes;
  }
};

// 2D: five slave nodes on an arc (body below, normals up; listed right to left so that the
// rotated tangent points up) and three master nodes above it (normals down). The slave arc
// penetrates the master in the middle and is open at its ends; the last slave segment pairs with
// nothing, it only moves the normal of its inner node.
void Build2D(Interface& in) {
  in.dim = 2;
  in.slave_direction = Array3(0.0, 1.0, 0.0);
  const double xs[] = {1.5, 0.5, -0.5, -1.5, -2.5};
  for (int i = 0; i < 5; ++i) MakeNode(in.root, 1 + i, Array3(xs[i], 0.02 - 0.04 * xs[i] * xs[i], 0.0));
  const double xm[] = {-1.2, 0.1, 1.3};
  for (int l = 0; l < 3; ++l) MakeNode(in.root, 101 + l, Array3(xm[l], 0.01 * xm[l] - 0.003 * xm[l] * xm[l], 0.0));
  in.slave = {{1, 2}, {2, 3}, {3, 4}, {4, 5}};
  in.master = {{101, 102}, {102, 103}};
}

// 3D: a 3x3-node slave patch on a curved, twisted surface (warped quads; normals up) and a
// non-matching 3x3-node master patch above it (faces listed clockwise seen from above).
void Build3D(Interface& in, bool slave_triangles, bool master_triangles) {
  in.dim = 3;
  in.slave_direction = Array3(0.0, 0.0, 1.0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x = i + 0.03 * j, y = j - 0.02 * i;
      const double z = 0.03 - 0.03 * ((x - 1) * (x - 1) + 0.7 * (y - 1) * (y - 1)) + 0.01 * x * y;
      MakeNode(in.root, 1 + i + 3 * j, Array3(x, y, z));
      const double xm = 0.3 + 1.1 * i, ym = 0.35 + 1.1 * j;
      MakeNode(in.root, 101 + i + 3 * j, Array3(xm, ym, 0.005 + 0.01 * xm - 0.005 * ym + 0.004 * xm * ym));
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const IndexType a = 1 + i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
      if (slave_triangles) {
        in.slave.push_back({a, b, c});
        in.slave.push_back({a, c, d});
      } else {
        in.slave.push_back({a, b, c, d});
      }
      if (master_triangles) {
        in.master.push_back({100 + a, 100 + c, 100 + b});
        in.master.push_back({100 + a, 100 + d, 100 + c});
      } else {
        in.master.push_back({100 + a, 100 + d, 100 + c, 100 + b});
      }
    }
}

using Builder = std::function<void(Interface&)>;

const std::map<std::string, Builder>& Builders() {
  static const std::map<std::string, Builder> builders = {
      {"2D2N", Build2D},
      {"3D4N", [](Interface& in) { Build3D(in, false, false); }},
      {"3D3N", [](Interface& in) { Build3D(in, true, true); }},
      {"3D3N4N", [](Interface& in) { Build3D(in, true, false); }},
      {"3D4N3N", [](Interface& in) { Build3D(in, false, true); }},
  };
  return builders;
}

// ---------------------------------------------------------------------------------------------
// 1. Derivatives of the nodal normals.

// `symmetry_plane`: the first slave node's VECTOR_LAGRANGE_MULTIPLIER_X is fixed, so its normal has
// no x component (NodalNormalSupport::SymmetryMask) and its derivatives are those of the masked sum.
void CheckNormalDerivatives(const std::string& case_name, bool symmetry_plane = false) {
  SCOPED_TRACE(case_name);
  Interface in;
  Builders().at(case_name)(in);
  Node* on_plane = in.SlaveNodes().front();
  if (symmetry_plane) on_plane->AddDof(VECTOR_LAGRANGE_MULTIPLIER_X).fixed = true;
  in.Finish();
  const NodalNormalSupport& support = *in.support;
  NodalNormalSupport::Derivatives d;
  const double h = 1e-6;
  double max_error = 0.0, max_derivative = 0.0;
  for (Node* node : in.SlaveNodes()) {
    support.Compute(*node, d);
    // The stored NORMAL is the same function, and points out of the slave body.
    EXPECT_LE((d.normal - NormalCalculationUtilities::GetNodalNormal(*node)).norm(), 1e-14) << "node " << node->Id();
    EXPECT_LE((d.normal - support.Normal(*node)).norm(), 0.0);
    EXPECT_GT(d.normal.dot(in.slave_direction), 0.9) << "node " << node->Id();
    if (symmetry_plane && node == on_plane) {
      Array3 unmasked = Array3::Zero();
      for (const Geometry* face : support.Faces(*node)) unmasked += NodalNormalSupport::UnitCornerNormal(*face, *node);
      EXPECT_GT(std::abs(unmasked.normalized().x()), 1e-3);  // the mask changes this normal
      EXPECT_EQ(d.normal.x(), 0.0);
    }
    for (Node* k : in.root.Nodes()) {
      const auto it = std::find(d.nodes.begin(), d.nodes.end(), k);
      for (int c = 0; c < in.dim; ++c) {
        const double x = k->Coordinates()[c];
        k->Coordinates()[c] = x + h;
        const Array3 plus = support.Normal(*node);
        k->Coordinates()[c] = x - h;
        const Array3 minus = support.Normal(*node);
        k->Coordinates()[c] = x;
        const Array3 fd = (plus - minus) / (2.0 * h);
        const Array3 exact = it == d.nodes.end() ? Array3::Zero() : Array3(d.dn_dx[it - d.nodes.begin()].col(c));
        EXPECT_LE((exact - fd).cwiseAbs().maxCoeff(), 1e-7) << "dn(" << node->Id() << ")/dx(" << k->Id() << ", " << c
                                                            << "): " << exact.transpose() << " vs " << fd.transpose();
        max_error = std::max(max_error, (exact - fd).cwiseAbs().maxCoeff());
        max_derivative = std::max(max_derivative, exact.cwiseAbs().maxCoeff());
      }
    }
  }
  EXPECT_GT(max_derivative, 0.1);
  std::cout << "[ normal derivatives " << case_name << " ] max |exact - FD| = " << max_error
            << ", max |dn/dx| = " << max_derivative << "\n";
}

TEST(NodalNormalSupport, Derivatives2DLines) { CheckNormalDerivatives("2D2N"); }
TEST(NodalNormalSupport, Derivatives3DQuadrilaterals) { CheckNormalDerivatives("3D4N"); }
TEST(NodalNormalSupport, Derivatives3DTriangles) { CheckNormalDerivatives("3D3N"); }
TEST(NodalNormalSupport, DerivativesOnASymmetryPlane) {
  for (const char* name : {"2D2N", "3D4N", "3D3N"}) CheckNormalDerivatives(name, true);
}

// A face's contribution to a nodal normal is its unit normal at that node (Kratos 10.4 evaluates
// UnitNormal at the node's local coordinates): on a warped quadrilateral it differs from corner
// to corner and from the centre's.
TEST(NodalNormalSupport, WarpedQuadCornerNormals) {
  Interface in;
  in.dim = 3;
  const Array3 points[] = {{0.0, 0.0, 0.0}, {2.0, 0.1, 0.3}, {1.7, 1.3, -0.2}, {-0.2, 0.9, 0.25}};
  for (int i = 0; i < 4; ++i) MakeNode(in.root, 1 + i, points[i]);
  const Geometry quad = in.Face({1, 2, 3, 4});
  const Array3 centre = quad.UnitNormal(quad.Reference().LocalCenter());
  for (std::size_t j = 0; j < 4; ++j) {
    const Array3 expected = quad.UnitNormal(quad.Reference().NodesLocalCoordinates()[j]);
    const Array3 corner = NodalNormalSupport::UnitCornerNormal(quad, quad[j]);
    EXPECT_LE((corner - expected).norm(), 1e-14) << "corner " << j;
    EXPECT_GT((corner - centre).norm(), 0.05) << "corner " << j;
  }
}

// ---------------------------------------------------------------------------------------------
// 2. The assembled tangent of the NV pairs.

template <template <int, int, int> class TFamily>
std::unique_ptr<PairedCondition> MakePair(IndexType id, const Geometry& s, const Geometry& m, Properties* p) {
  if (s.WorkingSpaceDimension() == 2) return std::make_unique<TFamily<2, 2, 2>>(id, s, p, m);
  if (s.PointsNumber() == 3 && m.PointsNumber() == 3) return std::make_unique<TFamily<3, 3, 3>>(id, s, p, m);
  if (s.PointsNumber() == 4 && m.PointsNumber() == 4) return std::make_unique<TFamily<3, 4, 4>>(id, s, p, m);
  if (s.PointsNumber() == 3) return std::make_unique<TFamily<3, 3, 4>>(id, s, p, m);
  return std::make_unique<TFamily<3, 4, 3>>(id, s, p, m);
}

using Pairs = std::vector<PairedCondition*>;

Pairs Pointers(const std::vector<std::unique_ptr<PairedCondition>>& owned) {
  Pairs pairs;
  for (const auto& pair : owned) pairs.push_back(pair.get());
  return pairs;
}

/// Global vectors over the union of the pairs' DoFs.
struct Assembly {
  DofsVectorType dofs;
  std::map<const Dof*, Eigen::Index> index;

  explicit Assembly(const Pairs& pairs, const ProcessInfo& info) {
    DofsVectorType local;
    for (const auto& pair : pairs) {
      pair->GetDofList(local, info);
      for (Dof* dof : local)
        if (index.try_emplace(dof, static_cast<Eigen::Index>(dofs.size())).second) dofs.push_back(dof);
    }
  }
  Eigen::Index Size() const { return static_cast<Eigen::Index>(dofs.size()); }

  Vector Residual(const Pairs& pairs, const ProcessInfo& info) const {
    Vector global = Vector::Zero(Size()), rhs;
    DofsVectorType local;
    for (const auto& pair : pairs) {
      pair->GetDofList(local, info);
      pair->CalculateRightHandSide(rhs, info);
      EXPECT_EQ(static_cast<std::size_t>(rhs.size()), local.size());
      for (std::size_t i = 0; i < local.size(); ++i) global[index.at(local[i])] += rhs[i];
    }
    return global;
  }

  Matrix Tangent(const Pairs& pairs, const ProcessInfo& info) const {
    Matrix global = Matrix::Zero(Size(), Size()), lhs;
    Vector rhs;
    DofsVectorType local;
    for (const auto& pair : pairs) {
      pair->GetDofList(local, info);
      pair->CalculateLocalSystem(lhs, rhs, info);
      EXPECT_EQ(static_cast<std::size_t>(lhs.rows()), local.size());
      for (std::size_t i = 0; i < local.size(); ++i)
        for (std::size_t k = 0; k < local.size(); ++k) global(index.at(local[i]), index.at(local[k])) += lhs(i, k);
    }
    return global;
  }
};

double CheckAgainstFiniteDifferences(const Pairs& nv, const Pairs* fixed_pairs, const ProcessInfo& info);

template <template <int, int, int> class TFixed, template <int, int, int> class TNormalVariation>
void CheckAssembledTangent(const std::string& case_name) {
  SCOPED_TRACE(case_name);
  Interface in;
  Builders().at(case_name)(in);
  in.Finish();
  const ProcessInfo& info = in.root.GetProcessInfo();
  Properties* properties = &in.root.GetProperties(1);

  // Every slave face with every master face (pairs without overlap contribute zeros), except a
  // 2D slave face that lies beyond the master: it only carries its inner node's normal.
  std::vector<std::unique_ptr<PairedCondition>> owned_nv, owned_fixed;
  IndexType id = 1000;
  for (std::size_t s = 0; s < in.slave.size(); ++s) {
    if (in.dim == 2 && s + 1 == in.slave.size()) continue;
    for (const auto& m : in.master) {
      const Geometry gs = in.Face(in.slave[s]), gm = in.Face(m);
      owned_nv.push_back(MakePair<TNormalVariation>(id, gs, gm, properties));
      owned_nv.back()->SetNodalNormalSupport(in.support);
      owned_nv.back()->Check(info);
      owned_fixed.push_back(MakePair<TFixed>(id++, gs, gm, properties));
      // Frictional pairs: D_n, M_n with the master shifted (a non-zero weighted slip).
      const Array3 offset = in.dim == 2 ? Array3(0.1, 0.01, 0.0) : Array3(0.08, -0.06, 0.01);
      for (PairedCondition* pair : {owned_nv.back().get(), owned_fixed.back().get()})
        InitializeWithMasterOffset(*pair, gm, offset, info);
    }
  }
  const Pairs nv = Pointers(owned_nv), fixed = Pointers(owned_fixed);
  // Some NV pairs reach beyond their own nodes (the neighbours of their slave nodes).
  std::size_t with_neighbours = 0;
  for (std::size_t i = 0; i < nv.size(); ++i) {
    DofsVectorType dofs_nv, dofs_fixed;
    nv[i]->GetDofList(dofs_nv, info);
    fixed[i]->GetDofList(dofs_fixed, info);
    ASSERT_GE(dofs_nv.size(), dofs_fixed.size());
    EXPECT_TRUE(std::equal(dofs_fixed.begin(), dofs_fixed.end(), dofs_nv.begin()));
    with_neighbours += dofs_nv.size() > dofs_fixed.size() ? 1 : 0;
  }
  EXPECT_GT(with_neighbours, 0u);

  const double error = CheckAgainstFiniteDifferences(nv, &fixed, info);
  std::cout << "[ " << nv.front()->Info() << " ] " << nv.size() << " pairs: max |K - FD| / max |FD| = " << error
            << "\n";
}

/// max |K - FD| / max |FD| of the assembled NV tangent, FD of the assembled residual (normals
/// follow the coordinates); `fixed` (optional): the plain conditions on the same pairs, whose
/// residual must be the same and whose tangent must fail the comparison.
double CheckAgainstFiniteDifferences(const Pairs& nv, const Pairs* fixed_pairs, const ProcessInfo& info) {
  const Assembly assembly(nv, info);
  // Same residual as the plain conditions with the refreshed nodal NORMAL.
  const Vector r = assembly.Residual(nv, info);
  EXPECT_GT(r.norm(), 0.0);
  const Matrix tangent = assembly.Tangent(nv, info);
  const Matrix fd = FiniteDifferenceJacobian(assembly.dofs, 1e-6, [&] { return assembly.Residual(nv, info); });
  const double scale = fd.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  const double error = (tangent - fd).cwiseAbs().maxCoeff() / scale;
  EXPECT_LE(error, 1e-6) << nv.front()->Info();
  if (fixed_pairs) {
    const Vector r_fixed = assembly.Residual(*fixed_pairs, info);
    EXPECT_LE((r - r_fixed).norm(), 1e-13 * r.norm());
    const double error_fixed = (assembly.Tangent(*fixed_pairs, info) - fd).cwiseAbs().maxCoeff() / scale;
    EXPECT_GT(error_fixed, 1e-4) << fixed_pairs->front()->Info() << ": the fixed-normal tangent should miss dn/du";
    std::cout << "[ " << nv.front()->Info() << " ] " << assembly.Size()
              << " DoFs, fixed-normal tangent: " << error_fixed << "\n";
  }
  return error;
}

template <class T>
class AssembledTangent : public ::testing::Test {};

template <template <int, int, int> class TFixed, template <int, int, int> class TNV>
struct Family {
  static void Check(const std::string& c) { CheckAssembledTangent<TFixed, TNV>(c); }
};
using ALM = Family<ALMFrictionlessMortarContactCondition, ALMNVFrictionlessMortarContactCondition>;
using Components =
    Family<ALMFrictionlessComponentsMortarContactCondition, ALMNVFrictionlessComponentsMortarContactCondition>;
using Penalty = Family<PenaltyFrictionlessMortarContactCondition, PenaltyNVFrictionlessMortarContactCondition>;
using ALMFrictional = Family<ALMFrictionalMortarContactCondition, ALMNVFrictionalMortarContactCondition>;
using PenaltyFrictional = Family<PenaltyFrictionalMortarContactCondition, PenaltyNVFrictionalMortarContactCondition>;
using Families = ::testing::Types<ALM, Components, Penalty, ALMFrictional, PenaltyFrictional>;
TYPED_TEST_SUITE(AssembledTangent, Families);

TYPED_TEST(AssembledTangent, Lines2D) { TypeParam::Check("2D2N"); }
TYPED_TEST(AssembledTangent, Quadrilaterals3D) { TypeParam::Check("3D4N"); }
TYPED_TEST(AssembledTangent, Triangles3D) { TypeParam::Check("3D3N"); }
TYPED_TEST(AssembledTangent, TrianglesOnQuadrilaterals3D) { TypeParam::Check("3D3N4N"); }
TYPED_TEST(AssembledTangent, QuadrilateralsOnTriangles3D) { TypeParam::Check("3D4N3N"); }

// ---------------------------------------------------------------------------------------------
// 3. Registration and DoF layout.

TEST(NormalVariationConditions, NamesResolveAndListNeighbourDofs) {
  RegisterContactConditions();
  const auto& registry = Registry<Condition>::Instance();
  for (const char* stem :
       {"ALMNVFrictionlessMortarContactCondition", "ALMNVFrictionlessComponentsMortarContactCondition",
        "PenaltyNVFrictionlessMortarContactCondition", "ALMNVFrictionalMortarContactCondition",
        "PenaltyNVFrictionalMortarContactCondition"})
    for (const char* token : {"2D2N", "3D3N", "3D4N", "3D3N4N", "3D4N3N"}) {
      const std::string name = std::string(stem) + token;
      ASSERT_TRUE(registry.Has(name)) << name;
      EXPECT_EQ(registry.Get(name).Info(), name);
      EXPECT_TRUE(dynamic_cast<const PairedCondition&>(registry.Get(name)).NeedsNodalNormalSupport()) << name;
    }

  Interface in;
  Build2D(in);
  in.Finish();
  const auto& prototype =
      dynamic_cast<const PairedCondition&>(registry.Get("ALMNVFrictionlessMortarContactCondition2D2N"));
  auto slave = prototype.Create(1, in.Face({2, 3}).Nodes(), nullptr);
  auto master = prototype.Create(2, in.Face({101, 102}).Nodes(), nullptr);
  auto pair = prototype.CreatePaired(7, *slave, *master, nullptr);
  EXPECT_EQ(pair->Info(), "ALMNVFrictionlessMortarContactCondition2D2N");
  Vector rhs;
  EXPECT_THROW(pair->CalculateRightHandSide(rhs, in.root.GetProcessInfo()), Error);  // no support yet
  pair->SetNodalNormalSupport(in.support);
  DofsVectorType dofs;
  pair->GetDofList(dofs, in.root.GetProcessInfo());
  // [master u (4), slave u (4), slave pressures (2), neighbours 1 and 4 u (4)]
  ASSERT_EQ(dofs.size(), 14u);
  EXPECT_EQ(dofs[8]->variable, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
  EXPECT_EQ(dofs[10]->node->Id(), 1u);
  EXPECT_EQ(dofs[10]->variable, &DISPLACEMENT_X);
  EXPECT_EQ(dofs[13]->node->Id(), 4u);
  EXPECT_EQ(dofs[13]->variable, &DISPLACEMENT_Y);
  pair->CalculateRightHandSide(rhs, in.root.GetProcessInfo());
  ASSERT_EQ(rhs.size(), 14);
  EXPECT_EQ(rhs.tail(4).norm(), 0.0);  // the neighbours only appear as columns
}

// The contact search hands its NodalNormalSupport to the NV pairs it creates; their assembled
// tangent is exact.
TEST(NormalVariationConditions, PairsFromTheContactSearch) {
  RegisterContactConditions();
  Interface in;
  Build2D(in);
  in.Finish();
  for (Condition* face : in.contact.Conditions()) {
    const bool slave = face->GetGeometry()[0].Id() < 100;
    face->Set(SLAVE, slave);
    face->Set(MASTER, !slave);
    for (Node* node : face->GetGeometry().Nodes()) {
      node->Set(SLAVE, slave);
      node->Set(MASTER, !slave);
    }
  }
  ContactSearchSlot slot;
  slot.condition_name = "ALMNVFrictionlessMortarContactCondition";
  ContactSearchProcess search(in.root, in.contact, Parameters(), slot);
  const ContactSearchStatistics stats = search.UpdateMortarConditions();
  EXPECT_EQ(stats.pairs, 4u);  // the slave segments over the master, with the masters they overlap
  Pairs pairs;
  for (Condition* condition : search.ComputingPart().Conditions()) {
    auto* pair = dynamic_cast<ALMNVFrictionlessMortarContactCondition<2, 2, 2>*>(condition);
    ASSERT_NE(pair, nullptr) << condition->Info();
    ASSERT_NE(pair->GetNodalNormalSupport(), nullptr);
    pairs.push_back(pair);
  }
  int j = 0;
  for (Node* node : in.SlaveNodes()) node->Set(ACTIVE, j++ % 3 != 1);  // the search predicted its own set
  EXPECT_LE(CheckAgainstFiniteDifferences(pairs, nullptr, in.root.GetProcessInfo()), 1e-6);
}

}  // namespace
}  // namespace mc::test
