// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/simple_mortar_mapper_process.h"

#include <Eigen/SparseCore>
#include <unordered_map>
#include <vector>

#include "core/parameters/no_effect_warnings.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/variables/variable_registry.h"
#include "custom_utilities/mortar_pair_coordinates.h"
#include "custom_utilities/mortar_pair_kinematics.h"
#include "custom_utilities/nodal_normal_support.h"

namespace mc {

/// The summed operators of one mapping: the mortar (slave) side's nodes with their lumped D, and M
/// (slave node x other-side node).
struct SimpleMortarMapperProcess::Operators {
  std::vector<Node*> slave_nodes, master_nodes;
  std::unordered_map<const Node*, Eigen::Index> slave_index, master_index;
  Eigen::VectorXd d;
  Eigen::SparseMatrix<double> m;
};

namespace {

const char* const kWhyExact =
    "the dual basis makes D diagonal: the mapping is exact in one pass, without Kratos' fixed-point iterations";

// The faces of a part: its conditions, or its elements (membranes) when asked or when it has no
// conditions (Kratos switches to the elements then too).
std::vector<const Geometry*> Faces(const ModelPart& part, bool conditions) {
  std::vector<const Geometry*> faces;
  if (conditions && part.NumberOfConditions() > 0) {
    for (const Condition* condition : part.Conditions()) faces.push_back(&condition->GetGeometry());
  } else {
    for (const Element* element : part.Elements()) faces.push_back(&element->GetGeometry());
  }
  for (const Geometry* face : faces) {
    const GeometryType type = face->Type();
    if (type != GeometryType::Line2D2 && type != GeometryType::Triangle3D3 && type != GeometryType::Quadrilateral3D4)
      throw InputError(Concat("mortar mapping: model part '", part.FullName(), "' has a face of ", face->PointsNumber(),
                              " nodes that is not a linear line (2D), triangle or quadrilateral"));
  }
  if (faces.empty())
    throw InputError(Concat("mortar mapping: model part '", part.FullName(), "' has no conditions or elements to map"));
  return faces;
}

double Size(const Geometry& face) {
  double size = 0.0;
  for (const Node* a : face.Nodes())
    for (const Node* b : face.Nodes()) size = std::max(size, (a->Coordinates() - b->Coordinates()).norm());
  return size;
}

/// Unit normals of the mortar side: each face's own (at its centre) or, averaged, the nodes'.
class SideNormals {
 public:
  SideNormals(const std::vector<const Geometry*>& faces, bool average) : average_(average) {
    if (!average) return;
    for (const Geometry* face : faces)
      for (const Node* node : face->Nodes())  // (Eigen's default constructor leaves the sum uninitialised)
        sums_.try_emplace(node, Array3::Zero()).first->second += NodalNormalSupport::UnitCornerNormal(*face, *node);
    for (auto& [node, sum] : sums_) sum.normalize();
  }
  Array3 Of(const Geometry& face, int j) const {
    return average_ ? sums_.at(&face[j]) : face.UnitNormal(Array3::Zero());
  }

