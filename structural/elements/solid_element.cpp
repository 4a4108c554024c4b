// SPDX-License-Identifier: BSD-3-Clause
#include "structural/elements/solid_element.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "structural/constitutive_laws/voigt_utilities.h"
#include "structural/elements/displacement_dofs.h"

namespace mc {

namespace {

constexpr int kMaxNodes = 27;
constexpr int kMaxDofs = 3 * kMaxNodes;
using NVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxNodes, 1>;
using Gradients = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxNodes, 3>;
using NodalValues = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxNodes, 3>;
using BMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, kMaxDofs>;
using DofVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDofs, 1>;
using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxNodes, kMaxNodes>;

/// Tensor index pairs of the rows of a 2D plane B-matrix (xx, yy, xy).
constexpr int kPlanePairs[3][2] = {{0, 0}, {1, 1}, {0, 1}};

// Reference coordinates and displacements of the nodes.
void Gather(const Geometry& geometry, NodalValues& X, NodalValues& U) {
  const auto n = static_cast<Eigen::Index>(geometry.PointsNumber());
  X.resize(n, 3);
  U.resize(n, 3);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Node& node = geometry[static_cast<std::size_t>(a)];
    X.row(a) = node.X0().transpose();
    U.row(a) = node.FastGetSolutionStepValue(DISPLACEMENT).transpose();
  }
}

// B-matrix of the variation of a symmetric strain: row (I, J) of node a, direction k is
// F(k, I) g(a, J) + F(k, J) g(a, I) (halved on the diagonal); the axisymmetric hoop row is
// hoop * N(a) on the radial direction.
void FillB(const Eigen::Matrix3d& F, const Gradients& g, const NVector& N, double hoop, int dim, int strain_size,
           BMatrix& B) {
  const auto n = g.rows();
  B.setZero(strain_size, n * dim);
  const int rows = dim == 3 ? 6 : 3;
  for (int p = 0; p < rows; ++p) {
    const int I = dim == 3 ? voigt::kPairs[p][0] : kPlanePairs[p][0];
    const int J = dim == 3 ? voigt::kPairs[p][1] : kPlanePairs[p][1];
    for (Eigen::Index a = 0; a < n; ++a)
      for (int k = 0; k < dim; ++k)
        B(p, a * dim + k) = I == J ? F(k, I) * g(a, I) : F(k, I) * g(a, J) + F(k, J) * g(a, I);
  }
  if (strain_size == 4)
    for (Eigen::Index a = 0; a < n; ++a) B(3, a * dim) = hoop * N[a];
}

// Kratos' "equivalent" deformation gradient of a small-strain element, I + eps (symmetric),
// from the law-sized strain vector (engineering shears).
Eigen::Matrix3d EquivalentF(const voigt::StrainVector& strain) {
  Eigen::Matrix3d F = voigt::StressToTensor(strain);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) *= i == j ? 1.0 : 0.5;  // engineering shears halved
  return F + Eigen::Matrix3d::Identity();
}

// The Green-Lagrange strain of F in the law's Voigt order.
voigt::StrainVector GreenLagrangeStrain(const Eigen::Matrix3d& F, int strain_size) {
  const voigt::Vector6 E = voigt::StrainToVoigt(0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity()));
  const auto comps = voigt::Components(strain_size);
  voigt::StrainVector strain(strain_size);
  for (int c = 0; c < strain_size; ++c) strain[c] = E[comps[c]];
  return strain;
}

}  // namespace

/// Kinematics of one integration point in the reference configuration.
struct SolidElement::PointState {
  NVector N;
  Gradients DN_DX;
  Eigen::Matrix3d F;
  double detJ0 = 0.0;
  double dV0 = 0.0;  ///< weight x det J0 x (thickness or 2 pi R)
  double R = 0.0;    ///< reference radius (axisymmetry)
  double r = 0.0;    ///< current radius (axisymmetry)
};

struct SolidElement::PointResults {
  voigt::StrainVector strain;
  voigt::StrainVector pk2;
  Eigen::Matrix3d pk2_tensor;
  Eigen::Matrix3d cauchy_tensor;
  double energy = 0.0;
};

