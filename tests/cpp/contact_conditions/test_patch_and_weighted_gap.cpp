// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (frictionless mortar contact conditions):
//  - flat matching patches (2D lines, 3D quadrilaterals, 3D triangles): a uniform contact
//    pressure p (scalar and vector multiplier, zero gap, k = 1) gives slave nodal forces
//    p n x tributary area and equal and opposite master forces, and zero multiplier residuals;
//  - the explicit contribution adds WEIGHTED_GAP = sum over pairs of -n . (D x1 - M x2) and
//    NODAL_AREA; on flat parallel surfaces at distance delta these are delta x tributary area
//    and the tributary area, and both are invariant under a rigid motion of the whole patch;
//  - registration: every name resolves to a condition reporting that name (the axisymmetric
//    2D2N names included; NV names: test_normal_variation.cpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "contact_condition_test_utilities.h"
#include "core/model/registry.h"
#include "core/utilities/error.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/contact_condition_utilities.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"
#include "custom_conditions/register_contact_conditions.h"

namespace mc::test {
namespace {

using Connectivity = std::vector<std::vector<IndexType>>;

struct Patch {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  Connectivity slave, master;
  std::vector<PairedCondition*> pairs;  ///< owned by the "ComputingContact" sub-model part

  static GeometryType Type(int dim, std::size_t nodes) {
    if (dim == 2) return GeometryType::Line2D2;
    return nodes == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4;
  }

  Geometry::NodesArray Nodes(const std::vector<IndexType>& ids) {
    Geometry::NodesArray nodes;
    for (IndexType id : ids) nodes.push_back(&root.GetNode(id));
    return nodes;
  }

  /// One pair per (slave, master) element, of the condition family TFamily.
  void Add(std::unique_ptr<PairedCondition> pair) {
    pairs.push_back(pair.get());
    ModelPart& computing = root.HasSubModelPart("ComputingContact") ? root.GetSubModelPart("ComputingContact")
                                                                    : root.CreateSubModelPart("ComputingContact");
    computing.AddCondition(std::unique_ptr<Condition>(std::move(pair)));
  }

  template <template <int, int, int> class TFamily>
  void MakePairs(int dim) {
    IndexType id = 1;
    for (const auto& s : slave)
      for (const auto& m : master) {
        Geometry gs(Type(dim, s.size()), Nodes(s)), gm(Type(dim, m.size()), Nodes(m));
        if (dim == 2)
          Add(std::make_unique<TFamily<2, 2, 2>>(id++, gs, nullptr, gm));
        else if (s.size() == 3 && m.size() == 3)
          Add(std::make_unique<TFamily<3, 3, 3>>(id++, gs, nullptr, gm));
        else if (s.size() == 4 && m.size() == 4)
          Add(std::make_unique<TFamily<3, 4, 4>>(id++, gs, nullptr, gm));
        else if (s.size() == 3)
          Add(std::make_unique<TFamily<3, 3, 4>>(id++, gs, nullptr, gm));
        else
          Add(std::make_unique<TFamily<3, 4, 3>>(id++, gs, nullptr, gm));
      }
  }

  /// Tributary measure of each slave node: element measure / number of nodes (exact for
  /// flat simplices and parallelograms).
  std::map<IndexType, double> Tributary(int dim) {
    std::map<IndexType, double> area;
    for (const auto& s : slave) {
      const Geometry g(Type(dim, s.size()), Nodes(s));
      for (IndexType id : s) area[id] += g.DomainSize() / static_cast<double>(s.size());
    }
    return area;
  }