 private:
  bool average_;
  std::unordered_map<const Node*, Array3> sums_;
};

struct PairContext {
  const SideNormals* normals;
  MortarIntegrationSettings settings;
  double distance_threshold;
};

// Adds one pair's D (lumped) and M; false without overlap.
template <int TDim, int TSlave, int TMaster>
bool AddPair(const Geometry& slave, const Geometry& master, const PairContext& context, Eigen::VectorXd& d,
             std::vector<Eigen::Triplet<double>>& m, const std::vector<Eigen::Index>& rows,
             const std::vector<Eigen::Index>& columns) {
  using Kinematics = MortarPairKinematics<TDim, TSlave, TMaster>;
  static thread_local Kinematics kinematics;  // large (derivative arrays); values only are used
  typename Kinematics::SlaveMatrix x1, n1;
  typename Kinematics::MasterMatrix x2;
  MortarPairCoordinates<TDim, TSlave, TMaster>(slave, master, x1, x2);
  for (int j = 0; j < TSlave; ++j) n1.row(j) = context.normals->Of(slave, j).template head<TDim>().transpose();
  const Array3 normal = slave.UnitNormal(Array3::Zero());
  if (std::abs((master.Center() - slave.Center()).dot(normal)) > context.distance_threshold) return false;
  if (!kinematics.ComputeValues(x1, x2, n1, context.settings)) return false;
  for (int j = 0; j < TSlave; ++j) {
    // The row sum: D itself with the pair's dual basis, the lumped D of a sliver's standard basis.
    d(rows[j]) += kinematics.D.row(j).sum();
    for (int l = 0; l < TMaster; ++l) m.emplace_back(rows[j], columns[l], kinematics.M(j, l));
  }
  return true;
}

bool AddAnyPair(const Geometry& slave, const Geometry& master, const PairContext& context, Eigen::VectorXd& d,
                std::vector<Eigen::Triplet<double>>& m, const std::vector<Eigen::Index>& rows,
                const std::vector<Eigen::Index>& columns) {
  const auto s = slave.PointsNumber(), n = master.PointsNumber();
  if (slave.Type() == GeometryType::Line2D2) {
    if (master.Type() != GeometryType::Line2D2)
      throw InputError("mortar mapping: a line (2D) face can only be paired with lines");
    return AddPair<2, 2, 2>(slave, master, context, d, m, rows, columns);
  }
  if (master.Type() == GeometryType::Line2D2)
    throw InputError("mortar mapping: a surface face cannot be paired with a line (2D) face");
  if (s == 3 && n == 3) return AddPair<3, 3, 3>(slave, master, context, d, m, rows, columns);
  if (s == 4 && n == 4) return AddPair<3, 4, 4>(slave, master, context, d, m, rows, columns);
  if (s == 3) return AddPair<3, 3, 4>(slave, master, context, d, m, rows, columns);
  return AddPair<3, 4, 3>(slave, master, context, d, m, rows, columns);
}

Eigen::Index IndexOf(std::vector<Node*>& nodes, std::unordered_map<const Node*, Eigen::Index>& index, Node* node) {
  const auto [it, inserted] = index.emplace(node, static_cast<Eigen::Index>(nodes.size()));
  if (inserted) nodes.push_back(node);
  return it->second;
}

struct MappedVariable {
  const VariableData* data = nullptr;
  bool historical = true;
  int components = 1;

  double Get(const Node& node, int c) const {
    if (components == 1) {
      const auto& v = static_cast<const Variable<double>&>(*data);
      return historical ? node.FastGetSolutionStepValue(v) : node.GetValue(v);
    }
    const auto& v = static_cast<const Variable<Array3>&>(*data);
    return historical ? node.FastGetSolutionStepValue(v)[c] : node.GetValue(v)[c];
  }
  void Set(Node& node, int c, double value) const {
    if (components == 1) {
      const auto& v = static_cast<const Variable<double>&>(*data);
      if (historical)
        node.FastGetSolutionStepValue(v) = value;
      else
        node.SetValue(v, value);
      return;
    }
    const auto& v = static_cast<const Variable<Array3>&>(*data);
    if (historical) {
      node.FastGetSolutionStepValue(v)[c] = value;
    } else {
      Array3 current = node.GetValue(v);
      current[c] = value;
      node.SetValue(v, current);
    }
  }
};

MappedVariable Resolve(const Parameters& name, bool historical, const ModelPart& part) {
  MappedVariable variable;
  variable.data = &VariableRegistry::Instance().Get(name.GetString());  // InputError with the nearest names
  variable.historical = historical;
  const ValueType type = variable.data->Type();
  if (type != ValueType::Double && type != ValueType::Array3)
    throw InputError(Concat(name.Where(), ": '", name.GetString(), "' is a ", ValueTypeName(type),
                            " variable; the mortar mapping maps scalars (double) and arrays"));
  variable.components = type == ValueType::Double ? 1 : 3;
  if (historical)
    for (const Node* node : part.Nodes())
      if (!node->HasSolutionStepValue(*variable.data))
        throw InputError(Concat(name.Where(), ": '", name.GetString(), "' is not a solution-step variable of '",
                                part.FullName(), "' (node ", node->Id(),
                                "); set the *_variable_historical key false "
                                "for a non-historical value"));
  return variable;
}

}  // namespace

Parameters SimpleMortarMapperProcess::GetDefaultParameters() {
  return Parameters(R"({
    "echo_level": 0,
    "consider_tessellation": false,
    "using_average_nodal_normal": true,
    "discontinuous_interface": false,
    "discontinous_interface_factor": 1.0e-4,
    "absolute_convergence_tolerance": 1.0e-9,
    "relative_convergence_tolerance": 1.0e-4,
    "max_number_iterations": 10,
    "integration_order": 2,
    "distance_threshold": 1.0e24,
    "zero_tolerance_factor": 1.0,
    "remove_isolated_conditions": false,
    "mapping_coefficient": 1.0,
    "origin_variable": "TEMPERATURE",
    "destination_variable": "",
    "origin_variable_historical": true,
    "origin_are_conditions": true,
    "destination_variable_historical": true,
    "destination_are_conditions": true,
    "update_interface": true,
    "search_parameters": {
      "allocation_size": 1000,
      "bucket_size": 4,
      "search_factor": 3.5
    },
    "conservative": false,
    "inverse_of_d": true
  })");
}