namespace {

void ComputePoint(const Geometry& geometry, int order, int g, const NodalValues& X, const NodalValues& U, int dim,
                  bool axisymmetric, double thickness, auto& k) {
  const auto& points = geometry.IntegrationPoints(order);
  const Matrix& N = geometry.ShapeFunctionsValues(order);
  // A max-size copy: products with the dynamic geometry matrix would need heap temporaries.
  const Gradients dN = geometry.ShapeFunctionsLocalGradients(order)[static_cast<std::size_t>(g)];
  const auto n = X.rows();
  k.N = N.row(g).transpose();
  Eigen::Matrix3d J0 = Eigen::Matrix3d::Identity();
  J0.topLeftCorner(dim, dim) = X.leftCols(dim).transpose() * dN;
  k.detJ0 = J0.determinant();
  const Eigen::Matrix3d J0inv = J0.inverse();
  k.DN_DX = dN * J0inv.topLeftCorner(dim, dim);
  k.F.setIdentity();
  k.F.topLeftCorner(dim, dim) += U.leftCols(dim).transpose() * k.DN_DX;
  double factor = dim == 2 ? thickness : 1.0;
  if (axisymmetric) {
    k.R = k.N.dot(X.col(0).head(n));
    k.r = k.R + k.N.dot(U.col(0).head(n));
    k.F(2, 2) = k.r / k.R;
    factor = 2.0 * std::numbers::pi * k.R;
  }
  k.dV0 = points[static_cast<std::size_t>(g)].weight * k.detJ0 * factor;
}

}  // namespace

int SolidElement::Dimension() const noexcept { return GetGeometry().Reference().WorkingSpaceDimension(); }

int SolidElement::StrainSize() const noexcept { return Dimension() == 3 ? 6 : (axisymmetric_ ? 4 : 3); }

std::unique_ptr<Element> SolidElement::Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const {
  return std::make_unique<SolidElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties, kinematics_,
                                        axisymmetric_);
}

std::string SolidElement::Info() const {
  static constexpr const char* kStem[] = {"SmallDisplacementElement", "TotalLagrangianElement",
                                          "UpdatedLagrangianElement"};
  return StructuralEntityName(kStem[static_cast<int>(kinematics_)], axisymmetric_, GetGeometry());
}

void SolidElement::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  GetDisplacementDofList(GetGeometry(), dofs);
}

bool SolidElement::HasConstantLeftHandSide() const {
  return kinematics_ == Kinematics::SmallDisplacement && !laws_.empty() &&
         std::all_of(laws_.begin(), laws_.end(), [](const auto& law) { return law->HasConstantTangent(); });
}

void SolidElement::Initialize(const ProcessInfo& info) {
  if (!HasProperties() || !GetProperties().HasConstitutiveLaw())
    throw InputError(Concat("element ", Id(), " (", Info(), "): ",
                            HasProperties() ? Concat("properties ", GetProperties().Id(), " have no constitutive law")
                                            : std::string("has no properties")));
  const Geometry& geometry = GetGeometry();
  const int order = geometry.DefaultIntegrationOrder();
  const auto npoints = geometry.IntegrationPoints(order).size();
  const Matrix& N = geometry.ShapeFunctionsValues(order);
  laws_.clear();
  laws_.reserve(npoints);
  for (std::size_t g = 0; g < npoints; ++g) {
    laws_.push_back(GetProperties().GetConstitutiveLaw()->Clone());
    laws_.back()->InitializeMaterial(GetProperties(), geometry, N.row(static_cast<Eigen::Index>(g)).transpose());
  }
}

void SolidElement::EnsureLaws() {
  if (laws_.size() != static_cast<std::size_t>(NumberOfIntegrationPoints())) Initialize(ProcessInfo{});
}

void SolidElement::FinalizeSolutionStep(const ProcessInfo& info) {
  EnsureLaws();
  for (int g = 0; g < static_cast<int>(laws_.size()); ++g) {
    PointResults results;
    EvaluateResults(g, results, info);
    ConstitutiveLawParameters values;
    values.properties = &GetProperties();
    values.process_info = &info;
    values.strain = results.strain;
    values.stress = results.pk2;
    values.compute_tangent = false;
    laws_[static_cast<std::size_t>(g)]->FinalizeMaterialResponse(values, ConstitutiveLaw::StressMeasure::PK2);
  }
}

void SolidElement::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

void SolidElement::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) { CalculateAll(&lhs, nullptr, info); }

void SolidElement::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) { CalculateAll(nullptr, &rhs, info); }

