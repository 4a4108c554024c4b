// SPDX-License-Identifier: BSD-3-Clause
#include "thermal/elements/laplacian_element.h"

#include <Eigen/LU>

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "thermal/variables/thermal_variables.h"

namespace mc {

std::string LaplacianElement::Info() const {
  const ReferenceElement& reference = GetGeometry().Reference();
  return Concat("LaplacianElement", reference.WorkingSpaceDimension(), "D", reference.NodesNumber(), "N");
}

std::unique_ptr<Element> LaplacianElement::Create(IndexType id, Geometry::NodesArray nodes,
                                                  Properties* properties) const {
  return std::make_unique<LaplacianElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
}

void LaplacianElement::GetDofList(DofsVectorType& dofs, const ProcessInfo&) const {
  const Geometry& geometry = GetGeometry();
  dofs.resize(geometry.PointsNumber());
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a) dofs[a] = &geometry[a].GetDof(TEMPERATURE);
}

void LaplacianElement::ConductivityAndSource(Matrix& conductivity, Vector& source) const {
  const Geometry& geometry = GetGeometry();
  const int dim = geometry.Reference().WorkingSpaceDimension();
  const auto n = static_cast<Eigen::Index>(geometry.PointsNumber());
  const double k = GetProperties().GetValue(CONDUCTIVITY);
  Matrix X(n, dim);
  Vector Q = Vector::Zero(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Node& node = geometry[static_cast<std::size_t>(a)];
    X.row(a) = node.X0().head(dim).transpose();
    if (node.HasSolutionStepValue(HEAT_FLUX)) Q(a) = node.FastGetSolutionStepValue(HEAT_FLUX);
  }
  conductivity.setZero(n, n);
  source.setZero(n);
  const int order = geometry.DefaultIntegrationOrder();
  const auto& points = geometry.IntegrationPoints(order);
  const Matrix& N = geometry.ShapeFunctionsValues(order);
  for (std::size_t g = 0; g < points.size(); ++g) {
    const Matrix& dN = geometry.ShapeFunctionsLocalGradients(order)[g];
    const Matrix J = X.transpose() * dN;
    const double det = J.determinant();
    if (!(det > 0.0))
      throw SolutionError(Concat("element ", Id(), " (", Info(), "): non-positive Jacobian ", det,
                                 " at integration point ", g, " (inverted or degenerate element)"));
    const Matrix gradients = dN * J.inverse();
    const double dV = points[g].weight * det;
    conductivity.noalias() += (k * dV) * gradients * gradients.transpose();
    source.noalias() +=
        (dV * N.row(static_cast<Eigen::Index>(g)).dot(Q)) * N.row(static_cast<Eigen::Index>(g)).transpose();
  }
}

void LaplacianElement::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo&) {
  ConductivityAndSource(lhs, rhs);
  const Geometry& geometry = GetGeometry();
  Vector temperature(static_cast<Eigen::Index>(geometry.PointsNumber()));
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a)
    temperature(static_cast<Eigen::Index>(a)) = geometry[a].FastGetSolutionStepValue(TEMPERATURE);
  rhs.noalias() -= lhs * temperature;
}

void LaplacianElement::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) {
  Vector rhs;
  ConductivityAndSource(lhs, rhs);
}

void LaplacianElement::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) {
  Matrix lhs;
  CalculateLocalSystem(lhs, rhs, info);
}

void LaplacianElement::Check(const ProcessInfo&) const {
  if (!HasProperties() || !GetProperties().Has(CONDUCTIVITY) || !(GetProperties().GetValue(CONDUCTIVITY) > 0.0))
    throw InputError(Concat("element ", Id(), " (", Info(), "): its properties",
                            HasProperties() ? Concat(" ", GetProperties().Id()) : std::string(),
                            " need a positive CONDUCTIVITY"));
  for (const Node* node : GetGeometry().Nodes())
    if (!node->HasSolutionStepValue(TEMPERATURE) || !node->HasDofFor(TEMPERATURE))
      throw InputError(Concat("element ", Id(), " (", Info(), "): node ", node->Id(),
                              " has no TEMPERATURE DoF (add it with solver_settings.auxiliary_dofs_list "
                              "[\"TEMPERATURE\"] and auxiliary_reaction_list [\"REACTION_FLUX\"])"));
}

}  // namespace mc