SimpleMortarMapperProcess::SimpleMortarMapperProcess(ModelPart& origin, ModelPart& destination, Parameters settings)
    : origin_(origin), destination_(destination), settings_(std::move(settings)) {
  const Parameters defaults = GetDefaultParameters();
  settings_.RecursivelyValidateAndAssignDefaults(defaults);
  for (const char* key : {"absolute_convergence_tolerance", "relative_convergence_tolerance", "max_number_iterations"})
    NoEffectWarnings::IfGiven(settings_, defaults, key, kWhyExact);
  NoEffectWarnings::IfGiven(settings_, defaults, "discontinous_interface_factor",
                            "only the discontinuous interface reads it, and it is not implemented");
  NoEffectWarnings::IfGiven(settings_, defaults, "remove_isolated_conditions",
                            "destination faces without overlap are left in their model part; their nodes keep "
                            "their values");
  for (const char* key : {"allocation_size", "bucket_size"})
    NoEffectWarnings::IfGiven(settings_["search_parameters"], defaults["search_parameters"], key,
                              "the pairs come from a brute-force bounding-ball test (no tree)");
  CheckSettings();
}

void SimpleMortarMapperProcess::CheckSettings() const {
  if (settings_["discontinuous_interface"].GetBool())
    throw NotImplementedError(Concat(settings_["discontinuous_interface"].Where(),
                                     ": true (the inverse database of discontinuous interfaces) is not implemented"));
  if (settings_["consider_tessellation"].GetBool())
    throw NotImplementedError(Concat(settings_["consider_tessellation"].Where(),
                                     ": true (Delaunay tessellation of the clipped polygons) is not implemented"));
  for (const char* key : {"distance_threshold", "zero_tolerance_factor"}) {
    const double value = settings_[key].GetDouble();
    if (!(value > 0.0)) throw InputError(Concat(settings_[key].Where(), ": must be a positive number, got ", value));
  }
  const double factor = settings_["search_parameters"]["search_factor"].GetDouble();
  if (!(factor > 0.0))
    throw InputError(
        Concat(settings_["search_parameters"]["search_factor"].Where(), ": must be a positive number, got ", factor));
  const int order = settings_["integration_order"].GetInt();
  if (order < 1 || order > 5)
    throw InputError(Concat(settings_["integration_order"].Where(), ": must be 1 to 5, got ", order));
}