void SolidElement::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  EnsureLaws();
  const Geometry& geometry = GetGeometry();
  const Properties& properties = GetProperties();
  const int dim = Dimension();
  const int strain_size = StrainSize();
  const auto n = static_cast<Eigen::Index>(geometry.PointsNumber());
  const Eigen::Index ndof = n * dim;
  if (lhs) lhs->setZero(ndof, ndof);
  if (rhs) rhs->setZero(ndof);

  NodalValues X, U;
  Gather(geometry, X, U);
  DofVector u(ndof);
  for (Eigen::Index a = 0; a < n; ++a) u.segment(a * dim, dim) = U.row(a).head(dim).transpose();

  const double thickness = properties.Has(THICKNESS) ? properties.GetValue(THICKNESS) : 1.0;
  const double density = properties.Has(DENSITY) ? properties.GetValue(DENSITY) : 0.0;
  NodalValues body;
  const bool has_body = rhs && density != 0.0 && geometry[0].HasSolutionStepValue(VOLUME_ACCELERATION);
  if (has_body) {
    body.resize(n, 3);
    for (Eigen::Index a = 0; a < n; ++a)
      body.row(a) = geometry[static_cast<std::size_t>(a)].FastGetSolutionStepValue(VOLUME_ACCELERATION).transpose();
  }

  thread_local ConstitutiveLawParameters values;
  values.properties = &properties;
  values.process_info = &info;
  values.compute_stress = rhs != nullptr || kinematics_ != Kinematics::SmallDisplacement;
  values.compute_tangent = lhs != nullptr;
  values.small_strain = kinematics_ == Kinematics::SmallDisplacement;

  const int order = geometry.DefaultIntegrationOrder();
  const int npoints = static_cast<int>(laws_.size());
  PointState k;
  BMatrix B;
  Gradients G;
  for (int g = 0; g < npoints; ++g) {
    ComputePoint(geometry, order, g, X, U, dim, axisymmetric_, thickness, k);
    values.F = k.F;
    values.detF = k.F.determinant();
    if (kinematics_ != Kinematics::SmallDisplacement && !(values.detF > 0.0))
      throw SolutionError(
          Concat("element ", Id(), " (", Info(), ") is inverted at integration point ", g, ": det F = ", values.detF));
    ConstitutiveLaw::StressMeasure measure = ConstitutiveLaw::StressMeasure::PK2;
    double radius = k.R;
    switch (kinematics_) {
      case Kinematics::SmallDisplacement:
        FillB(Eigen::Matrix3d::Identity(), k.DN_DX, k.N, 1.0 / k.R, dim, strain_size, B);
        values.strain = B * u;
        values.F = EquivalentF(values.strain);
        values.detF = values.F.determinant();
        break;
      case Kinematics::TotalLagrangian:
        FillB(k.F, k.DN_DX, k.N, k.F(2, 2) / k.R, dim, strain_size, B);
        values.strain = GreenLagrangeStrain(k.F, strain_size);
        G = k.DN_DX;
        break;
      case Kinematics::UpdatedLagrangian: {
        G = k.DN_DX * k.F.inverse().topLeftCorner(dim, dim);
        FillB(Eigen::Matrix3d::Identity(), G, k.N, 1.0 / k.r, dim, strain_size, B);
        measure = ConstitutiveLaw::StressMeasure::Kirchhoff;
        radius = k.r;
        break;
      }
    }
    laws_[static_cast<std::size_t>(g)]->CalculateMaterialResponse(values, measure);

    if (rhs) {
      rhs->noalias() -= k.dV0 * (B.transpose() * values.stress);
      if (has_body) {
        const Eigen::Vector3d b = density * (body.transpose() * k.N);
        for (Eigen::Index a = 0; a < n; ++a) rhs->segment(a * dim, dim) += k.dV0 * k.N[a] * b.head(dim);
      }
    }
    if (lhs) {
      const BMatrix CB = values.tangent * B;
      lhs->noalias() += k.dV0 * (B.transpose() * CB);
      if (kinematics_ != Kinematics::SmallDisplacement) {
        const Eigen::Matrix3d stress = voigt::StressToTensor(values.stress);
        const Gradients SG = G * stress.topLeftCorner(dim, dim);
        const NodeMatrix H = SG * G.transpose();
        for (Eigen::Index a = 0; a < n; ++a)
          for (Eigen::Index b = 0; b < n; ++b) {
            double hab = H(a, b);
            for (int c = 0; c < dim; ++c) (*lhs)(a * dim + c, b * dim + c) += k.dV0 * hab;
            if (axisymmetric_)
              (*lhs)(a * dim, b * dim) += k.dV0 * k.N[a] * k.N[b] * values.stress[3] / (radius * radius);
          }
      }
    }
  }
}

