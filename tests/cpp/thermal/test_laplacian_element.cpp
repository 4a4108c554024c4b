// SPDX-License-Identifier: BSD-3-Clause
// LaplacianElement against exact integrals: for a linear temperature T = a . x the conduction
// energy T^T K T is k |a|^2 V, K annihilates constants, and a constant source Q puts Q V on the
// nodes in total.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <memory>
#include <vector>

#include "core/geometries/reference_element.h"
#include "core/model/element.h"
#include "core/model/node.h"
#include "core/model/properties.h"
#include "core/model/registry.h"
#include "core/utilities/error.h"
#include "thermal/application/register_thermal.h"
#include "thermal/variables/thermal_variables.h"

namespace mc {
namespace {

struct Case {
  GeometryType type;
  const char* name;
};

class LaplacianElementTest : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    RegisterThermal();
    variables_.Add(TEMPERATURE);
    variables_.Add(REACTION_FLUX);
    variables_.Add(HEAT_FLUX);
    properties_.SetValue(CONDUCTIVITY, 2.5);
    const ReferenceElement& reference = ReferenceElement::Get(GetParam().type);
    dim_ = reference.WorkingSpaceDimension();
    // A sheared, stretched copy of the reference element: the volume is det(A) times the reference's.
    Eigen::Matrix3d A;
    A << 1.3, 0.4, 0.2, -0.1, 0.8, 0.3, 0.2, 0.1, 1.1;
    if (dim_ == 2) A.row(2).setZero(), A.col(2).setZero(), A(2, 2) = 1.0;
    Geometry::NodesArray placed;
    for (const Array3& xi : reference.NodesLocalCoordinates()) {
      nodes_.push_back(std::make_unique<Node>(nodes_.size() + 1, Array3(A * xi + Array3(1.0, -2.0, 0.5 * (dim_ == 3))),
                                              variables_, 1));
      nodes_.back()->AddDof(TEMPERATURE, &REACTION_FLUX);
      placed.push_back(nodes_.back().get());
    }
    element_ = Registry<Element>::Instance().Get(GetParam().name).Create(1, placed, &properties_);
    double reference_volume = 0.0;
    for (const auto& point : reference.IntegrationPoints(reference.DefaultIntegrationOrder()))
      reference_volume += point.weight;
    volume_ = reference_volume * A.topLeftCorner(dim_, dim_).determinant();
  }

  VariablesList variables_;
  Properties properties_{1};
  std::vector<std::unique_ptr<Node>> nodes_;
  std::unique_ptr<Element> element_;
  int dim_ = 0;
  double volume_ = 0.0;
};

TEST_P(LaplacianElementTest, ConductionEnergyOfALinearFieldIsExact) {
  const Array3 a(0.7, -1.2, dim_ == 3 ? 0.4 : 0.0);  // the 2D nodes have z = 0
  Vector T(static_cast<Eigen::Index>(nodes_.size()));
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    T(static_cast<Eigen::Index>(i)) = a.dot(nodes_[i]->X0()) + 3.0;
    nodes_[i]->FastGetSolutionStepValue(TEMPERATURE) = T(static_cast<Eigen::Index>(i));
  }
  Matrix K;
  Vector r;
  element_->CalculateLocalSystem(K, r, ProcessInfo{});
  EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
  EXPECT_LT((K * Vector::Ones(K.rows())).norm(), 1e-13 * K.norm());  // constants carry no flux
  EXPECT_NEAR(T.dot(K * T), 2.5 * a.squaredNorm() * volume_, 1e-12 * K.norm());
  EXPECT_LT((r + K * T).norm(), 1e-13 * K.norm());  // no source: the residual is -K T
}

TEST_P(LaplacianElementTest, ConstantSourceIntegratesToItsVolume) {
  for (const auto& node : nodes_) node->FastGetSolutionStepValue(HEAT_FLUX) = 4.0;
  Vector r;
  element_->CalculateRightHandSide(r, ProcessInfo{});
  EXPECT_NEAR(r.sum(), 4.0 * volume_, 1e-13 * volume_);
}

TEST_P(LaplacianElementTest, CheckNamesWhatIsMissing) {
  EXPECT_NO_THROW(element_->Check(ProcessInfo{}));
  properties_.SetValue(CONDUCTIVITY, 0.0);
  EXPECT_THROW(element_->Check(ProcessInfo{}), InputError);
}

INSTANTIATE_TEST_SUITE_P(Geometries, LaplacianElementTest,
                         ::testing::Values(Case{GeometryType::Triangle2D3, "LaplacianElement2D3N"},
                                           Case{GeometryType::Quadrilateral2D4, "LaplacianElement2D4N"},
                                           Case{GeometryType::Tetrahedra3D4, "LaplacianElement3D4N"},
                                           Case{GeometryType::Hexahedra3D8, "LaplacianElement3D8N"}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace mc