  /// Assembled RHS per (node id, DoF variable).
  std::map<std::pair<IndexType, const Variable<double>*>, double> AssembleRhs() {
    std::map<std::pair<IndexType, const Variable<double>*>, double> out;
    const ProcessInfo& info = root.GetProcessInfo();
    DofsVectorType dofs;
    Vector rhs;
    for (auto& pair : pairs) {
      pair->GetDofList(dofs, info);
      pair->CalculateRightHandSide(rhs, info);
      for (std::size_t i = 0; i < dofs.size(); ++i) out[{dofs[i]->node->Id(), dofs[i]->variable}] += rhs[i];
    }
    return out;
  }
};

const Variable<double>* const kU[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

// Slave ids 1.., master ids 101.. on the same points (matching), master elements reversed so
// that they face the slave. Returns the slave normal.
Array3 BuildMatchingPatch(Patch& patch, int dim, bool triangles) {
  ModelPart& root = patch.root;
  if (dim == 2) {
    for (int i = 0; i < 3; ++i) {
      MakeNode(root, 1 + i, Array3(0.5 * i, 0.0, 0.0));
      MakeNode(root, 101 + i, Array3(0.5 * i, 0.0, 0.0));
    }
    patch.slave = {{1, 2}, {2, 3}};
    patch.master = {{103, 102}, {102, 101}};
    return Array3(0.0, 1.0, 0.0);
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      MakeNode(root, 1 + i + 3 * j, Array3(0.5 * i, 0.5 * j, 0.0));
      MakeNode(root, 101 + i + 3 * j, Array3(0.5 * i, 0.5 * j, 0.0));
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const IndexType a = 1 + i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
      if (triangles) {
        patch.slave.push_back({a, b, c});
        patch.slave.push_back({a, c, d});
        patch.master.push_back({100 + a, 100 + c, 100 + b});
        patch.master.push_back({100 + a, 100 + d, 100 + c});
      } else {
        patch.slave.push_back({a, b, c, d});
        patch.master.push_back({100 + a, 100 + d, 100 + c, 100 + b});
      }
    }
  return Array3(0.0, 0.0, 1.0);
}

template <template <int, int, int> class TFamily>
void CheckUniformPressure(int dim, bool triangles, bool vector_multiplier) {
  Patch patch;
  const Array3 normal = BuildMatchingPatch(patch, dim, triangles);
  const double p = -3.0;
  for (const auto& s : patch.slave)
    for (IndexType id : s) {
      Node& node = patch.root.GetNode(id);
      NormalCalculationUtilities::SetNodalNormal(node, normal);
      node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = p;
      node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = p * normal;
      node.Set(ACTIVE, true);
    }
  patch.root.GetProcessInfo().SetValue(INITIAL_PENALTY, 1e3);
  patch.root.GetProcessInfo().SetValue(SCALE_FACTOR, 1.0);
  patch.MakePairs<TFamily>(dim);
  auto assembled = patch.AssembleRhs();
  auto rhs = [&](IndexType id, const Variable<double>* var) { return assembled[{id, var}]; };
  const auto tributary = patch.Tributary(dim);

  double total = 0.0;
  for (const auto& [id, area] : tributary) {
    total += area;
    for (int c = 0; c < dim; ++c) {
      EXPECT_NEAR(rhs(id, kU[c]), p * normal[c] * area, 1e-12) << "slave node " << id << " component " << c;
      EXPECT_NEAR(rhs(100 + id, kU[c]), -p * normal[c] * area, 1e-12) << "master node " << 100 + id;
    }
    if (vector_multiplier) {
      const Variable<double>* lm[3] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                       &VECTOR_LAGRANGE_MULTIPLIER_Z};
      for (int c = 0; c < dim; ++c) EXPECT_NEAR(rhs(id, lm[c]), 0.0, 1e-12);
    } else {
      EXPECT_NEAR(rhs(id, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), 0.0, 1e-12);
    }
  }
  EXPECT_NEAR(total, 1.0, 1e-12);  // unit length / unit square
}

TEST(UniformPressurePatch, Scalar2D) { CheckUniformPressure<ALMFrictionlessMortarContactCondition>(2, false, false); }
TEST(UniformPressurePatch, Scalar3DQuadrilaterals) {
  CheckUniformPressure<ALMFrictionlessMortarContactCondition>(3, false, false);
}
TEST(UniformPressurePatch, Scalar3DTriangles) {
  CheckUniformPressure<ALMFrictionlessMortarContactCondition>(3, true, false);
}
TEST(UniformPressurePatch, Components2D) {
  CheckUniformPressure<ALMFrictionlessComponentsMortarContactCondition>(2, false, true);
}
TEST(UniformPressurePatch, Components3DQuadrilaterals) {
  CheckUniformPressure<ALMFrictionlessComponentsMortarContactCondition>(3, false, true);
}
TEST(UniformPressurePatch, Components3DTriangles) {
  CheckUniformPressure<ALMFrictionlessComponentsMortarContactCondition>(3, true, true);
}

// Slave: the matching-patch slave side; master: a finer, shifted, mixed mesh at distance delta
// that covers the slave completely.
Array3 BuildGapPatch(Patch& patch, int dim, double delta) {
  ModelPart& root = patch.root;
  if (dim == 2) {
    for (int i = 0; i < 3; ++i) MakeNode(root, 1 + i, Array3(0.5 * i, 0.0, 0.0));
    for (int i = 0; i < 4; ++i) MakeNode(root, 101 + i, Array3(-0.1 + 0.4 * i, delta, 0.0));
    patch.slave = {{1, 2}, {2, 3}};
    patch.master = {{104, 103}, {103, 102}, {102, 101}};
    return Array3(0.0, 1.0, 0.0);
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) MakeNode(root, 1 + i + 3 * j, Array3(0.5 * i, 0.5 * j, 0.0));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const IndexType a = 1 + i + 3 * j;
      patch.slave.push_back({a, a + 1, a + 4, a + 3});
    }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) MakeNode(root, 101 + i + 4 * j, Array3(-0.1 + 0.4 * i, -0.05 + 0.38 * j, delta));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const IndexType a = 101 + i + 4 * j, b = a + 1, c = a + 5, d = a + 4;
      if ((i + j) % 2 == 0) {
        patch.master.push_back({a, d, c, b});
      } else {
        patch.master.push_back({a, c, b});
        patch.master.push_back({a, d, c});
      }
    }
  return Array3(0.0, 0.0, 1.0);
}