void SolidElement::CalculateMassMatrix(Matrix& mass, const ProcessInfo& info) {
  const Geometry& geometry = GetGeometry();
  const int dim = Dimension();
  const auto n = static_cast<Eigen::Index>(geometry.PointsNumber());
  const Properties& properties = GetProperties();
  if (!properties.Has(DENSITY))
    throw InputError(Concat("element ", Id(), " (", Info(), "): properties ", properties.Id(),
                            " have no DENSITY (needed for the mass matrix)"));
  const double density = properties.GetValue(DENSITY);
  const double thickness = properties.Has(THICKNESS) ? properties.GetValue(THICKNESS) : 1.0;
  NodalValues X, U;
  Gather(geometry, X, U);
  // N_a N_b is of twice the degree of the stiffness integrand's shape-function part.
  const int order = std::min(5, std::max(2, 2 * geometry.DefaultIntegrationOrder()));
  NodeMatrix M = NodeMatrix::Zero(n, n);
  PointState k;
  const int npoints = static_cast<int>(geometry.IntegrationPoints(order).size());
  for (int g = 0; g < npoints; ++g) {
    ComputePoint(geometry, order, g, X, U, dim, axisymmetric_, thickness, k);
    M.noalias() += density * k.dV0 * (k.N * k.N.transpose());
  }
  if (info.GetValue(COMPUTE_LUMPED_MASS_MATRIX)) {
    const double total = M.sum();
    const double diagonal = M.diagonal().sum();
    const NVector lumped = M.diagonal() * (total / diagonal);
    M.setZero();
    M.diagonal() = lumped;
  }
  mass.setZero(n * dim, n * dim);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b)
      for (int c = 0; c < dim; ++c) mass(a * dim + c, b * dim + c) = M(a, b);
}

void SolidElement::CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info) {
  const Properties& properties = GetProperties();
  const double alpha =
      properties.Has(RAYLEIGH_ALPHA) ? properties.GetValue(RAYLEIGH_ALPHA) : info.GetValue(RAYLEIGH_ALPHA);
  const double beta = properties.Has(RAYLEIGH_BETA) ? properties.GetValue(RAYLEIGH_BETA) : info.GetValue(RAYLEIGH_BETA);
  const auto ndof = static_cast<Eigen::Index>(GetGeometry().PointsNumber()) * Dimension();
  damping.setZero(ndof, ndof);
  thread_local Matrix buffer;
  if (alpha != 0.0) {
    CalculateMassMatrix(buffer, info);
    damping += alpha * buffer;
  }
  if (beta != 0.0) {
    CalculateAll(&buffer, nullptr, info);
    damping += beta * buffer;
  }
}

void SolidElement::Check(const ProcessInfo& info) const {
  const std::string name = Concat("element ", Id(), " (", Info(), ")");
  if (!HasProperties()) throw InputError(Concat(name, ": has no properties"));
  const Properties& properties = GetProperties();
  if (!properties.HasConstitutiveLaw())
    throw InputError(Concat(name, ": properties ", properties.Id(), " have no constitutive law"));
  const ConstitutiveLaw& law = *properties.GetConstitutiveLaw();
  const int dim = Dimension();
  if (law.WorkingSpaceDimension() != dim || law.StrainSize() != StrainSize())
    throw InputError(Concat(name, ": constitutive law ", law.Name(), " of properties ", properties.Id(), " works in ",
                            law.WorkingSpaceDimension(), "D with strain size ", law.StrainSize(),
                            "; the element needs ", dim, "D with strain size ", StrainSize(),
                            axisymmetric_ ? " (an axisymmetric law, e.g. LinearElasticAxisym2DLaw)" : ""));
  law.Check(properties);
  const Geometry& geometry = GetGeometry();
  CheckDisplacementDofs(geometry, name);
  NodalValues X, U;
  Gather(geometry, X, U);
  U.setZero();
  const double thickness = properties.Has(THICKNESS) ? properties.GetValue(THICKNESS) : 1.0;
  const int order = geometry.DefaultIntegrationOrder();
  const int npoints = static_cast<int>(geometry.IntegrationPoints(order).size());
  PointState k;
  for (int g = 0; g < npoints; ++g) {
    ComputePoint(geometry, order, g, X, U, dim, axisymmetric_, thickness, k);
    if (!(k.detJ0 > 0.0))
      throw InputError(Concat(name, " is inverted in the initial configuration at integration point ", g,
                              ": det J = ", k.detJ0, " (check the node ordering)"));
    if (axisymmetric_ && !(k.R > 0.0))
      throw InputError(
          Concat(name, ": integration point ", g, " has radius x = ", k.R, "; axisymmetric meshes must lie in x > 0"));
  }
}