void SimpleMortarMapperProcess::BuildOperators() {
  const bool conservative = settings_["conservative"].GetBool();
  // The mortar (slave) side: the destination for the consistent mapping, the origin for the
  // conservative one.
  ModelPart& slave_part = conservative ? origin_ : destination_;
  ModelPart& master_part = conservative ? destination_ : origin_;
  const bool slave_conditions =
      settings_[conservative ? "origin_are_conditions" : "destination_are_conditions"].GetBool();
  const bool master_conditions =
      settings_[conservative ? "destination_are_conditions" : "origin_are_conditions"].GetBool();
  const std::vector<const Geometry*> slaves = Faces(slave_part, slave_conditions);
  const std::vector<const Geometry*> masters = Faces(master_part, master_conditions);
  const SideNormals normals(slaves, settings_["using_average_nodal_normal"].GetBool());

  PairContext context{&normals, {}, settings_["distance_threshold"].GetDouble()};
  context.settings.integration_order = settings_["integration_order"].GetInt();
  context.settings.zero_tolerance_factor = settings_["zero_tolerance_factor"].GetDouble();
  const double search_factor = settings_["search_parameters"]["search_factor"].GetDouble();

  operators_ = std::make_shared<Operators>();
  Operators& op = *operators_;
  std::vector<Eigen::Index> rows, columns;
  for (const Geometry* face : slaves)
    for (Node* node : face->Nodes()) IndexOf(op.slave_nodes, op.slave_index, node);
  for (const Geometry* face : masters)
    for (Node* node : face->Nodes()) IndexOf(op.master_nodes, op.master_index, node);
  op.d = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(op.slave_nodes.size()));
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<Array3, double>> master_balls;
  for (const Geometry* face : masters) master_balls.emplace_back(face->Center(), Size(*face));
  pairs_ = 0;
  for (const Geometry* slave : slaves) {
    const Array3 centre = slave->Center();
    const double size = Size(*slave);
    rows.clear();
    for (const Node* node : slave->Nodes()) rows.push_back(op.slave_index.at(node));
    for (std::size_t k = 0; k < masters.size(); ++k) {
      const auto& [master_centre, master_size] = master_balls[k];
      if ((master_centre - centre).norm() > search_factor * std::max(size, master_size)) continue;
      columns.clear();
      for (const Node* node : masters[k]->Nodes()) columns.push_back(op.master_index.at(node));
      pairs_ += AddAnyPair(*slave, *masters[k], context, op.d, triplets, rows, columns) ? 1 : 0;
    }
  }
  op.m.resize(static_cast<Eigen::Index>(op.slave_nodes.size()), static_cast<Eigen::Index>(op.master_nodes.size()));
  op.m.setFromTriplets(triplets.begin(), triplets.end());
  built_ = true;
}

void SimpleMortarMapperProcess::Execute() {
  if (!built_ || settings_["update_interface"].GetBool()) BuildOperators();
  const Operators& op = *operators_;
  const bool conservative = settings_["conservative"].GetBool();
  const bool inverse = settings_["inverse_of_d"].GetBool();
  const double coefficient = settings_["mapping_coefficient"].GetDouble();
  const Parameters destination_name = settings_["destination_variable"].GetString().empty()
                                          ? settings_["origin_variable"]
                                          : settings_["destination_variable"];
  const MappedVariable from =
      Resolve(settings_["origin_variable"], settings_["origin_variable_historical"].GetBool(), origin_);
  const MappedVariable to =
      Resolve(destination_name, settings_["destination_variable_historical"].GetBool(), destination_);
  if (from.components != to.components)
    throw InputError(Concat(destination_name.Where(), ": '", destination_name.GetString(),
                            "' must be of the type of origin_variable '", settings_["origin_variable"].GetString(),
                            "'"));

  // Rows of D with a zero entry are not reached by any overlap.
  const Eigen::VectorXd inverse_d = op.d.unaryExpr([](double v) { return v > 0.0 ? 1.0 / v : 0.0; });
  const std::vector<Node*>& origin_nodes = conservative ? op.slave_nodes : op.master_nodes;
  const std::vector<Node*>& destination_nodes = conservative ? op.master_nodes : op.slave_nodes;
  // The destination nodes some overlap reaches.
  const Eigen::VectorXd reached =
      conservative ? Eigen::VectorXd(op.m.cwiseAbs().transpose() * Eigen::VectorXd::Ones(op.m.rows())) : op.d;
  mapped_nodes_ = static_cast<std::size_t>((reached.array() > 0.0).count());
  for (int c = 0; c < from.components; ++c) {
    Eigen::VectorXd values(static_cast<Eigen::Index>(origin_nodes.size()));
    for (std::size_t i = 0; i < origin_nodes.size(); ++i)
      values(static_cast<Eigen::Index>(i)) = from.Get(*origin_nodes[i], c);
    Eigen::VectorXd mapped;
    if (conservative) {
      mapped = op.m.transpose() * (inverse ? Eigen::VectorXd(values.cwiseProduct(inverse_d)) : values);
    } else {
      mapped = op.m * values;
      if (inverse) mapped = mapped.cwiseProduct(inverse_d);
    }
    for (std::size_t i = 0; i < destination_nodes.size(); ++i)
      if (reached(static_cast<Eigen::Index>(i)) > 0.0)
        to.Set(*destination_nodes[i], c, coefficient * mapped(static_cast<Eigen::Index>(i)));
  }
  if (settings_["echo_level"].GetInt() > 0)
    Logger::Info(Concat("mortar mapping '", origin_.FullName(), "' -> '", destination_.FullName(), "': ", pairs_,
                        " pairs, ", mapped_nodes_, " of ", destination_nodes.size(), " destination nodes reached"));
}

}  // namespace mc