void ResetAndAccumulate(Patch& patch) {
  for (const auto& s : patch.slave)
    for (IndexType id : s) patch.root.GetNode(id).FastGetSolutionStepValue(WEIGHTED_GAP) = 123.0;
  ContactConditionUtilities::ComputeExplicitContributions(patch.root.GetSubModelPart("ComputingContact"));
}

template <int D, int S, int M>
void AddDirectGap(const PairedCondition& pair, std::map<IndexType, double>& gap) {
  using K = MortarPairKinematics<D, S, M>;
  K k;
  typename K::SlaveMatrix x1, n1;
  typename K::MasterMatrix x2;
  for (int i = 0; i < S; ++i) {
    x1.row(i) = pair.GetGeometry()[i].Coordinates().template head<D>().transpose();
    n1.row(i) = NormalCalculationUtilities::GetNodalNormal(pair.GetGeometry()[i]).template head<D>().transpose();
  }
  for (int l = 0; l < M; ++l) x2.row(l) = pair.GetPairedGeometry()[l].Coordinates().template head<D>().transpose();
  if (!k.ComputeValues(x1, x2, n1, MortarIntegrationSettings{})) return;
  const typename K::SlaveMatrix jump = k.D * x1 - k.M * x2;
  for (int j = 0; j < S; ++j) gap[pair.GetGeometry()[j].Id()] -= n1.row(j).dot(jump.row(j));
}

void CheckWeightedGap(int dim) {
  Patch patch;
  const double delta = 0.04;
  const Array3 normal = BuildGapPatch(patch, dim, delta);
  for (const auto& s : patch.slave)
    for (IndexType id : s) NormalCalculationUtilities::SetNodalNormal(patch.root.GetNode(id), normal);
  patch.MakePairs<PenaltyFrictionlessMortarContactCondition>(dim);
  ResetAndAccumulate(patch);

  // Independent evaluation from D and M of each pair.
  std::map<IndexType, double> direct;
  for (const auto& pair : patch.pairs) {
    const Geometry& s = pair->GetGeometry();
    const Geometry& m = pair->GetPairedGeometry();
    if (dim == 2)
      AddDirectGap<2, 2, 2>(*pair, direct);
    else if (s.PointsNumber() == 4 && m.PointsNumber() == 4)
      AddDirectGap<3, 4, 4>(*pair, direct);
    else
      AddDirectGap<3, 4, 3>(*pair, direct);
  }

  std::map<IndexType, double> gap_before;
  for (const auto& [id, area] : patch.Tributary(dim)) {
    const Node& node = patch.root.GetNode(id);
    const double gap = node.FastGetSolutionStepValue(WEIGHTED_GAP);
    EXPECT_NEAR(gap, delta * area, 1e-12) << "node " << id;
    EXPECT_NEAR(gap, direct[id], 1e-12) << "node " << id;
    EXPECT_NEAR(node.GetValue(NODAL_AREA), area, 1e-12) << "node " << id;
    gap_before[id] = gap;
  }

  // Rigid motion of every node (through DISPLACEMENT), normals rotated with it.
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.4, Array3(0.3, -0.5, 0.8).normalized())).toRotationMatrix();
  const Eigen::Matrix3d r = dim == 2 ? Eigen::Matrix3d(Eigen::AngleAxisd(0.7, Array3::UnitZ())) : rotation;
  const Array3 shift = dim == 2 ? Array3(0.3, -1.2, 0.0) : Array3(0.3, -1.2, 2.0);
  for (Node* node : patch.root.Nodes()) {
    const Array3 x = r * node->X0() + shift;
    node->FastGetSolutionStepValue(DISPLACEMENT) = x - node->X0();
    node->Coordinates() = x;
  }
  for (const auto& s : patch.slave)
    for (IndexType id : s) NormalCalculationUtilities::SetNodalNormal(patch.root.GetNode(id), r * normal);
  ResetAndAccumulate(patch);
  for (const auto& [id, gap] : gap_before) {
    EXPECT_NEAR(patch.root.GetNode(id).FastGetSolutionStepValue(WEIGHTED_GAP), gap, 1e-12) << "node " << id;
  }
}