void SolidElement::EvaluateResults(int g, PointResults& results, const ProcessInfo& info) {
  EnsureLaws();
  const Geometry& geometry = GetGeometry();
  const Properties& properties = GetProperties();
  const int dim = Dimension();
  const int strain_size = StrainSize();
  const auto n = static_cast<Eigen::Index>(geometry.PointsNumber());
  NodalValues X, U;
  Gather(geometry, X, U);
  const double thickness = properties.Has(THICKNESS) ? properties.GetValue(THICKNESS) : 1.0;
  PointState k;
  ComputePoint(geometry, geometry.DefaultIntegrationOrder(), g, X, U, dim, axisymmetric_, thickness, k);
  ConstitutiveLawParameters values;
  values.properties = &properties;
  values.process_info = &info;
  values.F = k.F;
  values.detF = k.F.determinant();
  values.compute_tangent = false;
  values.small_strain = kinematics_ == Kinematics::SmallDisplacement;
  if (kinematics_ == Kinematics::SmallDisplacement) {
    DofVector u(n * dim);
    for (Eigen::Index a = 0; a < n; ++a) u.segment(a * dim, dim) = U.row(a).head(dim).transpose();
    BMatrix B;
    FillB(Eigen::Matrix3d::Identity(), k.DN_DX, k.N, 1.0 / k.R, dim, strain_size, B);
    results.strain = B * u;
    values.F = EquivalentF(results.strain);
    values.detF = values.F.determinant();
  } else {
    results.strain = GreenLagrangeStrain(k.F, strain_size);
  }
  values.strain = results.strain;
  ConstitutiveLaw& law = *laws_[static_cast<std::size_t>(g)];
  law.CalculateMaterialResponse(values, ConstitutiveLaw::StressMeasure::PK2);
  results.pk2 = values.stress;
  results.pk2_tensor = voigt::StressToTensor(results.pk2);
  results.cauchy_tensor = kinematics_ == Kinematics::SmallDisplacement
                              ? results.pk2_tensor
                              : Eigen::Matrix3d(k.F * results.pk2_tensor * k.F.transpose() / values.detF);
  results.energy = law.StrainEnergy(values);
}

template <class T, class Extract>
void SolidElement::CollectResults(std::vector<T>& out, const ProcessInfo& info, Extract extract) {
  const int npoints = NumberOfIntegrationPoints();
  out.resize(static_cast<std::size_t>(npoints));
  PointResults results;
  for (int g = 0; g < npoints; ++g) {
    EvaluateResults(g, results, info);
    out[static_cast<std::size_t>(g)] = extract(results);
  }
}

void SolidElement::CalculateOnIntegrationPoints(const Variable<double>& var, std::vector<double>& out,
                                                const ProcessInfo& info) {
  if (var != VON_MISES_STRESS && var != STRAIN_ENERGY) {
    Element::CalculateOnIntegrationPoints(var, out, info);
    return;
  }
  CollectResults(out, info, [&](const PointResults& results) {
    return var == VON_MISES_STRESS ? voigt::VonMises(results.cauchy_tensor) : results.energy;
  });
}

void SolidElement::CalculateOnIntegrationPoints(const Variable<Vector>& var, std::vector<Vector>& out,
                                                const ProcessInfo& info) {
  if (var != CAUCHY_STRESS_VECTOR && var != PK2_STRESS_VECTOR && var != GREEN_LAGRANGE_STRAIN_VECTOR) {
    Element::CalculateOnIntegrationPoints(var, out, info);
    return;
  }
  const int strain_size = StrainSize();
  const auto comps = voigt::Components(strain_size);
  CollectResults(out, info, [&](const PointResults& results) -> Vector {
    if (var == GREEN_LAGRANGE_STRAIN_VECTOR) return results.strain;
    if (var == PK2_STRESS_VECTOR) return results.pk2;
    Vector v(strain_size);
    for (int c = 0; c < strain_size; ++c)
      v[c] = results.cauchy_tensor(voigt::kPairs[comps[c]][0], voigt::kPairs[comps[c]][1]);
    return v;
  });
}

void SolidElement::CalculateOnIntegrationPoints(const Variable<Matrix>& var, std::vector<Matrix>& out,
                                                const ProcessInfo& info) {
  if (var != CAUCHY_STRESS_TENSOR && var != PK2_STRESS_TENSOR) {
    Element::CalculateOnIntegrationPoints(var, out, info);
    return;
  }
  const int size = axisymmetric_ ? 3 : Dimension();
  CollectResults(out, info, [&](const PointResults& results) {
    const Eigen::Matrix3d& t = var == CAUCHY_STRESS_TENSOR ? results.cauchy_tensor : results.pk2_tensor;
    return Matrix(t.topLeftCorner(size, size));
  });
}

}  // namespace mc