TEST(ExplicitWeightedGap, Flat2D) { CheckWeightedGap(2); }
TEST(ExplicitWeightedGap, Flat3DMixedMaster) { CheckWeightedGap(3); }

TEST(ContactConditionRegistry, NamesResolve) {
  RegisterContactConditions();
  RegisterContactConditions();  // idempotent
  const auto& registry = Registry<Condition>::Instance();
  for (const char* stem : {"ALMFrictionlessMortarContactCondition", "ALMFrictionlessComponentsMortarContactCondition",
                           "PenaltyFrictionlessMortarContactCondition", "ALMFrictionalMortarContactCondition",
                           "PenaltyFrictionalMortarContactCondition"})
    for (const char* token : {"2D2N", "3D3N", "3D4N", "3D3N4N", "3D4N3N"}) {
      const std::string name = std::string(stem) + token;
      ASSERT_TRUE(registry.Has(name)) << name;
      EXPECT_EQ(registry.Get(name).Info(), name);
    }

  // A pair created through the prototype, as the search does.
  Patch patch;
  BuildMatchingPatch(patch, 3, false);
  const auto& prototype =
      dynamic_cast<const PairedCondition&>(registry.Get("ALMFrictionlessMortarContactCondition3D4N"));
  auto slave = prototype.Create(1, patch.Nodes({1, 2, 5, 4}), nullptr);
  auto master = prototype.Create(2, patch.Nodes({101, 104, 105, 102}), nullptr);
  auto pair = prototype.CreatePaired(7, *slave, *master, nullptr);
  EXPECT_EQ(pair->Id(), 7u);
  EXPECT_EQ(pair->GetPairedCondition(), master.get());
  EXPECT_EQ(pair->GetPairedGeometry().pGetNode(1)->Id(), 104u);
  DofsVectorType dofs;
  pair->GetDofList(dofs, patch.root.GetProcessInfo());
  ASSERT_EQ(dofs.size(), 28u);  // [master u (12), slave u (12), slave pressures (4)]
  EXPECT_EQ(dofs[0]->node->Id(), 101u);
  EXPECT_EQ(dofs[12]->node->Id(), 1u);
  EXPECT_EQ(dofs[24]->variable, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);

  for (const char* name :
       {"ALMFrictionlessAxisymMortarContactCondition2D2N", "ALMNVFrictionlessAxisymMortarContactCondition2D2N",
        "PenaltyFrictionlessAxisymMortarContactCondition2D2N", "PenaltyNVFrictionlessAxisymMortarContactCondition2D2N",
        "ALMFrictionalAxisymMortarContactCondition2D2N", "ALMNVFrictionalAxisymMortarContactCondition2D2N",
        "PenaltyFrictionalAxisymMortarContactCondition2D2N", "PenaltyNVFrictionalAxisymMortarContactCondition2D2N"}) {
    ASSERT_TRUE(registry.Has(name)) << name;
    EXPECT_EQ(registry.Get(name).Info(), name);
  }
}

TEST(ContactConditionParameters, MissingPenaltyIsAnInputError) {
  Patch patch;
  const Array3 normal = BuildMatchingPatch(patch, 2, false);
  for (IndexType id : {1, 2}) {
    NormalCalculationUtilities::SetNodalNormal(patch.root.GetNode(id), normal);
    patch.root.GetNode(id).Set(ACTIVE, true);
  }
  patch.slave = {{1, 2}};
  patch.master = {{102, 101}};
  patch.MakePairs<ALMFrictionlessMortarContactCondition>(2);
  Vector rhs;
  try {
    patch.pairs[0]->CalculateRightHandSide(rhs, patch.root.GetProcessInfo());
    ADD_FAILURE() << "no INITIAL_PENALTY should be an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("INITIAL_PENALTY"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mc::test
